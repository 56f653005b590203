// SPDX-License-Identifier: MIT
#include "scenario/shear_cell.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "engine/plate.hpp"
#include "engine/walls/plane.hpp"
#include "scenario/size_distribution.hpp"

namespace silodem {
namespace {

// Volume of the part of a sphere (centre z0, radius r) between the planes z = a and z = b.
double sphere_slab(double z0, double r, double a, double b) {
  auto below = [&](double u) {  // cap below the plane z = u
    const double h = std::clamp(u - (z0 - r), 0.0, 2.0 * r);
    return kPi * h * h * (3.0 * r - h) / 3.0;
  };
  return below(b) - below(a);
}

class Cell {
 public:
  Cell(std::unique_ptr<Simulation> sim, double area, double d_mean)
      : sim_(std::move(sim)), area_(area), d_(d_mean) {
    floor_ = std::make_unique<Plate>(*sim_, 0);
    lid_ = std::make_unique<Plate>(*sim_, 1);
    floor_->add_to(*sim_);
    lid_->add_to(*sim_);
  }
  Simulation& sim() { return *sim_; }
  Plate& lid() { return *lid_; }
  Plate& floor() { return *floor_; }
  double lid_z() const { return dynamic_cast<const PlaneWall&>(sim_->wall(1)).point().z; }
  // Steps n times; returns the mean normal and shear stress on the lid over them.
  StressPoint run(long n) {
    double s = 0, t = 0;
    for (long k = 0; k < n; ++k) {
      sim_->step();
      const Vec3 f = lid_->force(*sim_);
      s += -dot(f, lid_->normal()) / area_;
      t += -f.x / area_;  // the lid moves along +x: the sample holds it back
    }
    return {s / double(n), t / double(n)};
  }
  double area() const { return area_; }
  double d() const { return d_; }

