// SPDX-License-Identifier: MIT
// Periodic boundaries along any of x, y, z: a particle leaving the box at one face comes back at
// the other, and two particles interact through the nearest of their images (the minimum-image
// convention; Allen & Tildesley, Computer Simulation of Liquids, 2nd ed., 1.6.3). The contact
// list is indexed by particle, not by image, so a contact's history survives the crossing.
#pragma once
#include <cmath>

#include "core/vec3.hpp"

namespace silodem {

struct PeriodicBox {
  bool on[3] = {false, false, false};
  double lo[3] = {0.0, 0.0, 0.0};   // m, lower face
  double len[3] = {0.0, 0.0, 0.0};  // m, period (upper face = lo + len)

  bool any() const { return on[0] || on[1] || on[2]; }
  // Sets axis a (0 = x, 1 = y, 2 = z) periodic over [lo, lo + len).
  void set(int a, double lo_a, double len_a) {
    on[a] = true;
    lo[a] = lo_a;
    len[a] = len_a;
  }
  // The nearest image of a separation d = x_i - x_j (each periodic component in [-len/2, len/2]).
  Vec3 image(Vec3 d) const {
    if (on[0]) d.x -= len[0] * std::nearbyint(d.x / len[0]);
    if (on[1]) d.y -= len[1] * std::nearbyint(d.y / len[1]);
    if (on[2]) d.z -= len[2] * std::nearbyint(d.z / len[2]);
    return d;
  }
  // A position brought into the box along the periodic axes.
  Vec3 wrap(Vec3 x) const {
    auto w = [](double c, double l0, double l) {
      const double u = c - l * std::floor((c - l0) / l);
      return u < l0 + l ? u : l0;  // floor's rounding may leave u = l0 + l exactly
    };
    if (on[0]) x.x = w(x.x, lo[0], len[0]);
    if (on[1]) x.y = w(x.y, lo[1], len[1]);
    if (on[2]) x.z = w(x.z, lo[2], len[2]);
    return x;
  }
};

}  // namespace silodem
