// sphtroch/machine/worst_window_mean.hpp — M(W), the largest |mean gravity| over a window of length
// W, whatever time the window starts: certified as a bracket [lower, upper].
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   const sphtroch::WorstWindowMean m = sphtroch::worst_window_mean(g, 600.0);
//   m.lower; m.upper;   // M(600 s) lies in [lower, upper], upper - lower <= 1e-9
//   m.start_s;          // a start time whose window mean is >= lower
//
// Method: a branch and bound over the window's centre tm in one period [0, T) (the window mean is
// periodic in tm with the gravity's period, so the sup over every start time is the sup over one
// period). With m(tm) the window mean (gravity_series.hpp) and s_k = sinc(W_k W / 2), on an
// interval [tc - h, tc + h] the proven bound (Taylor with a bound on the second derivative) is
//   |m(tc + d)| <= max(|m(tc) + m'(tc) h|, |m(tc) - m'(tc) h|) + L2 h^2 / 2,
//   L2 = sum_k |s_k| A_k W_k^2 >= |m''| everywhere (A_k the harmonic's amplitude),
// because |m(tc) + m'(tc) d| is convex in d. Rounding of m and m' in double is bounded by
// 1e-14 (|c| + sum |s_k| A_k + h sum |s_k| A_k |W_k|) (phases reduced exactly, ~3e-15 rad;
// sin_cos within one ulp) plus the sincs' own error, which is absolute, not relative (near a zero
// of sinc, at W a multiple of 2 pi / W_k, sin of the rounded argument is ~1e-16 x, not 0):
// 1e-15 per harmonic, so 1e-15 sum A_k (1 + h |W_k|); both are added to every upper bound and
// taken from every lower bound. The
// intervals are split best first (largest upper bound) until upper - lower <= the width asked.
// For G g_s (G times unit vectors) the upper bound is also at most G: a very short window, whose
// mean is within rounding of G long everywhere, is then certified at once.
// Lower: the largest |m| evaluated. Not interval arithmetic: a proven derivative bound.
// Cost: the period split into pieces of 0.5 / sqrt(L2 / L0) s (L0 = |c| + sum |s_k| A_k: the
// window damps the fast harmonics, so long windows start from few pieces; at most the refusal's
// count, 0.5 / max W_k s), then refinement near the maxima;
// ~1 ms for 1.33 / 2.00 rpm (docs/performance.md). The caller bounds the period's length
// (worst_window_mean_cost).
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/machine/gravity_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <vector>

