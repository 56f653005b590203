// SPDX-License-Identifier: MIT
#include "scenario/layered_filling.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "scenario/size_distribution.hpp"

namespace silodem {
namespace {

double top_of_bed(const ParticleStore& p, double floor) {
  double top = floor;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.x[i].z + p.radius[i]);
  return top;
}

// Inserts particles of one coal on a jittered square lattice, layer by layer from z_start, until
// their mass reaches `mass`. Returns the number inserted.
long insert_lattice(Simulation& sim, const SiloGeometry& g, const CoalProperties& coal,
                    const SizeSampler& sizes, int coal_index, double z_start, double mass,
                    double gap, Random& rng) {
  const double d = sizes.max_diameter();
  const double s = d * (1.0 + gap);
  const double jitter = 0.45 * (s - d);  // keeps every pair at least d apart
  auto& p = sim.particles();
  double placed = 0.0;
  long n = 0;
  std::vector<Vec3> sites;
  for (int layer = 0; placed < mass; ++layer) {
    // The first layer sits a jitter above the bed (or the valve plate), so that no jittered
    // sphere starts inside either.
    const double z = z_start + 0.5 * d + jitter + layer * s;
    if (z + 0.5 * d + jitter > g.total_height())
      throw SimulationError(fmt::format(
          "the silo is too small for the fill: {:.3g} kg of {} still to place above the top",
          mass - placed, coal.name));
    // Lowest point of the sphere sets the allowed radius (the cone widens upwards).
    const double r_allowed = g.radius_at(z - 0.5 * d - jitter) - 0.5 * d - jitter - 0.02 * d;
    const int m = int(std::floor(r_allowed / s));
    sites.clear();
    for (int iy = -m; iy <= m; ++iy)
      for (int ix = -m; ix <= m; ++ix)
        if (std::hypot(ix * s, iy * s) <= r_allowed) sites.push_back({ix * s, iy * s, z});
    // Random order (Fisher-Yates, seeded), so that a partly filled last layer is not lopsided.
    for (std::size_t k = sites.size(); k > 1; --k)
      std::swap(sites[k - 1], sites[std::size_t(rng.next_u64() % k)]);
    for (const Vec3& site : sites) {
      if (placed >= mass) break;
      const Vec3 x = site + Vec3{rng.uniform(-jitter, jitter), rng.uniform(-jitter, jitter),
                                 rng.uniform(-jitter, jitter)};
      const double di = sizes.sample(rng);
      const double mi = sphere_mass(di, coal.true_density);
      p.add(x, {}, {}, 0.5 * di, mi, coal_index);
      placed += mi;
      ++n;
    }
  }
  sim.request_rebuild();
  return n;
}

// Runs until the kinetic energy per particle is below the threshold at three checks in a row, and
// at least for `min_time` (inserted particles start at rest: the energy is low before they fall);
// returns the simulated time. The loop's state lives in `st` (settle_t0, below, min_time), set by
// the caller, so that a fill checkpointed between two checks continues the same loop; the
// checkpoint hook sees it after every check that does not end the settling.
double settle(Simulation& sim, double ke_threshold, double max_time, bool& settled,
              const Progress& progress, const std::string& what, FillProgress& st, Random& rng,
              const FillCheckpoint& checkpoint) {
  const double t0 = st.settle_t0;
  const long check = std::max(1L, long(2e-3 / sim.dt()));  // every 2 ms of simulated time
  settled = false;
  while (sim.time() - t0 < max_time) {
    sim.run_steps(check);
    const double ke = kinetic_energy_per_particle(sim);
    if (progress)
      progress(fmt::format("{}: settling t = {:.3f} s, KE/particle {:.2e} J (target {:.0e})", what,
                           sim.time() - t0, ke, ke_threshold));
    st.below = ke < ke_threshold ? st.below + 1 : 0;
    if (st.below >= 3 && sim.time() - t0 >= st.min_time) {
      settled = true;
      break;
    }
    if (checkpoint) {
      st.rng = rng.state();
      checkpoint(st);
    }
  }
  return sim.time() - t0;
}

// Free-fall time from the top of the bed to its base, plus 50 ms: no segment counts as settled
// before its highest particles could have landed.
double fall_time(const ParticleStore& p, double floor) {
  return std::sqrt(2.0 * std::max(0.0, top_of_bed(p, floor) - floor) / 9.81) + 0.05;
}

// Height that best separates particles with ids in [a0, a1) (below) from [b0, b1) (above): the cut
// with as many of the lower ones above it as of the upper ones below it.
double balanced_cut(const ParticleStore& p, std::uint64_t a0, std::uint64_t a1, std::uint64_t b0,
                    std::uint64_t b1) {
  std::vector<double> lo, hi;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.id[i] >= a0 && p.id[i] < a1) lo.push_back(p.x[i].z);
    if (p.id[i] >= b0 && p.id[i] < b1) hi.push_back(p.x[i].z);
  }
  if (lo.empty() || hi.empty()) return 0.0;
  std::sort(lo.begin(), lo.end());
  std::sort(hi.begin(), hi.end());
  // For a cut z: lower-above(z) decreases, upper-below(z) increases; find the crossing.
  double zl = std::min(lo.front(), hi.front()), zh = std::max(lo.back(), hi.back());
  for (int it = 0; it < 60; ++it) {
    const double z = 0.5 * (zl + zh);
    const long above = long(lo.end() - std::upper_bound(lo.begin(), lo.end(), z));
    const long below = long(std::lower_bound(hi.begin(), hi.end(), z) - hi.begin());
    (above > below ? zl : zh) = z;
  }
  return 0.5 * (zl + zh);
}

