// sphtroch/exact/tolerance_output.hpp — `sphtroch tolerance`: will a train made within tolerances
// draw the census of its drawing? The report (the nominal census, the box's topology, the certified
// margin, each node's enclosure and sensitivities, and optionally a Monte Carlo run beside the
// proof) computed with classify's census; its struct, JSON and text are tolerance/tolerance_report.hpp's.
// One home for the CLI and Python.
//
//   sphtroch::ToleranceReport r = sphtroch::tolerance_report(train, {1e-3, 1e-3, 0.0});
//   r.topology.verdict;  r.margin.lower;  r.nodes[0].max_displacement;
//   sphtroch::run_monte_carlo(r, 20, 7);                // r.monte_carlo: the spread seen by sampling
//   const sphtroch::TrainText typed{"pi/3", "pi/2", "5/2"};
//   std::cout << sphtroch::tolerance_json(typed, r).dump(2) << sphtroch::tolerance_text(typed, r);
//
// Certified: the census (classify's certificate), the topology (holds / changes), the margin's
// bracket, each max_displacement. The sensitivities are first-order values at the nominal train;
// the Monte Carlo figures are what sampling saw, not bounds. The train analysed is classify's
// (within 1e-10 of a boundary it is snapped onto it, docs/cli.md: classify).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/tolerance_output.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/parallel_for.hpp"  // ParallelProgress
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/exact/classification.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/tolerance/tolerance_report.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace sphtroch {

/// The report for the train and box (runs classify, the margin, the box topology, each node;
/// defined in tolerance_analysis.hpp). A function template (Box = ToleranceBox), like classify(),
/// so that files built with and without SPHTROCH_SEPARATE_EXACT share one program.
template <typename Box = ToleranceBox>
ToleranceReport tolerance_report(const GearTrain& train, const Box& box);

/// Classifies `samples` trains drawn uniformly from the box (std::mt19937_64 seeded with `seed`)
/// and sets r.monte_carlo; `progress` (when set) is called with (k, samples) after the k-th train,
/// on the calling thread, and may throw to stop the run. Throws InvalidInput("samples") as
/// check_monte_carlo_cost.
inline void run_monte_carlo(ToleranceReport& r, std::size_t samples, std::uint64_t seed,
                            const ParallelProgress& progress = {});

/// Throws InvalidInput("samples") unless 1 <= samples <= kMaxToleranceSamples and
/// samples x (|p| + q)^3 (x kNearConeSampleFactor when the box's a3 range, widened by 2 da2 for the
/// cone's move with a2, comes within kNearConeSampleReach of a pitch cone) <= kMaxToleranceSampleWork
/// (core/cost_bounds.hpp): refused up front.
inline void check_monte_carlo_cost(const GearTrain& train, const ToleranceBox& box, std::size_t samples);

// ------------------------------------------------------------------------------------------------

inline void check_monte_carlo_cost(const GearTrain& train, const ToleranceBox& box, std::size_t samples) {
  if (!(samples >= 1 && samples <= kMaxToleranceSamples))
    throw InvalidInput("samples", std::to_string(samples), "outside the valid range",
                       "integer 1 .. " + std::to_string(kMaxToleranceSamples));
  const Ratio& n = train.ratio();
  const ConeMargins cone = cone_margins(train);
  const bool near_cone = std::min(std::abs(cone.pitch), std::abs(cone.mirror)) <= box.da3 + 2 * box.da2 + kNearConeSampleReach;
  const double size = static_cast<double>(n.abs_p() + n.q());
  const double work = static_cast<double>(samples) * size * size * size * (near_cone ? kNearConeSampleFactor : 1.0);
  if (work > kMaxToleranceSampleWork)
    throw InvalidInput("samples", std::to_string(samples),
                       "estimated work " + number_text(work) + " for n = " + n.str() + (near_cone ? " next to a pitch cone" : "") + " over the bound",
                       "samples x (|p| + q)^3 (x 25 within 1e-3 rad of a pitch cone) <= 1e7 (about a minute)");
}

inline void run_monte_carlo(ToleranceReport& r, std::size_t samples, std::uint64_t seed,
                            const ParallelProgress& progress) {
  check_monte_carlo_cost(r.train, r.box, samples);
  MonteCarloSpread m;
  m.samples = samples;
  m.seed = seed;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const GearTrain& t = r.train;
  for (std::size_t k = 0; k < samples; ++k) {
    const double a2 = t.a2() + r.box.da2 * unit(rng), a3 = t.a3() + r.box.da3 * unit(rng);
    const double phase = t.phase() + r.box.dphase * unit(rng);
    const Classification c = classify(GearTrain(a2, a3, t.ratio(), phase), ClassifySettings{});
    if (c.nodes.size() == r.node_count && c.cusps.size() == r.cusp_count) ++m.same_census;
    for (const NodeTolerance& n : r.nodes) {
      double nearest = Constants<double>::pi();
      for (const Node& s : c.nodes) nearest = std::min(nearest, std::acos(std::clamp(n.position.dot(s.position), -1.0, 1.0)));
      if (!c.nodes.empty()) m.max_node_shift = std::max(m.max_node_shift, nearest);
    }
    if (progress) progress(k + 1, samples);
  }
  r.monte_carlo = m;
}

}  // namespace sphtroch
