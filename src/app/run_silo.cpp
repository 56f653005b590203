// SPDX-License-Identifier: MIT
// `silodem run` of a silo case: fill, discharge with probes and ParaView frames, outlet
// statistics, summary; checkpoints every [simulation] checkpoint_interval s of discharge (or
// checkpoint_wall_interval s of wall time, if sooner) and on
// SIGINT/SIGTERM; `--resume DIR` continues from DIR/checkpoint.bin bit for bit.
#include <fmt/format.h>
#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include "app/observers.hpp"
#include "app/progress.hpp"
#include "app/run_common.hpp"
#include "app/signals.hpp"
#include "io/checkpoint.hpp"
#include "io/config/load.hpp"
#include "io/csv.hpp"
#include "io/run_dir.hpp"
#include "io/run_metrics.hpp"
#include "io/run_progress.hpp"
#include "scenario/discharge.hpp"
#include "scenario/layered_filling.hpp"
#include "scenario/outlet_stats.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

// The outlet bins up to the last checkpoint of a discharge still under way (docs/runs.md).
constexpr const char* kOutletSoFar = "outlet_so_far.csv";

struct InterruptedFill {};

void write_fill_csv(const fs::path& path, const Case& c, const FillReport& f) {
  CsvWriter w(path.string(),
              {"segment", "coal", "z_low_m", "z_high_m", "z_low_settled_m", "z_high_settled_m",
               "particles", "mass_kg", "target_mass_kg", "bulk_density_kg_m3",
               "measured_bulk_density_kg_m3", "solid_fraction", "settle_time_s", "settled"});
  auto num = [](double x) { return fmt::format("{}", x); };
  for (const auto& s : f.segments)
    w.row(std::vector<std::string>{
        fmt::format("H{}", s.index), c.coals[std::size_t(s.coal)].name, num(s.z_low), num(s.z_high),
        num(s.z_low_settled), num(s.z_high_settled), fmt::format("{}", s.particles), num(s.mass),
        num(s.target_mass), num(s.bulk_density), num(s.bulk_density_measured),
        num(s.solid_fraction), num(s.settle_time), s.settled ? "true" : "false"});
  w.finish();
}

void write_outlet_csv(const fs::path& path, const Case& c, const std::vector<OutletBin>& bins) {
  std::vector<std::string> cols = {"t_start_s", "t_end_s", "mass_kg", "rate_kg_s", "cumulative_kg"};
  for (const auto& coal : c.coals) cols.push_back("fraction_" + coal.name);
  cols.push_back("calorific_kcal_kg");
  CsvWriter w(path.string(), cols);
  for (const auto& b : bins) {
    std::vector<double> row = {b.t_start, b.t_end, b.mass, b.rate, b.cumulative};
    row.insert(row.end(), b.fraction.begin(), b.fraction.end());
    row.push_back(b.calorific);
    w.row(row);
  }
  w.finish();
}

// One row per lost particle: where and how it was found, and where its centre crossed z = 0.
void write_lost_csv(const fs::path& path, const Case& c, const std::vector<LostRecord>& lost) {
  CsvWriter w(path.string(),
              {"time_s", "id", "coal", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s",
               "radius_m", "mass_kg", "reason", "nearest_wall", "wall_distance_m", "crossing_r_m"});
  auto num = [](double x) { return std::isnan(x) ? std::string() : fmt::format("{}", x); };
  for (const auto& l : lost)
    w.row(std::vector<std::string>{
        num(l.t), fmt::format("{}", l.id), c.coals[std::size_t(l.coal)].name, num(l.x.x),
        num(l.x.y), num(l.x.z), num(l.v.x), num(l.v.y), num(l.v.z), num(l.radius), num(l.mass),
        lost_reason_name(l.reason), surface_name(l.nearest.surface), num(l.nearest.distance),
        num(l.crossing_r)});
  w.finish();
}

// The measured outlet data, copied into the run directory, and its errors against the bins.
toml::table measured_summary(const Case& c, const fs::path& out,
                             const std::vector<OutletBin>& bins) {
  const MeasuredData& m = c.measured;
  CsvWriter w((out / "measured.csv").string(), {"t_s", "rate_kg_s", "calorific_kcal_kg"});
  for (std::size_t k = 0; k < m.t.size(); ++k) w.row({m.t[k], m.rate[k], m.calorific[k]});
  w.finish();
  const MeasuredErrors e = compare_with_measured(bins, m);
  toml::table t{{"file", "measured.csv"},
                {"source", c.output.measured},
                {"points", int64_t(m.t.size())},
                {"rate_points", e.rate_points},
                {"calorific_points", e.calorific_points}};
  auto put = [&](const char* key, double x) {
    if (std::isfinite(x)) t.insert(key, x);
  };
  put("rate_max_rel_error", e.rate_max);
  put("rate_mean_rel_error", e.rate_mean);
  put("calorific_max_rel_error", e.calorific_max);
  put("calorific_mean_rel_error", e.calorific_mean);
  return t;
}

