// SPDX-License-Identifier: MIT
// Structure-of-arrays particle state with one owner. remove() swaps the last particle into the
// hole (O(1)); remove_all() keeps the others' order (O(n)); stable ids survive both, indices do
// not.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/bytes.hpp"
#include "core/vec3.hpp"

namespace silodem {

class ParticleStore {
 public:
  std::vector<Vec3> x, v, omega;  // position (m), velocity (m/s), angular velocity (rad/s)
  std::vector<Vec3> f, t;         // force (N), torque (N m) of the current step
  std::vector<Vec3> f_ext;        // constant external force (N), e.g. a test's pull
  std::vector<double> radius, mass, inv_mass, inv_inertia;
  std::vector<int> material;
  std::vector<std::uint64_t> id;

  std::size_t size() const { return x.size(); }
  // Adds a solid sphere (I = 2/5 m R^2); returns its stable id.
  std::uint64_t add(const Vec3& pos, const Vec3& vel, const Vec3& spin, double r, double m,
                    int mat);
  void remove(std::size_t i);
  // Removes the particles at `idx` (any order, duplicates allowed), keeping the order of the
  // others (unlike remove()). Returns where each particle went: new index by old index, -1 for a
  // removed one.
  std::vector<int> remove_all(std::vector<std::size_t> idx);
  // Reorders every array: new index k holds the particle that was at order[k] (a permutation).
  void permute(const std::vector<std::size_t>& order);
  double inertia(std::size_t i) const { return 1.0 / inv_inertia[i]; }
  // Index of a stable id, or -1 (linear search: for tests and tools, not for loops).
  long index_of(std::uint64_t id) const;
  std::uint64_t next_id() const { return next_id_; }
  // Checkpoint: every array and the id counter.
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  std::uint64_t next_id_ = 0;
};

}  // namespace silodem
