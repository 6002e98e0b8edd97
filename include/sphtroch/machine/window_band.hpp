// sphtroch/machine/window_band.hpp — the window band: the smallest and the largest |mean gravity|
// over a window of W seconds, whatever time the window starts, each certified as a bracket; and
// whether every window mean lies within a target G +- D.
//
//   sphtroch::ClinostatSettings s;
//   s.tilt_deg = 67.7901;
//   s.outer = sphtroch::Rpm(5);
//   s.inner = sphtroch::Rpm(5, 100);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   const sphtroch::WindowBand b = sphtroch::window_band(g, 600.0);
//   b.min.lower, b.min.upper;   // min over t0 of |mean over [t0, t0 + 600 s]| lies in here (g0)
//   b.max.lower, b.max.upper;   // the max: M(600 s) (worst_window_mean.hpp)
//   b.min.lower;                // 0.2347483080: every 10-minute mean is in about [0.235, 0.247] g0
//   sphtroch::window_target(g, b, 0.241, 0.007).inside;   // true: every window mean in [0.234, 0.248]
//   sphtroch::window_target(g, b, 0.241, 0.004).start_s;  // 510 s: its window's mean, 0.2465 g0, is above 0.245
//
// Method: both extremes by the one branch and bound of worst_window_mean.hpp over the window's
// centre in one period (window_mean_extreme), with its proven bounds: the max by the
// Taylor upper bound of a piece, the min by the lower bound |m(tc) + m'(tc) d| >= the distance
// from 0 to the segment {m(tc) + m'(tc) d : |d| <= h}, less L2 h^2 / 2 and rounding. |m| is not
// smooth where m = 0, but the bound is of the vector m (smooth), not of |m|: a window mean that
// passes through 0 gives pieces whose lower bound is 0 and evaluations that come within the
// width of 0, so a minimum of 0 is bracketed as [0, upper], upper <= the width (1e-9).
// Cost: two searches over one period, each bounded as M(W)'s (worst_window_mean_cost refuses a
// period too long up front, naming the pieces it would need); the min's search costs more than
// the max's where |m| is nearly flat over the period (tilted frames), since fewer pieces prune.
// No bound over the motor torus: its ends would not be certified to 1e-9 (docs/clinostat.md).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/machine/clinostat.hpp"  // Clinostat::kMaxTime
#include "sphtroch/machine/gravity_series.hpp"
#include "sphtroch/machine/worst_window_mean.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace sphtroch {

/// The band of |window mean| over every start time, units of g0.
struct WindowBand {
  double window_s = 0;
  WorstWindowMean min;     ///< min over t0 in [lower, upper]; start_s: a start whose |mean| <= upper
  WorstWindowMean max;     ///< max over t0 (M(W)) in [lower, upper]; start_s: a start whose |mean| >= lower
  bool certified = false;  ///< both brackets within the width asked
  const char* bound = "period";  ///< the search covers one period of the window's start
};

/// The band for window W: each bracket at most `width` wide when certified. Throws
/// InvalidInput("window") unless W > 0 and finite, InvalidInput("outer") when the period is too
/// long to search (worst_window_mean_cost).
inline WindowBand window_band(const GravitySeries& g, double window_s, double width = 1e-9) {
  const auto never = [](double, double) { return false; };
  WindowBand b;
  b.window_s = window_s;
  b.max = window_mean_extreme(g, window_s, WindowExtreme::largest, width, never);
  b.min = window_mean_extreme(g, window_s, WindowExtreme::smallest, width, never);
  b.certified = b.min.certified && b.max.certified;
  return b;
}

