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

CoalDerived derive(const CoalProperties& c, double rumpf_porosity) {
  CoalDerived d;
  // Without the measured properties (cohesion_force_n given instead) Eq. 15-16 are not defined.
  const bool measured = c.bulk_density > 0.0 && c.friction_angle > 0.0;
  d.porosity = measured ? porosity(c.bulk_density, c.true_density, c.moisture) : 0.0;
  d.tensile_strength = measured ? tensile_strength(c.cohesion, c.friction_angle) : 0.0;
  d.rumpf_porosity = rumpf_porosity > 0.0 ? rumpf_porosity : d.porosity;
  d.cohesion_force =
      c.cohesion_force_override
          ? *c.cohesion_force_override
          : moisture_cohesion_force(c.sauter_diameter, d.tensile_strength, d.rumpf_porosity);
  d.particle_mass = sphere_mass(c.diameter, c.true_density);
  d.bond_number = d.cohesion_force / (d.particle_mass * kGravity);
  return d;
}

const std::vector<Bound<CoalProperties>>& coal_fields() {
  using F = Field;
  using S = CoalProperties;
  static const std::vector<Bound<S>> b = {
      bind(F::text("name", "name used by particles, lattices and reports", {}), &S::name),
      unbound<S>(F::text("symbol",
                         "letter(s) used in scenario names such as \"L3-I2\" (default: first "
                         "letter of the name)",
                         {}, "-")),
      bind(F::number("diameter_mm", "average particle diameter (the DEM size before k)", "mm",
                     units::mm)
               .needed()
               .above(0)
               .at_most(1e4),
           &S::diameter),
      bind(F::number("sauter_diameter_mm",
                     "Sauter mean diameter d_sv of Eq. 14 (default: diameter_mm)", "mm", units::mm)
               .above(0)
               .at_most(1e4),
           &S::sauter_diameter),
      bind(F::number("true_density_kg_m3", "particle (true) density", "kg/m^3")
               .needed()
               .above(0)
               .at_most(3e4),
           &S::true_density),
      bind(F::number("bulk_density_kg_m3", "measured bulk density (needed for cohesion)", "kg/m^3")
               .above(0)
               .at_most(3e4),
           &S::bulk_density),
      bind(
          F::number("cohesion_kpa", "cohesion C of the yield locus (Table 1 says N; it is kPa, E1)",
                    "kPa", units::kPa)
              .at_least(0)
              .at_most(1e4)
              .without_default(),
          &S::cohesion),
      bind(F::number("friction_angle_deg", "internal friction angle", "deg", units::deg)
               .above(0)
               .below(90),
           &S::friction_angle),
      bind(F::number("moisture_percent", "moisture content M", "%", units::percent)
               .at_least(0)
               .below(100)
               .without_default(),
           &S::moisture),
      bind(F::number("heating_value_kcal_kg", "lower heating value (Eq. 17)", "kcal/kg")
               .at_least(0)
               .at_most(1e5),
           &S::heating_value),
      bind<S>(F::number("cohesion_force_n", "F_L of one original particle, replacing Eq. 14", "N")
                  .at_least(0)
                  .at_most(1e6),
              [](S& s, const ParamValues& v) {
                s.cohesion_force_override = v.number("cohesion_force_n");
              }),
      unbound<S>(F::number_list("sieve_diameters_mm",
                                "size classes of a measured distribution (DEM sizes before k)",
                                "mm", units::mm)
                     .above(0)
                     .at_most(1e4)),
      unbound<S>(F::number_list("sieve_mass_fractions", "mass fraction of each size class (sum 1)")
                     .at_least(0)
                     .at_most(1)),
  };
  return b;
}

}  // namespace silodem
