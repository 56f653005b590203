// SPDX-License-Identifier: MIT
// Discharge: the valve opens at t = 0; a particle leaves when its centre crosses the outlet plane
// inside the outlet (the time of the first check after that is recorded, with its coal and mass)
// and is removed when it has fallen `sink_depth` below it. Where a centre crosses z = 0 is
// noted at the step it happens, so a particle that moves sideways before the next check is still
// classified by where it went through. Particles found outside the walls, or that crossed the
// outlet plane outside the outlet, are removed and counted as lost, each with a record (lost.csv).
// A particle that left through the outlet and then came back up outside the cone, round the rim
// (a cohesive particle can swing round the rim edge), has left the silo: it is removed there and
// counted as discharged. A run that empties or reaches `max_time` books the particles still
// falling between the outlet and the sink at their crossing times, as the sink would have
// (docs/models/silo.md). Ends when the target
// fraction has left or the silo is empty, when
// nothing has left for `stall_time` (a stopped flow: arching, reported as such; the clock starts
// once a particle could have reached the sink), at `max_time`, or on a simulation error (the
// results up to then are kept), or when the caller asks it to stop (a signal; the state is then
// checkpointed and the run can be resumed).
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/bytes.hpp"
#include "engine/simulation.hpp"
#include "scenario/case.hpp"
#include "scenario/silo_geometry.hpp"

namespace silodem {

struct OutletRecord {
  double t = 0.0;  // s since the valve opened
  int coal = 0;
  double mass = 0.0;  // kg
};

// Why a particle was counted lost.
enum class LostReason : std::uint8_t {
  OutsideWall,         // above z = 0, radially outside the wall by more than its radius
  AboveSilo,           // more than 0.5 m above the silo top
  BelowOutsideOutlet,  // below z = 0 at the sink or at the end, having crossed it outside the
                       // outlet
};
const char* lost_reason_name(LostReason r);  // "outside_wall", "above_silo", ...

struct LostRecord {
  double t = 0.0;  // s since the valve opened (the check that found it)
  std::uint64_t id = 0;
  int coal = 0;
  Vec3 x, v;  // m, m/s when found
  double radius = 0.0, mass = 0.0;
  LostReason reason = LostReason::OutsideWall;
  SurfaceDistance nearest;  // the silo surface nearest to x, and on which side of it x is
  double crossing_r = 0.0;  // m from the axis where its centre crossed z = 0 (NaN: never)
};

struct DischargeState {
  double t = 0.0;  // s since the valve opened
  std::size_t particles_left = 0;
  double discharged = 0.0, lost = 0.0, filled = 0.0;
  double recent_rate = 0.0;  // kg/s over the last bin
};

enum class DischargeEnd { Emptied, FlowStopped, TimeLimit, Error, Interrupted };

struct DischargeResult {
  std::vector<OutletRecord> outflow;  // sorted by time
  double filled_mass = 0.0, discharged_mass = 0.0, lost_mass = 0.0, remaining_mass = 0.0;
  long particles_filled = 0, particles_lost = 0;
  std::vector<LostRecord> lost;  // one per lost particle, in the order found
  // Discharged particles that came back up outside the cone round the outlet rim (removed there).
  long particles_round_rim = 0;
  double discharge_time = 0.0;  // s from the valve opening to the last particle out
  double end_time = 0.0;        // s simulated after the valve opened
  DischargeEnd end = DischargeEnd::TimeLimit;
  std::string error;  // DischargeEnd::Error: what went wrong (results up to then kept)
  long steps = 0;
};

using DischargeProgress = std::function<void(const DischargeState&)>;

// How a caller steers a long discharge: `stop` is polled after every step (a signal arrived: the
// run returns with DischargeEnd::Interrupted at once, its state ready to be checkpointed);
// `checkpoint` is called every `checkpoint_interval` s of discharge and every
// `checkpoint_wall_interval` s of wall-clock time, whichever comes first (0 = never). A checkpoint
// changes nothing in the state, so when it happens does not change the result.
struct DischargeControl {
  std::function<bool()> stop;
  std::function<void()> checkpoint;
  double checkpoint_interval = 0.0;
  double checkpoint_wall_interval = 0.0;
};

// The discharge as a resumable object: open() the valve, run() to the end; save()/load() carry
// its whole state (records, sink bookkeeping, position inside the current check interval) across
// a checkpoint, so that a resumed run continues bit for bit.
class Discharge {
 public:
  Discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
            const DischargeSpec& spec);
  void open();  // t = 0: the valve opens; the filled mass is what is in the silo now
  DischargeResult run(const DischargeProgress& progress, const DischargeControl& control = {});
  double t0() const { return t0_; }  // simulation time at the valve opening
  // The outflow booked so far, in booking order: a particle is booked (at the time of the check
  // that saw it cross the outlet plane) when it reaches the sink, so what is still falling
  // between the outlet and the sink is not in it yet.
  const std::vector<OutletRecord>& outflow_so_far() const { return r_.outflow; }
  void save(ByteWriter& w) const;
  void load(ByteReader& r);

 private:
  struct Crossing {
    double t = 0.0;  // s: the first check that saw it below z = 0; -1: it crossed outside
    double r = 0.0;  // m from the axis where it crossed (NaN: not known, an old checkpoint)
  };
  DischargeResult finish(DischargeResult r) const;
  void note_crossings();  // after every step: where centres first go below z = 0
  void check(double t, std::vector<std::size_t>& remove);
  // Books particle i as discharged at t_out (its crossing time), noted at check time t.
  void book_out(double t, std::size_t i, double t_out, std::vector<std::size_t>& remove);
  // At the end (emptied or time limit), what is between the outlet plane and the sink: what
  // went out through the outlet and is falling is discharged at its crossing time (at most
  // t_cap), what crossed outside the outlet is lost.
  void book_in_flight(double t, double t_cap, std::vector<std::size_t>& remove);
  void add_lost(double t, std::size_t i, LostReason why, double crossing_r);

  Simulation& sim_;
  SiloGeometry g_;
  std::size_t valve_;
  DischargeSpec spec_;
  long check_every_ = 1;
  double fall_ = 0.0;
  // State (checkpointed).
  double t0_ = 0.0;
  long steps0_ = 0;
  long step_in_interval_ = 0;
  double next_checkpoint_ = 0.0;
  double last_out_ = 0.0, bin_mass_ = 0.0, bin_start_ = 0.0, recent_rate_ = 0.0;
  std::map<std::uint64_t, Crossing> crossed_;  // id -> its crossing of z = 0, once checked
  std::map<std::uint64_t, double> entered_;    // id -> r where it first went below, until checked
  DischargeResult r_;                          // records and masses so far
};

// Opens the valve and runs to the end (no checkpoints).
DischargeResult discharge(Simulation& sim, const SiloGeometry& g, std::size_t valve_index,
                          const DischargeSpec& spec, const DischargeProgress& progress);

// Mass of every particle in the simulation (kg).
double total_mass(const ParticleStore& p);

}  // namespace silodem