// ---- one silo run -----------------------------------------------------------------------------

class SiloRun {
 public:
  SiloRun(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model,
          int threads)
      : o_(o), c_(c), report_(report) {
    sim_ = build_silo_simulation(c, report, std::move(model), &valve_, threads);
    dis_ = std::make_unique<Discharge>(*sim_, c.silo.geometry, valve_, c.discharge);
  }

  // A new run into an empty DIR: fill, then discharge.
  int start(const fs::path& out) {
    out_ = out;
    case_hash_ = RunDir(out_).case_hash();  // the case as started (an edit during it is a change)
    write_summary_running();
    return fill_and_discharge(nullptr);
  }

  // Continue an interrupted or killed run from DIR/checkpoint.bin: its fill, or its discharge.
  int resume(const fs::path& out, const RunHead& head, ByteReader& r) {
    out_ = out;
    case_hash_ = head.case_hash;
    wall_before_ = head.wall;
    if (head.phase == RunHead::Phase::Fill) {
      FillProgress from;
      from.load(r);
      sim_->load(r);
      if (!r.done()) throw std::runtime_error("checkpoint: unread bytes at the end");
      write_summary_running();
      fmt::print("resumed the fill in segment H{} at t = {:.3f} s ({} particles, step {})\n",
                 from.segment + 1, sim_->time(), sim_->particles().size(), sim_->step_count());
      return fill_and_discharge(&from);
    }
    fill_ = head.fill;
    sim_->load(r);
    dis_->load(r);
    observers_ = std::make_unique<Observers>(c_, out_, dis_->t0(), r);
    if (!r.done()) throw std::runtime_error("checkpoint: unread bytes at the end");
    observers_->attach(*sim_);
    write_summary_running();
    fmt::print("resumed at t = {:.3f} s after the valve opened ({} particles, step {})\n",
               sim_->time() - dis_->t0(), sim_->particles().size(), sim_->step_count());
    return discharge();
  }

 private:
  double wall() const { return wall_before_ + progress_.elapsed(); }

  // The fill (from the start, or continued from `from`), then the discharge. The fill is
  // checkpointed between settling chunks, by simulated and by wall time as the discharge is, and
  // on a signal.
  int fill_and_discharge(const FillProgress* from) {
    Random rng(c_.time.seed);
    double sim_at_ck = sim_->time(), wall_at_ck = wall();
    auto fill_checkpoint = [&](const FillProgress& fp) {
      const bool stop = stop_signal() != 0;
      const double dt_sim = c_.time.checkpoint_interval, dt_wall = c_.time.checkpoint_wall_interval;
      if (stop || (dt_sim > 0 && sim_->time() - sim_at_ck >= dt_sim) ||
          (dt_wall > 0 && wall() - wall_at_ck >= dt_wall)) {
        RunDir(out_).write_checkpoint(head(RunHead::Phase::Fill), [&](ByteWriter& w) {
          fp.save(w);
          sim_->save(w);
        });
        sim_at_ck = sim_->time(), wall_at_ck = wall();
      }
      if (stop) throw InterruptedFill{};
    };
    try {
      fill_ = fill_silo(
          *sim_, c_, report_.segment_coal, rng,
          [&](const std::string& s) {
            progress_.show(fmt::format("fill {}  particles {}  wall {:.0f} s", s,
                                       sim_->particles().size(), wall()));
            RunProgress p;
            p.phase = "fill";
            p.wall_s = wall();
            note_progress(p);
          },
          fill_checkpoint, from);
    } catch (const InterruptedFill&) {
      progress_.finish();
      if (!last_progress_.phase.empty()) {
        RunProgress p = last_progress_;
        p.wall_s = wall();
        note_progress(p, true);
      }
      error_ = fmt::format("interrupted by signal {} during the fill", stop_signal());
      write_summary("interrupted during the fill");
      fmt::print(stderr,
                 "interrupted during the fill; checkpoint written; continue with: silodem run "
                 "--resume {}\n",
                 out_.string());
      return kExitInterrupted;
    } catch (const SimulationError& e) {
      progress_.finish();
      error_ = e.what();
      write_summary("error during the fill");
      remove_run_progress(out_);
      fmt::print(stderr, "simulation error: {}\n", error_);
      return kExitSimulation;
    }
    progress_.finish();
    write_fill_csv(out_ / "fill.csv", c_, fill_);
    fmt::print("filled {} particles, {:.3f} kg in {:.0f} s wall ({:.2f} s simulated settling)\n",
               fill_.particles, fill_.mass, wall(), fill_.settle_time);
    for (const auto& w : fill_.warnings) fmt::print(stderr, "warning: {}\n", w);
    dis_->open();
    observers_ = std::make_unique<Observers>(c_, out_, dis_->t0());
    observers_->attach(*sim_);
    observers_->sample(*sim_);  // t = 0: the filled silo
    checkpoint();               // a kill from here on loses at most checkpoint_interval
    return discharge();
  }