// Top of the bed: where the solid fraction in horizontal slices of one diameter drops below half
// of the bed's median solid fraction.
double surface_height(const ParticleStore& p, const SiloGeometry& g, double d) {
  const double top = top_of_bed(p, 0.0);
  const int n = std::max(1, int(top / d) + 1);
  std::vector<double> vol(static_cast<std::size_t>(n), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int k = std::clamp(int(p.x[i].z / d), 0, n - 1);
    vol[std::size_t(k)] += kPi / 6.0 * 8.0 * p.radius[i] * p.radius[i] * p.radius[i];
  }
  std::vector<double> phi(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    phi[std::size_t(k)] = vol[std::size_t(k)] / g.volume(k * d, (k + 1) * d);
  std::vector<double> sorted(phi.begin(), phi.begin() + std::max(1, int(0.8 * n)));
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const double half = 0.5 * sorted[sorted.size() / 2];
  for (int k = n - 1; k >= 0; --k)
    if (phi[std::size_t(k)] >= half) {
      // Interpolate within the slice above the last full one.
      const double next = k + 1 < n ? phi[std::size_t(k + 1)] : 0.0;
      return (k + 1) * d + d * next / std::max(phi[std::size_t(k)], 1e-12);
    }
  return 0.0;
}

}  // namespace

double kinetic_energy_per_particle(const Simulation& sim) {
  const auto& p = sim.particles();
  if (p.size() == 0) return 0.0;
  double ke = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    ke += 0.5 * p.mass[i] * norm2(p.v[i]) + 0.5 / p.inv_inertia[i] * norm2(p.omega[i]);
  return ke / double(p.size());
}

void FillReport::save(ByteWriter& w) const {
  w.put(segments), w.put(particles), w.put(mass), w.put(settle_time);
  w.put(max_boundary_offset), w.put(std::uint64_t(warnings.size()));
  for (const auto& m : warnings) w.put(m);
}

void FillReport::load(ByteReader& r) {
  r.get(segments), r.get(particles), r.get(mass), r.get(settle_time);
  r.get(max_boundary_offset);
  warnings.resize(r.get_count(sizeof(std::uint64_t)));  // each string: its length, then its bytes
  for (auto& m : warnings) r.get(m);
}

void FillProgress::save(ByteWriter& w) const {
  w.tag("FPRG");
  w.put(std::uint64_t(segment)), w.put(std::int32_t(phase)), w.put(seg), w.put(start);
  w.put(settle_t0), w.put(min_time), w.put(std::int32_t(below));
  report.save(w);
  w.put(first_id), w.put(rng);
}

void FillProgress::load(ByteReader& r) {
  r.tag("FPRG");
  segment = std::size_t(r.get<std::uint64_t>());
  phase = r.get<std::int32_t>();
  r.get(seg), r.get(start), r.get(settle_t0), r.get(min_time);
  below = r.get<std::int32_t>();
  report.load(r);
  r.get(first_id), r.get(rng);
}

