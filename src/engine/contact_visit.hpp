// SPDX-License-Identifier: MIT
// What the force pass, the contact tally and the energy share: a particle's state as the laws
// see it, and the one loop over a particle's listed wall contacts.
#pragma once
#include <cstddef>

#include "core/inline.hpp"
#include "engine/neighbor/verlet_list.hpp"
#include "engine/particle_store.hpp"
#include "engine/walls/wall.hpp"
#include "model/contact/contact_geometry.hpp"

namespace silodem {

SILODEM_HOT BodyState body(const ParticleStore& p, std::size_t i) {
  // The inertia the integrator uses (infinite for a particle whose rotation is switched off); a
  // law that does not read it never pays for the division (dispatch.hpp).
  return {p.x[i],          p.v[i], p.omega[i], p.radius[i], p.mass[i], 1.0 / p.inv_inertia[i],
          p.inv_inertia[i]};
}

// Particle i's listed wall contacts, in list order. A listed wall acts if it is enabled and its
// surface is within `reach` of the centre (Wall::near): `hit(e, wall, h)` is called for those,
// `miss(e)` for the others (e: the contact's index in the list). The list omits disabled walls
// when it is built, but a wall switched off since (set_wall_enabled) stays listed until the next
// build, which the tally and the energy may read before.
template <class Hit, class Miss>
SILODEM_HOT void for_each_wall_contact(const VerletList& list, const WallList& walls, std::size_t i,
                                       const Vec3& x, double reach, Hit&& hit, Miss&& miss) {
  for (int e = list.wall_offset[i]; e < list.wall_offset[i + 1]; ++e) {
    const Wall& w = *walls[std::size_t(list.wall[e])];
    WallHit h;
    if (w.enabled && w.near(x, reach, h))
      hit(std::size_t(e), w, h);
    else
      miss(std::size_t(e));
  }
}

}  // namespace silodem