  RunHead head(RunHead::Phase phase) const {
    RunHead h;
    h.case_hash = case_hash_;
    h.threads = sim_->settings().threads;
    h.phase = phase;
    h.wall = wall();
    if (phase == RunHead::Phase::Discharge) h.fill = fill_;
    return h;
  }

  void checkpoint() {
    RunDir(out_).write_checkpoint(head(RunHead::Phase::Discharge), [&](ByteWriter& w) {
      sim_->save(w);
      dis_->save(w);
      observers_->save(w);
    });
    // Beside it, the outlet bins up to the checkpoint (removed when the run ends): a few
    // kilobytes that can be kept, committed, when a long run's checkpoint cannot and its machine
    // may be lost (docs/runs.md). Advisory, as progress.json: a failed write does not stop the run.
    try {
      write_outlet_csv(out_ / kOutletSoFar, c_,
                       outlet_bins(dis_->outflow_so_far(), c_.discharge.bin,
                                   sim_->time() - dis_->t0(), heating_values()));
    } catch (const std::exception& e) {
      if (!outlet_so_far_failed_)
        fmt::print(stderr, "warning: cannot write {} ({}); the run goes on\n", kOutletSoFar,
                   e.what());
      outlet_so_far_failed_ = true;
    }
  }

  std::vector<double> heating_values() const {
    std::vector<double> q;
    for (const auto& coal : c_.coals) q.push_back(coal.heating_value);
    return q;
  }

