// sphtroch/synthesis/identify.hpp — the inverse question for a timed trace: which gear train drew
// these samples? From (t_i, P_i), with t_i the carrier angle theta2 of each sample, it finds the
// ratio n as an exact fraction, a2, a3 and the phase, and how well they reproduce the samples.
// Eigen only.
//
//   const sphtroch::GearTrain hidden(1.1, 0.7, sphtroch::Ratio(-5, 3), 0.4);
//   const auto tr = sphtroch::sample_period(sphtroch::TracerCurve<double>(hidden), 600);
//   sphtroch::Identified id = sphtroch::identify(tr.t, tr.points);
//   id.train.ratio().str();   // "-5/3", exact
//   id.residual;              // max |P(t_i) - P_i| of the identified train, here about 1e-15
//
// Method (derivation ours, from Eqs. 3 and 4). P(t) = Rz(t) C(u) with u = n t + theta_p and
// C(u) = Rx(a2) Rz(u) Rx(a3) z: undoing the carrier turn, C_i = Rz(-t_i) P_i lies on the planet's
// circle, the small circle of angular radius a3 about the planet axis Z2 = (0, -sin a2, cos a2)
// of the carrier frame.
//  1. The circle: the plane through the C_i (least squares: the normal is the eigenvector of
//     the smallest eigenvalue of their covariance) has normal Z2 and offset cos a3, which gives
//     a2 (the normal oriented so that its y is negative: a2 in (0, pi)) and a3.
//  2. The planet angle of each sample: Rx(-a2) C_i = (sin a3 sin u, -sin a3 cos u, cos a3).
//  3. n and the phase: u_i, unwrapped along t (REQUIRES |n| times every step of t below pi), is a
//     line u = n t + theta_p. Its slope, with the standard error of the fit, gives an interval;
//     n is the simplest fraction in it (smallest q, then smallest |p|; Stern–Brocot), with
//     |p| <= max_p and q <= max_q.
//  4. Polish: Gauss–Newton on (a2, a3, theta_p) with n fixed, minimising sum |P(t_i) - P_i|^2.
// What is guaranteed: the returned train reproduces the samples to `residual` (measured, max over
// the samples) and no train of another ratio does within the accepted rms (below). identify
// refuses (InvalidInput, field "samples", one line with the reason) when:
//  - the samples do not lie on one planet circle, or its axis is the sun axis (a2 = 0 or pi);
//  - the planet circle is below the samples' resolution: with the accepted rms
//    tau = max(kIdentifyTolerance, 10 x the noise off the circle), a train of any other ratio
//    (the same a2, the planet circle shrunk) stays within about sin a3 of the samples, so n is
//    determined only when sin a3 >= kResolutionMargin x tau (exact samples: a3 >= 4e-6 from 0 or pi);
//  - the unwrapped angles are not a line (too sparse for this n), or no fraction within the bounds fits;
//  - the fit leaves an rms above tau, or above kIdentifyTolerance while the residual is
//    systematic: its point-to-point scatter (RMS of r_{i+1} - r_i over sqrt 2, which white noise
//    leaves at the noise and a wrong or mixed model's smooth misfit leaves far below the rms) is
//    below rms / kSystematicRatio. Two trains mixed along t are refused so. The rule assumes noise
//    that is independent from sample to sample: smoothed samples, or dense samples rounded to
//    few digits (the same rounding error over many neighbours), have a scatter below their rms
//    and are refused too when their rms is above 1e-6 (thin them, or write more digits).
// Noise of sigma radians gives a2, a3 to a few sigma / sqrt(N). Cost: O(N) per step, about 10 steps.
#pragma once

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch {

/// Fewest samples identify accepts.
constexpr std::size_t kMinIdentifySamples = 8;
/// A residual (max |P(t_i) - P_i|, chord) always accepted: exact samples are reproduced far below it.
constexpr double kIdentifyTolerance = 1e-6;
/// Samples must be unit vectors to this (the curve lies on the unit sphere).
constexpr double kUnitTolerance = 1e-6;
/// n is determined only when the planet circle's radius sin a3 is at least this many times the
/// accepted rms (a train of another ratio misses the samples by about sin a3 / sqrt 2 to sin a3).
constexpr double kResolutionMargin = 4.0;
/// A residual above kIdentifyTolerance whose rms exceeds its point-to-point scatter this many
/// times is a systematic misfit, not noise (white noise gives a ratio near 1).
constexpr double kSystematicRatio = 3.0;

struct IdentifyOptions {
  std::int64_t max_p = 1000;  // |p| <= max_p, 1 .. Ratio::kMaxTerm
  std::int64_t max_q = 1000;  // q <= max_q, 1 .. Ratio::kMaxTerm
};

struct Identified {
  GearTrain train{1.0, 1.0, Ratio(1)};  // n exact, a2, a3, phase (reduced to [-pi, pi])
  double residual = 0.0;                // max over the samples of |P(t_i) - P_i| (chord)
  double rms = 0.0;                     // root mean square of the same distances
  double noise = 0.0;                   // RMS distance of the C_i to the fitted plane (step 1)
  double slope = 0.0, slope_error = 0.0;  // step 3: the fitted dtheta3/dtheta2 and its standard error
};

/// The train that drew the timed samples (see header). Throws InvalidInput naming "t", "points"
/// or "samples" (one line: the value, the problem, the valid form).
inline Identified identify(const std::vector<double>& t, const std::vector<Vector3d>& points,
                           const IdentifyOptions& options = {});

/// The simplest fraction p/q in [lo, hi] (smallest q, then smallest |p|) with q <= max_q, or
/// nothing. REQUIRES lo <= hi, both finite.
inline std::optional<Ratio> simplest_fraction(double lo, double hi, std::int64_t max_q);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace identify_detail {

inline double wrap(double a) { return std::remainder(a, 2 * Constants<double>::pi()); }

/// The model point P(t) = Rz(t) Rx(a2) Rz(u) Rx(a3) z, u = n t + phase (Eq. 4).
inline Vector3d model_point(double t, double a2, double a3, double n, double phase) {
  const double u = n * t + phase, s3 = std::sin(a3), c3 = std::cos(a3), s2 = std::sin(a2), c2 = std::cos(a2);
  const Vector3d c(s3 * std::sin(u), -(s3 * c2 * std::cos(u) + c3 * s2), c2 * c3 - s2 * s3 * std::cos(u));
  const double ct = std::cos(t), st = std::sin(t);
  return Vector3d(ct * c.x() - st * c.y(), st * c.x() + ct * c.y(), c.z());
}

inline void check_inputs(const std::vector<double>& t, const std::vector<Vector3d>& points) {
  if (t.size() != points.size())
    throw InvalidInput("samples", std::to_string(t.size()) + " times, " + std::to_string(points.size()) + " points",
                       "not one time per point", "one theta2 per point");
  if (t.size() < kMinIdentifySamples)
    throw InvalidInput("samples", std::to_string(t.size()), "too few",
                       "at least " + std::to_string(kMinIdentifySamples) + " timed samples over one period");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1])))
      throw InvalidInput("t", "sample " + std::to_string(i) + ": " + number_text(t[i]), "not finite and increasing",
                         "finite carrier angles theta2 (radians), strictly increasing");
    const double norm = points[i].norm();
    if (!std::isfinite(norm) || std::abs(norm - 1.0) > kUnitTolerance)
      throw InvalidInput("points", "sample " + std::to_string(i) + ": |P| = " + number_text(norm),
                         "not on the unit sphere", "unit vectors x, y, z (|P| within 1e-6 of 1)");
  }
}

