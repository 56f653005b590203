// SPDX-License-Identifier: MIT
// The case-file keys of the scenario's sections, each bound to the member that holds its value.
// Defaults are the members' initial values in case.hpp.
#include "scenario/case.hpp"

#include "core/constants.hpp"

namespace silodem {

const std::vector<Bound<TimeSpec>>& time_fields() {
  using F = Field;
  using S = TimeSpec;
  static const std::vector<Bound<S>> b = {
      bind(F::number("end_time", "simulated time to run", "s").above(0), &S::end_time),
      bind(F::number("time_step", "explicit time step; 0 = t_col,min / steps_per_collision", "s")
               .at_least(0),
           &S::time_step),
      bind(F::number("steps_per_collision",
                     "N in dt = t_col,min / N (MFIX's DTSOLID_FACTOR default 50)")
               .at_least(10)
               .at_most(1e6),
           &S::steps_per_collision),
      bind(F::vec3("gravity", "gravitational acceleration (default [0, 0, -9.81])", "m/s^2"),
           &S::gravity),
      bind(F::number("skin", "Verlet skin as a fraction of the smallest CG diameter")
               .above(0)
               .at_most(5),
           &S::skin),
      bind(F::number("skin_floor",
                     "per-particle skin (speed only, like reorder_every: the same contacts and "
                     "fewer listed pairs out of range; the rebuilds, and with them the Morton "
                     "reorders, come at other steps): at each neighbour-list build a particle may "
                     "move skin/2 x min(1, max(skin_floor, 2 |v| / v_max)) before the next; 1 = "
                     "skin/2 for every particle")
               .above(0)
               .at_most(1),
           &S::skin_floor),
      bind(F::integer("reorder_every",
                      "sort the particles along a Morton curve before every N-th neighbour-list "
                      "build, so that neighbours are close in memory (speed only: changes the "
                      "summation order, not the physics; 0 = never)")
               .at_least(0)
               .at_most(1000000),
           &S::reorder_every),
      bind(F::integer("threads", "OpenMP threads; 0 = all cores").at_least(0).at_most(1024),
           &S::threads),
      bind(F::integer("seed", "seed of every random choice").at_least(0).at_most(9.0e15), &S::seed),
      bind(F::number("max_speed",
                     "guard: stop when a particle moves faster; 0 = derived (silo: "
                     "3 x the free-fall speed from the silo top to the sink + 1 m/s; generic "
                     "case: no bound)",
                     "m/s")
               .at_least(0)
               .at_most(1e6),
           &S::max_speed),
      bind(F::number("max_overlap",
                     "guard: stop when a contact overlaps by more than this "
                     "fraction of the smaller radius; 0 = off")
               .at_least(0)
               .at_most(10),
           &S::max_overlap),
      bind(F::number("checkpoint_interval",
                     "simulated time between checkpoints of a silo run, "
                     "its fill and its discharge (checkpoint.bin; also written on SIGINT/SIGTERM); "
                     "0 = only on a signal",
                     "s")
               .at_least(0)
               .at_most(1e6),
           &S::checkpoint_interval),
      bind(
          F::number("checkpoint_wall_interval",
                    "wall-clock time between checkpoints of a silo run, whichever of the two comes "
                    "first (a run killed without a signal loses about this at most); 0 = off",
                    "s")
              .at_least(0)
              .at_most(1e6),
          &S::checkpoint_wall_interval),
  };
  return b;
}

const std::vector<Bound<FillSpec>>& fill_fields() {
  using F = Field;
  using S = FillSpec;
  static const std::vector<Bound<S>> b = {
      bind(F::text("scenario", "coals from the top down with their segment counts, e.g. \"L3-I2\"",
                   {}),
           &S::scenario),
      bind(F::integer("segments", "equal height segments of the fill height (H1 at the bottom)")
               .at_least(1)
               .at_most(100),
           &S::segments),
      bind(F::number("fill_height_mm", "height of the fill; 0 = the cone height (E7)", "mm",
                     units::mm)
               .at_least(0)
               .at_most(1e5),
           &S::fill_height),
      bind<S>(F::text("mode",
                      "mass: each segment gets the measured bulk density x its volume; volume: "
                      "settle until the segment is full",
                      {"mass", "volume"}, S{}.mode == FillMode::Volume ? "volume" : "mass"),
              [](S& s, const ParamValues& v) {
                s.mode = v.string("mode") == "volume" ? FillMode::Volume : FillMode::Mass;
              }),
      bind(
          F::number("lattice_gap", "inserted particles sit on a lattice of spacing d_max (1 + gap)")
              .at_least(0.001)
              .at_most(1),
          &S::lattice_gap),
      bind(F::number("settle_ke_per_particle_j",
                     "settled when the kinetic energy per particle is below this", "J")
               .above(0)
               .at_most(1),
           &S::settle_ke),
      bind(F::number("settle_max_time", "longest settling per segment", "s").above(0).at_most(1e3),
           &S::settle_max_time),
  };
  return b;
}

const std::vector<Bound<DischargeSpec>>& discharge_fields() {
  using F = Field;
  using S = DischargeSpec;
  static const std::vector<Bound<S>> b = {
      bind(F::number("bin", "outlet statistics bin (the paper: 1 s)", "s")
               .at_least(1e-3)
               .at_most(1e3),
           &S::bin),
      bind(F::number("sink_depth_mm", "particles this far below the outlet are counted and removed",
                     "mm", units::mm)
               .above(0)
               .at_most(1e4),
           &S::sink_depth),
      bind(F::number("stall_time", "no outflow for this long = stopped flow (arching)", "s")
               .above(0)
               .at_most(1e4),
           &S::stall_time),
      bind(F::number("max_time", "longest discharge", "s").above(0).at_most(1e6), &S::max_time),
      bind(F::number("target_fraction", "discharged fraction of the filled mass that ends the run")
               .above(0)
               .at_most(1),
           &S::target_fraction),
  };
  return b;
}

const std::vector<Bound<ParticleSpec>>& particle_fields() {
  using F = Field;
  using S = ParticleSpec;
  static const std::vector<Bound<S>> b = {
      unbound<S>(F::text("coal", "coal name", {})),
      bind(F::vec3("position", "centre", "m").needed(), &S::x),
      bind(F::vec3("velocity", "initial velocity", "m/s"), &S::v),
      bind(F::vec3("angular_velocity", "initial angular velocity", "rad/s"), &S::omega),
      bind(F::number("diameter_mm", "simulated diameter (default: the coal's CG diameter)", "mm",
                     units::mm)
               .above(0)
               .at_most(1e5),
           &S::diameter),
  };
  return b;
}

const std::vector<Bound<LatticeSpec>>& lattice_fields() {
  using F = Field;
  using S = LatticeSpec;
  static const std::vector<Bound<S>> b = {
      unbound<S>(F::text("coal", "coal name", {})),
      bind(F::vec3("origin", "centre of the first particle", "m").needed(), &S::origin),
      bind(F::number("spacing", "centre-to-centre spacing", "m").needed().above(0), &S::spacing),
      unbound<S>(F::vec3("count", "particles along x, y, z").needed()),
      bind(F::vec3("velocity", "initial velocity", "m/s"), &S::v),
  };
  return b;
}

}  // namespace silodem