  int discharge() {
    DischargeControl control;
    control.stop = [] { return stop_signal() != 0; };
    control.checkpoint = [this] { checkpoint(); };
    control.checkpoint_interval = c_.time.checkpoint_interval;
    control.checkpoint_wall_interval = c_.time.checkpoint_wall_interval;
    // ETA (discharge_eta, io/run_progress.hpp): the mass still to leave at the outflow rate of
    // the last 5 simulated s (one bin's rate until then) gives the simulated seconds to go; a
    // step costs in proportion to the particles, which fall about linearly to none at a steady
    // outflow. The cost, wall time per particle and simulated second, is smoothed over snapshots
    // at least 1 s of wall apart (a shared machine changes speed). Not the fraction out so far,
    // which overestimates the time while the first bins still fill.
    double t_prev = -1.0, wall_prev = 0.0, n_prev = 0.0, cost = 0.0;
    OutflowWindow outflow;
    try {
      dis_result_ = dis_->run(
          [&](const DischargeState& s) {
            const double now = wall(), n = double(s.particles_left);
            if (t_prev < 0) {
              t_prev = s.t, wall_prev = now, n_prev = n;
            } else if (now - wall_prev >= 1.0 && s.t > t_prev && n + n_prev > 0) {
              // At most twice the running estimate per update: a run paused for a while
              // (SIGSTOP while the machine is needed) must not throw the ETA out by the pause,
              // while a lasting slowdown is still learned within a few updates.
              const double c = (now - wall_prev) / ((s.t - t_prev) * 0.5 * (n + n_prev));
              cost = cost > 0 ? 0.7 * cost + 0.3 * std::min(c, 2.0 * cost) : c;
              t_prev = s.t, wall_prev = now, n_prev = n;
            }
            outflow.add(s.t, s.discharged);
            const double frac = s.discharged / std::max(s.filled, 1e-30);
            const double to_go =
                std::max(0.0, c_.discharge.target_fraction * s.filled - s.discharged);
            const double window_rate = outflow.rate();
            // Unknown while nothing flows.
            const double eta_s = discharge_eta(
                cost, n, to_go, std::isfinite(window_rate) ? window_rate : s.recent_rate,
                c_.discharge.max_time - s.t);
            std::string eta = "?";
            if (std::isfinite(eta_s))
              eta = fmt::format("{:.0f} s", eta_s);
            else if (cost > 0)
              eta = "? (no outflow now)";
            RunProgress p;
            p.phase = "discharge";
            p.t_s = s.t, p.discharged_kg = s.discharged, p.fraction = frac;
            p.rate_kg_s = s.recent_rate, p.wall_s = now, p.eta_s = eta_s;
            note_progress(p);
            progress_.show(fmt::format(
                "discharge t = {:.2f} s  particles left {}  out {:.3f} kg ({:.1f}%)  "
                "rate {:.3f} kg/s  wall {:.0f} s  ETA {}",
                s.t, s.particles_left, s.discharged, 100 * frac, s.recent_rate, wall(), eta));
          },
          control);
    } catch (const std::exception& e) {  // writing a probe row, a frame or a checkpoint failed
      progress_.finish();
      error_ = fmt::format("output failed during the discharge: {}", e.what());
      write_summary("error during the discharge (output)");
      fmt::print(stderr, "error: {} (the last checkpoint is kept: fix it and resume)\n", error_);
      return 1;
    }
    progress_.finish();
    const DischargeResult& d = dis_result_;
    if (d.end == DischargeEnd::Interrupted) {
      checkpoint();
      // Where the checkpoint is: the resume starts here.
      RunProgress p = last_progress_;
      p.phase = "discharge";
      p.t_s = d.end_time, p.discharged_kg = d.discharged_mass;
      p.fraction = d.discharged_mass / std::max(d.filled_mass, 1e-30), p.wall_s = wall();
      note_progress(p, true);
      error_ = fmt::format("interrupted by signal {} at t = {:.3f} s", stop_signal(), d.end_time);
      write_summary("interrupted");
      fmt::print(stderr,
                 "interrupted at t = {:.3f} s of discharge; checkpoint written; continue with: "
                 "silodem run --resume {}\n",
                 d.end_time, out_.string());
      return kExitInterrupted;
    }
    if (d.end == DischargeEnd::Error) error_ = d.error;
    return finish();
  }

  int finish() {
    const DischargeResult& d = dis_result_;
    const std::vector<double> q = heating_values();
    // A time-limited run's last check lands just after max_time: its bins end at max_time (what
    // was in flight then is booked at max_time at the latest), not in a sliver bin after it.
    const double bins_end =
        d.end == DischargeEnd::TimeLimit ? std::min(d.end_time, c_.discharge.max_time) : d.end_time;
    const std::vector<OutletBin> bins = outlet_bins(d.outflow, c_.discharge.bin, bins_end, q);
    write_outlet_csv(out_ / "outlet.csv", c_, bins);
    write_lost_csv(out_ / "lost.csv", c_, d.lost);
    observers_->finish();
    {  // The final state, bit for bit (particles, contact history): for comparisons and tests.
      ByteWriter w;
      sim_->save(w);
      write_checkpoint((out_ / "final_state.bin").string(), w);
    }
    const char* end = d.end == DischargeEnd::Emptied ? "emptied"
                      : d.end == DischargeEnd::FlowStopped
                          ? "flow stopped (no outflow for stall_time)"
                      : d.end == DischargeEnd::Error ? "error during the discharge"
                                                     : "time limit";
    toml::table summary = summary_table(end, bins);
    write_text(out_ / "summary.json", to_json(summary));
    remove_run_progress(out_);  // the run has its result
    std::error_code ignored;
    fs::remove(out_ / kOutletSoFar, ignored);
    // Complete: nothing to resume. After an error the last good checkpoint stays (resume it
    // with --force after changing what caused the error, e.g. a smaller time step).
    if (error_.empty()) RunDir(out_).remove_checkpoint();
    if (!error_.empty()) {
      fmt::print(stderr, "simulation error: {}\n", error_);
      default_signals();
      if (o_.report) report_command(out_.string(), true);
      return kExitSimulation;
    }
    fmt::print(
        "{}: {:.3f} of {:.3f} kg out in {:.2f} s (mean {:.3f} kg/s), {:.3f} kg left, {:.3g} kg "
        "lost; wrote {}\n",
        end, d.discharged_mass, d.filled_mass, d.discharge_time,
        d.discharge_time > 0 ? d.discharged_mass / d.discharge_time : 0.0, d.remaining_mass,
        d.lost_mass, out_.string());
    default_signals();  // the run is complete: Ctrl-C during the report just stops the report
    if (o_.report) report_command(out_.string(), true);
    // A stopped flow is a result, not a success: the silo did not empty.
    return d.end == DischargeEnd::Emptied ? kExitOk : kExitNotEmptied;
  }