namespace sphtroch {

struct WorstWindowMean {
  double window_s = 0;
  double lower = 0, upper = 0;  ///< M(W) in [lower, upper], units of g0
  double start_s = 0;           ///< a start time in [0, T) whose window mean has |mean| >= lower (the
                                ///< smallest's search: <= upper)
  bool certified = false;       ///< upper - lower <= the width asked
};

/// The pieces the branch and bound starts from, T max|W_k| / 0.5: the cost's measure. Throws
/// InvalidInput("outer") when beyond kMaxWindowPieces (a period too long for the search).
constexpr double kMaxWindowPieces = 4e6;
inline double worst_window_mean_cost(const GravitySeries& g) {
  if (!g.period_s()) return 1;
  double fastest = 0;
  for (const GravityHarmonic& h : g.oscillating()) fastest = std::max(fastest, std::fabs(h.omega));
  const double pieces = std::ceil(*g.period_s() * fastest / 0.5);
  if (pieces > kMaxWindowPieces)
    throw InvalidInput("outer", g.machine().settings().outer.str(),
                       "the speeds' period (" + number_text(*g.period_s()) + " s) is too long for the worst window mean and the band: " +
                           number_text(pieces) + " pieces to search, at most 4e6",
                       "speeds whose period has at most ~318000 turns of |outer| + |inner|");
  return std::max(8.0, pieces);
}

/// A closed-form bound on sup |F| over the torus of frame angles, F = c + sum_k s_k B_k e(th_k),
/// B_k = [a_k b_k] (3 x 2), e(th) = (cos th, sin th): expanding |F|^2 and bounding each product
/// over independent angles, |B_k^T c| >= |c . B_k e| and sigma_km = the largest singular value of
/// B_k^T B_m >= |B_k e . B_m e'|, so
///   |F|^2 <= |c|^2 + 2 sum_k |s_k| |B_k^T c| + sum_k sum_m |s_k| |s_m| sigma_km.
/// Harmonics in orthogonal directions do not add up (sigma_km = 0), so it is never above the
/// triangle bound |c| + sum_k |s_k| A_k and often far below. The sigmas depend on the machine's
/// geometry only: computed once here, then `upper(w)` costs one sinc per harmonic.
class TorusGramBound {
 public:
  explicit TorusGramBound(const GravitySeries& g) : g_(g) {
    const std::vector<GravityHarmonic>& h = g.oscillating();
    const Vector3d c = g.period_mean();
    for (std::size_t k = 0; k < h.size(); ++k) {
      centre_.push_back(Eigen::Vector2d(h[k].a.dot(c), h[k].b.dot(c)).norm());
      for (std::size_t m = 0; m < h.size(); ++m) {
        Eigen::Matrix2d product;
        product << h[k].a.dot(h[m].a), h[k].a.dot(h[m].b), h[k].b.dot(h[m].a), h[k].b.dot(h[m].b);
        sigma_.push_back(Eigen::JacobiSVD<Eigen::Matrix2d>(product).singularValues()(0));
      }
    }
  }
  /// The bound for window W (g0), rounded up.
  double upper(double w) const {
    const std::vector<GravityHarmonic>& h = g_.oscillating();
    std::vector<double> s(h.size());
    // |sinc| rounded up by its absolute error (~5e-16: the rounding of W_k W / 2); the bound grows with each s_k.
    for (std::size_t k = 0; k < h.size(); ++k) s[k] = std::fabs(GravitySeries::sinc(h[k].omega * w / 2)) + 1e-15;
    double square = g_.period_mean().squaredNorm(), size = g_.period_mean().norm();
    for (std::size_t k = 0; k < h.size(); ++k) {
      square += 2 * s[k] * centre_[k];
      size += s[k] * h[k].amplitude;
      for (std::size_t m = 0; m < h.size(); ++m) square += s[k] * s[m] * sigma_[k * h.size() + m];
    }
    return std::sqrt(square) * (1 + 1e-13) + 1e-14 * (size + 1);  // the sums' and the SVD's rounding
  }