/// The rms a fit may leave: kIdentifyTolerance, or 10 x the noise seen off the planet circle.
inline double accepted_rms(double noise) { return std::max(kIdentifyTolerance, 10 * noise); }

/// Refuses a planet circle too small for the samples to tell one ratio from another (see header).
inline void check_resolution(double radius, double noise) {
  const double tau = accepted_rms(noise);
  if (radius >= kResolutionMargin * tau) return;
  throw InvalidInput("samples", "planet circle radius sin a3 = " + number_text(radius),
                     "below the samples' resolution (accepted rms " + number_text(tau) +
                         "): a train of every ratio n reproduces them, so they do not determine n",
                     "a tracer whose planet circle has sin a3 >= " + number_text(kResolutionMargin) +
                         " x max(1e-6, 10 x the noise off the circle)");
}

/// Step 1: a2, a3 and the noise off the circle, from the plane through C_i = Rz(-t_i) P_i.
struct Circle {
  double a2, a3, noise;
};

inline Circle planet_circle(const std::vector<Vector3d>& c) {
  Vector3d mean = Vector3d::Zero();
  for (const Vector3d& x : c) mean += x;
  mean /= static_cast<double>(c.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vector3d& x : c) cov += (x - mean) * (x - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vector3d m = eig.eigenvectors().col(0);  // smallest eigenvalue: the plane's normal
  if (m.y() > 0) m = -m;                   // Z2 = (0, -sin a2, cos a2), sin a2 > 0
  const double d = std::clamp(m.dot(mean), -1.0, 1.0);
  double noise = 0.0;
  for (const Vector3d& x : c) noise += (m.dot(x) - d) * (m.dot(x) - d);
  noise = std::sqrt(noise / static_cast<double>(c.size()));
  const double spread = std::sqrt(std::max(0.0, eig.eigenvalues()(1)) / static_cast<double>(c.size()));
  check_resolution(std::sqrt(2.0) * spread, noise);  // a circle of radius r spreads r / sqrt 2 each way
  if (!(spread > 10 * noise) || std::abs(m.x()) > 1e-3 + 10 * noise)
    throw InvalidInput("samples", std::to_string(c.size()) + " samples",
                       "do not lie on one circle of the carrier frame (off-plane " + number_text(noise) + ", spread " +
                           number_text(spread) + ", normal x " + number_text(m.x()) + ")",
                       "a timed trace of one gear train: t, P(t)");
  const double a2 = std::atan2(-m.y(), m.z());
  if (!carrier_twist_in_range(a2))
    throw InvalidInput("samples", std::to_string(c.size()) + " samples",
                       "lie on a circle about the sun axis (a2 = " + number_text(a2) +
                           "): no gear train of a2 in [1e-6, pi - 1e-6] draws them",
                       "a timed trace of one gear train: t, P(t)");
  check_resolution(std::sin(std::acos(d)), noise);
  return {a2, std::acos(d), noise};
}

/// Step 3: the line u = slope t + intercept through the unwrapped planet angles, and the
/// standard error of its slope. Throws when consecutive angles jump by more than 3/4 of pi.
struct Line {
  double slope, slope_error, intercept;
};

inline Line planet_angle_line(const std::vector<double>& t, const std::vector<double>& u_wrapped) {
  std::vector<double> u(u_wrapped.size());
  u[0] = u_wrapped[0];
  for (std::size_t i = 1; i < u.size(); ++i) {
    const double step = wrap(u_wrapped[i] - u_wrapped[i - 1]);
    if (std::abs(step) > 0.75 * Constants<double>::pi())
      throw InvalidInput("samples", "samples " + std::to_string(i - 1) + ", " + std::to_string(i),
                         "too far apart to follow the planet (its angle turns by " + number_text(step) + " rad)",
                         "samples dense enough that the planet turns by less than 3pi/4 between two");
    u[i] = u[i - 1] + step;
  }
  const double n = static_cast<double>(t.size());
  double mt = 0, mu = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    mt += t[i];
    mu += u[i];
  }
  mt /= n;
  mu /= n;
  double stt = 0, stu = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    stt += (t[i] - mt) * (t[i] - mt);
    stu += (t[i] - mt) * (u[i] - mu);
  }
  const double slope = stu / stt, intercept = mu - slope * mt;
  double sse = 0;
  for (std::size_t i = 0; i < t.size(); ++i) sse += std::pow(u[i] - (slope * t[i] + intercept), 2);
  return {slope, std::sqrt(sse / std::max(1.0, n - 2) / stt), intercept};
}