 private:
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<Plate> floor_, lid_;
  double area_, d_;
};

}  // namespace

void check_shear_spec(const ShearTestSpec& spec) {
  if (spec.normals.size() < 2)
    throw InputError({}, "--normal", "needs at least two normal stresses for a yield locus");
  for (double s : spec.normals)
    if (!(s > 0 && s < spec.preshear))
      throw InputError({}, "--normal",
                       fmt::format("{:g} kPa: each normal stress must lie in (0, {:g}) kPa, below "
                                   "the pre-shear stress",
                                   s / 1e3, spec.preshear / 1e3));
  if (!(spec.steady_step > 0 && spec.steady_window > 0 && spec.sample_strain > 0))
    throw InputError({}, "steady_step",
                     fmt::format("the steady-shear step {:g}, window {:g} and row {:g} of strain "
                                 "must be positive",
                                 spec.steady_step, spec.steady_window, spec.sample_strain));
  if (!(spec.preshear_max_strain >= spec.preshear_strain))
    throw InputError({}, "--preshear-max-strain",
                     fmt::format("{:g}: must be at least the first pre-shear's least strain "
                                 "(--preshear-strain, {:g})",
                                 spec.preshear_max_strain, spec.preshear_strain));
}

bool shear_is_steady(const std::vector<ShearSample>& rows, std::size_t per_window,
                     const ShearTestSpec& spec) {
  const std::size_t n = rows.size();
  if (per_window == 0 || n < 2 * per_window) return false;
  struct Mean {
    double sigma = 0, tau = 0, height = 0;
  };
  auto mean = [&](std::size_t i0) {
    Mean m;
    for (std::size_t i = i0; i < i0 + per_window; ++i)
      m.sigma += rows[i].sigma, m.tau += rows[i].tau, m.height += rows[i].height;
    return m;  // sums: the ratios below do not need the count
  };
  const Mean last = mean(n - per_window), before = mean(n - 2 * per_window);
  if (!(last.height > 0 && last.sigma > 0 && before.sigma > 0)) return false;
  const double r_last = last.tau / last.sigma, r_before = before.tau / before.sigma;
  return std::abs(last.height - before.height) < spec.steady_height_change * last.height &&
         std::abs(r_last - r_before) < spec.steady_ratio_change * std::abs(r_last);
}

ShearTestResult run_shear_test(const ScenarioCase& c, const CaseReport& report,
                               const ContactModel& model, int coal, const ShearTestSpec& spec,
                               const ShearProgress& progress,
                               const ShearCheckpointing* checkpointing) {
  check_shear_spec(spec);
  const CoalProperties& coal_p = c.coals[std::size_t(coal)];
  const CoalReport& cr = report.coals[std::size_t(coal)];
  ShearTestResult res;
  res.coal = coal_p.name;

  // Sizes: the coal's CG distribution; its number mean sets the cell.
  Random rng(spec.seed * 0x9e3779b97f4a7c15ULL + std::uint64_t(coal) + 1);
  const SizeSampler sizes(coal_p, c.cg);
  double d_mean = 0;
  {
    Random probe(spec.seed);
    for (int k = 0; k < 4000; ++k) d_mean += sizes.sample(probe) / 4000.0;
  }
  const double d_max = sizes.max_diameter(), d_min = sizes.min_diameter();
  res.mean_diameter = d_mean;

  SimulationSettings s = settings_of(c, report, d_min, spec.threads);
  s.gravity = {};
  s.max_speed = 0.0;
  const double cut = d_max * (1.0 + model.max_reach_over_d()) + s.skin;
  double L = spec.width * d_mean;
  if (L < 2.05 * cut) {
    res.warnings.push_back(fmt::format(
        "the cell is {:.4g} m wide, not {:g} mean diameters: the periodic box must be at least "
        "twice the neighbour cut-off",
        2.05 * cut, spec.width));
    L = 2.05 * cut;
  }
  s.periodic.set(0, 0.0, L);
  s.periodic.set(1, 0.0, L);
  res.width = L;
  res.dt = s.dt;

  // The loose sample: a jittered lattice with the solid volume of the sample at a solid fraction
  // of 0.6 between the plates (the sheared height plus the two glued layers).
  const double h_total = (spec.height + 2.0) * d_mean;
  const double solid = 0.6 * L * L * h_total;
  const int nxy = std::max(1, int(std::floor(L / (1.05 * d_max))));
  const double sxy = L / nxy, sz = 1.05 * d_max;
  const double jitter = 0.45 * (std::min(sxy, sz) - d_max);
  auto sim = std::make_unique<Simulation>(model, s);
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, 0}, Vec3{0, 0, 1}));
  auto& p = sim->particles();
  double placed = 0, z_top = 0;
  for (int layer = 0; placed < solid; ++layer) {
    const double z = 0.5 * d_max + jitter + layer * sz;
    for (int iy = 0; iy < nxy && placed < solid; ++iy)
      for (int ix = 0; ix < nxy && placed < solid; ++ix) {
        const double di = sizes.sample(rng);
        const Vec3 x{(ix + 0.5) * sxy + rng.uniform(-jitter, jitter),
                     (iy + 0.5) * sxy + rng.uniform(-jitter, jitter),
                     z + rng.uniform(-jitter, jitter)};
        p.add(s.periodic.wrap(x), {}, {}, 0.5 * di, sphere_mass(di, coal_p.true_density), coal);
        placed += kPi / 6.0 * di * di * di;
        z_top = std::max(z_top, z + 0.5 * d_max + jitter);
      }
  }
  sim->add_wall(std::make_unique<PlaneWall>(Vec3{0, 0, z_top + 0.01 * d_max}, Vec3{0, 0, -1}));
  res.particles = int(p.size());
  Cell cell(std::move(sim), L * L, d_mean);
  Simulation& S = cell.sim();

  // The servo's gain: stable when gain x (c + k dt) < 1 over the lid's contacts (plate.hpp). A
  // contact of a CG particle on a wall has k = m (pi / t_col)^2 and at most the critical damping
  // 2 sqrt(m k); the lid (or its glued layer) touches about one particle per d^2 of its area.
  const double m_cg = cr.cg_mass, t_w = cr.wall_collision_time;
  const double k_w = m_cg * kPi * kPi / (t_w * t_w), c_w = 2.0 * std::sqrt(m_cg * k_w);
  const double contacts = (L / d_mean) * (L / d_mean);
  const double gain = 0.5 / (contacts * (c_w + k_w * s.dt));
  const double sigma_min = *std::min_element(spec.normals.begin(), spec.normals.end());
  const double t_col = report.collision_time_min;
  // The integral time: with the bulk's stiffness, about (L / d)^2 k / (H / d), the proportional
  // loop's time is about 10 t_col; 50 t_col damps the integral's loop (damping ratio about 1).
  auto servo = [&](double sigma, double vx, double v_cap) {
    cell.lid().set_control({{vx, 0, 0}, true, sigma, cell.area(), gain, v_cap, 50.0 * t_col});
  };
  const long chunk = std::max(100L, long(20.0 * t_col / s.dt));
  auto log = [&](const std::string& m) {
    if (progress) progress(fmt::format("{}: {}", coal_p.name, m));
  };
  auto record = [&](const std::string& phase, int point, double strain, const StressPoint& st) {
    res.series.push_back({phase, point, S.time(), strain, st.sigma, st.tau, cell.lid_z()});
  };

  // Where the test is: its stage (kStages below, then four per normal stress) and the state of
  // the stage under way, so that a checkpoint can be taken after any row or chunk.
  struct Cursor {
    int stage = 0;
    bool begun = false;     // the stage has set its control and started its state below
    double t0 = 0.0;        // hold: when it began
    int good = 0;           // hold: chunks in a row within 2% of the load
    double x0 = 0.0;        // shear: the lid's displacement when it began
    double target = 0.0;    // shear: the strain to reach before the next steadiness check
    std::size_t first = 0;  // shear: its first row in res.series
    std::size_t least = 0;  // shear: its rows when it reached its least strain (0: not yet)
    StressPoint pre_sum;    // the pre-shear points so far
    int n_pre = 0;
  } cur;
  enum : int { kCompress, kConsolidate, kGlue, kFirstPreshear, kBulk, kStages };
  const int end_stage = kStages + 4 * int(spec.normals.size());

  // After the plates are glued: the sheared height sets the shear speed and the rows.
  double h_shear = 0.0, v_shear = 0.0, v_cap = 0.0;
  long per_row = 1;
  auto set_shear = [&] {
    h_shear = res.sheared_height;
    v_shear = res.shear_velocity;
    per_row = std::max(1L, long(std::llround(spec.sample_strain * h_shear / v_shear / s.dt)));
    v_cap = 0.5 * v_shear;  // the lid's normal speed, at most half the shear speed
  };

  // SHC1: the first layout of a test's state (a new layout gets a new tag, so an old file is
  // refused instead of misread).
  auto save_state = [&](ByteWriter& w) {
    w.tag("SHC1");
    w.put(std::int32_t(S.settings().threads));
    w.put(cur.stage), w.put(std::uint8_t(cur.begun)), w.put(cur.t0), w.put(cur.good);
    w.put(cur.x0), w.put(cur.target), w.put(std::uint64_t(cur.first));
    w.put(std::uint64_t(cur.least)), w.put(cur.pre_sum), w.put(cur.n_pre);
    save_shear_result(w, res);
    S.save(w);
    cell.floor().save(w, S);
    cell.lid().save(w, S);
  };
  if (checkpointing && checkpointing->resume) {
    ByteReader& r = *checkpointing->resume;
    std::int32_t threads = 0;
    try {
      r.tag("SHC1");
      r.get(threads);
      r.get(cur.stage), cur.begun = r.get<std::uint8_t>() != 0, r.get(cur.t0), r.get(cur.good);
      r.get(cur.x0), r.get(cur.target), cur.first = std::size_t(r.get<std::uint64_t>());
      cur.least = std::size_t(r.get<std::uint64_t>()), r.get(cur.pre_sum), r.get(cur.n_pre);
      res = load_shear_result(r);
      S.load(r);
      cell.floor().load(r, S);
      cell.lid().load(r, S);
    } catch (const std::runtime_error& e) {  // damaged, or a layout this build does not write
      throw ShearResumeError(e.what());
    }
    if (!r.done()) throw ShearResumeError("the shear test's state has bytes left over");
    if (!(cur.stage >= 0 && cur.stage <= end_stage) || cur.first > res.series.size() ||
        res.coal != coal_p.name)
      throw ShearResumeError("the shear test's state does not fit this test");
    if (cur.stage > kGlue) set_shear();
    log(fmt::format("resumed at t = {:.3f} s, {} steps", S.time(), S.step_count()));
    if (threads != S.settings().threads) {
      res.warnings.push_back(fmt::format(
          "resumed at t = {:.3f} s with {} threads where it had {}: not bitwise the test that "
          "was never stopped (summation order)",
          S.time(), S.settings().threads, threads));
      log(res.warnings.back());
    }
  }
  // A checkpoint now if asked for; after a stop, none of the test's work is lost.
  auto tick = [&] {
    if (!checkpointing) return;
    const bool stop = checkpointing->stop && checkpointing->stop();
    if (stop || (checkpointing->due && checkpointing->due())) {
      if (checkpointing->write) checkpointing->write(save_state);
      if (stop) throw ShearInterrupted{};
    }
  };

  // Hold `sigma` without shearing until the mean load over three chunks in a row is within 2% of
  // it (at most 5000 t_col). The sample still creeps then, slowly; the shear that follows sets
  // its state.
  auto hold = [&](const std::string& phase, int point, double sigma) {
    if (!cur.begun) {
      servo(sigma, 0.0, 0.0);
      cur.good = 0;
      cur.t0 = S.time();
      cur.begun = true;
    }
    while (cur.good < 3 && S.time() - cur.t0 < 5000 * t_col) {
      const StressPoint st = cell.run(chunk);
      record(phase, point, 0.0, st);
      cur.good = std::abs(st.sigma / sigma - 1.0) < 0.02 ? cur.good + 1 : 0;
      tick();
    }
    if (cur.good < 3)
      res.warnings.push_back(
          fmt::format("{} at {:g} kPa: the load did not settle within 5000 "
                      "collision times",
                      phase, sigma / 1e3));
  };

  // A shear's rows, and how many of them it took to reach its least strain.
  struct Shear {
    std::vector<ShearSample> rows;
    std::size_t least = 0;
  };
  // Shears at `sigma` by `strain`, then on in steps of spec.steady_step while `settled` (if
  // given) says no and the strain is below `max_strain`.
  using Settled = std::function<bool(const std::vector<ShearSample>&)>;
  auto shear = [&](const std::string& phase, int point, double sigma, double strain,
                   double max_strain, const Settled& settled) {
    if (!cur.begun) {
      servo(sigma, v_shear, v_cap);
      cur.x0 = cell.lid().displacement().x;
      cur.target = strain;
      cur.first = res.series.size();
      cur.least = 0;
      cur.begun = true;
    }
    auto rows = [&] {
      return std::vector<ShearSample>(res.series.begin() + long(cur.first), res.series.end());
    };
    for (;;) {
      while (cell.lid().displacement().x - cur.x0 < cur.target * h_shear) {
        const StressPoint st = cell.run(per_row);
        record(phase, point, (cell.lid().displacement().x - cur.x0) / h_shear, st);
        tick();
      }
      if (cur.least == 0) cur.least = res.series.size() - cur.first;
      if (!settled || cur.target >= max_strain || settled(rows())) break;
      cur.target = std::min(max_strain, cur.target + spec.steady_step);
    }
    Shear out{rows(), cur.least};
    log(fmt::format("{} {} at {:g} kPa: strain {:.2f} done, t = {:.3f} s, {} steps", phase, point,
                    sigma / 1e3, out.rows.empty() ? 0.0 : out.rows.back().strain, S.time(),
                    S.step_count()));
    return out;
  };
  const auto per_window =
      std::size_t(std::max(1L, std::lround(spec.steady_window / spec.sample_strain)));
  // The end of a pre-shear: the mean of its last rows, as many as a third of its least strain
  // took (of the whole pre-shear when it ran a fixed strain, as before 2026-12-07).
  auto preshear_end = [](const Shear& sh) {
    const std::size_t n = sh.rows.size(), a = n - std::min(n, sh.least / 3);
    StressPoint m;
    for (std::size_t i = a; i < n; ++i) m.sigma += sh.rows[i].sigma, m.tau += sh.rows[i].tau;
    const double k = double(std::max<std::size_t>(1, n - a));
    return StressPoint{m.sigma / k, m.tau / k};
  };

  for (; cur.stage < end_stage; ++cur.stage, cur.begun = false, tick()) {
    switch (cur.stage) {
      case kCompress: {
        // 1. Press the loose sample to the pre-shear stress: the lid comes down at a set speed
        // until it carries half the load, then the servo takes over (kConsolidate).
        if (!cur.begun) {
          const double v_press = std::min(0.1, 0.05 * h_total / (200 * t_col));
          cell.lid().set_control({{0, 0, -v_press}});
          log(fmt::format("{} particles in a {:.1f} mm cell; pressing to {:g} kPa", res.particles,
                          L * 1e3, spec.preshear / 1e3));
          cur.begun = true;
        }
        for (;;) {
          const StressPoint st = cell.run(chunk);
          record("compress", 0, 0.0, st);
          if (st.sigma > spec.preshear / 2) break;
          if (cell.lid_z() < 0.5 * h_total)
            throw SimulationError(
                "shear cell: the lid came down to half the sample height without "
                "meeting the pre-shear load");
          tick();
        }
        break;
      }
      case kConsolidate:
        hold("consolidate", 0, spec.preshear);
        break;
      case kGlue: {
        // 2. Rough plates of the coal itself.
        std::vector<std::size_t> bottom, top;
        const double zl = cell.lid_z();
        for (std::size_t i = 0; i < p.size(); ++i) {
          if (S.particles().x[i].z < d_mean) bottom.push_back(i);
          if (S.particles().x[i].z > zl - d_mean) top.push_back(i);
        }
        cell.floor().glue(S, bottom);
        cell.lid().glue(S, top);
        res.glued = int(bottom.size() + top.size());
        res.sheared_height = cell.lid_z() - 2.0 * d_mean;
        res.shear_velocity = spec.inertial_number * res.sheared_height *
                             std::sqrt(sigma_min / coal_p.true_density) / d_mean;
        set_shear();
        break;
      }
      case kFirstPreshear: {
        // 3. The first pre-shear, until steady.
        const Shear first =
            shear("preshear", 0, spec.preshear, spec.preshear_strain, spec.preshear_max_strain,
                  [&](const std::vector<ShearSample>& rows) {
                    return shear_is_steady(rows, per_window, spec);
                  });
        cur.pre_sum = preshear_end(first);
        cur.n_pre = 1;
        res.preshear_steady = shear_is_steady(first.rows, per_window, spec);
        res.preshear_strain = first.rows.empty() ? 0.0 : first.rows.back().strain;
        if (!res.preshear_steady)
          res.warnings.push_back(fmt::format(
              "the first pre-shear was not steady by a strain of {:.2f} (--preshear-max-strain): "
              "the sample height or tau / sigma still changed by more than {:g}% or {:g}% over "
              "{:g} of strain",
              res.preshear_strain, 100 * spec.steady_height_change, 100 * spec.steady_ratio_change,
              spec.steady_window));
        break;
      }
      case kBulk: {
        // The bulk density between the glued layers after the first pre-shear.
        const double a = d_mean, b = cell.lid_z() - d_mean;
        double v = 0;
        const auto& q = S.particles();
        for (std::size_t i = 0; i < q.size(); ++i) v += sphere_slab(q.x[i].z, q.radius[i], a, b);
        res.solid_fraction = v / (L * L * (b - a));
        res.bulk_density = res.solid_fraction * coal_p.true_density;
        break;
      }
      default: {
        // 4. For each lower stress: hold the pre-shear stress, pre-shear again, stop, hold the
        // lower stress, shear to failure.
        const std::size_t k = std::size_t(cur.stage - kStages) / 4;
        const int point = int(k) + 1;
        const double sigma = spec.normals[k];
        switch ((cur.stage - kStages) % 4) {
          case 0:  // back to the pre-shear stress first (the servo's speed is capped in a shear)
            hold("consolidate", point, spec.preshear);
            break;
          case 1: {
            const Shear pre =
                shear("preshear", point, spec.preshear, spec.represhear_strain, 0.0, nullptr);
            ShearPoint sp;
            sp.sigma_target = sigma;
            sp.preshear = preshear_end(pre);
            // Steady over its two halves (a later pre-shear is shorter than two windows).
            sp.preshear_steady =
                shear_is_steady(pre.rows, std::min(per_window, pre.rows.size() / 2), spec);
            cur.pre_sum.sigma += sp.preshear.sigma, cur.pre_sum.tau += sp.preshear.tau;
            ++cur.n_pre;
            res.points.push_back(sp);
            break;
          }
          case 2:
            hold("relax", point, sigma);
            break;
          default:
            shear("shear", point, sigma, spec.failure_strain, 0.0, nullptr);
        }
      }
    }
  }
  res.preshear = {cur.pre_sum.sigma / cur.n_pre, cur.pre_sum.tau / cur.n_pre};
  evaluate_failure(res, spec);
  res.steps = S.step_count();
  return res;
}