 private:
  const GravitySeries& g_;
  std::vector<double> centre_, sigma_;
};

/// Which extreme of |m| over one period a search brackets: the sup (M(W)) or the inf (the lower
/// edge of the window band, window_band.hpp).
enum class WindowExtreme { largest, smallest };

namespace detail {

/// t reduced into [0, period) seconds, zero unsigned (fmod of a negative multiple of the period
/// is -0, a start no report should print).
inline double start_in_period(double t, double period) {
  const double r = std::fmod(t, period) + 0.0;
  return r < 0 ? r + period : r;
}

/// The window mean m(tm) of one window length and the bounds of the header.
class WindowMeanFunction {
 public:
  WindowMeanFunction(const GravitySeries& g, double w) : g_(g) {
    double l0 = g.period_mean().norm(), l1 = 0, sinc_error = 0, sinc_error_slope = 0;
    for (std::size_t k = 0; k < g.oscillating().size(); ++k) {
      const GravityHarmonic& h = g.oscillating()[k];
      sincs_.push_back(GravitySeries::sinc(h.omega * w / 2));
      const double s = std::fabs(sincs_.back()) * h.amplitude;
      l0 += s;
      l1 += s * std::fabs(h.omega);
      l2_ += s * h.omega * h.omega;
      sinc_error += 1e-15 * h.amplitude;
      sinc_error_slope += 1e-15 * h.amplitude * std::fabs(h.omega);
    }
    typical_frequency_ = l0 > 0 ? std::sqrt(l2_ / l0) : 0;
    rounding_ = 1e-14 * l0 + sinc_error;
    rounding_slope_ = 1e-14 * l1 + sinc_error_slope;
  }
  struct Value {
    Vector3d m, dm;  ///< the window mean and its derivative in tm
  };
  Value at(double tm) const {
    const Clinostat& machine = g_.machine();
    const HarmonicAngles angles(machine.outer_angle(tm), machine.inner_angle(tm));
    Value v{g_.period_mean(), Vector3d::Zero()};
    for (std::size_t k = 0; k < g_.oscillating().size(); ++k) {
      const GravityHarmonic& h = g_.oscillating()[k];
      const SinCos<double> th = angles.of(h.j, h.l);
      const double s = sincs_[k];
      v.m += s * (h.a * th.cos + h.b * th.sin);
      v.dm += s * h.omega * (h.b * th.cos - h.a * th.sin);
    }
    return v;
  }
  /// sqrt(L2 / L0), L0 = |c| + sum_k |s_k| A_k: the frequency of the harmonics that the window
  /// leaves (rad/s). Pieces of 0.5 / it s start the search (any piece size keeps the bound true).
  double typical_frequency() const { return typical_frequency_; }
  double lower(const Value& v) const { return std::max(0.0, v.m.norm() - rounding_); }
  double upper(const Value& v, double h) const {
    return std::max((v.m + v.dm * h).norm(), (v.m - v.dm * h).norm()) + l2_ * h * h / 2 + rounding_ + rounding_slope_ * h;
  }
  /// |m(tc)| rounded up: an upper bound on the smallest |m|.
  double upper(const Value& v) const { return v.m.norm() + rounding_; }
  /// A lower bound on |m| over [tc - h, tc + h]: |m(tc + d)| >= |m(tc) + m'(tc) d| - L2 h^2 / 2
  /// (Taylor), and the smallest |m + m' d| over |d| <= h is the distance from 0 to that segment,
  /// at d = -m.m' / |m'|^2 clamped to [-h, h]. A d rounded off the minimiser (~1e-16 h) raises
  /// the distance by at most |m'| 1e-16 h: within rounding_slope_ h, taken off with the rest.
  double lower(const Value& v, double h) const {
    const double slope2 = v.dm.squaredNorm();
    const double d = slope2 > 0 ? std::clamp(-v.m.dot(v.dm) / slope2, -h, h) : 0.0;
    return std::max(0.0, (v.m + v.dm * d).norm() - l2_ * h * h / 2 - rounding_ - rounding_slope_ * h);
  }

