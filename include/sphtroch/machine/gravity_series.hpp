// sphtroch/machine/gravity_series.hpp — a clinostat's gravity as a finite trigonometric series in
// time, its period, and its mean over any window in closed form.
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::GravitySeries g = sphtroch::GravitySeries::of_gravity(sphtroch::Clinostat(s));
//   g.period_s();                 // 6000: both frames are back after 100 min
//   g.window_mean(0.0, 600.0);    // the mean of g_s over [0 s, 600 s], units of g0
//   g.period_mean();              // the mean over a period: 0 for perpendicular axes
//
// g_s = R^T (0, 0, -1) is a trigonometric polynomial of degree 1 in each frame angle (phi_o, phi_i);
// the effective gravity of an off-centre sample adds terms of degree 2 in phi_i. So
//   f(t) = c0 + sum_k (a_k cos th_k(t) + b_k sin th_k(t)),  th_k = j_k phi_o(t) + l_k phi_i(t),
// with |j| <= 1, |l| <= 2. The vector coefficients are the exact discrete Fourier transform of
// f on a 5 x 5 grid of angles (exact for these degrees, up to rounding ~1e-16; parts below
// 1e-15, which are that rounding, are set to 0 so that an exact 0 reads as 0). A harmonic's
// frequency j w_o + l w_i is an exact rational; one that is exactly 0 (a resonance such as
// w_o = w_i) is constant in time and belongs to the mean over a period. The window mean is
//   mean(t0, W) = c + sum_{k oscillating} (a_k cos th_k(tm) + b_k sin th_k(tm)) sinc(W_k W / 2),
// tm = t0 + W / 2, W_k = 2 pi (j w_o + l w_i) / 60 rad/s: exact in closed form; rounding ~1e-15.
// Period: the smallest T > 0 at which every harmonic present is back, 60 / gcd of their
// frequencies (rpm, exact). Which harmonics are present is decided from the typed angles exactly:
// no outer harmonic when the outer axis is vertical, only the combined angle phi_o +- phi_i when
// the axes are parallel; constant gravity (no period) when nothing turns it.
#pragma once

#include "sphtroch/core/portable_trig.hpp"
#include "sphtroch/machine/clinostat.hpp"

#include <algorithm>
#include <complex>
#include <cstdlib>
#include <limits>
#include <optional>
#include <vector>

namespace sphtroch {

/// One oscillating term a cos th + b sin th, th = j phi_o + l phi_i.
/// max over th of |a cos th + b sin th|: the square root of the larger eigenvalue of the Gram
/// matrix [[a.a, a.b], [a.b, b.b]], rounded up by 1e-14 relative (its own rounding is ~1e-16).
inline double semi_major_axis(const Vector3d& a, const Vector3d& b) {
  const double aa = a.squaredNorm(), bb = b.squaredNorm(), ab = a.dot(b);
  const double half_difference = (aa - bb) / 2;
  return std::sqrt((aa + bb) / 2 + std::sqrt(half_difference * half_difference + ab * ab)) * (1 + 1e-14);
}

/// sin and cos of j x + l y, |j| <= 1, |l| <= 2 (the harmonics' angles), from one sin_cos_pair
/// by angle addition and doubling: within a few ulp of sin_cos(j x + l y), as that is of the
/// exact value (the callers' rounding allowances, 1e-14 relative, cover both).
class HarmonicAngles {
 public:
  HarmonicAngles(double x, double y) {
    const SinCosPair<double> p = sin_cos_pair(x, y);
    x_ = p.first;
    y_[1] = p.second;
    y_[2] = {2 * p.second.sin * p.second.cos, (p.second.cos - p.second.sin) * (p.second.cos + p.second.sin)};
  }
  SinCos<double> of(int j, int l) const {
    const SinCos<double> a = j == 0 ? SinCos<double>{0, 1} : SinCos<double>{j * x_.sin, x_.cos};
    const SinCos<double> y = y_[std::abs(l)];
    const SinCos<double> b{l < 0 ? -y.sin : y.sin, y.cos};
    return {a.sin * b.cos + a.cos * b.sin, a.cos * b.cos - a.sin * b.sin};
  }

 private:
  SinCos<double> x_{0, 1};
  SinCos<double> y_[3] = {{0, 1}, {0, 1}, {0, 1}};
};

struct GravityHarmonic {
  int j = 0, l = 0;
  Rpm::Frequency frequency{0, 1};  ///< j w_o + l w_i, rpm, exact
  double omega = 0;                ///< the same in rad/s
  Vector3d a = Vector3d::Zero(), b = Vector3d::Zero();
  double amplitude = 0;            ///< max over th of |a cos th + b sin th| (the ellipse's semi-major axis), rounded up
};

class GravitySeries {
 public:
  /// G g_s of the machine (G: the environment's gravity, settings' gravity_g0, 1 by default).
  static GravitySeries of_gravity(const Clinostat& m) { return GravitySeries(m, false); }
  /// The effective gravity of its sample point (g_s when the offset is 0).
  static GravitySeries of_effective_gravity(const Clinostat& m) { return GravitySeries(m, true); }

