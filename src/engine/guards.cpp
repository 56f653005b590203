// SPDX-License-Identifier: MIT
// Simulation's guards: the overlap and speed bounds and the non-finite state, each stopping the run
// with a diagnostic that names the particle and the likely cause.
#include <fmt/format.h>
#include <algorithm>

#include "core/error.hpp"
#include "engine/simulation.hpp"

namespace silodem {

std::string Simulation::likely_cause(std::size_t i) const {
  const int m = p_.material[i];
  const double t_col =
      std::min(model_.pair_collision_time(m, m, p_.mass[i], p_.mass[i], p_.radius[i], p_.radius[i]),
               model_.wall_collision_time(m, p_.mass[i], p_.radius[i]));
  if (s_.dt > t_col / 10.0)
    return fmt::format(
        "the time step dt = {:.3g} s is {:.2g} x this particle's collision time "
        "t_col = {:.3g} s (use dt <= t_col / 10, better t_col / 50)",
        s_.dt, s_.dt / t_col, t_col);
  return fmt::format(
      "a particle placed inside a wall or another particle, or a contact too "
      "soft for the load (dt = {:.3g} s = t_col / {:.0f})",
      s_.dt, t_col / s_.dt);
}

void Simulation::overlap_stop(std::size_t i, long j, double overlap) const {
  const std::string with =
      j >= 0 ? fmt::format("particle {}", p_.id[std::size_t(j)]) : fmt::format("wall {}", -1 - j);
  throw SimulationError(fmt::format(
      "overlap guard at step {} (t = {:.6g} s): particle {} at ({:.4g}, {:.4g}, {:.4g}) m, "
      "velocity ({:.3g}, {:.3g}, {:.3g}) m/s, overlaps {} by {:.3g} m = {:.2f} of its radius "
      "(limit {}); likely cause: {}",
      steps_, time_, p_.id[i], p_.x[i].x, p_.x[i].y, p_.x[i].z, p_.v[i].x, p_.v[i].y, p_.v[i].z,
      with, overlap, overlap / p_.radius[i], s_.max_overlap, likely_cause(i)));
}

void Simulation::check_state() const {
  const double v2max = s_.max_speed > 0 ? s_.max_speed * s_.max_speed : 1e300;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (norm2(p_.v[i]) > v2max && is_finite(p_.v[i]))
      throw SimulationError(fmt::format(
          "speed guard at step {} (t = {:.6g} s): particle {} at ({:.4g}, {:.4g}, {:.4g}) m moves "
          "at {:.3g} m/s, velocity ({:.3g}, {:.3g}, {:.3g}), above the bound {:.3g} m/s; likely "
          "cause: {}",
          steps_, time_, p_.id[i], p_.x[i].x, p_.x[i].y, p_.x[i].z, norm(p_.v[i]), p_.v[i].x,
          p_.v[i].y, p_.v[i].z, s_.max_speed, likely_cause(i)));
    if (!is_finite(p_.x[i]) || !is_finite(p_.v[i]) || !is_finite(p_.omega[i]))
      throw SimulationError(fmt::format(
          "particle {} has a non-finite state at step {} (t = {:.6g} s): position ({}, {}, {}), "
          "velocity ({}, {}, {}); likely cause: time step too large for the stiffness (dt = {:.3g} "
          "s) or particles created overlapping",
          p_.id[i], steps_, time_, p_.x[i].x, p_.x[i].y, p_.x[i].z, p_.v[i].x, p_.v[i].y, p_.v[i].z,
          s_.dt));
  }
}

}  // namespace silodem
