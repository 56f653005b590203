// SPDX-License-Identifier: MIT
// Probes: observers of the time loop that turn the state into rows of numbers. A probe owns no
// file; the app writes each probe's rows to probe_<name>.csv as they come. Probes read the state
// through a ProbeView, which computes the per-particle contact tally once per sample, however many
// probes ask for it.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/bytes.hpp"
#include "engine/simulation.hpp"
#include "probes/probe_spec.hpp"

namespace silodem {

using ProbeRow = std::vector<double>;

class ProbeView {
 public:
  // t: the probes' clock (s since the valve opened in a silo run).
  ProbeView(const Simulation& sim, double t) : sim_(sim), t_(t) {}
  const Simulation& sim() const { return sim_; }
  const ParticleStore& particles() const { return sim_.particles(); }
  double t() const { return t_; }
  const ContactTally& tally() {
    if (!tally_) tally_ = sim_.contact_tally();
    return *tally_;
  }

 private:
  const Simulation& sim_;
  double t_;
  std::optional<ContactTally> tally_;
};

class Probe {
 public:
  virtual ~Probe() = default;
  virtual std::string name() const = 0;  // the file is probe_<name>.csv
  virtual std::vector<std::string> columns() const = 0;
  // One sample; appends zero or more rows.
  virtual void sample(ProbeView& view, std::vector<ProbeRow>& rows) = 0;
  // At the end of the run (time averages); appends zero or more rows.
  virtual void finish(std::vector<ProbeRow>& rows) { (void)rows; }
  // Checkpoint of the probe's accumulators (none by default).
  virtual void save(ByteWriter& w) const { (void)w; }
  virtual void load(ByteReader& r) { (void)r; }
};

// "In the hopper": above the outlet plane (z >= 0); what has passed the outlet is on its way out.
inline bool in_hopper(const ParticleStore& p, std::size_t i) {
  return p.x[i].z >= 0.0;
}

}  // namespace silodem