/// Step 4: Gauss–Newton on x = (a2, a3, phase) with n fixed, on the normal equations (3 x 3)
/// with the analytic Jacobian of P(t) = Rz(t) C(u); returns the polished x. Stops when a step
/// is below 1e-14 rad or after 12 steps.
inline Eigen::Vector3d polish(const std::vector<double>& t, const std::vector<Vector3d>& p, double n, Eigen::Vector3d x) {
  for (int it = 0; it < 12; ++it) {
    const double s2 = std::sin(x(0)), c2 = std::cos(x(0)), s3 = std::sin(x(1)), c3 = std::cos(x(1));
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double u = n * t[i] + x(2), su = std::sin(u), cu = std::cos(u);
      const Eigen::Matrix3d rz = Eigen::AngleAxisd(t[i], Vector3d::UnitZ()).toRotationMatrix();
      const Vector3d c(s3 * su, -(s3 * c2 * cu + c3 * s2), c2 * c3 - s2 * s3 * cu);
      Eigen::Matrix3d j;
      j.col(0) = rz * Vector3d(0, s3 * s2 * cu - c3 * c2, -s2 * c3 - c2 * s3 * cu);  // d/da2
      j.col(1) = rz * Vector3d(c3 * su, -(c3 * c2 * cu - s3 * s2), -c2 * s3 - s2 * c3 * cu);  // d/da3
      j.col(2) = rz * Vector3d(s3 * cu, s3 * c2 * su, s2 * s3 * su);  // d/dphase
      const Vector3d r = rz * c - p[i];
      jtj += j.transpose() * j;
      jtr += j.transpose() * r;
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    if (!step.allFinite()) break;
    x += step;
    if (step.norm() < 1e-14) break;
  }
  return x;
}

}  // namespace identify_detail