void save_shear_result(ByteWriter& w, const ShearTestResult& r) {
  w.tag("SHRS");
  w.put(r.coal), w.put(r.particles), w.put(r.glued), w.put(r.width), w.put(r.sheared_height);
  w.put(r.mean_diameter), w.put(r.shear_velocity), w.put(r.dt), w.put(r.bulk_density);
  w.put(r.solid_fraction), w.put(r.preshear), w.put(std::uint8_t(r.preshear_steady));
  w.put(r.preshear_strain);
  w.put(std::uint64_t(r.points.size()));
  for (const ShearPoint& p : r.points) {
    w.put(p.sigma_target), w.put(p.sigma), w.put(p.tau), w.put(p.strain_at_peak);
    w.put(p.preshear), w.put(std::uint8_t(p.preshear_steady));
  }
  const YieldLocus& y = r.locus;
  w.put(y.cohesion), w.put(y.friction_angle), w.put(y.rms_residual), w.put(y.cohesion_stderr);
  w.put(y.friction_angle_stderr), w.put(y.unconfined), w.put(y.consolidation);
  w.put(y.unconfined_yield), w.put(y.major_consolidation), w.put(y.flow_function);
  w.put(std::uint8_t(y.consolidation_tangent));
  w.put(std::uint64_t(r.series.size()));
  for (const ShearSample& s : r.series) {
    w.put(s.phase), w.put(s.point), w.put(s.time), w.put(s.strain), w.put(s.sigma), w.put(s.tau);
    w.put(s.height);
  }
  w.put(r.steps);
  w.put(std::uint64_t(r.warnings.size()));
  for (const auto& m : r.warnings) w.put(m);
}

