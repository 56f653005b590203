// SPDX-License-Identifier: MIT
// The contact model of a run: one ContactLaw per coal pair and per coal-wall pair, built from the
// four chosen slot laws, and the evaluation of one contact (the body of the force loop).
#pragma once
#include <string>
#include <vector>

#include "model/coarse_graining.hpp"
#include "model/contact/contact_history.hpp"
#include "model/contact/registry.hpp"

namespace silodem {

struct SlotChoice {
  std::string law;     // registry name
  ParamValues values;  // validated against the law's fields
};

// The case file's [contact.particle_particle] or [contact.particle_wall].
struct ContactSpec {
  SlotChoice normal, tangential, rolling, cohesion;
};

struct ContactResult {
  Vec3 force_i;  // on i; j gets -force_i
  Vec3 torque_i, torque_j;
  double cohesion = 0.0;  // attractive force magnitude acting (N)
  double normal = 0.0;    // elastic + damping normal force (N, repulsive > 0)
  bool touching = false;
};

class ContactModel {
 public:
  // cohesion_cg[a]: F_L,cg of coal a (already coarse-grained).
  static ContactModel build(const ContactSpec& particle_particle, const ContactSpec& particle_wall,
                            const std::vector<double>& cohesion_cg, const CoarseGraining& cg,
                            std::vector<std::string>* warnings);

  int materials() const { return n_; }
  const ContactLaw& pair(int a, int b) const { return pp_[a * n_ + b]; }
  const ContactLaw& wall(int a) const { return pw_[a]; }
  // Largest reach of any cohesion law beyond contact, as a fraction of d_ref.
  double max_reach_over_d() const { return max_reach_; }
  // Collision time of a pair / of a particle against a wall (Eq. 10 with E3).
  double pair_collision_time(int a, int b, double m_a, double m_b) const;
  double wall_collision_time(int a, double m) const;

 private:
  int n_ = 0;
  std::vector<ContactLaw> pp_, pw_;
  double max_reach_ = 0.0;
};

// One contact (dispatch.hpp's evaluate<K> for the laws `law` was configured with); the force loop
// calls evaluate<K> directly.
ContactResult evaluate_contact(const ContactLaw& law, const ContactGeometry& g, ContactState& s,
                               double dt);

// Configure a full ContactLaw for one pair kind (used by build() and by tests).
ContactLaw configure_contact_law(const ContactSpec& spec, const LawContext& ctx);

}  // namespace silodem
