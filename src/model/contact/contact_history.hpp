// SPDX-License-Identifier: MIT
// Per-contact state that lives as long as the contact: the tangential spring (accumulated
// tangential displacement, PHYSICS.md 2) and the rolling spring torque of the EPSD law.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/inline.hpp"
#include "core/vec3.hpp"

namespace silodem {

struct ContactState {
  Vec3 tangential;  // m, spring elongation (force = -k_t * tangential)
  Vec3 rolling;     // N m, elastic rolling torque on i (EPSD)
};

// Rotate a vector stored in the old tangent plane into the plane normal to n, keeping its
// length (the contact frame turns as the particles roll over each other).
SILODEM_HOT void rotate_into_tangent_plane(Vec3& s, const Vec3& n) {
  // Without branches: for s = 0 (a new contact) or s parallel to n the result is 0 either way.
  const double before = norm2(s);
  s -= dot(s, n) * n;
  const double after = norm2(s);
  s *= std::sqrt(before / std::max(after, std::numeric_limits<double>::min()));
}

}  // namespace silodem