ShearTestResult load_shear_result(ByteReader& r) {
  ShearTestResult o;
  r.tag("SHRS");
  r.get(o.coal), r.get(o.particles), r.get(o.glued), r.get(o.width), r.get(o.sheared_height);
  r.get(o.mean_diameter), r.get(o.shear_velocity), r.get(o.dt), r.get(o.bulk_density);
  r.get(o.solid_fraction), r.get(o.preshear), o.preshear_steady = r.get<std::uint8_t>() != 0;
  r.get(o.preshear_strain);
  o.points.resize(r.get_count(sizeof(double)));
  for (ShearPoint& p : o.points) {
    r.get(p.sigma_target), r.get(p.sigma), r.get(p.tau), r.get(p.strain_at_peak);
    r.get(p.preshear), p.preshear_steady = r.get<std::uint8_t>() != 0;
  }
  YieldLocus& y = o.locus;
  r.get(y.cohesion), r.get(y.friction_angle), r.get(y.rms_residual), r.get(y.cohesion_stderr);
  r.get(y.friction_angle_stderr), r.get(y.unconfined), r.get(y.consolidation);
  r.get(y.unconfined_yield), r.get(y.major_consolidation), r.get(y.flow_function);
  y.consolidation_tangent = r.get<std::uint8_t>() != 0;
  o.series.resize(r.get_count(sizeof(double)));
  for (ShearSample& s : o.series) {
    r.get(s.phase), r.get(s.point), r.get(s.time), r.get(s.strain), r.get(s.sigma), r.get(s.tau);
    r.get(s.height);
  }
  r.get(o.steps);
  o.warnings.resize(r.get_count(sizeof(std::uint64_t)));
  for (auto& m : o.warnings) r.get(m);
  return o;
}

