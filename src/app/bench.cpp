// SPDX-License-Identifier: MIT
// `silodem bench`: the throughput of a real silo bed (issue 6). Fills the case's silo (by default
// cases/paper/L3-I2.toml, the paper's L3-I2 at k = 3) or loads that fill from a cache, then
// times N steps of the settled bed (valve closed) and N steps right after the valve opens. With
// --flowing T it also discharges the bed to T s (cached as well) and times N steps there: a
// flowing bed anyone can make again, not a checkpoint on one machine.
// Figures: particle-steps per second, neighbour-list rebuilds, contacts per particle, peak
// resident memory. BENCHMARKS.md records them ("Settled silo bed", "Flowing beds", "Memory per
// particle").
#include <fmt/format.h>
#include <sys/resource.h>
#include <toml++/toml.h>
#include <unistd.h>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/run_common.hpp"
#include "core/random.hpp"
#include "io/checkpoint.hpp"
#include "io/config/load.hpp"
#include "scenario/discharge.hpp"
#include "scenario/layered_filling.hpp"

namespace fs = std::filesystem;

namespace silodem::app {
namespace {

// Bump when a change to the fill or the particle state would make old cached beds wrong, or
// when the state's format changes (2: Simulation's SIM2, which older builds cannot read), so
// that builds of two formats keep their own caches.
constexpr int kFillCacheVersion = 2;

fs::path default_cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "silodem";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "silodem";
  return fs::temp_directory_path() / "silodem-cache";
}

long peak_rss_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return long(u.ru_maxrss) * 1024;  // Linux: kilobytes
}

// Resets the kernel's peak-RSS mark (VmHWM) to the current RSS (Linux >= 4.0), so that the peak of
// the timed steps can be told from that of the fill or of reading the cached bed.
bool reset_peak_rss() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  return bool(out.flush());
}

long status_kb(const char* key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string want = std::string(key) + ":";
  while (std::getline(in, line))
    if (line.rfind(want, 0) == 0) return std::atol(line.c_str() + want.size());
  return -1;
}

long current_rss_bytes() {
  std::ifstream in("/proc/self/statm");
  long pages = 0, resident = 0;
  in >> pages >> resident;
  return resident * long(sysconf(_SC_PAGESIZE));
}

// The pair loop's imbalance over the threads since the last reset: the slowest thread's time in
// it over the mean (1 = balanced; the others wait at the barrier for the slowest).
double pair_loop_imbalance(const Simulation& sim) {
  const auto& s = sim.pair_loop_seconds();
  const std::size_t nt = std::min(s.size(), std::size_t(std::max(1, sim.settings().threads)));
  double mx = 0.0, sum = 0.0;
  for (std::size_t k = 0; k < nt; ++k) mx = std::max(mx, s[k]), sum += s[k];
  return sum > 0 ? mx / (sum / double(nt)) : 0.0;
}

struct Phase {
  long steps = 0;
  double seconds = 0.0;
  long rebuilds = 0;
  double imbalance = 0.0;  // pair_loop_imbalance
  double rate(std::size_t n) const { return seconds > 0 ? double(n) * double(steps) / seconds : 0; }
};

Phase time_steps(Simulation& sim, long steps, ProgressLine& progress, const char* what) {
  Phase ph;
  ph.steps = steps;
  const long builds0 = sim.neighbors().builds;
  sim.reset_pair_loop_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const long chunk = std::max(1L, steps / 20);
  for (long done = 0; done < steps;) {
    const long k = std::min(chunk, steps - done);
    sim.run_steps(k);
    done += k;
    progress.show(fmt::format("{}: {} of {} steps", what, done, steps));
  }
  ph.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ph.rebuilds = sim.neighbors().builds - builds0;
  ph.imbalance = pair_loop_imbalance(sim);
  return ph;
}

// N steps of a discharge (particles leave through the outlet as in a run; no probes, no
// checkpoints), in chunks so that a progress line can show.
struct FlowPhase {
  long steps = 0;
  double particle_steps = 0.0, seconds = 0.0;
  long rebuilds = 0;
  double imbalance = 0.0;  // pair_loop_imbalance
  DischargeEnd end = DischargeEnd::Interrupted;
  double rate() const { return seconds > 0 ? particle_steps / seconds : 0.0; }
};

