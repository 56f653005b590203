// SPDX-License-Identifier: MIT
// Small silo runs through the scenario layer (VERIFICATION.md 4.4): T-I4 mass bookkeeping,
// T-I7 determinism, T-I5 cohesion monotonicity, and the outlet calorific value of two stacking
// orders (Eq. 17).
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <cmath>

#include "io/config/load.hpp"
#include "scenario/discharge.hpp"
#include "scenario/layered_filling.hpp"
#include "scenario/outlet_stats.hpp"
#include "scenario/setup.hpp"

namespace silodem {
namespace {

// A 40 mm outlet (D/d = 8), 100 mm cone, filled 50 mm high in two segments with two coals of
// equal mechanics but different heating values; d = 5 mm, soft contacts.
std::string small_case(const std::string& scenario, double bond_number, std::uint64_t seed) {
  const double m = 3.14159265358979323846 / 6 * 125e-9 * 1500;  // particle mass (kg)
  const double f = bond_number * m * 9.81;
  const std::string cohesion = bond_number > 0 ? "\"overlap-only\"" : "\"none\"";
  return fmt::format(R"(
[simulation]
seed = {seed}
threads = 1
[[coal]]
name = "Low"
symbol = "L"
diameter_mm = 5
bulk_density_kg_m3 = 850
true_density_kg_m3 = 1500
heating_value_kcal_kg = 4788
cohesion_force_n = {f}
[[coal]]
name = "High"
symbol = "I"
diameter_mm = 5
bulk_density_kg_m3 = 850
true_density_kg_m3 = 1500
heating_value_kcal_kg = 3108
cohesion_force_n = {f}
[contact.particle_particle]
normal = {{ law = "linear_spring_dashpot", stiffness = 2e3, restitution = 0.3 }}
tangential = {{ law = "linear_history", friction = 0.5 }}
rolling = {{ law = "epsd", friction = 0.1 }}
cohesion = {{ law = {cohesion} }}
[contact.particle_wall]
normal = {{ law = "linear_spring_dashpot", stiffness = 2e3, restitution = 0.3 }}
tangential = {{ law = "linear_history", friction = 0.5 }}
rolling = {{ law = "epsd", friction = 0.1 }}
cohesion = {{ law = {cohesion} }}
[silo]
outlet_diameter_mm = 40
cone_height_mm = 100
cylinder_diameter_mm = 120
cylinder_height_mm = 60
[fill]
scenario = "{scenario}"
segments = 2
fill_height_mm = 50
settle_max_time = 1.0
settle_ke_per_particle_j = 1e-8
[discharge]
bin = 0.05
sink_depth_mm = 30
stall_time = 0.5
max_time = 5
)",
                     fmt::arg("seed", seed), fmt::arg("f", f), fmt::arg("cohesion", cohesion),
                     fmt::arg("scenario", scenario));
}

struct SmallRun {
  FillReport fill;
  DischargeResult result;
  std::vector<OutletBin> bins;
  double inventory_q = 0.0;  // Eq. 17 of the actual filled masses
  double max_speed = 0.0;
  bool ledger_ok = true;
  long checks = 0;
};

SmallRun run_small(const std::string& scenario, double bond_number, std::uint64_t seed = 1) {
  const Case c = config::load_case_text(small_case(scenario, bond_number, seed), "small.toml");
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  std::size_t valve = 0;
  auto sim = build_silo_simulation(c, report, std::move(model), &valve);
  Random rng(c.time.seed);
  SmallRun r;
  r.fill = fill_silo(*sim, c, report.segment_coal, rng, nullptr);
  std::vector<double> mass(2, 0.0), q = {4788, 3108};
  for (const auto& s : r.fill.segments) mass[std::size_t(s.coal)] += s.mass;
  r.inventory_q = mixture_calorific(mass, q);
  const std::size_t n0 = sim->particles().size();
  r.result = discharge(*sim, c.silo.geometry, valve, c.discharge, [&](const DischargeState& s) {
    // T-I4: filled = in silo + discharged + lost, in particles and in mass, at every check.
    ++r.checks;
    const auto& p = sim->particles();
    const double in_silo = total_mass(p);
    if (std::fabs(in_silo + s.discharged + s.lost - s.filled) > 1e-12 * s.filled)
      r.ledger_ok = false;
    for (std::size_t i = 0; i < p.size(); ++i) r.max_speed = std::max(r.max_speed, norm(p.v[i]));
    if (s.particles_left > n0) r.ledger_ok = false;
  });
  r.bins = outlet_bins(r.result.outflow, c.discharge.bin, r.result.end_time, q);
  return r;
}

TEST(SmallSilo, TI4_MassBookkeeping) {
  const SmallRun r = run_small("L1-I1", 0.0);
  EXPECT_TRUE(r.ledger_ok);
  EXPECT_GT(r.checks, 10);
  EXPECT_EQ(r.result.end, DischargeEnd::Emptied);
  EXPECT_EQ(r.result.particles_lost, 0);
  EXPECT_NEAR(r.result.filled_mass, r.result.discharged_mass + r.result.remaining_mass, 1e-12);
  EXPECT_EQ(long(r.result.outflow.size()) +
                long(std::lround(r.result.remaining_mass / 9.817477042468103e-05)),
            r.result.particles_filled);
  // Free fall from the top of the fill to the sink bounds every speed.
  const double h = 0.05 + 0.03;
  EXPECT_LT(r.max_speed, 1.5 * std::sqrt(2 * 9.81 * h));
}

TEST(SmallSilo, TI7_DeterministicWithTheSameSeed) {
  const SmallRun a = run_small("L1-I1", 0.0, 7), b = run_small("L1-I1", 0.0, 7);
  ASSERT_EQ(a.result.outflow.size(), b.result.outflow.size());
  for (std::size_t k = 0; k < a.result.outflow.size(); ++k) {
    EXPECT_EQ(a.result.outflow[k].t, b.result.outflow[k].t);
    EXPECT_EQ(a.result.outflow[k].coal, b.result.outflow[k].coal);
    EXPECT_EQ(a.result.outflow[k].mass, b.result.outflow[k].mass);
  }
}

TEST(SmallSilo, CalorificValueFollowsTheStackingOrder) {
  for (const char* scenario : {"L1-I1", "I1-L1"}) {
    const SmallRun r = run_small(scenario, 0.0);
    ASSERT_EQ(r.result.end, DischargeEnd::Emptied) << scenario;
    const bool low_on_top = std::string(scenario)[0] == 'L';
    const double bottom_q = low_on_top ? 3108 : 4788, top_q = low_on_top ? 4788 : 3108;
    // First bin with outflow: mostly the bottom coal; last: mostly the top coal.
    const OutletBin* first = nullptr;
    const OutletBin* last = nullptr;
    double weighted = 0.0, mass = 0.0;
    for (const auto& b : r.bins) {
      if (b.mass <= 0) continue;
      if (!first) first = &b;
      last = &b;
      weighted += b.mass * b.calorific;
      mass += b.mass;
    }
    ASSERT_NE(first, nullptr);
    EXPECT_NEAR(first->calorific, bottom_q, 0.1 * 1680) << scenario;
    EXPECT_NEAR(last->calorific, top_q, 0.1 * 1680) << scenario;
    // Mass-weighted mean of the outlet value = the inventory's Eq. 17 value, within 0.5%.
    EXPECT_NEAR(weighted / mass / r.inventory_q, 1.0, 0.005) << scenario;
  }
}

TEST(SmallSilo, TI5_CohesionSlowsOrStopsTheFlow) {
  double previous = 1e300;
  double w0 = 0.0;
  bool jammed = false;
  for (double bo : {0.0, 5.0, 50.0}) {
    const SmallRun r = run_small("L2", bo);
    const double w = r.result.end == DischargeEnd::FlowStopped || r.result.discharge_time <= 0
                         ? 0.0
                         : r.result.discharged_mass / r.result.discharge_time;
    if (bo == 0.0) {
      w0 = w;
      EXPECT_EQ(r.result.end, DischargeEnd::Emptied);
    }
    // Strictly slower, or a jam (reported as such) that a stronger cohesion cannot undo.
    if (r.result.end == DischargeEnd::FlowStopped) {
      jammed = true;
    } else {
      EXPECT_FALSE(jammed) << "a weaker cohesion jammed but Bo = " << bo << " flows";
      EXPECT_LT(w, previous) << "Bo = " << bo;
    }
    if (bo == 50.0) {
      EXPECT_TRUE(w / w0 < 0.6 || r.result.end == DischargeEnd::FlowStopped);
    }
    previous = w;
  }
}

}  // namespace
}  // namespace silodem
