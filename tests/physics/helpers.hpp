// SPDX-License-Identifier: MIT
// Test helpers: contact models from a flat list of parameters, and small simulations.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <utility>
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

// A law's kernel with the Params `law` was configured with (Law must be the law chosen there).
template <class Law, class... Args>
auto kernel(const ContactLaw& law, Args&&... args) {
  return Law::kernel(law.params<Law>(), std::forward<Args>(args)...);
}
// The normal law's force at g (any normal law), and numbers of the linear normal law and of the
// cohesion law (0 for a law without a force).
NormalForce normal_force(const ContactLaw& law, const ContactGeometry& g);
// The same with the normal law's history in s (updated).
NormalForce normal_force_with(const ContactLaw& law, const ContactGeometry& g, ContactState& s);
double normal_stiffness(const ContactLaw& law);
double cohesion_force(const ContactLaw& law);

inline double sphere_mass_of(double d, double rho) {
  return 3.14159265358979323846 / 6.0 * d * d * d * rho;
}

}  // namespace silodem::test