FlowPhase time_discharge(Simulation& sim, Discharge& dis, long steps, ProgressLine& progress,
                         const std::string& what) {
  FlowPhase ph;
  long target = 0;
  DischargeControl control;
  control.stop = [&] {
    ph.particle_steps += double(sim.particles().size());
    return ++ph.steps >= target;
  };
  const long builds0 = sim.neighbors().builds;
  std::string error;
  sim.reset_pair_loop_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const long chunk = std::max(1L, steps / 20);
  while (ph.steps < steps && ph.end == DischargeEnd::Interrupted) {
    target = std::min(steps, ph.steps + chunk);
    const DischargeResult r = dis.run({}, control);
    ph.end = r.end, error = r.error;
    progress.show(fmt::format("{}: {} of {} steps", what, ph.steps, steps));
  }
  ph.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ph.rebuilds = sim.neighbors().builds - builds0;
  ph.imbalance = pair_loop_imbalance(sim);
  if (ph.end == DischargeEnd::Error)
    throw SimulationError(fmt::format("after {} steps: {}", ph.steps, error));
  return ph;
}

// The bed and what a peer code needs to rebuild it (bench/peers/liggghts/): one row per
// particle, and the silo, time step, skin and contact parameters as JSON.
void export_bed(const fs::path& dir, const Case& c, const CaseReport& report,
                const Simulation& sim) {
  fs::create_directories(dir);
  const ParticleStore& p = sim.particles();
  std::string csv = "id,coal,x_m,y_m,z_m,radius_m,mass_kg\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    csv += fmt::format("{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", p.id[i], p.material[i],
                       p.x[i].x, p.x[i].y, p.x[i].z, p.radius[i], p.mass[i]);
  write_text(dir / "bed.csv", csv);
  const SiloGeometry& g = c.silo.geometry;
  const ContactModel& m = sim.model();
  // The peers (bench/peers/) run a linear spring-dashpot; the other slots' numbers are read where
  // the chosen law has them (zero where it has none, e.g. no friction for `none`).
  auto law_table = [](const ContactLaw& l) {
    if (l.law_names[0] != NormalLinearSpringDashpot::name)
      throw InputError({}, "contact.*.normal.law",
                       fmt::format("'{}': the bed export for the peer codes needs '{}' (the "
                                   "peers' model)",
                                   l.law_names[0], NormalLinearSpringDashpot::name));
    const auto& n = l.params<NormalLinearSpringDashpot>();
    auto member = [](const auto& slot, auto get) {
      return std::visit([&](const auto& x) { return get(x); }, slot);
    };
    const double ratio = member(l.tangential, [](const auto& q) {
      if constexpr (requires { q.stiffness_ratio; }) return q.stiffness_ratio;
      return 0.0;
    });
    return toml::table{
        {"normal", l.law_names[0]},
        {"tangential", l.law_names[1]},
        {"rolling", l.law_names[2]},
        {"cohesion", l.law_names[3]},
        {"stiffness_n_N_m", n.stiffness},
        {"restitution", n.restitution},
        {"damping_ratio", n.damping_ratio},
        {"stiffness_t_N_m", ratio * n.stiffness},
        {"tangential_damping_fraction", member(l.tangential,
                                               [](const auto& q) {
                                                 if constexpr (requires { q.damping_fraction; })
                                                   return q.damping_fraction;
                                                 return 0.0;
                                               })},
        {"friction", member(l.tangential,
                            [](const auto& q) {
                              if constexpr (requires { q.friction; }) return q.friction;
                              return 0.0;
                            })},
        {"rolling_friction", member(l.rolling,
                                    [](const auto& q) {
                                      if constexpr (requires { q.friction; }) return q.friction;
                                      return 0.0;
                                    })},
        {"cohesion_force_N", member(l.cohesion, [](const auto& q) {
           if constexpr (requires { q.force; }) return q.force;
           return 0.0;
         })}};
  };
  toml::array pairs, walls, coals;
  for (int a = 0; a < m.materials(); ++a) {
    coals.push_back(toml::table{{"name", c.coals[std::size_t(a)].name},
                                {"cg_diameter_m", report.coals[std::size_t(a)].cg_diameter}});
    walls.push_back(law_table(m.wall(a)));
    for (int b = 0; b < m.materials(); ++b) {
      toml::table t = law_table(m.pair(a, b));
      t.insert("a", a), t.insert("b", b);
      pairs.push_back(std::move(t));
    }
  }
  toml::table t{{"particles", int64_t(p.size())},
                {"time_step_s", sim.settings().dt},
                {"skin_m", sim.settings().skin},
                {"gravity_m_s2", -sim.settings().gravity.z},
                {"silo", toml::table{{"outlet_diameter_m", g.outlet_diameter},
                                     {"cone_height_m", g.cone_height},
                                     {"cylinder_diameter_m", g.cylinder_diameter},
                                     {"cylinder_height_m", g.cylinder_height},
                                     {"valve_gap_m", g.valve_gap}}},
                {"coals", std::move(coals)},
                {"particle_particle", std::move(pairs)},
                {"particle_wall", std::move(walls)}};
  write_text(dir / "bed.json", to_json(t));
}