 private:
  const GravitySeries& g_;
  std::vector<double> sincs_;  // s_k = sinc(W_k W / 2), one per oscillating harmonic
  double l2_ = 0, typical_frequency_ = 0, rounding_ = 0, rounding_slope_ = 0;
};

/// Best-first branch and bound of one extreme of |m| over one period; stop(lower, upper) ends it
/// early. Largest: a piece's bound is WindowMeanFunction::upper (the piece of largest bound
/// first), the bracket [largest |m| evaluated less rounding, largest bound]. Smallest: a piece's
/// bound is WindowMeanFunction::lower (the piece of smallest bound first), the bracket [smallest
/// bound, smallest |m| evaluated plus rounding]. start_s: the start of the window evaluated at
/// the bracket's found end.
template <typename Stop>
WorstWindowMean search_window_extreme(const GravitySeries& g, double w, double width, WindowExtreme side, Stop stop,
                                      double* work = nullptr) {
  if (!(w > 0) || !std::isfinite(w)) throw InvalidInput("window", report_number(w), "not a positive window", "seconds > 0");
  WorstWindowMean out;
  out.window_s = w;
  if (!g.period_s() || g.oscillating().empty()) {  // the gravity does not move: every window mean is c
    out.lower = out.upper = g.period_mean().norm();
    out.certified = true;
    return out;
  }
  const bool largest = side == WindowExtreme::largest;
  const double period = *g.period_s();
  const WindowMeanFunction f(g, w);
  struct Piece {
    double centre, half, bound, key;  // key: the bound signed so that the most promising piece is on top
    bool operator<(const Piece& o) const { return key < o.key; }
  };
  std::priority_queue<Piece> pieces;
  double found = largest ? 0.0 : std::numeric_limits<double>::infinity(), found_at = 0;
  const auto add = [&](double centre, double half) {
    if (work) *work += 1;
    const WindowMeanFunction::Value v = f.at(centre);
    const double point = largest ? f.lower(v) : f.upper(v);
    if (largest ? point > found : point < found) {
      found = point;
      found_at = centre;
    }
    const double bound = largest ? f.upper(v, half) : f.lower(v, half);
    pieces.push({centre, half, bound, largest ? bound : -bound});
  };
  const auto bracket = [&](double bound) {  // the queue's top bound and the extreme found
    out.lower = largest ? found : bound;
    out.upper = largest ? std::min(bound, g.norm_bound()) : found;  // a mean of G g_s is at most G long
  };
  const double count = std::clamp(std::ceil(period * f.typical_frequency() / 0.5), 8.0, worst_window_mean_cost(g));
  const double half = period / count / 2;
  for (double k = 0; k < count; ++k) {
    add((2 * k + 1) * half, half);
    out.lower = largest ? found : 0.0;  // the other side unknown yet
    out.upper = largest ? std::numeric_limits<double>::infinity() : found;
    if (stop(out.lower, out.upper)) {  // one side proven already
      out.start_s = detail::start_in_period(found_at - w / 2, period);
      return out;
    }
  }
  const double finest = std::max(1e-12, period * 1e-15);
  while (true) {
    const Piece top = pieces.top();
    bracket(top.bound);
    if (out.upper - out.lower <= width || stop(out.lower, out.upper)) break;
    if (top.half < finest || pieces.size() > kMaxWindowPieces) break;  // cannot refine further (resolution or
                                                                       // memory): left uncertified
    pieces.pop();
    add(top.centre - top.half / 2, top.half / 2);
    add(top.centre + top.half / 2, top.half / 2);
  }
  if (largest) out.upper = std::max(out.upper, out.lower);
  else out.lower = std::min(out.lower, out.upper);
  out.certified = out.upper - out.lower <= width;
  out.start_s = detail::start_in_period(found_at - w / 2, period);
  return out;
}

/// Best-first search of sup |m| over one period (M(W)); stop(lower, upper) ends it early.
template <typename Stop>
WorstWindowMean search_worst_window_mean(const GravitySeries& g, double w, double width, Stop stop, double* work = nullptr) {
  return search_window_extreme(g, w, width, WindowExtreme::largest, stop, work);
}

/// sup |F| (or inf |F|) over the whole torus of frame angles, F(x, y) = c + sum_k s_k (a_k
/// cos(j x + l y) + b_k sin(j x + l y)), bracketed: the window mean at any start lies on it, so
/// M(W) <= the sup's upper and the smallest window mean >= the inf's lower, at a cost independent
/// of the period (the other end bounds the torus' extreme, not the path's: the path may miss it).
/// A box of half-widths (hx, hy) about (x, y), second derivative along d bounded by sum_k |s_k|
/// A_k (|j| hx + |l| hy)^2 / 2, plus rounding: for the sup, bounded above by the largest |F + F_x
/// dx + F_y dy| over its corners (convex in d); for the inf, below by the larger of |F| - |F_x|
/// hx - |F_y| hy and |n . F| (n the unit normal of F_x, F_y: F + F_x dx + F_y dy keeps that
/// component; at the inf F is along n, so the bound closes quadratically). Best first; stop(lower,
/// upper) ends it early, else it ends at kMaxTorusBoxes boxes.
constexpr int kMaxTorusBoxes = 4096;
struct TorusBracket {
  double lower = 0, upper = 0;
};
template <typename Stop>
TorusBracket torus_extreme(const GravitySeries& g, double w, WindowExtreme side, Stop stop, double* work = nullptr) {
  struct Term {
    int j, l;
    double s;
    const GravityHarmonic* h;
  };
  std::vector<Term> terms;
  double size = g.period_mean().norm();
  for (const GravityHarmonic& h : g.oscillating()) {
    terms.push_back({h.j, h.l, GravitySeries::sinc(h.omega * w / 2), &h});
    size += std::fabs(terms.back().s) * h.amplitude;
  }
  double amplitudes = 0;
  for (const GravityHarmonic& h : g.oscillating()) amplitudes += h.amplitude;
  const double rounding = 1e-14 * (size + 1) + 1e-15 * amplitudes;  // and the sincs' absolute error
  const bool largest = side == WindowExtreme::largest;
  struct Box {
    double x, y, half, bound, key;  // key: the bound signed so that the most promising box is on top
    bool operator<(const Box& o) const { return key < o.key; }
  };
  std::priority_queue<Box> boxes;
  TorusBracket out;
  double found = largest ? 0.0 : std::numeric_limits<double>::infinity();
  const auto add = [&](double x, double y, double half) {
    if (work) *work += 1;
    Vector3d f = g.period_mean(), fx = Vector3d::Zero(), fy = Vector3d::Zero();
    double curvature = 0;
    const HarmonicAngles angles(x, y);
    for (const Term& t : terms) {
      const SinCos<double> th = angles.of(t.j, t.l);
      const Vector3d value = t.s * (t.h->a * th.cos + t.h->b * th.sin), slope = t.s * (t.h->b * th.cos - t.h->a * th.sin);
      f += value;
      fx += t.j * slope;
      fy += t.l * slope;
      const double reach = (std::abs(t.j) + std::abs(t.l)) * half;
      curvature += std::fabs(t.s) * t.h->amplitude * reach * reach / 2;
    }
    double bound = 0;
    if (largest) {
      for (const double sx : {-half, half})
        for (const double sy : {-half, half}) bound = std::max(bound, (f + fx * sx + fy * sy).norm());
      bound += curvature + rounding;
      found = std::max(found, f.norm() - rounding);
    } else {
      const Vector3d normal = fx.cross(fy);
      const double across = normal.norm() > 0 ? std::fabs(normal.dot(f)) / normal.norm() : 0.0;
      bound = std::max(0.0, std::max(f.norm() - (fx.norm() + fy.norm()) * half, across) - curvature - rounding);
      found = std::min(found, f.norm() + rounding);
    }
    boxes.push({x, y, half, bound, largest ? bound : -bound});
  };
  const double pi = Constants<double>::pi();
  const int n = 4;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) add((2 * a + 1) * pi / n, (2 * b + 1) * pi / n, pi / n);
  for (int count = n * n;; count += 4) {
    out.lower = largest ? found : std::min(found, boxes.top().bound);
    out.upper = largest ? std::max(found, boxes.top().bound) : found;
    if (count >= kMaxTorusBoxes || stop(out.lower, out.upper)) return out;
    const Box top = boxes.top();
    boxes.pop();
    const double q = top.half / 2;
    for (const double dx : {-q, q})
      for (const double dy : {-q, q}) add(top.x + dx, top.y + dy, q);
  }
}

/// sup |F| over the whole torus (torus_extreme's largest): `upper` bounds M(W).
template <typename Stop>
TorusBracket torus_bracket(const GravitySeries& g, double w, Stop stop, double* work = nullptr) {
  return torus_extreme(g, w, WindowExtreme::largest, stop, work);
}

/// True when sup |F| <= epsilon is proven over the whole torus (torus_bracket): M(W) <= epsilon
/// follows. False when some |F| > epsilon is found or after kMaxTorusBoxes boxes (then the
/// caller searches the path itself).
inline bool torus_below(const GravitySeries& g, double w, double epsilon, double* work = nullptr) {
  const TorusBracket b = torus_bracket(g, w, [epsilon](double lower, double upper) { return lower > epsilon || upper <= epsilon; }, work);
  return b.upper <= epsilon;
}

}  // namespace detail

