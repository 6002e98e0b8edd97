// sphtroch/core/sampling.hpp — a trajectory as parameters t_i and unit vectors P(t_i).
//
//   sphtroch::TracerCurve<double> curve(train);
//   auto closed = sphtroch::sample_period(curve, 720);      // t_i = 2*pi*q * i / N, i < N
//   auto open   = sphtroch::sample_turns(curve, 2.5, 1801); // t_i = 2*pi*K * i / (N - 1), i <= N-1
//
// A closed trajectory lists each point once (the edge from the last sample back to the first
// closes it). Consecutive samples of a closed trajectory are joined by great-circle arcs; with
// N >= min_samples_for_short_arcs(train) every arc is shorter than pi.
#pragma once

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/types.hpp"

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
constexpr const char* kTurnsRange = "a number in (0, 1e6] carrier turns";

/// The one turns check of the library, the CLI, scenes and Python: throws
/// InvalidInput("turns", text, ...) unless 0 < turns <= kMaxTurns. `text` is the value as given.
inline bool turns_in_range(double turns) { return turns > 0.0 && turns <= kMaxTurns; }
inline void check_turns(double turns, const std::string& text) {
  if (!turns_in_range(turns)) throw InvalidInput("turns", text, "outside the valid range", kTurnsRange);
}

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

/// The largest default sample count; above it the caller must choose N (see trace_sample_count).
constexpr std::size_t kMaxDefaultSamples = 1000000;

/// The largest K whose default open-curve count 360 (1 + |n|) K + 1 stays within
/// kMaxDefaultSamples, as a double that reads back as itself (the bound printed is the bound used).
inline double max_default_turns(const GearTrain& train) {
  const double per_turn = 360.0 * (1.0 + std::abs(train.ratio().value()));
  double k = (static_cast<double>(kMaxDefaultSamples) - 1.0) / per_turn;
  while (k > 0.0 && per_turn * k + 1.0 > static_cast<double>(kMaxDefaultSamples)) k = std::nextafter(k, 0.0);
  return k;
}

/// Default sample count of a trajectory (`sphtroch trace`, the analysis object): 360 per unit
/// of (q + |p|) for a closed curve (about 0.5 degree of planet or carrier motion per step),
/// 360*(1 + |n|)*K + 1 for an open one over K carrier turns; at least kMinSamples. Throws
/// InvalidInput("samples", ...) when that exceeds kMaxDefaultSamples (e.g. n = 999999/1000000):
/// a default that silently undersamples or writes gigabytes is worse than asking for --samples.
inline std::size_t trace_sample_count(const GearTrain& train, std::optional<double> turns = std::nullopt) {
  const auto& r = train.ratio();
  const double n = turns ? 360.0 * (1.0 + std::abs(r.value())) * *turns + 1.0
                         : 360.0 * static_cast<double>(r.q() + r.abs_p());
  if (n > static_cast<double>(kMaxDefaultSamples)) {
    if (turns)
      throw InvalidInput("turns", report_number(*turns),
                         "needs 360 (1 + |n|) K + 1 = " + number_text(std::ceil(n)) + " samples, more than 1000000",
                         "K <= " + number_text(max_default_turns(train)) + " carrier turns for this n");
    throw InvalidInput("samples", "(default)",
                       "n = " + r.str() + " (as read: a decimal n is read exactly) needs 360 (q + |p|) = " +
                           number_text(std::ceil(n)) + " samples per period, more than 1000000",
                       "give the number of samples explicitly (3 .. 10000000), or a ratio with smaller terms");
  }
  return static_cast<std::size_t>(std::max(std::ceil(n), static_cast<double>(kMinSamples)));
}

/// Default sample count of a rotation chain's closed curve (`sphtroch chain trace`, Chain.trace):
/// 360 per unit of s times sum_i |N_i| over the period 2 pi L / g, i.e. 360 sum_i |p_i| (L / q_i) / g
/// (about 0.5 degree of every joint's motion per step; for k = 2 with rates 1, p/q trace's
/// 360 (q + |p|)), at least kMinSamples. Throws InvalidInput("samples", "(default)") above
/// kMaxDefaultSamples, as trace_sample_count.
inline std::size_t chain_trace_sample_count(const RotationChain& chain) {
  const double n = 360.0 * chain.total_turns();
  if (n > static_cast<double>(kMaxDefaultSamples))
    throw InvalidInput("samples", "(default)",
                       "rates " + chain.rates_text() + " need 360 sum |N_i| L / g = " + number_text(std::ceil(n)) +
                           " samples per period, more than 1000000",
                       "give the number of samples explicitly (3 .. 10000000), or rates with smaller terms");
  return static_cast<std::size_t>(std::max(std::ceil(n), static_cast<double>(kMinSamples)));
}

