// SPDX-License-Identifier: MIT
// A case as plain data, in SI units, produced by io/config from a TOML file. Places in the file
// are kept so that errors found while setting up (overlaps, a too large dt) can name the line.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/error.hpp"
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

struct OutputSpec {
  long every = 0;                  // steps between rows of trajectory.csv; 0 = final state only
  std::vector<std::uint64_t> ids;  // particles to write; empty = all
  double vtk_interval = 0.0;       // s between ParaView frames of a silo run; 0 = none
  std::string measured;            // measured outlet data (CSV), resolved against the case file
  SourcePlace measured_place;
};

// Measured outlet data (optional): times with a mass flow rate and/or a calorific value.
struct MeasuredData {
  std::vector<double> t;          // s since the valve opened
  std::vector<double> rate;       // kg/s (NaN where not measured)
  std::vector<double> calorific;  // kcal/kg (NaN where not measured)
  bool has_rate = false, has_calorific = false;
};

// Probes of a silo run (src/probes), sampled every `every` steps of the discharge.
struct ProbeSpec {
  long every = 1000;  // steps; 0 = no probes
  std::vector<double> slab_times{0.0, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 60.0, 80.0};
  double slab_thickness = 0.02;                        // m
  std::vector<double> profile_heights{0.1, 0.2, 0.3};  // m above the outlet
  double profile_bin = 0.01;                           // m
  double profile_from = 0.0, profile_to = 1e9;         // s, averaging window
  double adhesion_threshold = 1e-3;                    // N
  double level_radius = 0.02;                          // m around the axis
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

struct Case {
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
  OutputSpec output;
  MeasuredData measured;
  ProbeSpec probes;
  SiloSpec silo;
  FillSpec fill;
  DischargeSpec discharge;
  std::vector<std::string> coal_symbols;  // per coal, for the scenario notation
};

}  // namespace silodem