/// M(W) as a bracket of width <= `width` (certified) or wider (certified = false: the search hit
/// its resolution). Throws InvalidInput("window") unless W > 0 and finite.
inline WorstWindowMean worst_window_mean(const GravitySeries& g, double window_s, double width = 1e-9) {
  return detail::search_worst_window_mean(g, window_s, width, [](double, double) { return false; });
}

/// One extreme over every start time of |mean over [t0, t0 + W]|: the largest (M(W)) or the
/// smallest, as a bracket of width <= `width` (certified) unless the search hits its resolution;
/// stop(lower, upper) ends the search early (then certified says whether the width was reached).
/// Throws InvalidInput("window") unless W > 0 and finite, InvalidInput("outer") when the period
/// is too long (worst_window_mean_cost).
template <typename Stop>
WorstWindowMean window_mean_extreme(const GravitySeries& g, double window_s, WindowExtreme side, double width, Stop stop) {
  return detail::search_window_extreme(g, window_s, width, side, stop);
}

/// One extreme of |F| over the whole torus of frame angles (detail::torus_extreme): {lower, upper}
/// with upper - lower <= width or after kMaxTorusBoxes boxes. Largest: upper >= M(W); smallest:
/// lower <= the smallest window mean, whatever the period.
inline auto torus_window_extreme(const GravitySeries& g, double window_s, WindowExtreme side, double width) {
  return detail::torus_extreme(g, window_s, side, [width](double lower, double upper) { return upper - lower <= width; });
}

