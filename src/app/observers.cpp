// SPDX-License-Identifier: MIT
#include "app/observers.hpp"

#include <fmt/format.h>

namespace fs = std::filesystem;

namespace silodem::app {

Observers::Observers(const Case& c, const fs::path& out, double t0) : c_(c), out_(out), t0_(t0) {
  for (auto& p : make_probes(c.probes, c.probe_site())) {
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

Observers::Observers(const Case& c, const fs::path& out, double t0, ByteReader& r)
    : c_(c), out_(out), t0_(t0) {
  r.tag("OBSV");
  auto made = make_probes(c.probes, c.probe_site());
  if (r.get<std::uint64_t>() != made.size())
    throw std::runtime_error("checkpoint: the case has a different set of probes");
  for (auto& p : made) {
    p->load(r);
    const auto bytes = r.get<std::uint64_t>();
    files_.push_back(std::make_unique<CsvWriter>(
        (out / fmt::format("probe_{}.csv", p->name())).string(), p->columns().size(), bytes));
    probes_.push_back(std::move(p));
  }
  const bool vtk = r.get<std::uint8_t>() != 0;
  if (vtk != (c.output.vtk_interval > 0))
    throw std::runtime_error("checkpoint: output.vtk_interval was switched on or off");
  if (vtk) {
    pvd_ = std::make_unique<PvdCollection>((out / "particles.pvd").string());
    std::vector<double> times;
    r.get(times);
    for (double t : times)
      pvd_->restore(t, fmt::format("vtk/particles_{:06d}.vtp", pvd_->frames()));
    r.get(next_frame_);
  }
}

void Observers::attach(Simulation& sim) {
  if (!probes_.empty())
    sim.add_hook({"probes", Phase::StepEnd, c_.probes.every, [this](Simulation& s) { sample(s); }});
  if (pvd_)
    sim.add_hook({"vtk", Phase::StepEnd, 1, [this](Simulation& s) {
                    if (s.time() - t0_ >= next_frame_ - 0.5 * s.dt()) frame(s);
                  }});
}

void Observers::sample(const Simulation& sim) {
  ProbeView view(sim, sim.time() - t0_);
  std::vector<ProbeRow> rows;
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    rows.clear();
    probes_[k]->sample(view, rows);
    for (const auto& r : rows) files_[k]->row(r);
  }
}

void Observers::frame(const Simulation& sim) {
  const std::string name = fmt::format("vtk/particles_{:06d}.vtp", pvd_->frames());
  write_particles_vtp((out_ / name).string(), sim, sim.contact_tally());
  pvd_->add(sim.time() - t0_, name);
  next_frame_ += c_.output.vtk_interval;
}

void Observers::finish() {
  std::vector<ProbeRow> rows;
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    rows.clear();
    probes_[k]->finish(rows);
    for (const auto& r : rows) files_[k]->row(r);
    files_[k]->finish();
  }
}

void Observers::save(ByteWriter& w) {
  w.tag("OBSV");
  w.put(std::uint64_t(probes_.size()));
  for (std::size_t k = 0; k < probes_.size(); ++k) {
    probes_[k]->save(w);
    w.put(files_[k]->flush());
  }
  w.put(std::uint8_t(pvd_ != nullptr));
  if (pvd_) {
    w.put(pvd_->times());
    w.put(next_frame_);
  }
}

toml::array Observers::files() const {
  toml::array a;
  for (const auto& p : probes_) a.push_back(fmt::format("probe_{}.csv", p->name()));
  return a;
}

}  // namespace silodem::app
