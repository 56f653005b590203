// SPDX-License-Identifier: MIT
#include "model/material.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace silodem {

double porosity(double bulk_density, double true_density, double moisture) {
  return 1.0 - (bulk_density / true_density) * (1.0 - moisture);  // Eq. 15
}

double tensile_strength(double cohesion, double friction_angle) {
  return cohesion / std::tan(friction_angle);  // Eq. 16
}

double moisture_cohesion_force(double sauter_diameter, double sigma_t, double eps) {
  return sauter_diameter * sauter_diameter * sigma_t * eps / (1.0 - eps);  // Eq. 14
}

double sphere_mass(double diameter, double density) {
  return kPi / 6.0 * diameter * diameter * diameter * density;
}

CoalDerived derive(const CoalProperties& c) {
  CoalDerived d;
  // Without the measured properties (cohesion_force_n given instead) Eq. 15-16 are not defined.
  const bool measured = c.bulk_density > 0.0 && c.friction_angle > 0.0;
  d.porosity = measured ? porosity(c.bulk_density, c.true_density, c.moisture) : 0.0;
  d.tensile_strength = measured ? tensile_strength(c.cohesion, c.friction_angle) : 0.0;
  d.cohesion_force =
      c.cohesion_force_override
          ? *c.cohesion_force_override
          : moisture_cohesion_force(c.sauter_diameter, d.tensile_strength, d.porosity);
  d.particle_mass = sphere_mass(c.diameter, c.true_density);
  d.bond_number = d.cohesion_force / (d.particle_mass * kGravity);
  return d;
}

}  // namespace silodem
