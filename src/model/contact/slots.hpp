// SPDX-License-Identifier: MIT
// The four slots of a contact law (PHYSICS.md 2-3): normal, tangential, rolling, cohesion.
// Each slot holds one law, chosen by name from the lists in contact/laws.hpp: a pure kernel (the
// force loop inlines it, dispatch.hpp; the pointer here is for tests and tools) plus its
// parameters, checked once. A law reads only the parameters of its slot.
#pragma once
#include "core/vec3.hpp"
#include "model/contact/contact_geometry.hpp"

namespace silodem {

// ---- normal -------------------------------------------------------------------------------
struct NormalParams {
  double stiffness = 0.0;        // k_n, N/m
  double restitution = 1.0;      // e actually used (after the CG policy)
  double damping_ratio = 0.0;    // zeta(e); eta_n = 2 zeta sqrt(m_eff k_n)
  bool clip_attractive = false;  // clip the attractive dashpot force at the end of a contact
};
struct NormalForce {
  double elastic = 0.0;  // k_n delta_n (repulsive > 0)
  double damping = 0.0;  // eta_n d(delta_n)/dt
  double total = 0.0;    // elastic + damping, after clipping
  double eta = 0.0;      // eta_n of this contact (tangential damping is a fraction of it)
};
using NormalKernel = NormalForce (*)(const NormalParams&, const ContactGeometry&);

// ---- tangential ---------------------------------------------------------------------------
struct TangentialParams {
  double stiffness = 0.0;         // k_t, N/m
  double damping_fraction = 0.0;  // eta_t / eta_n
  double friction = 0.0;          // mu_s
  bool cap_sees_cohesion =
      false;  // Coulomb cap on |F_el + F_damp - F_coh| instead of |F_el + F_damp|
};
// Returns the tangential force on i; updates the spring.
using TangentialKernel = Vec3 (*)(const TangentialParams&, const ContactGeometry&, double eta_n,
                                  double cap_normal_force, Vec3& spring, double dt);

// ---- rolling ------------------------------------------------------------------------------
struct RollingParams {
  double friction = 0.0;             // mu_r
  double length = 0.0;               // mfix-21: L = MFiX 21.3's MEW_R, a length (m)
  double stiffness_factor = 2.25;    // EPSD: k_r = factor k_n mu_r^2 R_eff^2 (Ai et al. 2011)
  double damping_fraction = 0.3;     // EPSD: eta_r, fraction of critical rolling damping
  bool limit_sees_cohesion = false;  // EPSD limit on |F_n - F_coh| instead of |F_n|
  bool regularize = true;            // mfix, mfix-21: smooth the sign(omega) switch near omega = 0
};
struct RollingTorque {
  Vec3 on_i, on_j;
};
using RollingKernel = RollingTorque (*)(const RollingParams&, const ContactGeometry&,
                                        const NormalParams&, const NormalForce&, double cohesion,
                                        Vec3& spring, double dt);

// ---- cohesion -----------------------------------------------------------------------------
struct CohesionParams {
  double force = 0.0;         // F_L,cg of this pair (after pair rule / wall factor), N
  double range_over_d = 0.0;  // constant-range: gap s_c / d_ref
  double inner_over_d = 0.0;  // mfix-like: s_in / d_ref
  double outer_over_d = 0.0;  // mfix-like: s_out / d_ref
  double reach_over_d = 0.0;  // largest gap (/ d_ref) at which the law acts; 0 = contact only
};
// Returns the attractive force magnitude (>= 0) at the current gap.
using CohesionKernel = double (*)(const CohesionParams&, const ContactGeometry&);

}  // namespace silodem
