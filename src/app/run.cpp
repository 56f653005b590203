// SPDX-License-Identifier: MIT
// `silodem run CASE.toml --out DIR`: the generic case (walls + placed particles); writes the
// trajectories asked for in [output] as CSV.
#include <fmt/format.h>
#include <unistd.h>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "app/commands.hpp"
#include "io/config/load.hpp"
#include "io/csv.hpp"
#include "io/report_json.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

std::vector<std::string> trajectory_columns() {
  return {"step",   "t_s",    "id",     "coal",     "x_m",      "y_m",     "z_m",
          "vx_m_s", "vy_m_s", "vz_m_s", "wx_rad_s", "wy_rad_s", "wz_rad_s"};
}

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

void write_text(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".partial";
  {
    std::ofstream o(tmp, std::ios::binary);
    o << text;
    if (!o) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

}  // namespace

int run_command(const RunOptions& o) {
  // Everything that can be wrong with the input is found before the output directory exists.
  const Case c = config::load_case_file(o.case_path);
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  auto sim = build_simulation(c, report, std::move(model), o.threads);

  const fs::path out(o.out_dir);
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
    throw InputError({}, "--out",
                     fmt::format("'{}' exists and is not empty; refusing to overwrite "
                                 "(choose a new directory)",
                                 o.out_dir));
  fs::create_directories(out);
  fs::copy_file(o.case_path, out / "case.toml", fs::copy_options::overwrite_existing);
  write_text(out / "check.json", case_report_json(c, report));

  CsvWriter traj((out / "trajectory.csv").string(), trajectory_columns());
  write_rows(traj, *sim, c.output.ids);
  if (c.output.every > 0) {
    sim->add_hook({"trajectory", Phase::StepEnd, c.output.every,
                   [&](Simulation& s) { write_rows(traj, s, c.output.ids); }});
  }

  const auto t0 = std::chrono::steady_clock::now();
  auto last = t0;
  const bool tty = isatty(STDERR_FILENO);
  const long total = long(c.time.end_time / sim->dt() + 0.5);
  int status = kExitOk;
  std::string error;
  try {
    while (sim->time() + 0.5 * sim->dt() < c.time.end_time) {
      sim->step();
      const auto now = std::chrono::steady_clock::now();
      if (now - last > std::chrono::seconds(tty ? 1 : 5)) {
        last = now;
        const double wall = std::chrono::duration<double>(now - t0).count();
        const double frac = double(sim->step_count()) / double(std::max(total, 1L));
        fmt::print(stderr,
                   "{}t = {:.4f} / {:.4f} s  steps {}  particles {}  wall {:.0f} s  ETA {:.0f} s{}",
                   tty ? "\r" : "", sim->time(), c.time.end_time, sim->step_count(),
                   sim->particles().size(), wall, wall * (1.0 / std::max(frac, 1e-9) - 1.0),
                   tty ? "" : "\n");
      }
    }
    if (c.output.every == 0 || sim->step_count() % c.output.every != 0)
      write_rows(traj, *sim, c.output.ids);
    traj.finish();
  } catch (const SimulationError& e) {
    status = kExitSimulation;
    error = e.what();
  }
  if (tty) fmt::print(stderr, "\n");
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  write_text(
      out / "summary.json",
      fmt::format("{{\n  \"complete\": {},\n  \"error\": \"{}\",\n  \"steps\": {},\n  "
                  "\"time_s\": {:.17g},\n  \"time_step_s\": {:.17g},\n  \"particles\": {},\n  "
                  "\"k\": {:g},\n  \"wall_time_s\": {:.3f}\n}}\n",
                  status == kExitOk, error, sim->step_count(), sim->time(), sim->dt(),
                  sim->particles().size(), report.k, wall));
  if (status != kExitOk) {
    fmt::print(stderr, "error: {}\n", error);
    return status;
  }
  fmt::print("wrote {} ({} steps, {:.1f} s wall)\n", out.string(), sim->step_count(), wall);
  return kExitOk;
}

}  // namespace silodem::app