FillReport fill_silo(Simulation& sim, const ScenarioCase& c, const std::vector<int>& segment_coal,
                     Random& rng, const Progress& progress, const FillCheckpoint& checkpoint,
                     const FillProgress* from) {
  const SiloGeometry& g = c.silo.geometry;
  const double fill_height = c.fill.fill_height > 0 ? c.fill.fill_height : g.cone_height;
  const double h = fill_height / c.fill.segments;
  FillProgress st;
  if (from) {
    st = *from;
    rng.set_state(st.rng);
  }
  FillReport& r = st.report;
  std::vector<std::uint64_t>& first_id = st.first_id;
  std::vector<SizeSampler> samplers;
  for (const auto& coal : c.coals) samplers.emplace_back(coal, c.cg);
  // Each segment in phases (FillProgress): insert, settle; by volume also cut and settle again.
  for (; st.segment < segment_coal.size(); ++st.segment, st.phase = 0) {
    const std::size_t s = st.segment;
    const int ci = segment_coal[s];
    const CoalProperties& coal = c.coals[std::size_t(ci)];
    SegmentReport& seg = st.seg;
    const std::string what = fmt::format("H{} ({})", int(s) + 1, coal.name);
    if (st.phase == 0) {
      seg = SegmentReport{};
      seg.index = int(s) + 1;
      seg.coal = ci;
      seg.z_low = double(s) * h;
      seg.z_high = double(s + 1) * h;
      seg.bulk_density_measured = coal.bulk_density;
      first_id.push_back(sim.particles().next_id());
      st.start = top_of_bed(sim.particles(), -g.valve_gap);
      // E13, by mass: the segment holds the measured bulk density times its volume. By volume:
      // over-fill (at most random close packing), settle, cut at the segment top, settle again.
      const double mass =
          c.fill.mode == FillMode::Mass
              ? coal.bulk_density * g.volume(seg.z_low, seg.z_high)
              : 0.64 * coal.true_density * g.volume(std::max(st.start, 0.0), seg.z_high);
      if (c.fill.mode == FillMode::Mass) seg.target_mass = mass;
      insert_lattice(sim, g, coal, samplers[std::size_t(ci)], ci, st.start, mass,
                     c.fill.lattice_gap, rng);
      st.phase = 1, st.settle_t0 = sim.time(), st.below = 0;
      st.min_time = fall_time(sim.particles(), st.start);
    }
    if (st.phase == 1) {
      seg.settle_time = settle(sim, c.fill.settle_ke, c.fill.settle_max_time, seg.settled, progress,
                               what, st, rng, checkpoint);
      if (c.fill.mode == FillMode::Volume) {
        std::vector<std::size_t> above;
        const auto& p = sim.particles();
        for (std::size_t i = 0; i < p.size(); ++i)
          if (p.id[i] >= first_id.back() && p.x[i].z > seg.z_high) above.push_back(i);
        if (top_of_bed(p, 0.0) < seg.z_high)
          r.warnings.push_back(
              fmt::format("{}: the settled bed did not reach the segment top", what));
        sim.remove_particles(above);
        st.phase = 2, st.settle_t0 = sim.time(), st.below = 0, st.min_time = 0.05;
      }
    }
    if (st.phase == 2) {
      bool again = false;
      seg.settle_time += settle(sim, c.fill.settle_ke, c.fill.settle_max_time, again, progress,
                                what, st, rng, checkpoint);
      seg.settled = seg.settled && again;
      seg.target_mass = 0.0;
    }
    if (!seg.settled)
      r.warnings.push_back(
          fmt::format("{}: not settled after {:g} s (kinetic energy per particle "
                      "still above {:g} J)",
                      what, c.fill.settle_max_time, c.fill.settle_ke));
    r.settle_time += seg.settle_time;
    r.segments.push_back(seg);
  }
  first_id.push_back(sim.particles().next_id());

  // Per segment: count, mass, where it settled, the bulk density it reached.
  const auto& p = sim.particles();
  double d_max = 0.0;
  for (const auto& smp : samplers) d_max = std::max(d_max, smp.max_diameter());
  for (std::size_t s = 0; s < r.segments.size(); ++s) {
    auto& seg = r.segments[s];
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] >= first_id[s] && p.id[i] < first_id[s + 1])
        ++seg.particles, seg.mass += p.mass[i];
    seg.z_low_settled = s == 0 ? 0.0 : r.segments[s - 1].z_high_settled;
    seg.z_high_settled = s + 1 < r.segments.size() ? balanced_cut(p, first_id[s], first_id[s + 1],
                                                                  first_id[s + 1], first_id[s + 2])
                                                   : surface_height(p, g, d_max);
    const double v = g.volume(seg.z_low_settled, seg.z_high_settled);
    seg.bulk_density = v > 0 ? seg.mass / v : 0.0;
    seg.solid_fraction = seg.bulk_density / c.coals[std::size_t(seg.coal)].true_density;
    if (s + 1 < r.segments.size())
      r.max_boundary_offset =
          std::max(r.max_boundary_offset, std::fabs(seg.z_high_settled - seg.z_high));
    r.particles += seg.particles;
    r.mass += seg.mass;
  }
  if (r.max_boundary_offset > d_max)
    r.warnings.push_back(fmt::format(
        "a settled coal boundary lies {:.1f} mm from its segment boundary, more than one CG "
        "diameter ({:.1f} mm): the fill by mass packs at a bulk density other than the measured "
        "one (see fill.csv; mode = \"volume\" fills each segment to its top)",
        r.max_boundary_offset * 1e3, d_max * 1e3));
  return r;  // a copy: st (and its report) ends here
}

}  // namespace silodem
