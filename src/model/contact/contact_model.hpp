// SPDX-License-Identifier: MIT
// The contact model of a run: one ContactLaw per coal pair and per coal-wall pair, built from the
// four chosen slot laws, and the evaluation of one contact (the body of the force loop).
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "model/coarse_graining.hpp"
#include "model/contact/contact_history.hpp"
#include "model/contact/laws.hpp"
#include "model/contact/registry.hpp"

namespace silodem {

struct SlotChoice {
  std::string law;     // registry name
  ParamValues values;  // validated against the law's fields
};

// [contact.<section>.coal.<name>]: numbers that replace the section's in the contacts of one
// coal, slot by slot (only the keys given; `section` of each names the override table). The laws
// stay the section's: only their parameters differ between coals.
struct CoalContactValues {
  ParamValues slot[4];  // by Slot
  bool empty() const;
};

// The case file's [contact.particle_particle] or [contact.particle_wall].
struct ContactSpec {
  SlotChoice normal, tangential, rolling, cohesion;
  // By coal index (empty: no coal has its own values). A pair of two different coals takes, for
  // each number either coal replaces, the `mixing` mean of the two coals' values (mean | min |
  // harmonic, as cohesion_pair_rule); a wall contact takes its coal's values.
  std::vector<CoalContactValues> per_coal;
  std::vector<std::string> coal_names;  // for messages about a pair of two coals
  std::string mixing = "harmonic";
};

// The spec of the contacts of coal a with coal b (b < 0: with a wall), per-coal values applied:
// coal a's own values exactly for b == a or a wall, the `mixing` mean for two coals.
ContactSpec spec_for(const ContactSpec& spec, int a, int b);
// mean | min | harmonic (2 / (1/x + 1/y); 0 if either is 0) of two non-negative values.
double mix_values(const std::string& mixing, double x, double y);

// One law per slot for one kind of pair (coal a - coal b, or coal a - wall): each law's own
// Params, and where its per-contact values sit.
struct ContactLaw {
  SlotParams<NormalLaws> normal;
  SlotParams<TangentialLaws> tangential;
  SlotParams<RollingLaws> rolling;
  SlotParams<CohesionLaws> cohesion;
  double reach_over_d = 0.0;        // the cohesion law's: largest gap / d_ref at which it acts
  StateLayout layout;               // the four laws' history values, in slot order
  std::string law_names[4];         // by Slot, for reports
  int law_index[4] = {0, 0, 0, 0};  // by Slot: position of the law in its list (laws.hpp)

  // The Params of Law, which must be the law chosen for its slot (else std::logic_error).
  template <class Law>
  const typename Law::Params& params() const {
    const auto* p = std::get_if<IndexInList<Law, List<Law>>::value>(&slot<Law>(*this));
    if (!p)
      throw std::logic_error(std::string("ContactLaw: the law of this slot is not ") + Law::name);
    return *p;
  }
  template <class Law>
  void set_params(const typename Law::Params& p) {
    slot<Law>(*this).template emplace<IndexInList<Law, List<Law>>::value>(p);
  }

 private:
  template <class Law>
  using List =
      std::conditional_t<Law::slot == Slot::Normal, NormalLaws,
                         std::conditional_t<Law::slot == Slot::Tangential, TangentialLaws,
                                            std::conditional_t<Law::slot == Slot::Rolling,
                                                               RollingLaws, CohesionLaws>>>;
  template <class Law, class Self>
  static auto& slot(Self& self) {
    if constexpr (Law::slot == Slot::Normal)
      return self.normal;
    else if constexpr (Law::slot == Slot::Tangential)
      return self.tangential;
    else if constexpr (Law::slot == Slot::Rolling)
      return self.rolling;
    else
      return self.cohesion;
  }
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
  // Collision time of a pair / of a particle against a wall, from the normal law (Eq. 10 with E3
  // for the linear law); the radii matter to a Hertz law.
  double pair_collision_time(int a, int b, double m_a, double m_b, double r_a, double r_b) const;
  double wall_collision_time(int a, double m, double r) const;

 private:
  int n_ = 0;
  std::vector<ContactLaw> pp_, pw_;
  double max_reach_ = 0.0;
};

// The moisture force the cohesion law of `law` applies (its Params' `force`: F_L,cg after the
// pair rule or wall factor and cohesion.factor, N); NaN for a law without one (none).
double applied_cohesion_force(const ContactLaw& law);

// One contact (dispatch.hpp's evaluate<K> for the laws `law` was configured with); the force loop
// calls evaluate<K> directly.
ContactResult evaluate_contact(const ContactLaw& law, const ContactGeometry& g, ContactState& s,
                               double dt);

// What the normal law of `law` says of a contact: its elastic energy, and for reports its
// collision time and damping coefficient for a pair of effective mass and radius m_eff, r_eff.
double normal_elastic_energy(const ContactLaw& law, const ContactGeometry& g,
                             const ContactState& s);
double normal_collision_time(const ContactLaw& law, double m_eff, double r_eff);
double normal_damping_coefficient(const ContactLaw& law, double m_eff, double r_eff);

// Configure a full ContactLaw for one pair kind (used by build() and by tests).
ContactLaw configure_contact_law(const ContactSpec& spec, const LawContext& ctx);

}  // namespace silodem
