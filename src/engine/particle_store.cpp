// SPDX-License-Identifier: MIT
#include "engine/particle_store.hpp"

#include <algorithm>
#include <stdexcept>

namespace silodem {

std::uint64_t ParticleStore::add(const Vec3& pos, const Vec3& vel, const Vec3& spin, double r,
                                 double m, int mat) {
  x.push_back(pos);
  v.push_back(vel);
  omega.push_back(spin);
  f.push_back({});
  t.push_back({});
  f_ext.push_back({});
  radius.push_back(r);
  mass.push_back(m);
  inv_mass.push_back(1.0 / m);
  inv_inertia.push_back(1.0 / (0.4 * m * r * r));
  material.push_back(mat);
  id.push_back(next_id_);
  return next_id_++;
}

template <class T>
static void swap_pop(std::vector<T>& a, std::size_t i) {
  a[i] = a.back();
  a.pop_back();
}

void ParticleStore::remove(std::size_t i) {
  swap_pop(x, i), swap_pop(v, i), swap_pop(omega, i), swap_pop(f, i), swap_pop(t, i);
  swap_pop(f_ext, i), swap_pop(radius, i), swap_pop(mass, i), swap_pop(inv_mass, i);
  swap_pop(inv_inertia, i), swap_pop(material, i), swap_pop(id, i);
}

// Keeps the order of the rest (one compaction pass over every array): swapping the last particle
// into each hole, as remove() does, would put a particle from the top of a silo (filled last) among
// those at its outlet, and a discharge removes thousands, until memory order no longer follows
// space and the force loop waits for memory (BENCHMARKS.md, "What the engine does to be fast").
template <class T>
static void compact(std::vector<T>& a, const std::vector<int>& to) {
  std::size_t w = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (to[k] >= 0) a[w++] = a[k];
  a.resize(w);
}

std::vector<int> ParticleStore::remove_all(std::vector<std::size_t> idx) {
  std::sort(idx.begin(), idx.end());
  idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
  if (!idx.empty() && idx.back() >= size())
    throw std::out_of_range("ParticleStore::remove_all: index beyond the last particle");
  std::vector<int> to(size(), 0);
  for (std::size_t k : idx) to[k] = -1;
  int next = 0;
  for (int& k : to) k = k < 0 ? -1 : next++;
  if (idx.empty()) return to;
  compact(x, to), compact(v, to), compact(omega, to), compact(f, to), compact(t, to);
  compact(f_ext, to), compact(radius, to), compact(mass, to), compact(inv_mass, to);
  compact(inv_inertia, to), compact(material, to), compact(id, to);
  return to;
}

template <class T>
static void apply(std::vector<T>& a, const std::vector<std::size_t>& order) {
  std::vector<T> b(a.size());
  for (std::size_t k = 0; k < order.size(); ++k) b[k] = a[order[k]];
  a.swap(b);
}

void ParticleStore::permute(const std::vector<std::size_t>& order) {
  apply(x, order), apply(v, order), apply(omega, order), apply(f, order), apply(t, order);
  apply(f_ext, order), apply(radius, order), apply(mass, order), apply(inv_mass, order);
  apply(inv_inertia, order), apply(material, order), apply(id, order);
}

long ParticleStore::index_of(std::uint64_t want) const {
  for (std::size_t i = 0; i < id.size(); ++i)
    if (id[i] == want) return static_cast<long>(i);
  return -1;
}

void ParticleStore::save(ByteWriter& w) const {
  w.tag("PART");
  w.put(x), w.put(v), w.put(omega), w.put(f), w.put(t), w.put(f_ext);
  w.put(radius), w.put(mass), w.put(inv_mass), w.put(inv_inertia);
  w.put(material), w.put(id), w.put(next_id_);
}

void ParticleStore::load(ByteReader& r) {
  r.tag("PART");
  r.get(x), r.get(v), r.get(omega), r.get(f), r.get(t), r.get(f_ext);
  r.get(radius), r.get(mass), r.get(inv_mass), r.get(inv_inertia);
  r.get(material), r.get(id), r.get(next_id_);
  const std::size_t n = x.size();
  for (std::size_t s :
       {v.size(), omega.size(), f.size(), t.size(), f_ext.size(), radius.size(), mass.size(),
        inv_mass.size(), inv_inertia.size(), material.size(), id.size()})
    if (s != n) throw std::runtime_error("checkpoint: particle arrays of different lengths");
}

}  // namespace silodem
