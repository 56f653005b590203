// SPDX-License-Identifier: MIT
// Measured coal properties -> porosity, tensile strength and moisture-induced cohesive force
// (PHYSICS.md 3; paper Eq. 14-16). SI units throughout.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/schema.hpp"

namespace silodem {

// One sieve class of a measured size distribution (original, not coarse-grained, size).
struct SizeClass {
  double diameter = 0.0;       // m
  double mass_fraction = 0.0;  // of the coal's mass, sums to 1 over the table
};

struct CoalProperties {
  std::string name;
  double diameter = 0.0;         // m, average particle diameter (DEM size when no PSD)
  double sauter_diameter = 0.0;  // m, d_sv of Eq. 14 (E8: its own input; default = diameter)
  double bulk_density = 0.0;     // kg/m^3, measured (wet) bulk density rho_b
  double true_density = 0.0;     // kg/m^3, particle density rho_p
  double cohesion = 0.0;         // Pa, C of the Mohr-Coulomb fit (E1: kPa in the table)
  double friction_angle = 0.0;   // rad, internal friction angle phi
  double moisture = 0.0;         // fraction (0..1), M/100 of Eq. 15
  double heating_value = 0.0;    // kcal/kg, lower heating value (Eq. 17)
  std::optional<double> cohesion_force_override;  // N, replaces Eq. 14 when given
  std::vector<SizeClass> size_classes;            // empty = monodisperse at `diameter`
};

struct CoalDerived {
  double porosity = 0.0;          // eps, Eq. 15 (the measured packing)
  double rumpf_porosity = 0.0;    // eps used in Eq. 14: Eq. 15's, or the case's rumpf_porosity
  double tensile_strength = 0.0;  // sigma_t = C / tan(phi), Pa, Eq. 16
  double cohesion_force = 0.0;    // F_L, N, Eq. 14 (original particle)
  double particle_mass = 0.0;     // kg, sphere of `diameter` at the true density
  double bond_number = 0.0;       // F_L / (m g), original particle
};

// Eq. 15: eps = 1 - (rho_b / rho_p)(1 - M).
double porosity(double bulk_density, double true_density, double moisture);
// Eq. 16: sigma_t = C / tan(phi).
double tensile_strength(double cohesion, double friction_angle);
// Eq. 14 (Rumpf/Molerus): F_L = d_sv^2 sigma_t eps / (1 - eps).
double moisture_cohesion_force(double sauter_diameter, double sigma_t, double eps);
double sphere_mass(double diameter, double density);

// `rumpf_porosity` > 0 replaces Eq. 15's porosity in Eq. 14 (coarse_graining.rumpf_porosity:
// the porosity of the packing whose bulk tensile strength F_L must give); 0 keeps Eq. 15's.
CoalDerived derive(const CoalProperties& coal, double rumpf_porosity = 0.0);

// The [[coal]] keys, bound to CoalProperties' members. `symbol` and the sieve lists are read by the
// loader (the symbols of all coals and the size classes are checked together); a measured input
// not given stays 0 and is asked for only when a cohesion law needs it.
const std::vector<Bound<CoalProperties>>& coal_fields();

}  // namespace silodem
