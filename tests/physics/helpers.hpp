// SPDX-License-Identifier: MIT
// Test helpers: contact models from a flat list of parameters, and small simulations.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/simulation.hpp"
#include "engine/walls/plane.hpp"
#include "model/contact/contact_model.hpp"

namespace silodem::test {

// One pair kind's laws and parameters, with the registry's defaults for anything not set.
struct Laws {
  std::string normal = "linear_spring_dashpot";
  std::string tangential = "none";
  std::string rolling = "none";
  std::string cohesion = "none";
  std::map<std::string, double> normal_p{{"stiffness", 1e4}, {"restitution", 0.5}};
  std::map<std::string, double> tangential_p, rolling_p, cohesion_p;
  std::map<std::string, std::string> cohesion_s;  // e.g. pair_rule
};

ContactSpec spec_of(const Laws& l, bool wall);
// cohesion_cg: F_L,cg per material; the same laws for particle-particle and particle-wall
// unless `wall` is given.
ContactModel model_of(const Laws& pp, const std::vector<double>& cohesion_cg = {0.0},
                      const Laws* wall = nullptr, CoarseGraining cg = {});
ContactLaw law_of(const Laws& l, bool wall, double f_i = 0.0, double f_j = 0.0,
                  CoarseGraining cg = {});

inline double sphere_mass_of(double d, double rho) {
  return 3.14159265358979323846 / 6.0 * d * d * d * rho;
}

}  // namespace silodem::test