  const Clinostat& machine() const noexcept { return m_; }
  /// The terms that move, each with a non-zero exact frequency.
  const std::vector<GravityHarmonic>& oscillating() const noexcept { return terms_; }
  /// The mean over a period: the constant term and every harmonic of frequency exactly 0.
  const Vector3d& period_mean() const noexcept { return constant_; }
  /// The period in seconds, empty when the gravity does not move at all.
  const std::optional<double>& period_s() const noexcept { return period_s_; }
  /// A bound on |f(t)| for every t: G for G g_s (g_s a unit vector; so every window mean too),
  /// none (infinity) for the effective gravity of an off-centre sample.
  double norm_bound() const noexcept { return unit_ ? m_.settings().gravity_g0 : std::numeric_limits<double>::infinity(); }
  /// The period in minutes as an exact fraction (num / den); {0, 1} without a period.
  std::pair<__int128, __int128> period_minutes() const noexcept { return period_minutes_; }

  /// f(t) from the series (equal to G gravity(t) / effective_gravity(t) within ~1e-15 G).
  Vector3d value(double t) const { return centred_mean(t, 0.0, 0.0); }

  /// The mean of f over [t0, t0 + W]. REQUIRES W >= 0 (W = 0: f(t0)).
  Vector3d window_mean(double t0, double w) const { return centred_mean(t0, w / 2, w); }

  /// The mean over the window of length W centred at t + dt (the angles of t and dt are added, so t + dt is never rounded).
  Vector3d centred_mean(double t, double dt, double w) const {
    const HarmonicAngles angles(m_.outer_angle(t, dt), m_.inner_angle(t, dt));
    Vector3d sum = constant_;
    for (const GravityHarmonic& h : terms_) {
      const SinCos<double> th = angles.of(h.j, h.l);
      sum += (h.a * th.cos + h.b * th.sin) * sinc(h.omega * w / 2);
    }
    return sum;
  }

  /// sin(x) / x, 1 at 0 (series below 1e-4: error < 1e-17).
  static double sinc(double x) {
    if (std::fabs(x) < 1e-4) return 1 - x * x / 6;
    return sin_cos(x).sin / x;
  }

 private:
  GravitySeries(const Clinostat& m, bool effective) : m_(m), unit_(!(effective && m.has_offset())) {
    const int kGrid = 5;  // resolves |j|, |l| <= 2
    const double step = 2 * Constants<double>::pi() / kGrid;
    std::complex<double> coeff[kGrid][kGrid][3] = {};
    double largest = 0;  // max |f| on the grid: the transform's rounding is ~1e-16 of it
    for (int x = 0; x < kGrid; ++x)
      for (int y = 0; y < kGrid; ++y) {
        const Vector3d f = effective ? m.effective_gravity_at(x * step, y * step) : m.settings().gravity_g0 * m.gravity_at(x * step, y * step);
        largest = std::max(largest, f.norm());
        for (int j = 0; j < kGrid; ++j)
          for (int l = 0; l < kGrid; ++l) {
            // polar(1/25, angle) with portable_trig.hpp's sines: the same bits natively and in the explorer
            const SinCos<double> sc = sin_cos(-step * (j * x + l * y));
            const double r = 1.0 / (kGrid * kGrid);
            const std::complex<double> e(r * sc.cos, r * sc.sin);
            for (int c = 0; c < 3; ++c) coeff[j][l][c] += f[c] * e;
          }
      }
    const double kRoundingZero = 1e-15 * largest;
    const auto at = [&](int j, int l) {  // the coefficient of exp(i (j phi_o + l phi_i)), any sign
      const int jj = (j + kGrid) % kGrid, ll = (l + kGrid) % kGrid;
      Eigen::Vector3cd c(coeff[jj][ll][0], coeff[jj][ll][1], coeff[jj][ll][2]);
      for (int k = 0; k < 3; ++k)  // parts within the transform's rounding of 0 are 0
        c[k] = {std::fabs(c[k].real()) < kRoundingZero ? 0.0 : c[k].real(), std::fabs(c[k].imag()) < kRoundingZero ? 0.0 : c[k].imag()};
      return c;
    };
    constant_ = at(0, 0).real();
    // One of each pair +-(j, l): j = 1 with any l, or j = 0 with l > 0; |l| <= 2 only with an offset.
    const int degree = effective && m.has_offset() ? 2 : 1;
    for (int j = 0; j <= 1; ++j)
      for (int l = (j == 0 ? 1 : -degree); l <= degree; ++l) {
        if (!present(j, l)) continue;
        const Eigen::Vector3cd c = at(j, l);
        GravityHarmonic h;
        h.j = j;
        h.l = l;
        h.a = 2 * c.real();
        h.b = -2 * c.imag();
        h.frequency = Rpm::frequency(j, m.settings().outer, l, m.settings().inner);
        h.omega = 2 * Constants<double>::pi() * h.frequency.value() / 60;
        h.amplitude = semi_major_axis(h.a, h.b);
        if (h.frequency.is_zero()) {
          const SinCos<double> th = sin_cos(j * m.outer_angle(0) + l * m.inner_angle(0));
          constant_ += h.a * th.cos + h.b * th.sin;  // a resonance: constant in time
        } else {
          add_term(fold_still_frame(h, m));
        }
      }
    if (std::all_of(terms_.begin(), terms_.end(), [&](const GravityHarmonic& h) { return h.amplitude <= kRoundingZero; })) {
      terms_.clear();  // nothing moves: the mean is the gravity itself, exactly
      constant_ = (effective ? m.effective_gravity(0.0) : m.settings().gravity_g0 * m.gravity(0.0)) + Vector3d::Zero();  // + 0: no -0
    }
    set_period();
  }

