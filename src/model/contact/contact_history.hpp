// SPDX-License-Identifier: MIT
// Per-contact state that lives as long as the contact. Each law declares how many values it keeps
// (its `history`, laws.hpp); a contact's state is the laws' values side by side, in slot order
// (normal, tangential, rolling, cohesion), as LAMMPS's granular sub-models declare
// `size_history`. The engine stores `StateLayout::size` doubles per contact and knows nothing of
// what they mean, except how each one turns when the pair's i and j swap.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/inline.hpp"
#include "core/vec3.hpp"

namespace silodem {

// The most values the four laws of a contact may keep together.
inline constexpr int kMaxHistory = 8;

struct ContactState {
  double h[kMaxHistory] = {};

  Vec3 vec(int at) const { return {h[at], h[at + 1], h[at + 2]}; }
  void set_vec(int at, const Vec3& v) { h[at] = v.x, h[at + 1] = v.y, h[at + 2] = v.z; }
  bool nonzero() const {
    bool any = false;
    for (double v : h) any = any || v != 0.0;
    return any;
  }
};

// Where each slot's values sit in a contact's state, and what they do when i and j swap.
struct StateLayout {
  int size = 0;                   // values per contact
  int offset[4] = {0, 0, 0, 0};   // by Slot
  int count[4] = {0, 0, 0, 0};    // by Slot
  std::string law[4];             // by Slot: the law that owns the values (checkpoints name it)
  double swap[kMaxHistory] = {};  // factor of each value when i and j swap (-1: a vector on i)

  ContactState swapped(const ContactState& s) const {
    ContactState o;
    for (int k = 0; k < size; ++k) o.h[k] = swap[k] * s.h[k];
    return o;
  }
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
