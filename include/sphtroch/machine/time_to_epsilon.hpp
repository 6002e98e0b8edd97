// sphtroch/machine/time_to_epsilon.hpp — how long a clinostat must average before the mean gravity
// is below epsilon, whenever the experiment starts.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   const sphtroch::TimeToEpsilon t = sphtroch::time_to_epsilon(g, 0.01, 1.0);
//   t.first_s;              // the shortest window W (a multiple of 1 s) with M(W) <= 0.01
//   t.stays_below_from_s;   // the shortest W from which every longer window (on the grid) is below
//
// Windows are the multiples of the resolution r: W = r, 2r, ... M(W) (worst_window_mean.hpp) is
// not monotone in W, hence the two answers. Both are decided by certified comparisons and a proof
// of the tail:
// - M(W) >= |c| for every W (c the mean over a period: the mean over start times of the window
//   means is c), so when |c| > epsilon no window qualifies: both empty, with the reason (and when
//   |c| is within rounding of epsilon the answer is not certified, and says so).
// - |mean(t0, W) - c| <= sum_k A_k |sinc(W_k W / 2)| <= (sum_k 2 A_k / |W_k|) / W = C / W, so every
//   W >= C / (epsilon - |c|) is below: the grid is searched up to there, downwards for the last W
//   above epsilon. A cheap bound settles most windows without a search: TorusGramBound
//   (worst_window_mean.hpp), which is never above |c| + sum_k A_k |sinc(W_k W / 2)|.
// Between grid points M can exceed its values at the grid by at most (1 + |c| + sum A_k) r / W
// (|d/dW (W mean)| <= |f|); the answers are stated for the grid.
// Cost: one comparison per grid window up to the first below epsilon, and one per window above
// the cheap bound (TorusGramBound) while going down from C / (epsilon - |c|); bounded up front by kMaxWindows, and
// while running by kMaxTimeToEpsilonWork evaluations (then not certified, and it says so: speeds
// near a resonance, whose slow beat puts many windows within a hair of epsilon).
#pragma once

#include "sphtroch/machine/worst_window_mean.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace sphtroch {

struct TimeToEpsilon {
  double epsilon = 0, resolution_s = 0;
  std::optional<double> first_s;             ///< the smallest grid W with M(W) <= epsilon
  std::optional<double> stays_below_from_s;  ///< the smallest grid W with M(W') <= epsilon for all grid W' >= W
  std::string reason;                        ///< why both are empty, or why not certified
  bool certified = true;                     ///< false: a comparison was undecided (reason says where)
  double tail_s = 0;                         ///< C / (epsilon - |c|): every W beyond is proven below
};

/// The largest number of grid windows searched (the tail bound over the resolution).
constexpr double kMaxWindows = 1e7;
/// The largest number of evaluations of the window mean the search spends (~10 s); beyond, the
/// answer is not certified and says so (near-resonant speeds with a small epsilon).
constexpr double kMaxTimeToEpsilonWork = 3e7;

/// Throws InvalidInput("epsilon") unless 0 < epsilon <= 1e9, ("resolution") unless 0 < r <= 1e6 s,
/// and ("resolution") when the tail C / (epsilon - |c|) holds more than kMaxWindows grid windows.
/// `max_work`: the evaluations the search may spend (default kMaxTimeToEpsilonWork).
inline TimeToEpsilon time_to_epsilon(const GravitySeries& g, double epsilon, double resolution_s,
                                     double max_work = kMaxTimeToEpsilonWork) {
  if (!(epsilon > 0 && epsilon <= 1e9)) throw InvalidInput("epsilon", number_text(epsilon), "not a bound in range", "0 < epsilon <= 1e9 (units of g0)");
  if (!(resolution_s > 0 && resolution_s <= 1e6))
    throw InvalidInput("resolution", number_text(resolution_s), "not a positive step", "0 < resolution <= 1e6 seconds");
  TimeToEpsilon out;
  out.epsilon = epsilon;
  out.resolution_s = resolution_s;
  const double c = g.period_mean().norm();
  if (std::fabs(c - epsilon) <= epsilon * 1e-12 + 1e-14) {  // c's rounding (~1e-16) could put it on either side
    out.certified = false;
    out.reason = "the mean over a period, " + number_text(c) + " g0, is within rounding of epsilon: not decided";
    return out;
  }
  if (c > epsilon) {
    out.reason = "the mean over a period, " + number_text(c) + " g0, is above epsilon: no window is below (M(W) >= it for every W)";
    return out;
  }
  double tail = 0;
  for (const GravityHarmonic& h : g.oscillating()) tail += 2 * h.amplitude / std::fabs(h.omega);
  out.tail_s = tail / (epsilon - c);
  const double last = std::ceil(out.tail_s / resolution_s);
  if (out.tail_s / kMaxWindows > 1e6)  // no resolution would do
    throw InvalidInput("epsilon", number_text(epsilon),
                       "so close to the mean over a period (" + number_text(c) + " g0) that the proven tail is at " + number_text(out.tail_s) + " s",
                       "an epsilon whose tail, (sum 2 A_k / |W_k|) / (epsilon - |c|), is at most 1e13 s: a larger epsilon");
  if (last > kMaxWindows)
    throw InvalidInput("resolution", number_text(resolution_s),
                       "the search would cover " + number_text(last) + " windows up to the proven tail at " + number_text(out.tail_s) + " s",
                       "a resolution >= " + number_text(out.tail_s / kMaxWindows) + " s, or a larger epsilon");
  const TorusGramBound torus_bound(g);
  const auto cheap_upper = [&](double w) { return torus_bound.upper(w); };

  double hint = 0;  // the start of the last window found above epsilon
  double work = 0;
  const auto side = [&](double k) {
    const double w = k * resolution_s;
    if (cheap_upper(w) <= epsilon) return WindowSide::below;
    if (work > max_work) return WindowSide::undecided;
    return compare_worst_window_mean(g, w, epsilon, &hint, &work);
  };
  const auto undecided = [&](double k) {
    out.certified = false;
    out.first_s.reset();
    out.stays_below_from_s.reset();
    out.reason = work > max_work
                     ? "the search reached its work bound (" + number_text(max_work) + " evaluations) at W = " + number_text(k * resolution_s) +
                           " s: not decided; a coarser resolution or a larger epsilon"
                     : "M(W) at W = " + number_text(k * resolution_s) + " s is within rounding of epsilon: not decided";
    return out;
  };
  double first = 1;
  for (; first <= last; ++first) {
    const WindowSide s = side(first);
    if (s == WindowSide::undecided) return undecided(first);
    if (s == WindowSide::below) break;
  }
  first = std::min(first, std::max(1.0, last));  // at the tail's grid point the cheap bound holds
  out.first_s = first * resolution_s;
  double stays = first;
  for (double k = last; k > first; --k) {
    const WindowSide s = side(k);
    if (s == WindowSide::undecided) return undecided(k);
    if (s == WindowSide::above) {
      stays = k + 1;
      break;
    }
  }
  out.stays_below_from_s = stays * resolution_s;
  return out;
}

}  // namespace sphtroch
