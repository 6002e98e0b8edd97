// sphtroch/machine/running_mean.hpp — the running mean of a clinostat's averaged gravity from a
// start time: the mean vector of g over [start, start + T] and its magnitude, for each T asked
// (the one number every clinostat simulator prints). Closed form: the gravity series' window mean
// (gravity_series.hpp, each harmonic integrated exactly), so the error is the rounding of the
// series' terms (about 1e-15 g0 at the speeds of a clinostat), not a quadrature's.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(1);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   const std::vector<sphtroch::RunningMean> m = sphtroch::running_means(g, 0.0, {60.0, 600.0});
//   m[1].magnitude;   // |mean of g over [0 s, 600 s]|, units of g0
//
// Throws InvalidInput("running-mean") for no time, more than kMaxRunningMeans times, or a time
// that is not in (0, 1e12] s, and InvalidInput("start") for a start beyond |t| <= 1e12 s or a
// start + T beyond it.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/gravity_series.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace sphtroch {

constexpr std::size_t kMaxRunningMeans = 10000;

/// The mean over [start_s, start_s + t_s] (units of g0) and its magnitude.
struct RunningMean {
  double t_s = 0;
  Vector3d mean = Vector3d::Zero();
  double magnitude = 0;
};

/// The running means of `series` from start_s at each of `times_s` (in the order given).
inline std::vector<RunningMean> running_means(const GravitySeries& series, double start_s, const std::vector<double>& times_s) {
  const std::string valid = "T1,T2,...: 1 to " + std::to_string(kMaxRunningMeans) + " durations in (0, 1e12] seconds";
  if (times_s.empty() || times_s.size() > kMaxRunningMeans)
    throw InvalidInput("running-mean", std::to_string(times_s.size()) + " times", "not 1 to " + std::to_string(kMaxRunningMeans) + " times", valid);
  if (!(std::fabs(start_s) <= Clinostat::kMaxTime)) throw InvalidInput("start", number_text(start_s), "not a finite time", "|t| <= 1e12 seconds");
  std::vector<RunningMean> out;
  out.reserve(times_s.size());
  for (const double t : times_s) {
    if (!(t > 0) || t > Clinostat::kMaxTime) throw InvalidInput("running-mean", number_text(t), "not a duration in (0, 1e12] s", valid);
    if (!(std::fabs(start_s + t) <= Clinostat::kMaxTime))
      throw InvalidInput("start", number_text(start_s), "start + " + number_text(t) + " s is beyond 1e12 s", "|start + T| <= 1e12 seconds");
    RunningMean m;
    m.t_s = t;
    m.mean = series.window_mean(start_s, t);
    m.magnitude = m.mean.norm();
    out.push_back(m);
  }
  return out;
}

}  // namespace sphtroch
