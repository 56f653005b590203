// SPDX-License-Identifier: MIT
// A virtual shear cell: the FT-4 shear test (ASTM D7891) applied to one coal of a case, with the
// case's contact model, coarse graining and laws unchanged, so that its yield locus is a property
// of the DEM material.
//
// The cell is periodic in x and y, at least `width` mean CG diameters across, between a floor and
// a lid (planes). The coal is put in loose on a lattice and pressed by the lid to the pre-shear
// stress (servo, plate.hpp). Then the particles whose centres lie within one mean diameter of the
// floor or of the lid are glued to them: rough plates of the coal itself. The lid shears the
// sample along x at a constant speed (set by an inertial number, GDR MiDi 2004: quasi-static
// below about 1e-3) while the servo holds the normal stress. The procedure is the standard one:
// pre-shear to steady state at the pre-shear stress; then for each lower normal stress, pre-shear
// again, stop, lower the normal stress, and shear to failure; the failure point is where the
// mobilised friction tau / sigma peaks (or, as before 2026-12-05, the shear stress:
// yield_locus.hpp's FailureCriterion says why).
// Gravity is off in the cell: the plates set the stress (at 3 kPa the weight of an 11-diameter
// k = 3 sample would add about 1.4 kPa from top to bottom).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/bytes.hpp"
#include "scenario/setup.hpp"
#include "scenario/yield_locus.hpp"