// `bench --from DIR`: N steps of a run's discharge from its checkpoint, particles leaving through
// the outlet as in the run (no probes, no checkpoints written). This is the flowing bed that
// target 5 runs through, which the settled bed does not show: many listed pairs out of contact,
// frequent rebuilds, particles removed.
int bench_from_checkpoint(const BenchOptions& o) {
  const long rss_start = current_rss_bytes();
  if (o.steps < 1) throw InputError({}, "--steps", "must be at least 1");
  // --set changes the run's case from the checkpoint on (e.g. a speed-only key such as
  // simulation.reorder_every, or a what-if); the run directory itself is not touched.
  RunCheckpoint rc = open_run_checkpoint(o.from_dir, /*force=*/false, "--from");
  if (rc.head.phase == RunHead::Phase::Fill)
    throw InputError({}, "--from",
                     fmt::format("'{}' stopped during its fill: finish it first (silodem run "
                                 "--resume {})",
                                 o.from_dir, o.from_dir));
  if (!o.overrides.empty()) {
    std::vector<std::string> all = rc.overrides;
    all.insert(all.end(), o.overrides.begin(), o.overrides.end());
    rc.c = config::load_case_file(rc.case_path, all, rc.base_dir);
  }
  ContactModel model;
  const CaseReport report = derive_case(rc.c, &model);
  std::size_t valve = 0;
  auto sim = build_silo_simulation(rc.c, report, std::move(model), &valve,
                                   o.threads > 0 ? o.threads : rc.head.threads);
  Discharge dis(*sim, rc.c.silo.geometry, valve, rc.c.discharge);
  sim->load(rc.reader);
  dis.load(rc.reader);         // the probes' state follows; not needed here
  rc.reader = ByteReader({});  // the file's bytes go before the memory is measured
  const std::size_t n0 = sim->particles().size();
  const double t_start = sim->time() - dis.t0();

  ProgressLine progress;
  const bool peak_reset = reset_peak_rss();
  const FlowPhase ph = time_discharge(*sim, dis, o.steps, progress,
                                      fmt::format("discharge from t = {:.3f} s", t_start));
  progress.finish();
  const long done = ph.steps;
  const double particle_steps = ph.particle_steps, seconds = ph.seconds;
  const DischargeEnd end = ph.end;
  const long hwm_kb = status_kb("VmHWM");
  const long stepping_peak = peak_reset && hwm_kb > 0 ? hwm_kb * 1024 : peak_rss_bytes();
  const std::size_t n1 = sim->particles().size();
  const double simulated = double(done) * sim->settings().dt;
  const long rebuilds = ph.rebuilds;
  const double rate = ph.rate();
  const ContactTally tally = sim->contact_tally();
  long contacts = 0;
  for (int k : tally.particle_contacts) contacts += k;
  const double contacts_per = double(contacts) / double(std::max<std::size_t>(n1, 1));
  const double mean_n = done > 0 ? particle_steps / double(done) : double(n0);
  toml::table t{{"from", o.from_dir},
                {"k", report.k},
                {"time_step_s", report.time_step},
                {"threads", int64_t(sim->settings().threads)},
                {"discharge_time_start_s", t_start},
                {"steps", int64_t(done)},
                {"particles_start", int64_t(n0)},
                {"particles_end", int64_t(n1)},
                {"discharge_particle_steps_per_s", rate},
                {"wall_s", seconds},
                {"wall_s_per_simulated_s", simulated > 0 ? seconds / simulated : 0.0},
                {"neighbor_rebuilds", int64_t(rebuilds)},
                {"pair_loop_imbalance", ph.imbalance},
                {"steps_per_rebuild", rebuilds > 0 ? double(done) / double(rebuilds) : 0.0},
                {"list_pairs_per_particle",
                 double(sim->neighbors().partner.size()) / double(std::max<std::size_t>(n1, 1))},
                {"contacts_per_particle", contacts_per},
                {"stepping_peak_rss_bytes", int64_t(stepping_peak)},
                {"memory_bytes_per_particle", double(stepping_peak - rss_start) / mean_n},
                {"run_ended", end != DischargeEnd::Interrupted}};
  if (o.json) {
    fmt::print("{}\n", to_json(t));
    return kExitOk;
  }
  fmt::print(
      "{}: discharge from t = {:.3f} s, {} steps (dt = {:.3g} s), {} threads\n"
      "  particles {} -> {}; {:.3g} particle-steps/s ({:.1f} s wall, {:.0f} s of wall per "
      "simulated s)\n"
      "  {} rebuilds (one per {:.1f} steps), list pairs per particle {:.2f}, contacts per "
      "particle {:.2f}\n"
      "  peak memory while stepping {:.1f} MiB{}\n",
      o.from_dir, t_start, done, report.time_step, sim->settings().threads, n0, n1, rate, seconds,
      simulated > 0 ? seconds / simulated : 0.0, rebuilds,
      rebuilds > 0 ? double(done) / double(rebuilds) : 0.0,
      double(sim->neighbors().partner.size()) / double(std::max<std::size_t>(n1, 1)), contacts_per,
      double(stepping_peak) / (1024.0 * 1024.0),
      end != DischargeEnd::Interrupted ? " (the discharge ended before --steps)" : "");
  return kExitOk;
}

}  // namespace