  // progress.json (io/run_progress.hpp), at most every few seconds of wall time. It is advisory:
  // a failed write (a full disk) is reported once and does not stop the run.
  void note_progress(const RunProgress& p, bool now = false) {
    last_progress_ = p;
    if (!now && wall() - progress_written_ < 5.0) return;
    progress_written_ = wall();
    try {
      write_run_progress(out_, p);
    } catch (const std::exception& e) {
      if (!progress_failed_)
        fmt::print(stderr, "warning: cannot write progress.json ({}); the run goes on\n", e.what());
      progress_failed_ = true;
    }
  }

  // summary.json before the end: complete = false, so a killed run never looks finished.
  void write_summary_running() {
    toml::table s{{"complete", false},
                  {"end", "running"},
                  {"title", c_.title},
                  {"case", o_.case_path},
                  {"scenario", c_.fill.scenario}};
    write_text(out_ / "summary.json", to_json(s));
  }

  void write_summary(const char* end) {
    toml::table s = summary_table(end, {});
    write_text(out_ / "summary.json", to_json(s));
  }

  toml::table summary_table(const char* end, const std::vector<OutletBin>& bins) {
    const DischargeResult& d = dis_result_;
    const std::vector<double> q = heating_values();
    std::vector<double> out_per_coal(c_.coals.size(), 0.0);
    // Eq. 17 over the planned masses (measured bulk density x segment volume); a coal without a
    // measured bulk density (a dry case filled by volume) has no plan: the filled masses then.
    double inventory_calorific = report_.inventory_calorific;
    if (!std::isfinite(inventory_calorific)) {
      std::vector<double> filled(c_.coals.size(), 0.0);
      for (const auto& seg : fill_.segments) filled[std::size_t(seg.coal)] += seg.mass;
      inventory_calorific = mixture_calorific(filled, q);
    }
    for (const auto& r : d.outflow) out_per_coal[std::size_t(r.coal)] += r.mass;
    const double ledger_error =
        std::fabs(d.filled_mass - (d.remaining_mass + d.discharged_mass + d.lost_mass));
    toml::array fill_warnings, coals;
    for (const auto& w : fill_.warnings) fill_warnings.push_back(w);
    for (std::size_t k = 0; k < c_.coals.size(); ++k)
      coals.push_back(toml::table{{"name", c_.coals[k].name},
                                  {"symbol", c_.coal_symbols[k]},
                                  {"heating_value_kcal_kg", c_.coals[k].heating_value}});
    const SiloGeometry& g = c_.silo.geometry;
    const bool complete = error_.empty() && std::string(end) != "interrupted" &&
                          std::string(end).rfind("interrupted", 0) != 0;
    toml::table summary{
        {"complete", complete},
        {"error", error_},
        {"title", c_.title},
        {"case", o_.case_path},
        {"coals", std::move(coals)},
        {"silo", toml::table{{"outlet_diameter_m", g.outlet_diameter},
                             {"cone_height_m", g.cone_height},
                             {"cylinder_diameter_m", g.cylinder_diameter},
                             {"cylinder_height_m", g.cylinder_height}}},
        {"probe_files", observers_ ? observers_->files() : toml::array{}},
        {"vtk_frames", int64_t(observers_ ? observers_->frames() : 0)},
        {"scenario", c_.fill.scenario},
        {"filled_mass_kg", d.filled_mass},
        {"discharged_mass_kg", d.discharged_mass},
        {"remaining_mass_kg", d.remaining_mass},
        {"lost_mass_kg", d.lost_mass},
        {"particles_lost", d.particles_lost},
        {"particles_round_rim", d.particles_round_rim},
        {"mass_ledger_error_kg", ledger_error},
        {"discharge_time_s", d.discharge_time},
        // Mean rate up to the last particle out (a stall after it does not count).
        {"mean_rate_kg_s", d.discharge_time > 0 ? d.discharged_mass / d.discharge_time : 0.0},
        {"flow_stopped", d.end == DischargeEnd::FlowStopped},
        {"end", end},
        {"particles_filled", d.particles_filled},
        {"fill_settle_time_s", fill_.settle_time},
        {"fill_max_boundary_offset_m", fill_.max_boundary_offset},
        {"outlet_mean_calorific_kcal_kg", mixture_calorific(out_per_coal, q)},
        {"inventory_calorific_kcal_kg", inventory_calorific},
        {"k", report_.k},
        {"time_step_s", sim_->dt()},
        {"discharge_steps", d.steps},
        {"discharge_end_time_s", d.end_time},
        {"threads", sim_->settings().threads},
        {"fill_warnings", std::move(fill_warnings)},
        {"wall_time_s", wall()},
    };
    if (!complete && std::string(end) == "interrupted")
      summary.insert("resume", fmt::format("silodem run --resume {}", out_.string()));
    if (!bins.empty() && !c_.measured.t.empty())
      summary.insert("measured", measured_summary(c_, out_, bins));
    return summary;
  }