void evaluate_failure(ShearTestResult& r, const ShearTestSpec& spec) {
  std::vector<StressPoint> failure;
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    ShearPoint& sp = r.points[k];
    std::vector<StressPoint> rows;
    std::vector<double> strains;
    for (const auto& row : r.series)
      if (row.phase == "shear" && row.point == int(k) + 1)
        rows.push_back({row.sigma, row.tau}), strains.push_back(row.strain);
    if (rows.empty())
      throw SimulationError(fmt::format("shear test: no shear rows for the point at {:g} kPa",
                                        sp.sigma_target / 1e3));
    FailurePick pick;
    try {
      pick = pick_failure(rows, spec.failure);
    } catch (const std::invalid_argument& e) {
      throw SimulationError(
          fmt::format("shear test: the shear at {:g} kPa: {}", sp.sigma_target / 1e3, e.what()));
    }
    sp.sigma = pick.point.sigma, sp.tau = pick.point.tau;
    sp.strain_at_peak = strains[pick.row];
    if (sp.strain_at_peak > 0.95 * spec.failure_strain)
      r.warnings.push_back(
          fmt::format("shear at {:g} kPa: {} (strain {:g}); its largest {} is used",
                      sp.sigma_target / 1e3, kNoPeakWarning, spec.failure_strain,
                      spec.failure == FailureCriterion::PeakTau ? "shear stress" : "tau / sigma"));
    failure.push_back(pick.point);
  }
  try {
    r.locus = fit_yield_locus(failure, r.preshear);
  } catch (const std::invalid_argument& e) {
    throw SimulationError(std::string("shear test: ") + e.what());
  }
}

}  // namespace silodem