int bench_command(const BenchOptions& o) {
  if (!o.from_dir.empty()) return bench_from_checkpoint(o);
  const long rss_start = current_rss_bytes();  // the program and its libraries, before any particle
  const Case c = config::load_case_file(o.case_path, o.overrides);
  if (!c.silo.present)
    throw InputError({}, "bench",
                     fmt::format("{} has no [silo]: bench times a silo bed", o.case_path));
  if (o.steps < 1) throw InputError({}, "--steps", "must be at least 1");
  ContactModel model;
  const CaseReport report = derive_case(c, &model);
  std::size_t valve = 0;
  auto sim = build_silo_simulation(c, report, std::move(model), &valve, o.threads);
  const int threads = sim->settings().threads;

  // The cache key: the case as given (text and overrides) and the cache format. Overrides of
  // keys that only change the speed (threads, reorder_every, skin_floor) keep the cached bed, so
  // that they can be timed on the same one.
  std::string key_text = read_text(o.case_path);
  for (const auto& s : o.overrides)
    if (s.rfind("simulation.threads=", 0) != 0 && s.rfind("simulation.reorder_every=", 0) != 0 &&
        s.rfind("simulation.skin_floor=", 0) != 0)
      key_text += "\n--set " + s;
  key_text += fmt::format("\n--version {}", kFillCacheVersion);
  const fs::path cache_dir = o.cache_dir.empty() ? default_cache_dir() : fs::path(o.cache_dir);
  const fs::path cache = cache_dir / fmt::format("fill-{:016x}.bin", text_hash(key_text));

  ProgressLine progress;
  double fill_wall = 0.0;
  bool cached = false;
  if (!o.refill && fs::exists(cache)) {
    try {
      ByteReader r = read_checkpoint(cache.string());
      sim->load(r);
      if (!r.done()) throw std::runtime_error("unread bytes at the end");
    } catch (const std::exception& e) {
      throw std::runtime_error(
          fmt::format("the cached fill {} cannot be read ({}); run again with --refill",
                      cache.string(), e.what()));
    }
    cached = true;
    if (!o.json) fmt::print("loaded the fill from {}\n", cache.string());
  } else {
    Random rng(c.time.seed);
    const FillReport f = fill_silo(*sim, c, report.segment_coal, rng, [&](const std::string& s) {
      progress.show(fmt::format("fill {}  particles {}  wall {:.0f} s", s, sim->particles().size(),
                                progress.elapsed()));
    });
    progress.finish();
    fill_wall = progress.elapsed();
    fs::create_directories(cache_dir);
    ByteWriter w;
    sim->save(w);
    write_checkpoint(cache.string(), w);
    if (!o.json)
      fmt::print("filled {} particles ({:.3f} kg) in {:.0f} s wall; cached in {}\n", f.particles,
                 f.mass, fill_wall, cache.string());
  }
  const std::size_t n = sim->particles().size();
  if (!o.export_dir.empty()) export_bed(o.export_dir, c, report, *sim);
  const long rss_bed = current_rss_bytes();

  const bool peak_reset = reset_peak_rss();
  // Warm-up: builds the list, touches the buffers.
  sim->run_steps(10);
  const ContactTally tally = sim->contact_tally();
  long contacts = 0;
  for (int k : tally.particle_contacts) contacts += k;
  const double list_pairs =
      double(sim->neighbors().partner.size()) / double(std::max<std::size_t>(n, 1));

  const Phase settled = time_steps(*sim, o.steps, progress, "settled bed");
  sim->set_wall_enabled(valve, false);  // the valve opens
  const Phase flowing = time_steps(*sim, o.steps, progress, "discharge");
  progress.finish();
  const long peak = peak_rss_bytes();
  // What the particles cost while stepping: the peak since the reset, above the program's own
  // footprint (neighbour list, contact history, its stash during rebuilds and the force buffers
  // included; the fill and the reading of a cached bed excluded).
  const long hwm_kb = status_kb("VmHWM");
  const long stepping_peak = peak_reset && hwm_kb > 0 ? hwm_kb * 1024 : peak;
  const double per_particle =
      double(stepping_peak - rss_start) / double(std::max<std::size_t>(n, 1));

  // --flowing T: the bed T seconds into its discharge (cached too), and N steps of it.
  FlowPhase flow;
  std::size_t flow_n = 0;
  double flow_t = 0.0, flow_list_pairs = 0.0;
  bool flow_cached = false;
  fs::path flow_cache;
  if (o.flowing > 0) {
    sim.reset();  // the settled bed's memory goes before the flowing bed's comes
    ContactModel model2;
    const CaseReport report2 = derive_case(c, &model2);
    std::size_t valve2 = 0;
    auto fsim = build_silo_simulation(c, report2, std::move(model2), &valve2, o.threads);
    Discharge dis(*fsim, c.silo.geometry, valve2, c.discharge);
    flow_cache =
        cache_dir / fmt::format("flow-{:016x}.bin",
                                text_hash(key_text + fmt::format("\n--flowing {}", o.flowing)));
    if (!o.refill && fs::exists(flow_cache)) {
      try {
        ByteReader r = read_checkpoint(flow_cache.string());
        fsim->load(r);
        dis.load(r);
        if (!r.done()) throw std::runtime_error("unread bytes at the end");
      } catch (const std::exception& e) {
        throw std::runtime_error(
            fmt::format("the cached flowing bed {} cannot be read ({}); run again with --refill",
                        flow_cache.string(), e.what()));
      }
      flow_cached = true;
    } else {
      // The discharge to T takes hours at k = 3: it checkpoints into flow-*.resume.bin every
      // few minutes of wall time, and a later bench with the same case and T continues from there.
      const fs::path resume = fs::path(flow_cache).replace_extension(".resume.bin");
      if (!o.refill && fs::exists(resume)) {
        try {
          ByteReader r = read_checkpoint(resume.string());
          fsim->load(r);
          dis.load(r);
          if (!r.done()) throw std::runtime_error("unread bytes at the end");
        } catch (const std::exception& e) {
          throw std::runtime_error(fmt::format(
              "the partly discharged bed {} cannot be read ({}); run again with --refill",
              resume.string(), e.what()));
        }
        if (!o.json)
          fmt::print("continuing the discharge to t = {} s from {} (t = {:.3f} s)\n", o.flowing,
                     resume.string(), fsim->time() - dis.t0());
      } else {
        ByteReader r = read_checkpoint(cache.string());  // the settled bed as filled
        fsim->load(r);
        dis.open();
      }
      DischargeControl control;
      control.stop = [&] { return fsim->time() - dis.t0() >= o.flowing; };
      control.checkpoint = [&] {
        ByteWriter w;
        fsim->save(w);
        dis.save(w);
        write_checkpoint(resume.string(), w);
      };
      control.checkpoint_wall_interval = 300.0;
      const DischargeResult d = dis.run(
          [&](const DischargeState& st) {
            progress.show(
                fmt::format("discharging the bed to t = {} s: t = {:.3f} s, {} "
                            "particles left",
                            o.flowing, st.t, st.particles_left));
          },
          control);
      progress.finish();
      if (d.end != DischargeEnd::Interrupted)
        throw SimulationError(fmt::format(
            "the bed's discharge ended ({}) at t = {:.3f} s, before --flowing {} s: choose an "
            "earlier time",
            d.end == DischargeEnd::Emptied       ? "the silo emptied"
            : d.end == DischargeEnd::FlowStopped ? "the flow stopped"
            : d.end == DischargeEnd::TimeLimit   ? "max_time"
                                                 : d.error,
            d.end_time, o.flowing));
      ByteWriter w;
      fsim->save(w);
      dis.save(w);
      write_checkpoint(flow_cache.string(), w);
      std::error_code ec;
      fs::remove(resume, ec);
    }
    flow_n = fsim->particles().size();
    flow_t = fsim->time() - dis.t0();
    flow = time_discharge(*fsim, dis, o.steps, progress,
                          fmt::format("flowing bed at t = {:.3f} s", flow_t));
    progress.finish();
    flow_list_pairs = double(fsim->neighbors().partner.size()) /
                      double(std::max<std::size_t>(fsim->particles().size(), 1));
  }

  toml::table t{{"case", o.case_path},
                {"particles", int64_t(n)},
                {"k", report.k},
                {"time_step_s", report.time_step},
                {"steps", int64_t(o.steps)},
                {"threads", int64_t(threads)},
                {"particle_steps_per_s", settled.rate(n)},
                {"discharge_particle_steps_per_s", flowing.rate(n)},
                {"neighbor_rebuilds", int64_t(settled.rebuilds + flowing.rebuilds)},
                {"settled_rebuilds", int64_t(settled.rebuilds)},
                {"pair_loop_imbalance", settled.imbalance},
                {"discharge_rebuilds", int64_t(flowing.rebuilds)},
                {"contacts_per_particle", double(contacts) / double(std::max<std::size_t>(n, 1))},
                {"list_pairs_per_particle", list_pairs},
                {"peak_rss_bytes", int64_t(peak)},
                {"rss_after_fill_bytes", int64_t(rss_bed)},
                {"stepping_peak_rss_bytes", int64_t(stepping_peak)},
                {"rss_at_start_bytes", int64_t(rss_start)},
                {"memory_bytes_per_particle", per_particle},
                {"fill_cached", cached},
                {"fill_wall_s", fill_wall},
                {"cache", cache.string()}};
  if (o.flowing > 0) {
    t.insert("flowing_time_s", flow_t);
    t.insert("flowing_particles", int64_t(flow_n));
    t.insert("flowing_steps", int64_t(flow.steps));
    t.insert("flowing_particle_steps_per_s", flow.rate());
    t.insert("flowing_neighbor_rebuilds", int64_t(flow.rebuilds));
    t.insert("flowing_list_pairs_per_particle", flow_list_pairs);  // at the end
    t.insert("flowing_pair_loop_imbalance", flow.imbalance);
    t.insert("flowing_cached", flow_cached);
    t.insert("flowing_cache", flow_cache.string());
  }
  if (o.json) {
    fmt::print("{}\n", to_json(t));
    return kExitOk;
  }
  fmt::print(
      "{} particles, {} threads, {} steps each (dt = {:.3g} s)\n"
      "  settled bed : {:.3g} particle-steps/s ({:.1f} s, {} rebuilds)\n"
      "  discharge   : {:.3g} particle-steps/s ({:.1f} s, {} rebuilds)\n"
      "  contacts per particle {:.2f}, list pairs per particle {:.2f}\n"
      "  peak memory {:.1f} MiB; while stepping {:.1f} MiB, above the program's own {:.1f} MiB: "
      "{:.0f} bytes per particle\n",
      n, threads, o.steps, report.time_step, settled.rate(n), settled.seconds, settled.rebuilds,
      flowing.rate(n), flowing.seconds, flowing.rebuilds,
      double(contacts) / double(std::max<std::size_t>(n, 1)), list_pairs,
      double(peak) / (1024.0 * 1024.0), double(stepping_peak) / (1024.0 * 1024.0),
      double(rss_start) / (1024.0 * 1024.0), per_particle);
  if (o.flowing > 0)
    fmt::print(
        "  flowing bed : {:.3g} particle-steps/s at t = {:.3f} s of discharge ({} particles "
        "at the start, {} steps, {:.1f} s, {} rebuilds; {:.2f} list pairs per particle at the "
        "end){}\n",
        flow.rate(), flow_t, flow_n, flow.steps, flow.seconds, flow.rebuilds, flow_list_pairs,
        flow_cached ? "; loaded from " + flow_cache.string() : "");
  return kExitOk;
}

}  // namespace silodem::app
