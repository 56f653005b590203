// SPDX-License-Identifier: MIT
// From a ScenarioCase to the derived numbers (what `check` prints) and to a ready Simulation.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "engine/simulation.hpp"
#include "scenario/case.hpp"

namespace silodem {

struct CoalReport {
  std::string name;
  CoalDerived measured;            // porosity, sigma_t, F_L, Bond number of the original particle
  double cg_diameter = 0.0;        // m
  double cg_mass = 0.0;            // kg
  double cohesion_cg = 0.0;        // F_L,cg (N)
  double bond_number_cg = 0.0;     // F_L,cg / (m_cg g)
  double restitution_input = 0.0;  // e of its own particle-particle contacts, as given
  RestitutionCg restitution;       // e_cg and how it came about (particle-particle law)
  double damping_normal = 0.0;     // eta_n of a pair of two such CG particles (N s/m)
  double collision_time = 0.0;     // t_col of that pair (s)
  double wall_damping_normal = 0.0, wall_collision_time = 0.0;
};

struct SegmentPlan {
  int index = 0;  // 1 = H1 (bottom)
  int coal = 0;
  double z_low = 0.0, z_high = 0.0, volume = 0.0;
  double mass = 0.0;  // measured bulk density x volume (kg)
};

// The moisture force one kind of contact gets, as the contact model applies it.
struct AppliedCohesion {
  int coal_a = 0, coal_b = -1;  // coal_b < 0: a contact with a wall
  std::string law;              // the cohesion law
  double force = 0.0;           // N (cohesion.factor, pair rule or wall_factor applied)
};

struct CaseReport {
  std::vector<CoalReport> coals;
  // Each coal pair (a <= b) and each coal at a wall whose cohesion law has a force.
  std::vector<AppliedCohesion> cohesion_applied;
  double k = 1.0;
  double collision_time_min = 0.0;  // smallest t_col over all pair kinds and sizes present
  double time_step = 0.0;
  std::vector<std::string> warnings;
  // Silo cases: the nominal fill (by measured bulk density) and its calorific value (Eq. 17).
  std::vector<SegmentPlan> fill_plan;
  std::vector<int> segment_coal;  // coal of each filled segment, bottom first
  double inventory_calorific = 0.0;
};

// Derives every number and checks the time step (refuses dt > t_col / 10).
CaseReport derive_case(const ScenarioCase& c, ContactModel* model_out = nullptr);

// Time step, gravity, skin (a fraction of the smallest CG diameter d_min), guards and threads of a
// case (threads_override > 0 replaces the case's).
SimulationSettings settings_of(const ScenarioCase& c, const CaseReport& report, double d_min,
                               int threads_override);

// Silo case: a simulation holding the silo walls with the valve closed, and no particles yet.
std::unique_ptr<Simulation> build_silo_simulation(const ScenarioCase& c, const CaseReport& report,
                                                  ContactModel model, std::size_t* valve_index,
                                                  int threads_override = 0);

// Builds the simulation: walls, placed and lattice particles (refusing overlaps).
std::unique_ptr<Simulation> build_simulation(const ScenarioCase& c, const CaseReport& report,
                                             ContactModel model, int threads_override = 0);

}  // namespace silodem
