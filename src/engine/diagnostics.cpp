// SPDX-License-Identifier: MIT
// Read-only passes over Simulation's contacts for observers: the per-particle contact tally
// (probes, VTK) and the energy budget. They copy the contact history and never advance it.
#include <algorithm>
#include <cmath>

#include "engine/contact_visit.hpp"
#include "engine/simulation.hpp"
#include "model/contact/dispatch.hpp"

namespace silodem {

ContactTally Simulation::contact_tally() const {
  const std::size_t n = p_.size();
  ContactTally t;
  t.particle_contacts.assign(n, 0);
  t.wall_contacts.assign(n, 0);
  t.cohesion_sum.assign(n, 0.0);
  t.cohesion_max_pp.assign(n, 0.0);
  if (!initialized_) return t;
  for (std::size_t i = 0; i < n; ++i) {
    const BodyState bi = body(p_, i);
    for (int e = list_.offset[i]; e < list_.offset[i + 1]; ++e) {
      const std::size_t j = std::size_t(list_.partner[e]);
      const ContactLaw& law = model_.pair(p_.material[i], p_.material[j]);
      const double reach = (p_.radius[i] + p_.radius[j]) * (1.0 + law.reach_over_d);
      const Vec3 d = separation(i, j);
      if (norm2(d) >= reach * reach) continue;
      ContactState copy = list_.state(std::size_t(e));
      BodyState bj = body(p_, j);
      if (s_.periodic.any()) bj.x = p_.x[i] - d;  // the image next to i
      const ContactResult r = evaluate_contact(law, pair_geometry(bi, bj), copy, s_.dt);
      if (r.touching) ++t.particle_contacts[i], ++t.particle_contacts[j];
      t.cohesion_sum[i] += r.cohesion;
      t.cohesion_sum[j] += r.cohesion;
      t.cohesion_max_pp[i] = std::max(t.cohesion_max_pp[i], r.cohesion);
      t.cohesion_max_pp[j] = std::max(t.cohesion_max_pp[j], r.cohesion);
    }
    const ContactLaw& wl = model_.wall(p_.material[i]);
    const double reach = p_.radius[i] * (1.0 + 2.0 * wl.reach_over_d);
    for_each_wall_contact(
        list_, walls_, i, p_.x[i], reach,
        [&](std::size_t e, const Wall& w, const WallHit& hit) {
          ContactState copy = list_.wall_state(e);
          const ContactResult r = evaluate_contact(
              wl, wall_geometry(bi, hit.n, hit.distance, w.velocity()), copy, s_.dt);
          if (r.touching) ++t.wall_contacts[i];
          t.cohesion_sum[i] += r.cohesion;
        },
        [](std::size_t) {});
  }
  return t;
}

EnergyBudget Simulation::energy() const {
  EnergyBudget e;
  const double g = norm(s_.gravity);
  const Vec3 up = g > 0 ? -s_.gravity / g : Vec3{0, 0, 1};
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const BodyState bi = body(p_, i);
    e.translational += 0.5 * p_.mass[i] * norm2(p_.v[i]);
    e.rotational += 0.5 / p_.inv_inertia[i] * norm2(p_.omega[i]);
    e.gravitational += p_.mass[i] * g * dot(p_.x[i], up);
    for (int k = list_.offset[i]; k < list_.offset[i + 1]; ++k) {
      const std::size_t j = std::size_t(list_.partner[k]);
      BodyState bj = body(p_, j);
      if (s_.periodic.any()) bj.x = p_.x[i] - separation(i, j);  // the image next to i
      const ContactGeometry gc = pair_geometry(bi, bj);
      if (gc.overlap > 0)
        e.elastic += normal_elastic_energy(model_.pair(p_.material[i], p_.material[j]), gc,
                                           list_.state(std::size_t(k)));
    }
    const ContactLaw& wl = model_.wall(p_.material[i]);
    for_each_wall_contact(
        list_, walls_, i, p_.x[i], p_.radius[i] * (1.0 + 2.0 * wl.reach_over_d),
        [&](std::size_t we, const Wall& w, const WallHit& hit) {
          const ContactGeometry gc = wall_geometry(bi, hit.n, hit.distance, w.velocity());
          if (gc.overlap > 0) e.elastic += normal_elastic_energy(wl, gc, list_.wall_state(we));
        },
        [](std::size_t) {});
  }
  return e;
}

}  // namespace silodem
