// sphtroch/machine/time_to_epsilon.hpp — how long a clinostat must average before the mean gravity
// is below epsilon, whenever the experiment starts.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   const sphtroch::TimeToEpsilon t = sphtroch::time_to_epsilon(g, 0.01, 1.0);
//   t.first_s;              // the shortest window W (a multiple of 1 s) with M(W) <= 0.01
//   t.stays_below_from_s;   // a multiple of 1 s from which every longer window (any length) is below
//
// Two answers, because M(W) (worst_window_mean.hpp) is not monotone in W:
// - first_s: the shortest window on the grid W = r, 2r, ... (r the resolution) with M(W) <= epsilon.
//   The grid is of decimals: W = k r is the double nearest the decimal k x r, r read as the
//   shortest decimal of its double (detail::DecimalGrid), so 3755 steps of 0.01 s are 37.55 s.
// - stays_below_from_s: a multiple of r from which EVERY window, of any real length W, is below
//   epsilon (not only the grid's: a machine whose periods divide r is below at every grid point
//   and far above in between). above_s, when found, is a length certified above epsilon within
//   2 r below it, so the true threshold lies in [above_s, stays_below_from_s].
// Both are decided by certified comparisons and a proof of the tail:
// - M(W) >= |c| for every W (c the mean over a period: the mean over start times of the window
//   means is c), so when |c| > epsilon no window qualifies: both empty, with the reason (and when
//   |c| is within rounding of epsilon the answer is not certified, and says so).
// - |mean(t0, W) - c| <= sum_k A_k |sinc(W_k W / 2)| <= (sum_k 2 A_k / |W_k|) / W = C / W, so every
//   W >= C / (epsilon - |c|) is below.
// - Between lengths: for a fixed start, W' mean(t0, W') differs from W mean(t0, W) by at most
//   |W' - W| G (G >= sup |g(t)|), so M(W') <= (W M(W) + h G) / (W - h) for |W' - W| <= h: one
//   comparison of M(w) with tau = epsilon - h (epsilon + G) / w covers [w - h, w + h]. The
//   search walks down from the tail with h growing after each covered piece and halving after a
//   failed one; a failed piece is compared with epsilon itself (above: above_s), and the walk
//   stops at an above point or when h < r / 1024 (then eight lengths within r below are tried
//   for an above point).
// A cheap bound settles most comparisons without a search: TorusGramBound (worst_window_mean.hpp),
// which is never above |c| + sum_k A_k |sinc(W_k W / 2)|.
// Cost: one comparison per grid window up to the first below epsilon, and about
// 2 (G + epsilon) / (epsilon - M) ln(tail / stays) comparisons for the walk (most by the cheap
// bound); bounded up front by kMaxWindows, and while running by kMaxTimeToEpsilonWork
// evaluations (then not certified, and it says so: speeds near a resonance, whose slow beat puts
// many windows within a hair of epsilon).
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/machine/worst_window_mean.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace sphtroch {

struct TimeToEpsilon {
  double epsilon = 0, resolution_s = 0;
  std::optional<double> first_s;             ///< the smallest grid W with M(W) <= epsilon
  std::optional<double> stays_below_from_s;  ///< a grid W with M(W') <= epsilon for every real W' >= W (certified)
  std::optional<double> above_s;             ///< a length with M > epsilon (certified) in [stays - 2 r, stays), when found
  std::string reason;                        ///< why both are empty, or why not certified
  bool certified = true;                     ///< false: a comparison was undecided (reason says where)
  double tail_s = 0;                         ///< C / (epsilon - |c|): every W beyond is proven below
};

/// The smallest epsilon (g0): the mean over a period is known to ~1e-14, so a smaller bound could
/// not be told from it.
constexpr double kMinEpsilon = 1e-12;
/// The largest number of grid windows searched (the tail bound over the resolution).
constexpr double kMaxWindows = 1e7;
/// The largest number of evaluations of the window mean the search spends (~10 s); beyond, the
/// answer is not certified and says so (near-resonant speeds with a small epsilon).
constexpr double kMaxTimeToEpsilonWork = 3e7;

namespace detail {

/// The grid W_k = k r of a resolution r, k = 1, 2, ... up to max_k: the double nearest the decimal
/// k x r, r read as its shortest decimal R x 10^scale (number_text: 0.01 is 1 x 10^-2), so that a
/// window printed reads as the multiple it is (3755 x 0.01 = 37.55, where the product of doubles
/// is 37.550000000000004). k R and 10^|scale| are exact doubles and one division or product
/// rounds them correctly when k R <= 2^53 and |scale| <= 22; beyond (r of many digits), k * r.
/// at() is nondecreasing in k either way.
class DecimalGrid {
 public:
  DecimalGrid(double step, double max_k) : step_(step) {
    const DecimalDigits d = decimal_digits(step);
    scale_ = d.exponent - static_cast<int>(d.digits.size()) + 1;
    const double units = d.digits.size() <= 17 ? std::stod(d.digits) : 0;
    constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
    exact_ = units > 0 && units <= kExactIntegers && units * max_k <= kExactIntegers && std::abs(scale_) <= 22;
    units_ = units;
    for (int i = 0; i < std::abs(scale_); ++i) power_ *= 10;  // exact: 10^22 < 2^53 x 2^22
  }
  double at(double k) const {
    if (!exact_) return k * step_;
    return scale_ < 0 ? k * units_ / power_ : k * units_ * power_;
  }

 private:
  double step_, units_ = 0, power_ = 1;
  int scale_ = 0;
  bool exact_ = false;
};

/// sup_t |g(t)| bounded: the unit vectors' 1, else the torus bound with every sinc 1.
inline double gravity_bound(const GravitySeries& g, const TorusGramBound& torus) {
  return std::min(g.norm_bound(), torus.upper(0.0));
}

/// The walk of the header down from the tail: `covered` (every real W >= it is below epsilon,
/// certified), `above` (a length certified above epsilon, 0 when none found) and `out_of_work`
/// (the work bound ended it: nothing certified below the tail).
struct DownwardWalk {
  double covered = 0, above = 0;
  bool out_of_work = false;
};
inline DownwardWalk walk_down(const GravitySeries& g, const TorusGramBound& torus, double epsilon, double resolution_s, double tail_s,
                              double max_work, double& work, double& hint) {
  const double big_g = gravity_bound(g, torus);
  DownwardWalk walk;
  walk.covered = tail_s;
  const double finest = resolution_s / 1024;
  double h = resolution_s, lowest = 0;
  while (walk.covered - lowest > finest && walk.covered > finest) {
    h = std::min(h, (walk.covered - lowest) / 2);
    const double w = walk.covered - h;                       // covers [w - h, w + h] when below tau
    const double tau = (epsilon * (w - h) - h * big_g) / w * (1 - 1e-13);
    WindowSide side = WindowSide::undecided;
    if (tau > 0 && torus.upper(w) <= tau) side = WindowSide::below;
    else if (tau > 0 && work <= max_work) side = compare_worst_window_mean(g, w, tau, &hint, &work);
    if (work > max_work) {
      walk.out_of_work = true;
      return walk;
    }
    if (side == WindowSide::below) {
      walk.covered = std::max(lowest, w - h);
      h *= 2;
      continue;
    }
    if (compare_worst_window_mean(g, w, epsilon, &hint, &work) == WindowSide::above) {
      walk.above = std::max(walk.above, w);
      lowest = w;
    }
    h /= 2;
    if (h < finest) break;
  }
  // Stuck short of an above point (M within ~finest (G + epsilon) / W of epsilon): one within a
  // resolution below, if the search finds one, bounds the threshold from below.
  for (int k = 1; k <= 8 && walk.above < walk.covered - resolution_s && work <= max_work; ++k) {
    const double w = walk.covered - resolution_s * k / 8;
    if (w > 0 && compare_worst_window_mean(g, w, epsilon, &hint, &work) == WindowSide::above) walk.above = w;
  }
  return walk;
}

}  // namespace detail

/// Throws InvalidInput("epsilon") unless 1e-12 <= epsilon <= 1e9, ("resolution") unless 0 < r <= 1e6 s,
/// and ("resolution") when the tail C / (epsilon - |c|) holds more than kMaxWindows grid windows.
/// `max_work`: the evaluations the search may spend (default kMaxTimeToEpsilonWork).
inline TimeToEpsilon time_to_epsilon(const GravitySeries& g, double epsilon, double resolution_s,
                                     double max_work = kMaxTimeToEpsilonWork) {
  if (!(epsilon >= kMinEpsilon && epsilon <= 1e9))
    throw InvalidInput("epsilon", report_number(epsilon), "not a bound in range",
                       "1e-12 <= epsilon <= 1e9 (units of g0; the mean over a period is known to ~1e-14)");
  if (!(resolution_s > 0 && resolution_s <= 1e6))
    throw InvalidInput("resolution", report_number(resolution_s), "not a positive step", "0 < resolution <= 1e6 seconds");
  TimeToEpsilon out;
  out.epsilon = epsilon;
  out.resolution_s = resolution_s;
  const double c = g.period_mean().norm();
  if (std::fabs(c - epsilon) <= epsilon * 1e-12 + 1e-14) {  // c's rounding (~1e-16) could put it on either side
    out.certified = false;
    out.reason = "the mean over a period, " + report_number(c) + " g0, is within rounding of epsilon: not decided";
    return out;
  }
  if (c > epsilon) {
    out.reason = "the mean over a period, " + report_number(c) + " g0, is above epsilon: no window is below (M(W) >= it for every W)";
    return out;
  }
  double tail = 0;
  for (const GravityHarmonic& h : g.oscillating()) tail += 2 * h.amplitude / std::fabs(h.omega);
  out.tail_s = tail / (epsilon - c);
  const double last = std::ceil(out.tail_s / resolution_s);
  if (out.tail_s / kMaxWindows > 1e6)  // no resolution would do
    throw InvalidInput("epsilon", report_number(epsilon),
                       "so close to the mean over a period (" + report_number(c) + " g0) that the proven tail is at " + report_number(out.tail_s) + " s",
                       "an epsilon whose tail, (sum 2 A_k / |W_k|) / (epsilon - |c|), is at most 1e13 s: a larger epsilon");
  if (last > kMaxWindows)
    throw InvalidInput("resolution", report_number(resolution_s),
                       "the search would cover " + report_number(last) + " windows up to the proven tail at " + report_number(out.tail_s) + " s",
                       "a resolution >= " + report_number(out.tail_s / kMaxWindows) + " s, or a larger epsilon");
  const detail::DecimalGrid grid(resolution_s, last + 2);
  const TorusGramBound torus_bound(g);
  const auto cheap_upper = [&](double w) { return torus_bound.upper(w); };

  double hint = 0;  // the start of the last window found above epsilon
  double work = 0;
  const auto side = [&](double k) {
    const double w = grid.at(k);
    if (cheap_upper(w) <= epsilon) return WindowSide::below;
    if (work > max_work) return WindowSide::undecided;
    return compare_worst_window_mean(g, w, epsilon, &hint, &work);
  };
  const auto undecided = [&](double w) {
    out.certified = false;
    out.first_s.reset();
    out.stays_below_from_s.reset();
    out.reason = work > max_work
                     ? "the search reached its work bound (" + report_number(max_work) + " evaluations) at W = " + report_number(w) +
                           " s: not decided; a coarser resolution or a larger epsilon"
                     : "M(W) at W = " + report_number(w) + " s is within rounding of epsilon: not decided";
    return out;
  };
  double first = 1;
  for (; first <= last; ++first) {
    const WindowSide s = side(first);
    if (s == WindowSide::undecided) return undecided(grid.at(first));
    if (s == WindowSide::below) break;
  }
  first = std::min(first, std::max(1.0, last));  // at the tail's grid point the cheap bound holds
  out.first_s = grid.at(first);
  const detail::DownwardWalk walk = detail::walk_down(g, torus_bound, epsilon, resolution_s, out.tail_s, max_work, work, hint);
  if (walk.out_of_work) return undecided(walk.covered);
  double stays = std::max(first, std::ceil(walk.covered / resolution_s));
  if (grid.at(stays) < walk.covered) stays += 1;  // the division's rounding
  out.stays_below_from_s = grid.at(stays);
  if (walk.above > 0 && walk.above >= out.stays_below_from_s.value() - 2 * resolution_s) out.above_s = walk.above;
  return out;
}

}  // namespace sphtroch
