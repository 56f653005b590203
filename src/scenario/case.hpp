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

namespace silodem {

struct TimeSpec {
  double end_time = 1.0;            // s
  double time_step = 0.0;           // s; 0 = t_col,min / steps_per_collision
  double steps_per_collision = 50;  // N in dt = t_col / N (MFIX's DTSOLID_FACTOR default)
  Vec3 gravity{0.0, 0.0, -9.81};    // m/s^2
  double skin = 0.25;               // Verlet skin / smallest CG diameter
  int threads = 0;                  // 0 = all cores
  std::uint64_t seed = 1;
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
};

}  // namespace silodem
