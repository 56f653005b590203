// SPDX-License-Identifier: MIT
// `silodem run CASE.toml --out DIR`: a generic case (walls + placed particles, trajectories as
// CSV) or a silo case (layered fill, discharge, outlet statistics, fill report, summary).
#include <fmt/format.h>
#include <toml++/toml.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "io/config/load.hpp"
#include "io/csv.hpp"
#include "io/report_json.hpp"
#include "io/vtk.hpp"
#include "probes/registry.hpp"
#include "scenario/discharge.hpp"
#include "scenario/layered_filling.hpp"
#include "scenario/outlet_stats.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

void write_text(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".partial";
  {
    std::ofstream o(tmp, std::ios::binary);
    o << text;
    if (!o) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

std::string to_json(const toml::table& t) {
  std::ostringstream os;
  os << toml::json_formatter{t} << "\n";
  return os.str();
}

// Creates DIR (refusing a non-empty one) with a copy of the case and its derived numbers.
fs::path prepare_out(const RunOptions& o, const Case& c, const CaseReport& report) {
  const fs::path out(o.out_dir);
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
    throw InputError({}, "--out",
                     fmt::format("'{}' exists and is not empty; refusing to overwrite (choose a "
                                 "new directory)",
                                 o.out_dir));
  fs::create_directories(out);
  fs::copy_file(o.case_path, out / "case.toml", fs::copy_options::overwrite_existing);
  std::string overrides;
  for (const auto& s : o.overrides) overrides += s + "\n";
  if (!overrides.empty()) write_text(out / "overrides.txt", overrides);
  write_text(out / "check.json", case_report_json(c, report));
  return out;
}

// ---- generic case ---------------------------------------------------------------------------

void write_rows(CsvWriter& w, const Simulation& sim, const std::vector<std::uint64_t>& ids) {
  const ParticleStore& p = sim.particles();
  auto one = [&](std::size_t i) {
    w.row({double(sim.step_count()), sim.time(), double(p.id[i]), double(p.material[i]), p.x[i].x,
           p.x[i].y, p.x[i].z, p.v[i].x, p.v[i].y, p.v[i].z, p.omega[i].x, p.omega[i].y,
           p.omega[i].z});
  };
  if (ids.empty()) {
    for (std::size_t i = 0; i < p.size(); ++i) one(i);
  } else {
    for (auto id : ids) {
      const long i = p.index_of(id);
      if (i >= 0) one(std::size_t(i));
    }
  }
}

int run_generic(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model) {
  auto sim = build_simulation(c, report, std::move(model), o.threads);
  const fs::path out = prepare_out(o, c, report);
  CsvWriter traj((out / "trajectory.csv").string(),
                 {"step", "t_s", "id", "coal", "x_m", "y_m", "z_m", "vx_m_s", "vy_m_s", "vz_m_s",
                  "wx_rad_s", "wy_rad_s", "wz_rad_s"});
  write_rows(traj, *sim, c.output.ids);
  if (c.output.every > 0)
    sim->add_hook({"trajectory", Phase::StepEnd, c.output.every,
                   [&](Simulation& s) { write_rows(traj, s, c.output.ids); }});
  ProgressLine progress;
  const long total = std::max(1L, long(c.time.end_time / sim->dt() + 0.5));
  std::string error;
  try {
    while (sim->time() + 0.5 * sim->dt() < c.time.end_time) {
      sim->run_steps(std::min(100L, total - sim->step_count()));
      const double frac = double(sim->step_count()) / double(total);
      progress.show(
          fmt::format("t = {:.4f} / {:.4f} s  steps {}  particles {}  wall {:.0f} s  "
                      "ETA {:.0f} s",
                      sim->time(), c.time.end_time, sim->step_count(), sim->particles().size(),
                      progress.elapsed(), progress.elapsed() * (1.0 / std::max(frac, 1e-9) - 1.0)));
    }
    if (c.output.every == 0 || sim->step_count() % c.output.every != 0)
      write_rows(traj, *sim, c.output.ids);
    traj.finish();
  } catch (const SimulationError& e) {
    error = e.what();
  }
  progress.finish();
  toml::table summary{{"complete", error.empty()},
                      {"error", error},
                      {"steps", sim->step_count()},
                      {"time_s", sim->time()},
                      {"time_step_s", sim->dt()},
                      {"particles", int64_t(sim->particles().size())},
                      {"k", report.k},
                      {"wall_time_s", progress.elapsed()}};
  write_text(out / "summary.json", to_json(summary));
  if (!error.empty()) {
    fmt::print(stderr, "simulation error: {}\n", error);
    return kExitSimulation;
  }
  fmt::print("wrote {} ({} steps, {:.1f} s wall)\n", out.string(), sim->step_count(),
             progress.elapsed());
  return kExitOk;
}

// ---- silo case ------------------------------------------------------------------------------

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

// The probes of the discharge, each streaming its rows into probe_<name>.csv, and the ParaView
// frames every vtk_interval seconds. Clock: seconds since the valve opened (t0 = fill end).
class Observers {
 public:
  Observers(const Case& c, const fs::path& out, double t0) : c_(c), out_(out), t0_(t0) {
    for (auto& p : make_probes(c)) {
      files_.push_back(std::make_unique<CsvWriter>(
          (out / fmt::format("probe_{}.csv", p->name())).string(), p->columns()));
      probes_.push_back(std::move(p));
    }
    if (c.output.vtk_interval > 0) {
      fs::create_directories(out / "vtk");
      write_silo_vtp((out / "silo.vtp").string(), c.silo.geometry);
      pvd_ = std::make_unique<PvdCollection>((out / "particles.pvd").string());
    }
  }
  void attach(Simulation& sim) {
    if (!probes_.empty())
      sim.add_hook(
          {"probes", Phase::StepEnd, c_.probes.every, [this](Simulation& s) { sample(s); }});
    if (pvd_)
      sim.add_hook({"vtk", Phase::StepEnd, 1, [this](Simulation& s) {
                      if (s.time() - t0_ >= next_frame_ - 0.5 * s.dt()) frame(s);
                    }});
  }
  void sample(const Simulation& sim) {
    ProbeView view(sim, sim.time() - t0_);
    std::vector<ProbeRow> rows;
    for (std::size_t k = 0; k < probes_.size(); ++k) {
      rows.clear();
      probes_[k]->sample(view, rows);
      for (const auto& r : rows) files_[k]->row(r);
    }
  }
  void frame(const Simulation& sim) {
    const std::string name = fmt::format("vtk/particles_{:06d}.vtp", pvd_->frames());
    write_particles_vtp((out_ / name).string(), sim, sim.contact_tally());
    pvd_->add(sim.time() - t0_, name);
    next_frame_ += c_.output.vtk_interval;
  }
  // Final rows (time averages) and the files renamed to their final names.
  void finish() {
    std::vector<ProbeRow> rows;
    for (std::size_t k = 0; k < probes_.size(); ++k) {
      rows.clear();
      probes_[k]->finish(rows);
      for (const auto& r : rows) files_[k]->row(r);
      files_[k]->finish();
    }
  }
  toml::array files() const {
    toml::array a;
    for (const auto& p : probes_) a.push_back(fmt::format("probe_{}.csv", p->name()));
    return a;
  }
  std::size_t frames() const { return pvd_ ? pvd_->frames() : 0; }

 private:
  const Case& c_;
  fs::path out_;
  double t0_;
  std::vector<std::unique_ptr<Probe>> probes_;
  std::vector<std::unique_ptr<CsvWriter>> files_;
  std::unique_ptr<PvdCollection> pvd_;
  double next_frame_ = 0.0;
};

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

int run_silo(const RunOptions& o, const Case& c, const CaseReport& report, ContactModel model) {
  std::size_t valve = 0;
  auto sim = build_silo_simulation(c, report, std::move(model), &valve, o.threads);
  const fs::path out = prepare_out(o, c, report);
  ProgressLine progress;
  Random rng(c.time.seed);
  std::string error;
  FillReport fill;
  DischargeResult dis;
  bool filled = false;
  std::unique_ptr<Observers> observers;
  try {
    fill = fill_silo(*sim, c, report.segment_coal, rng, [&](const std::string& s) {
      progress.show(fmt::format("fill {}  particles {}  wall {:.0f} s", s, sim->particles().size(),
                                progress.elapsed()));
    });
    progress.finish();
    filled = true;
    write_fill_csv(out / "fill.csv", c, fill);
    fmt::print("filled {} particles, {:.3f} kg in {:.0f} s wall ({:.2f} s simulated settling)\n",
               fill.particles, fill.mass, progress.elapsed(), fill.settle_time);
    for (const auto& w : fill.warnings) fmt::print(stderr, "warning: {}\n", w);
    const double fill_wall = progress.elapsed();
    observers = std::make_unique<Observers>(c, out, sim->time());
    observers->attach(*sim);
    observers->sample(*sim);  // t = 0: the filled silo
    dis = discharge(*sim, c.silo.geometry, valve, c.discharge, [&](const DischargeState& s) {
      const double wall = progress.elapsed() - fill_wall;
      const double frac = s.discharged / std::max(s.filled, 1e-30);
      progress.show(fmt::format(
          "discharge t = {:.2f} s  particles left {}  out {:.3f} kg ({:.1f}%)  "
          "rate {:.3f} kg/s  wall {:.0f} s  ETA {}",
          s.t, s.particles_left, s.discharged, 100 * frac, s.recent_rate, progress.elapsed(),
          frac > 0.01 ? fmt::format("{:.0f} s", wall * (1 / frac - 1)) : "?"));
    });
    progress.finish();
    if (dis.end == DischargeEnd::Error) error = dis.error;
  } catch (const SimulationError& e) {
    progress.finish();
    error = e.what();
  }
  std::vector<double> q;
  for (const auto& coal : c.coals) q.push_back(coal.heating_value);
  std::vector<OutletBin> bins;
  if (filled) {  // also after an error: what left until then is kept
    bins = outlet_bins(dis.outflow, c.discharge.bin, dis.end_time, q);
    write_outlet_csv(out / "outlet.csv", c, bins);
  }
  if (observers) observers->finish();
  // Mass ledger: filled = in silo + discharged + lost.
  const double ledger_error =
      std::fabs(dis.filled_mass - (dis.remaining_mass + dis.discharged_mass + dis.lost_mass));
  std::vector<double> out_per_coal(c.coals.size(), 0.0);
  for (const auto& r : dis.outflow) out_per_coal[std::size_t(r.coal)] += r.mass;
  const char* end = !filled                            ? "error during the fill"
                    : dis.end == DischargeEnd::Emptied ? "emptied"
                    : dis.end == DischargeEnd::FlowStopped
                        ? "flow stopped (no outflow for stall_time)"
                    : dis.end == DischargeEnd::Error ? "error during the discharge"
                                                     : "time limit";
  toml::array fill_warnings;
  for (const auto& w : fill.warnings) fill_warnings.push_back(w);
  toml::array coals;
  for (const auto& coal : c.coals)
    coals.push_back(toml::table{{"name", coal.name},
                                {"symbol", c.coal_symbols[std::size_t(&coal - c.coals.data())]},
                                {"heating_value_kcal_kg", coal.heating_value}});
  const SiloGeometry& g = c.silo.geometry;
  toml::table summary{
      {"complete", error.empty()},
      {"error", error},
      {"title", c.title},
      {"case", o.case_path},
      {"coals", std::move(coals)},
      {"silo", toml::table{{"outlet_diameter_m", g.outlet_diameter},
                           {"cone_height_m", g.cone_height},
                           {"cylinder_diameter_m", g.cylinder_diameter},
                           {"cylinder_height_m", g.cylinder_height}}},
      {"probe_files", observers ? observers->files() : toml::array{}},
      {"vtk_frames", int64_t(observers ? observers->frames() : 0)},
      {"scenario", c.fill.scenario},
      {"filled_mass_kg", dis.filled_mass},
      {"discharged_mass_kg", dis.discharged_mass},
      {"remaining_mass_kg", dis.remaining_mass},
      {"lost_mass_kg", dis.lost_mass},
      {"particles_lost", dis.particles_lost},
      {"mass_ledger_error_kg", ledger_error},
      {"discharge_time_s", dis.discharge_time},
      // Mean rate up to the last particle out (a stall after it does not count).
      {"mean_rate_kg_s", dis.discharge_time > 0 ? dis.discharged_mass / dis.discharge_time : 0.0},
      {"flow_stopped", dis.end == DischargeEnd::FlowStopped},
      {"end", end},
      {"particles_filled", dis.particles_filled},
      {"fill_settle_time_s", fill.settle_time},
      {"fill_max_boundary_offset_m", fill.max_boundary_offset},
      {"outlet_mean_calorific_kcal_kg", mixture_calorific(out_per_coal, q)},
      {"inventory_calorific_kcal_kg", report.inventory_calorific},
      {"k", report.k},
      {"time_step_s", sim->dt()},
      {"discharge_steps", dis.steps},
      {"discharge_end_time_s", dis.end_time},
      {"threads", sim->settings().threads},
      {"fill_warnings", std::move(fill_warnings)},
      {"wall_time_s", progress.elapsed()},
  };
  if (filled && !c.measured.t.empty()) summary.insert("measured", measured_summary(c, out, bins));
  write_text(out / "summary.json", to_json(summary));
  if (!error.empty()) {
    fmt::print(stderr, "simulation error: {}\n", error);
    if (filled && o.report) report_command(out.string(), true);
    return kExitSimulation;
  }
  fmt::print(
      "{}: {:.3f} of {:.3f} kg out in {:.2f} s (mean {:.3f} kg/s), {:.3f} kg left, {:.3g} kg "
      "lost; wrote {}\n",
      end, dis.discharged_mass, dis.filled_mass, dis.discharge_time,
      dis.discharge_time > 0 ? dis.discharged_mass / dis.discharge_time : 0.0, dis.remaining_mass,
      dis.lost_mass, out.string());
  if (o.report) report_command(out.string(), true);
  // A stopped flow is a result, not a success: the silo did not empty.
  return dis.end == DischargeEnd::Emptied ? kExitOk : kExitNotEmptied;
}

}  // namespace

int run_command(const RunOptions& o) {
  // Everything that can be wrong with the input is found before the output directory exists.
  const Case c = config::load_case_file(o.case_path, o.overrides);
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  return c.silo.present ? run_silo(o, c, report, std::move(model))
                        : run_generic(o, c, report, std::move(model));
}

}  // namespace silodem::app
