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
#include "app/run_common.hpp"
#include "io/atomic_file.hpp"
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
std::string to_json(const toml::table& t) {
  std::ostringstream os;
  os << toml::json_formatter{t} << "\n";
  return os.str();
}

fs::path prepare_out(const RunOptions& o, const Case& c, const CaseReport& report) {
  return RunDir::create(o.out_dir, o.case_path, o.overrides, case_report_json(c, report)).path();
}

namespace {

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

}  // namespace

int run_command(const RunOptions& o) {
  if (!o.resume_dir.empty()) return resume_silo(o);
  // Everything that can be wrong with the input is found before the output directory exists.
  const Case c = config::load_case_file(o.case_path, o.overrides);
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  return c.silo.present ? run_silo(o, c, report, std::move(model))
                        : run_generic(o, c, report, std::move(model));
}

}  // namespace silodem::app
