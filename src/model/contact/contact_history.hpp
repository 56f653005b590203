// SPDX-License-Identifier: MIT
// Per-contact state that lives as long as the contact: the tangential spring (accumulated
// tangential displacement, PHYSICS.md 2) and the rolling spring torque of the EPSD law.
#pragma once
#include <cmath>

#include "core/vec3.hpp"

namespace silodem {

struct ContactState {
  Vec3 tangential;  // m, spring elongation (force = -k_t * tangential)
  Vec3 rolling;     // N m, elastic rolling torque on i (EPSD)
};

// Rotate a vector stored in the old tangent plane into the plane normal to n, keeping its
// length (the contact frame turns as the particles roll over each other).
inline void rotate_into_tangent_plane(Vec3& s, const Vec3& n) {
  const double before = norm2(s);
  if (before == 0.0) return;
  s -= dot(s, n) * n;
  const double after = norm2(s);
  if (after > 0.0) s *= std::sqrt(before / after);
}

}  // namespace silodem
