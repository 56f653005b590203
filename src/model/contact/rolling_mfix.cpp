// SPDX-License-Identifier: MIT
// MFIX's rolling friction (PHYSICS.md 2 and E10): each particle feels a torque
//   T_i = -mu_r d_i k_n delta_n omega_i / |omega_i|
// against its own angular velocity, with d_i its own diameter ("mew_r is multiplied by the
// diameter") and the elastic normal force only. A constant-torque (Ai et al. 2011 type A) law:
// a rolling sphere decelerates at (10/7) mu_r g on a plane; at rest it chatters around omega = 0.
#include <cmath>

#include "model/contact/registry.hpp"

namespace silodem {
namespace {

Vec3 oppose(const Vec3& omega, double magnitude) {
  const double w = norm(omega);
  return w > 0.0 ? omega * (-magnitude / w) : Vec3{};
}

RollingTorque kernel(const RollingParams& p, const ContactGeometry& g, const NormalParams& np,
                     const NormalForce&, double, Vec3&, double) {
  const double elastic = np.stiffness * g.overlap;  // k_n delta_n, elastic part only
  RollingTorque t;
  t.on_i = oppose(g.omega_i, p.friction * g.d_i * elastic);
  if (g.d_j > 0.0) t.on_j = oppose(g.omega_j, p.friction * g.d_j * elastic);
  return t;
}

std::vector<Field> fields(bool) {
  return {Field::number("friction", "rolling friction coefficient mu_r (torque mu_r d k_n delta_n)")
              .needed()
              .at_least(0)
              .at_most(10)};
}

void configure(const ParamValues& v, const LawContext&, ContactLaw& law) {
  law.rp.friction = v.number("friction");
  law.rolling = &kernel;
}

}  // namespace

LawEntry rolling_mfix_entry() {
  return {"mfix", Slot::Rolling,
          "MFIX: torque mu_r d k_n delta_n against each particle's own spin (E10)", &fields,
          &configure};
}

}  // namespace silodem