  const RunOptions& o_;
  const Case& c_;
  const CaseReport& report_;
  fs::path out_;
  std::unique_ptr<Simulation> sim_;
  std::size_t valve_ = 0;
  std::unique_ptr<Discharge> dis_;
  std::unique_ptr<Observers> observers_;
  FillReport fill_;
  DischargeResult dis_result_;
  std::string error_;
  ProgressLine progress_;
  double wall_before_ = 0.0;
  RunProgress last_progress_;
  bool progress_failed_ = false;
  bool outlet_so_far_failed_ = false;
  double progress_written_ =
      -std::numeric_limits<double>::infinity();  // wall() when progress.json was last written
  std::uint64_t case_hash_ = 0;
};

}  // namespace

int run_silo(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model) {
  SiloRun run(o, c, report, std::move(model), o.threads);
  const fs::path out = prepare_out(o, c, report);
  SignalGuard signals;
  return run.start(out);
}

RunCheckpoint open_run_checkpoint(const fs::path& out, bool force, const char* option) {
  const RunDir dir(out);
  if (!dir.has_checkpoint()) {
    throw InputError({}, option,
                     run_state(out) == RunState::Finished  // summary.json read as JSON
                         ? fmt::format("'{}' is a complete run: nothing to resume", out.string())
                         : fmt::format("'{}' has no checkpoint.bin (a run killed before its "
                                       "first checkpoint in the fill restarts from the case: "
                                       "silodem run {}/case.toml --out NEW_DIR)",
                                       out.string(), out.string()));
  }
  // A truncated, foreign or other-version file is bad input to the command: one line, exit 2.
  RunCheckpoint rc;
  try {
    rc.reader = dir.read_checkpoint(rc.head);
  } catch (const std::runtime_error& e) {
    throw InputError({}, option, e.what());
  }
  if (rc.head.case_hash != dir.case_hash() && !force)
    throw InputError({(out / "case.toml").string(), 0, 0}, option,
                     std::string_view(option) == "--resume"
                         ? "the case file (or overrides.txt) changed since the checkpoint; "
                           "resuming would mix two cases (use --force to resume anyway)"
                         : "the case file (or overrides.txt) changed since the checkpoint; the "
                           "state would not be the case's (restore the file and change the "
                           "case with --set instead)");
  rc.case_path = dir.case_file();
  rc.overrides = dir.overrides();
  // Relative paths in the case (measured data) are relative to where the case file was.
  rc.base_dir = dir.case_dir();
  rc.c = config::load_case_file(rc.case_path, rc.overrides, rc.base_dir);
  if (!rc.c.silo.present) throw InputError({}, option, "only silo runs are resumable");
  return rc;
}

int resume_silo(const RunOptions& o) {
  const fs::path out(o.resume_dir);
  RunCheckpoint rc = open_run_checkpoint(out, o.force, "--resume");
  RunOptions opts = o;
  opts.case_path = rc.case_path;
  opts.overrides = rc.overrides;
  ContactModel model;
  const CaseReport report = derive_case(rc.c, &model);
  if (o.threads > 0 && o.threads != rc.head.threads)
    fmt::print(stderr,
               "warning: resuming with {} threads, the run had {}: the result will not be bitwise "
               "equal to an uninterrupted run (summation order)\n",
               o.threads, rc.head.threads);
  SiloRun run(opts, rc.c, report, std::move(model), o.threads > 0 ? o.threads : rc.head.threads);
  SignalGuard signals;
  return run.resume(out, rc.head, rc.reader);
}

}  // namespace silodem::app