namespace identify_detail {

/// The simplest fraction (p, q) in [a, b], 0 < a <= b, by continued fractions: the integer
/// ceil(a) when it is <= b, else floor(a) + 1 / (the simplest fraction in [1/(b - f), 1/(a - f)]).
inline std::optional<std::pair<double, double>> simplest_positive(double a, double b, double max_q, int depth) {
  if (depth > 64) return std::nullopt;
  const double c = std::ceil(a);
  if (c <= b) return std::make_pair(c, 1.0);
  const double f = std::floor(a);
  const auto r = simplest_positive(1 / (b - f), 1 / (a - f), max_q, depth + 1);
  if (!r || r->first > max_q) return std::nullopt;
  return std::make_pair(f * r->first + r->second, r->first);  // f + q/p
}

}  // namespace identify_detail

inline std::optional<Ratio> simplest_fraction(double lo, double hi, std::int64_t max_q) {
  if (!(lo <= hi) || (lo <= 0 && hi >= 0)) return std::nullopt;  // n = 0 is no gear ratio
  const bool negative = hi < 0;
  const auto r = identify_detail::simplest_positive(negative ? -hi : lo, negative ? -lo : hi,
                                                    static_cast<double>(max_q), 0);
  if (!r || r->second > static_cast<double>(max_q) || r->first > static_cast<double>(Ratio::kMaxTerm)) return std::nullopt;
  const auto p = static_cast<std::int64_t>(r->first), q = static_cast<std::int64_t>(r->second);
  return Ratio(negative ? -p : p, q);
}

namespace identify_detail {

/// Half the window the ratio is looked for in around the fitted slope: 8 standard errors, and
/// at least the planet angles' systematic error over the samples' span T (the points' rounding
/// and the fitted circle's, ~5e-14 at most measured, over the circle's radius sin a3: 1e-12 /
/// (sin a3 T), 20x margin; a3 = 2e-4, n = 1/7 gave a slope 5.7e-12 off; at most 1e-8, far below
/// the 1e-6 that separates fractions with q <= 1000: on a circle too small for that, no fraction
/// may fit, or one that does is refused by the rms check after the polish), and 1e-12 relative.
inline double slope_window(const Line& line, const Circle& circle, const std::vector<double>& t) {
  const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
  const double span = std::max(*hi - *lo, 1e-300);
  const double rounding = std::min(1e-8, 1e-12 / (std::max(std::sin(circle.a3), 1e-300) * span));
  return std::max({8 * line.slope_error, 1e-12 * std::max(1.0, std::abs(line.slope)), rounding});
}

}  // namespace identify_detail

