// SPDX-License-Identifier: MIT
#include "engine/particle_store.hpp"

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

long ParticleStore::index_of(std::uint64_t want) const {
  for (std::size_t i = 0; i < id.size(); ++i)
    if (id[i] == want) return static_cast<long>(i);
  return -1;
}

}  // namespace silodem