/// The band of a period too long to search (worst_window_mean_cost refuses it), bound "torus":
/// max.upper and min.lower bound the window means over every pair of frame angles (the torus,
/// torus_window_extreme), so over every start; max.lower and min.upper are the largest and the
/// smallest |window mean| of kTorusBandStarts starts spread over one period (the path's own
/// values, rounding allowed for), each with its start. The brackets are proven but not 1e-9 wide
/// in general (certified says whether they are): the path need not reach the torus' extremes.
constexpr int kTorusBandStarts = 1 << 16;
inline WindowBand window_band_torus(const GravitySeries& g, double window_s, double width = 1e-9) {
  WindowBand b;
  b.window_s = window_s;
  b.bound = "torus";
  b.min.window_s = b.max.window_s = window_s;
  b.min.upper = std::numeric_limits<double>::infinity();
  double sizes = 1 + g.period_mean().norm();  // the window mean's rounding is within 1e-14 (1 + |c| + sum A_k)
  for (const GravityHarmonic& h : g.oscillating()) sizes += h.amplitude;
  // Starts sampled over one period, or over the first kMaxTime - W seconds of a longer one (the
  // starts a window mean is defined for): they only give max.lower and min.upper, valid from any start.
  const double period = std::min(g.period_s().value_or(1.0), Clinostat::kMaxTime - window_s);
  for (int k = 0; k < kTorusBandStarts; ++k) {
    const double t0 = period * k / kTorusBandStarts, m = g.window_mean(t0, window_s).norm();
    if (m - 1e-14 * sizes > b.max.lower) b.max.lower = m - 1e-14 * sizes, b.max.start_s = t0;
    if (m + 1e-14 * sizes < b.min.upper) b.min.upper = m + 1e-14 * sizes, b.min.start_s = t0;
  }
  b.max.lower = std::max(0.0, b.max.lower);
  const auto top = torus_window_extreme(g, window_s, WindowExtreme::largest, width);
  const auto bottom = torus_window_extreme(g, window_s, WindowExtreme::smallest, width);
  b.max.upper = std::max(b.max.lower, std::min(top.upper, g.norm_bound()));
  b.min.lower = std::min(b.min.upper, bottom.lower);
  b.max.certified = b.max.upper - b.max.lower <= width;
  b.min.certified = b.min.upper - b.min.lower <= width;
  b.certified = b.min.certified && b.max.certified;
  return b;
}

/// Whether every window mean's length lies in [g - tolerance, g + tolerance] (closed).
struct WindowTarget {
  double g = 0, tolerance = 0;   ///< units of g0
  std::optional<bool> inside;    ///< empty: not decided (an extreme within rounding of an end)
  std::optional<double> start_s; ///< when outside: a start time whose window mean leaves the target
};

namespace detail {

/// Searches one extreme again (width 0) until its side of `limit` is proven: the largest above
/// (lower > limit) or not (upper <= limit); the smallest below (upper < limit) or not (lower >= limit).
inline WorstWindowMean refine_against(const GravitySeries& g, double w, WindowExtreme side, double limit) {
  if (side == WindowExtreme::largest)
    return window_mean_extreme(g, w, side, 0.0, [limit](double lower, double upper) { return lower > limit || upper <= limit; });
  return window_mean_extreme(g, w, side, 0.0, [limit](double lower, double upper) { return upper < limit || lower >= limit; });
}

}  // namespace detail

/// Throws InvalidInput("target-g") unless G is finite and >= 0, InvalidInput("tolerance") unless
/// D is finite and >= 0 (units of g0).
inline void check_window_target(double target, double tolerance) {
  if (!std::isfinite(target) || target < 0) throw InvalidInput("target-g", report_number(target), "not a gravity", "a finite number >= 0, units of g0");
  if (!std::isfinite(tolerance) || tolerance < 0)
    throw InvalidInput("tolerance", report_number(tolerance), "not a tolerance", "a finite number >= 0, units of g0");
}

/// The target G +- D against the band `b` of series g: outside when max.lower > G + D or min.upper
/// < G - D (proven, with the start reaching it), inside when max.upper <= G + D and min.lower >= G
/// - D; an end within the brackets is searched again against that limit until one side is
/// proven (a "period" band; a "torus" band's brackets are all there is), else left undecided. Throws as check_window_target.
inline WindowTarget window_target(const GravitySeries& g, const WindowBand& b, double target, double tolerance) {
  check_window_target(target, tolerance);
  WindowTarget out;
  out.g = target, out.tolerance = tolerance;
  const double high = target + tolerance, low = target - tolerance;
  WorstWindowMean max = b.max, min = b.min;
  const bool searchable = std::string(b.bound) == "period";  // the torus' ends are not searched again
  if (searchable && !(max.lower > high) && max.upper > high) max = detail::refine_against(g, b.window_s, WindowExtreme::largest, high);
  if (max.lower > high) {
    out.inside = false, out.start_s = max.start_s;
    return out;
  }
  if (searchable && !(min.upper < low) && min.lower < low) min = detail::refine_against(g, b.window_s, WindowExtreme::smallest, low);
  if (min.upper < low) {
    out.inside = false, out.start_s = min.start_s;
    return out;
  }
  if (max.upper <= high && min.lower >= low) out.inside = true;
  return out;
}

}  // namespace sphtroch
