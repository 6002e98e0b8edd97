// sphtroch/sampling.hpp — a trajectory as parameters t_i and unit vectors P(t_i).
//
//   sphtroch::TracerCurve<double> curve(train);
//   auto closed = sphtroch::sample_period(curve, 720);      // t_i = 2*pi*q * i / N, i < N
//   auto open   = sphtroch::sample_turns(curve, 2.5, 1801); // t_i = 2*pi*K * i / (N - 1), i <= N-1
//
// A closed trajectory lists each point once (the edge from the last sample back to the first
// closes it). Consecutive samples of a closed trajectory are joined by great-circle arcs; with
// N >= min_samples_for_short_arcs(train) every arc is shorter than pi.
#pragma once

#include "sphtroch/curve.hpp"
#include "sphtroch/errors.hpp"
#include "sphtroch/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Bounds on sample counts accepted from users.
constexpr std::size_t kMinSamples = 3;
constexpr std::size_t kMaxSamples = 10000000;
/// Bounds on the number of carrier turns of an open trajectory.
constexpr double kMaxTurns = 1000000.0;

template <typename Scalar>
struct Trajectory {
  std::vector<Scalar> t;                // theta2 of each sample, radians
  std::vector<Vector3<Scalar>> points;  // P(t_i), unit vectors
  std::vector<Vector3<Scalar>> velocities;  // dP/dtheta2 at t_i; empty unless requested
  bool closed = true;                   // true: an edge joins the last point to the first
  std::size_t size() const noexcept { return t.size(); }
};

/// The smallest closed-curve sample count whose arcs are all shorter than pi: the speed
/// |omega x P| <= |omega| <= 1 + |n|, so N > 2*(q + |p|) bounds each step below pi.
inline std::size_t min_samples_for_short_arcs(const GearTrain& train) {
  const auto& r = train.ratio();
  return static_cast<std::size_t>(2 * (r.q() + r.abs_p()) + 1);
}

inline void check_sample_count(std::size_t n, const char* field = "samples") {
  if (n < kMinSamples || n > kMaxSamples)
    throw InvalidInput(field, std::to_string(n), "outside the valid range",
                       "integer " + std::to_string(kMinSamples) + " .. " + std::to_string(kMaxSamples));
}

/// Default sample count of a trajectory (`sphtroch trace`, the analysis object): 360 per unit
/// of (q + |p|) for a closed curve (about 0.5 degree of planet or carrier motion per step),
/// 360*(1 + |n|)*K + 1 for an open one over K carrier turns; clamped to [kMinSamples, 1e6].
inline std::size_t trace_sample_count(const GearTrain& train, std::optional<double> turns = std::nullopt) {
  const auto& r = train.ratio();
  const double n = turns ? 360.0 * (1.0 + std::abs(r.value())) * *turns + 1.0
                         : 360.0 * static_cast<double>(r.q() + r.abs_p());
  return static_cast<std::size_t>(std::clamp(std::ceil(n), static_cast<double>(kMinSamples), 1.0e6));
}

namespace detail {
/// t_i = span * i / divisor, the one formula of every uniform sampling (so that a stage that needs
/// the parameters only, e.g. the screw axis, gets bit-identical t_i without evaluating points).
template <typename Scalar>
Scalar uniform_parameter(const Scalar& span, std::size_t i, std::size_t divisor) {
  return span * Scalar(static_cast<double>(i)) / Scalar(static_cast<double>(divisor));
}

template <typename Scalar>
Trajectory<Scalar> sample_uniform(const TracerCurve<Scalar>& curve, const Scalar& span, std::size_t n,
                                  std::size_t divisor, bool closed, bool with_velocity) {
  Trajectory<Scalar> tr;
  tr.closed = closed;
  tr.t.reserve(n);
  tr.points.reserve(n);
  if (with_velocity) tr.velocities.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Scalar t = uniform_parameter(span, i, divisor);
    tr.t.push_back(t);
    tr.points.push_back(curve.point(t));
    if (with_velocity) tr.velocities.push_back(curve.velocity(t));
  }
  return tr;
}
}  // namespace detail

/// N uniform samples over one closing period [0, 2*pi*q). REQUIRES kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
Trajectory<Scalar> sample_period(const TracerCurve<Scalar>& curve, std::size_t n, bool with_velocity = false) {
  check_sample_count(n);
  return detail::sample_uniform(curve, curve.period(), n, n, true, with_velocity);
}

/// N uniform samples over K carrier turns [0, 2*pi*K], both ends included (open curve).
/// REQUIRES 0 < turns <= kMaxTurns and kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
Trajectory<Scalar> sample_turns(const TracerCurve<Scalar>& curve, double turns, std::size_t n,
                                bool with_velocity = false) {
  if (!(turns > 0.0 && turns <= kMaxTurns))
    throw InvalidInput("turns", detail::to_text(turns), "outside the valid range", "(0, 1e6] carrier turns");
  check_sample_count(n);
  return detail::sample_uniform(curve, Constants<Scalar>::two_pi() * Scalar(turns), n, n - 1, false, with_velocity);
}

}  // namespace sphtroch
