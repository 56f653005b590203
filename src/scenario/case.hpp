// SPDX-License-Identifier: MIT
// The part of a case that the scenario layer reads, as plain data in SI units: the time stepping,
// the coals, the contact model, the bodies or the silo, its fill and its discharge. io/config
// makes it from a TOML file, as part of its `Case` (which adds what the probes and the writers
// read). Each spec struct's default member values are the case file's defaults: each key is bound
// to its member once, in the field lists below (scenario/case.cpp), which io/config validates
// against and generates docs/config.md from. Places in the file are kept so that errors found
// while setting up (overlaps, a too large dt) can name the line.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/schema.hpp"
#include "core/vec3.hpp"
#include "model/coarse_graining.hpp"
#include "model/contact/contact_model.hpp"
#include "model/material.hpp"
#include "scenario/silo_geometry.hpp"

namespace silodem {

struct TimeSpec {
  double end_time = 1.0;            // s
  double time_step = 0.0;           // s; 0 = t_col,min / steps_per_collision
  double steps_per_collision = 50;  // N in dt = t_col / N (MFIX's DTSOLID_FACTOR default)
  Vec3 gravity{0.0, 0.0, -9.81};    // m/s^2
  double skin = 0.25;               // Verlet skin / smallest CG diameter
  double skin_floor = 1.0;          // per-particle skin: smallest allowance / (skin / 2); 1 = off
  int reorder_every = 10;           // Morton reorder every N list builds (0 = never)
  int threads = 0;                  // 0 = all cores
  std::uint64_t seed = 1;
  double max_speed = 0.0;                   // m/s guard; 0 = derived (silo) or none (generic)
  double max_overlap = 0.5;                 // guard, fraction of the smaller radius; 0 = off
  double checkpoint_interval = 10.0;        // s of discharge between checkpoints; 0 = signals only
  double checkpoint_wall_interval = 600.0;  // s of wall time between checkpoints; 0 = off
  SourcePlace time_step_place, steps_place;
};

struct WallSpec {
  std::string type;
  ParamValues values;
};

struct ParticleSpec {
  int coal = 0;
  Vec3 x, v, omega;
  double diameter = 0.0;  // m; 0 = the coal's coarse-grained diameter
  SourcePlace place;
  std::string key;  // "particle[3]"
};

struct LatticeSpec {
  int coal = 0;
  Vec3 origin, v;
  double spacing = 0.0;  // m
  int nx = 1, ny = 1, nz = 1;
  SourcePlace place;
  std::string key;
};

enum class FillMode { Mass, Volume };

struct SiloSpec {
  bool present = false;  // a silo case (fill + discharge) rather than a generic one
  SiloGeometry geometry;
};

struct FillSpec {
  std::string scenario;  // "L3-I2", top first
  SourcePlace scenario_place;
  int segments = 5;                // equal height segments of the fill height (H1 at the bottom)
  double fill_height = 0.0;        // m; 0 = the cone height (E7)
  FillMode mode = FillMode::Mass;  // by mass (measured bulk density x volume) or by volume (E13)
  double lattice_gap = 0.05;       // spacing of inserted particles = d_max (1 + gap)
  double settle_ke = 1e-8;         // J per particle: settled below this kinetic energy
  double settle_max_time = 3.0;    // s of simulated settling per segment at most
};

struct DischargeSpec {
  double bin = 1.0;                // s, outlet statistics bin
  double sink_depth = 0.1;         // m below the outlet where particles are removed and counted
  double stall_time = 5.0;         // s without outflow = stopped flow (arching)
  double max_time = 600.0;         // s of discharge at most
  double target_fraction = 0.995;  // of the filled mass: discharged = done
};

struct ScenarioCase {
  std::string path;
  std::string title;
  TimeSpec time;
  CoarseGraining cg;
  std::vector<CoalProperties> coals;
  std::vector<SourcePlace> coal_places;
  ContactSpec particle_particle, particle_wall;
  std::vector<WallSpec> walls;
  std::vector<ParticleSpec> particles;
  std::vector<LatticeSpec> lattices;
  SiloSpec silo;
  FillSpec fill;
  DischargeSpec discharge;
  std::vector<std::string> coal_symbols;  // per coal, for the scenario notation
};

// The keys of each section, bound to their members (scenario/case.cpp). ParticleSpec and
// LatticeSpec name their coal, which the loader looks up; [silo] is silo_fields().
const std::vector<Bound<TimeSpec>>& time_fields();            // [simulation]
const std::vector<Bound<FillSpec>>& fill_fields();            // [fill]
const std::vector<Bound<DischargeSpec>>& discharge_fields();  // [discharge]
const std::vector<Bound<ParticleSpec>>& particle_fields();    // [[particle]]
const std::vector<Bound<LatticeSpec>>& lattice_fields();      // [[lattice]]

}  // namespace silodem