namespace silodem {

inline constexpr double kDefaultCellWidth = 14.0;   // mean CG diameters
inline constexpr double kDefaultCellHeight = 11.0;  // mean CG diameters

struct ShearTestSpec {
  double preshear = 9e3;                                 // Pa
  std::vector<double> normals{7e3, 6e3, 5e3, 4e3, 3e3};  // Pa, each below the pre-shear
  // Cell side and sheared height (between the glued layers), mean CG diameters. 14 x 11: the
  // smallest of the sizes tried whose friction angle does not change with size
  // (docs/validation/shear-cell.md 5.1; 10 x 8 was the default before 2026-12-06).
  double width = kDefaultCellWidth;
  double height = kDefaultCellHeight;
  double inertial_number = 2e-3;  // of the shear at the lowest normal stress
  // The first pre-shear runs at least preshear_strain (shear displacement / sheared height),
  // then on in steps of steady_step until it is steady (shear_is_steady over windows of
  // steady_window) or reaches preshear_max_strain (== preshear_strain: a fixed strain, the
  // procedure before 2026-12-07, which gives the same series and points; only the steady flags
  // follow shear_is_steady).
  double preshear_strain = 0.5;
  double preshear_max_strain = 2.0;
  double steady_step = 0.1;
  double steady_window = 0.2;
  double steady_height_change = 0.005;  // relative, between two windows
  double steady_ratio_change = 0.10;    // relative, of tau / sigma between two windows
  double represhear_strain = 0.2;       // each later pre-shear
  double failure_strain = 0.25;         // each shear to failure
  double sample_strain = 0.005;         // strain per row of the series
  FailureCriterion failure = FailureCriterion::PeakRatio;
  std::uint64_t seed = 1;
  int threads = 0;
};

struct ShearSample {
  std::string phase;                // compress, consolidate, preshear, relax, shear
  int point = 0;                    // 0: the first pre-shear; i: the i-th normal stress
  double time = 0.0, strain = 0.0;  // s; shear strain of this phase
  double sigma = 0.0, tau = 0.0;    // Pa, means over the row
  double height = 0.0;              // m, floor to lid
};

struct ShearPoint {
  double sigma_target = 0.0;      // Pa
  double sigma = 0.0, tau = 0.0;  // Pa, at the peak of the shear to failure
  double strain_at_peak = 0.0;
  StressPoint preshear;  // the pre-shear just before
  bool preshear_steady = false;
};

struct ShearTestResult {
  std::string coal;
  int particles = 0, glued = 0;
  double width = 0.0, sheared_height = 0.0;         // m
  double mean_diameter = 0.0;                       // m, CG, by number
  double shear_velocity = 0.0, dt = 0.0;            // m/s, s
  double bulk_density = 0.0, solid_fraction = 0.0;  // between the glued layers, after pre-shear
  StressPoint preshear;                             // mean over all pre-shears (the end of each)
  bool preshear_steady = false;  // the first pre-shear ended steady (shear_is_steady)
  double preshear_strain = 0.0;  // the strain the first pre-shear ran
  std::vector<ShearPoint> points;
  YieldLocus locus;
  std::vector<ShearSample> series;
  long steps = 0;
  std::vector<std::string> warnings;
};

using ShearProgress = std::function<void(const std::string&)>;

// Throws InputError for a spec the test cannot run: fewer than two normal stresses, or one not
// in (0, pre-shear); a first pre-shear's largest strain below its least; a steady-shear step,
// window or row of strain that is not positive.
void check_shear_spec(const ShearTestSpec& spec);

// Steady shear (ASTM D7891; Schulze, Powders and Bulk Solids, ch. 3: the pre-shear goes on until
// the shear stress is constant, which is steady-state flow at a constant bulk density): the last
// `per_window` rows of a shear and the `per_window` rows before them have mean sample heights
// within spec.steady_height_change of each other and mobilised friction (mean tau over mean
// sigma) within spec.steady_ratio_change, both relative to the last window's. The height is the
// quieter sign in a small cell, whose stresses swing as force chains form and buckle; a sample
// that still compacts or dilates is not steady whatever its stresses. False with fewer than
// 2 per_window rows, or per_window 0.
bool shear_is_steady(const std::vector<ShearSample>& rows, std::size_t per_window,
                     const ShearTestSpec& spec);

// The failure points and the yield locus from the series: each point's shear rows (phase
// "shear") give its failure point by spec.failure, and the locus is fitted through them with
// r.preshear. Adds a warning (containing kNoPeakWarning) for each shear without a peak before
// 95% of spec.failure_strain. r.points must hold one point (sigma_target, preshear) per shear in
// the series; throws SimulationError if a point has no rows or no row with sigma > 0.
// run_shear_test ends with it; `shear-test --refit` applies it to a recorded series.
void evaluate_failure(ShearTestResult& r, const ShearTestSpec& spec);
inline constexpr const char* kNoPeakWarning = "no peak before the end of the shear";

// Checkpoints of a test under way. After each row or chunk of steps (and between stages) the
// test asks `stop`, then `due`; if either says so it hands `write` a function that puts the
// test's whole state into a writer (the caller adds its own head and writes the file), and after
// a stop it throws ShearInterrupted. With `resume` (a reader positioned where such a function
// began writing) the test continues from that state: the same case, spec and coal give the
// same series, points and locus as a test never interrupted (with the same threads; with
// others, a warning in the result says so). A state that cannot be continued throws
// ShearResumeError.
struct ShearCheckpointing {
  std::function<bool()> stop;  // e.g. a signal
  std::function<bool()> due;   // e.g. the wall time since the last checkpoint
  std::function<void(const std::function<void(ByteWriter&)>& state)> write;
  ByteReader* resume = nullptr;
};
struct ShearInterrupted {};
// A `resume` state that cannot be read (damaged, of another layout) or that is not this test's.
struct ShearResumeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A result, finished or not, in a checkpoint (a test of several coals keeps its finished ones).
void save_shear_result(ByteWriter& w, const ShearTestResult& r);
ShearTestResult load_shear_result(ByteReader& r);

// Runs the test on coal `coal` of the case (report and model from derive_case); checks the spec
// first. `checkpointing` may be null (no checkpoints).
ShearTestResult run_shear_test(const ScenarioCase& c, const CaseReport& report,
                               const ContactModel& model, int coal, const ShearTestSpec& spec,
                               const ShearProgress& progress,
                               const ShearCheckpointing* checkpointing = nullptr);

}  // namespace silodem