/// Whether M(W) <= epsilon: below (upper <= epsilon), above (lower > epsilon) or undecided (M(W)
/// within rounding of epsilon). Stops as soon as one side is proven; first tries the bound over
/// all frame angles (detail::torus_below), whose cost does not grow with the period.
enum class WindowSide { below, above, undecided };
/// `hint` (optional, in and out): a window start to try first, set to the start found above
/// epsilon (a scan over W passes the last one on: the worst start moves little from W to W + r).
/// `work` (optional): adds the number of evaluations spent (the cost's measure).
inline WindowSide compare_worst_window_mean(const GravitySeries& g, double window_s, double epsilon, double* hint = nullptr,
                                            double* work = nullptr) {
  double sizes = 1;  // the window mean's rounding is within 1e-14 (1 + |c| + sum A_k) (header)
  for (const GravityHarmonic& h : g.oscillating()) sizes += h.amplitude;
  if (hint && g.window_mean(*hint, window_s).norm() > epsilon * (1 + 1e-13) + 1e-14 * (sizes + g.period_mean().norm())) return WindowSide::above;
  if (detail::torus_below(g, window_s, epsilon, work)) return WindowSide::below;
  const WorstWindowMean m = detail::search_worst_window_mean(
      g, window_s, 0.0, [epsilon](double lower, double upper) { return lower > epsilon || upper <= epsilon; }, work);
  if (hint && m.lower > epsilon) *hint = m.start_s;
  if (m.lower > epsilon) return WindowSide::above;
  if (m.upper <= epsilon) return WindowSide::below;
  return WindowSide::undecided;
}

/// M(W) at `count` windows W = longest k / count, k = 1 .. count: each bracketed by the search
/// over one period (width 1e-6) when the count times worst_window_mean_cost stays within
/// kMaxCurvePieces (~15 s), else by the bound over every frame angle (torus_bracket: `upper`
/// bounds M(W), `lower` is the torus' and not M's; `torus` says so): its cost does not grow with
/// the period, at most count kMaxTorusBoxes evaluations.
constexpr double kMaxCurvePieces = 2e7;
struct WindowCurve {
  std::vector<WorstWindowMean> points;
  bool torus = false;
};
inline WindowCurve window_curve(const GravitySeries& g, double longest, int count) {
  WindowCurve out;
  double cost = kMaxWindowPieces;
  try {
    cost = worst_window_mean_cost(g);
  } catch (const InvalidInput&) {  // a period too long for the search: the torus bound
  }
  out.torus = cost * count > kMaxCurvePieces;
  for (int k = 1; k <= count; ++k) {
    const double w = longest * k / count;
    if (!out.torus) {
      out.points.push_back(worst_window_mean(g, w, 1e-6));
      continue;
    }
    const detail::TorusBracket b = detail::torus_bracket(g, w, [](double lower, double upper) { return upper - lower <= 1e-6; });
    WorstWindowMean m;
    m.window_s = w, m.lower = b.lower, m.upper = std::min(b.upper, g.norm_bound());
    m.certified = false;
    out.points.push_back(m);
  }
  return out;
}

}  // namespace sphtroch