  /// A term of a machine with one frame still (speed 0) written in the turning frame's angle
  /// alone: a cos(th' + d) + b sin(th' + d) = (a cos d + b sin d) cos th' + (b cos d - a sin d)
  /// sin th', d the still frame's part of th (its angle is constant); a negative multiple of the
  /// turning angle flips b. Terms of both frames turning are returned as they are.
  static GravityHarmonic fold_still_frame(GravityHarmonic h, const Clinostat& m) {
    const bool outer_still = m.settings().outer.is_zero(), inner_still = m.settings().inner.is_zero();
    if (!(outer_still && h.j != 0) && !(inner_still && h.l != 0)) return h;
    const SinCos<double> d = sin_cos(outer_still ? h.j * m.outer_angle(0) : h.l * m.inner_angle(0));
    const Vector3d a = h.a * d.cos + h.b * d.sin, b = h.b * d.cos - h.a * d.sin;
    const int sign = outer_still && h.l < 0 ? -1 : 1;
    h.a = a, h.b = sign * b;
    if (outer_still) h.j = 0, h.l = std::abs(h.l);
    else h.l = 0;
    h.frequency = Rpm::frequency(h.j, m.settings().outer, h.l, m.settings().inner);
    h.omega = 2 * Constants<double>::pi() * h.frequency.value() / 60;
    h.amplitude = semi_major_axis(h.a, h.b);
    return h;
  }

  /// Adds a term, or merges it into the term of the same (j, l) (a still frame's folded terms).
  void add_term(const GravityHarmonic& h) {
    for (GravityHarmonic& t : terms_)
      if (t.j == h.j && t.l == h.l) {
        t.a += h.a, t.b += h.b;
        t.amplitude = semi_major_axis(t.a, t.b);
        return;
      }
    terms_.push_back(h);
  }

  /// Whether harmonic (j, l) can be non-zero, from the typed angles (header).
  bool present(int j, int l) const {
    if (!m_.turns_with_outer() && j != 0) return false;
    if (m_.axes_parallel()) {
      const int s = m_.frame_angle().cos > 0 ? 1 : -1;  // v = +-u: R = Rot(u, phi_o +- phi_i)
      return l == s * j && j != 0;
    }
    return true;
  }

  void set_period() {
    // gcd of the frequencies present (rationals over a common denominator).
    __int128 num = 0, den = 1;
    for (const GravityHarmonic& h : terms_) {
      const __int128 d = lcm(den, h.frequency.den);
      num = gcd(num * (d / den), absolute(h.frequency.num) * (d / h.frequency.den));
      den = d;
      const __int128 g = gcd(num, den);
      num /= g;
      den /= g;
    }
    if (num == 0) return;  // nothing moves
    period_minutes_ = {den, num};
    period_s_ = 60.0 * static_cast<double>(den) / static_cast<double>(num);
  }
  static __int128 absolute(__int128 x) { return x < 0 ? -x : x; }
  static __int128 gcd(__int128 a, __int128 b) {
    a = absolute(a);
    b = absolute(b);
    while (b != 0) {
      const __int128 r = a % b;
      a = b;
      b = r;
    }
    return a;
  }
  static __int128 lcm(__int128 a, __int128 b) { return a / gcd(a, b) * b; }

  Clinostat m_;
  bool unit_ = true;  // f is g_s, a unit vector
  Vector3d constant_ = Vector3d::Zero();
  std::vector<GravityHarmonic> terms_;
  std::optional<double> period_s_;
  std::pair<__int128, __int128> period_minutes_{0, 1};
};

}  // namespace sphtroch