inline Identified identify(const std::vector<double>& t, const std::vector<Vector3d>& points,
                           const IdentifyOptions& options) {
  using namespace identify_detail;
  if (options.max_p < 1 || options.max_p > Ratio::kMaxTerm || options.max_q < 1 || options.max_q > Ratio::kMaxTerm)
    throw InvalidInput("max_terms", std::to_string(options.max_p) + "/" + std::to_string(options.max_q),
                       "outside the valid range", "1 .. 1000000 for |p| and q");
  check_inputs(t, points);
  std::vector<Vector3d> c(points.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    c[i] = Eigen::AngleAxisd(-t[i], Vector3d::UnitZ()) * points[i].normalized();
  const Circle circle = planet_circle(c);
  std::vector<double> u(c.size());
  const Eigen::AngleAxisd undo_a2(-circle.a2, Vector3d::UnitX());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vector3d d = undo_a2 * c[i];
    u[i] = std::atan2(d.x(), -d.y());
  }
  const Line line = planet_angle_line(t, u);
  const double width = slope_window(line, circle, t);
  const std::optional<Ratio> n = simplest_fraction(line.slope - width, line.slope + width, options.max_q);
  if (!n || n->abs_p() > options.max_p)
    throw InvalidInput("samples", "slope " + number_text(line.slope) + " +- " + number_text(width),
                       "do not determine n: no fraction p/q within the bounds fits the planet's turning",
                       "|p| <= " + std::to_string(options.max_p) + ", q <= " + std::to_string(options.max_q) +
                           ", and samples over at least one period");
  // The phase with n fixed: the circular mean of u_i - n t_i.
  double sx = 0, sy = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    sx += std::cos(u[i] - n->value() * t[i]);
    sy += std::sin(u[i] - n->value() * t[i]);
  }
  const Eigen::Vector3d x = polish(t, points, n->value(), Eigen::Vector3d(circle.a2, circle.a3, std::atan2(sy, sx)));
  Identified out;
  try {
    out.train = GearTrain(x(0), x(1), *n, wrap(x(2)));
  } catch (const InvalidInput& e) {  // the polish left the gear trains: the samples' problem, not a typed a2
    throw InvalidInput("samples", std::to_string(t.size()) + " samples",
                       "the best fit of n = " + n->str() + " is no gear train (" + e.field() + " = " + e.value() + ")",
                       "a timed trace of one gear train: t, P(t)");
  }
  out.noise = circle.noise;
  out.slope = line.slope;
  out.slope_error = line.slope_error;
  double sum = 0, steps = 0;
  Vector3d previous = Vector3d::Zero();
  for (std::size_t i = 0; i < t.size(); ++i) {
    const Vector3d r = model_point(t[i], x(0), x(1), n->value(), x(2)) - points[i];
    out.residual = std::max(out.residual, r.norm());
    sum += r.squaredNorm();
    if (i > 0) steps += (r - previous).squaredNorm();
    previous = r;
  }
  out.rms = std::sqrt(sum / static_cast<double>(t.size()));
  const double scatter = std::sqrt(steps / (2.0 * static_cast<double>(t.size() - 1)));
  if (!(out.rms <= accepted_rms(circle.noise)))
    throw InvalidInput("samples", "rms " + number_text(out.rms), "no train of n = " + n->str() + " fits them",
                       "a timed trace of one gear train, noise below the fit (rms <= max(1e-6, 10 x noise))");
  if (out.rms > kIdentifyTolerance && !(out.rms <= kSystematicRatio * scatter))
    throw InvalidInput("samples", "rms " + number_text(out.rms),
                       "the best train of n = " + n->str() + " misses them systematically (the residual's point-to-point "
                           "scatter is only " + number_text(scatter) + "): not one gear train, e.g. two trains mixed",
                       "a timed trace of one gear train, its residual noise-like (rms <= 3 x scatter) or below 1e-6");
  return out;
}

}  // namespace sphtroch