/// A uniform sampling: t_i = span * i / divisor for i < count (closed: divisor = count, the last
/// point joins the first; open: divisor = count - 1, both ends included). The one formula of
/// every uniform sampling, so that a stage that needs only the parameters (the screw axis, a
/// streamed trace) gets bit-identical t_i.
template <typename Scalar>
struct UniformSampling {
  Scalar span;
  std::size_t count = 0;
  std::size_t divisor = 1;
  bool closed = true;
  Scalar parameter(std::size_t i) const {
    return span * Scalar(static_cast<double>(i)) / Scalar(static_cast<double>(divisor));
  }
};

/// N samples over one closing period [0, 2*pi*q). Throws InvalidInput unless kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
UniformSampling<Scalar> period_sampling(const TracerCurve<Scalar>& curve, std::size_t n) {
  check_sample_count(n);
  return UniformSampling<Scalar>{curve.period(), n, n, true};
}

/// N samples over K carrier turns [0, 2*pi*K], both ends included (open curve). Throws
/// InvalidInput unless 0 < turns <= kMaxTurns and kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
UniformSampling<Scalar> turns_sampling(const TracerCurve<Scalar>& curve, double turns, std::size_t n) {
  (void)curve;
  check_turns(turns, number_text(turns));
  check_sample_count(n);
  return UniformSampling<Scalar>{Constants<Scalar>::two_pi() * Scalar(turns), n, n - 1, false};
}

/// The trajectory of a sampling (points, and velocities when asked) of a curve with point(t) and
/// velocity(t) in Scalar: TracerCurve<Scalar> or ChainCurve<Scalar> (core/rotation_chain.hpp).
template <typename Curve, typename Scalar>
Trajectory<Scalar> sample(const Curve& curve, const UniformSampling<Scalar>& s, bool with_velocity = false) {
  Trajectory<Scalar> tr;
  tr.closed = s.closed;
  tr.t.reserve(s.count);
  tr.points.reserve(s.count);
  if (with_velocity) tr.velocities.reserve(s.count);
  for (std::size_t i = 0; i < s.count; ++i) {
    const Scalar t = s.parameter(i);
    tr.t.push_back(t);
    tr.points.push_back(curve.point(t));
    if (with_velocity) tr.velocities.push_back(curve.velocity(t));
  }
  return tr;
}

/// t_i = span * i / divisor, rounded exactly as every sampler here computes it
/// (UniformSampling::parameter).
template <typename Scalar>
Scalar uniform_parameter(const Scalar& span, std::size_t i, std::size_t divisor) {
  return UniformSampling<Scalar>{span, 0, divisor, true}.parameter(i);
}

/// N uniform samples over one closing period [0, 2*pi*q). REQUIRES kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
Trajectory<Scalar> sample_period(const TracerCurve<Scalar>& curve, std::size_t n, bool with_velocity = false) {
  return sample(curve, period_sampling(curve, n), with_velocity);
}

/// N uniform samples over K carrier turns [0, 2*pi*K], both ends included (open curve).
/// REQUIRES 0 < turns <= kMaxTurns and kMinSamples <= n <= kMaxSamples.
template <typename Scalar>
Trajectory<Scalar> sample_turns(const TracerCurve<Scalar>& curve, double turns, std::size_t n,
                                bool with_velocity = false) {
  return sample(curve, turns_sampling(curve, turns, n), with_velocity);
}

// The census's sample counts (the polyline census, exact/polyline_census.hpp).

/// Fewest uniform samples a user may ask of the census (the CLI's --samples, a scene's census_samples).
constexpr std::size_t kMinCensusSamples = 1024;

/// Uniform samples at escalation level k: 4^k times `samples` (k <= 8).
inline std::size_t escalated_samples(std::size_t samples, unsigned escalation) {
  return samples << (2 * std::min(escalation, 8u));
}

/// Default uniform sample count: 256 per unit of (q + |p|), at least 1024.
inline std::size_t census_sample_count(const GearTrain& train) {
  const auto& r = train.ratio();
  return std::min<std::size_t>(kMaxSamples, std::max<std::size_t>(1024, 256 * static_cast<std::size_t>(r.q() + r.abs_p())));
}

}  // namespace sphtroch
