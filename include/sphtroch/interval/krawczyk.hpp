// sphtroch/interval/krawczyk.hpp — the one Krawczyk step of every certified solver (root
// isolation: precision points, free axis; the chain census, its tangencies and its events; node
// tolerance), with what surrounds it: boxes, the midpoint inverse, Newton's correction in
// doubles, epsilon-inflation and the contraction test of a uniqueness region.
//
//   sphtroch::RoundingGuard upward;                                   // REQUIRED for the step
//   // F(x) = (x0^2 - 2, x1 - x0) on X = [1.4, 1.5] x [1.3, 1.6]; y its centre
//   const sphtroch::IntervalBox<2> x{sphtroch::Interval(1.4, 1.5), sphtroch::Interval(1.3, 1.6)};
//   const sphtroch::PointN<2> y = sphtroch::centre(x);
//   const sphtroch::IntervalBox<2> fy{sphtroch::Interval(y[0]) * y[0] - 2.0, sphtroch::Interval(y[1]) - y[0]};
//   const sphtroch::IntervalMatrix<2> jx{{{2.0 * x[0], sphtroch::Interval(0.0)}, {sphtroch::Interval(-1.0), sphtroch::Interval(1.0)}}};
//   const auto inverse = sphtroch::midpoint_inverse<2>(sphtroch::midpoint(jx));
//   const sphtroch::KrawczykStep<2> k = sphtroch::krawczyk_step(x, y, fy, jx, *inverse);
//   k.verdict;   // KrawczykVerdict::unique: exactly one root (sqrt 2, sqrt 2) in X, and in k.box
//
// The step (Krawczyk 1969; Moore, Kearfott & Cloud, Introduction to Interval Analysis, 2009, 8.2):
// for a box X, a point y in X, F(y) enclosed, J(X) enclosing the Jacobian of F over X and any
// real matrix Y (the better Y ~ J(y)^-1, the sharper the step),
//   K(X) = y - Y F(y) + (I - Y J(X)) (X - y)
// holds every root of F in X. Hence: K(X) disjoint from X proves no root in X (verdict none);
// K(X) in the interior of X proves exactly one root in X, inside K(X) (unique); otherwise X
// intersected with K(X) holds every root of X (narrowed). Each row is computed in the order
// y_r - sum_m Y_rm F_m + sum_c (delta_rc - sum_m Y_rm J_mc)(X_c - y_c), outward rounded.
// REQUIRES: the rounding mode upward while the step runs (hold a RoundingGuard); y exact doubles.
// Errors: every verdict is proved whatever Y is (a poor Y only leaves boxes narrowed, never
// wrong); a singular midpoint (no inverse) gives no step: the caller bisects.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/interval/krawczyk.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/interval/interval.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

namespace sphtroch {

/// A box: one interval per unknown.
template <std::size_t N>
using IntervalBox = std::array<Interval, N>;
/// A point: one double per unknown.
template <std::size_t N>
using PointN = std::array<double, N>;
/// A Jacobian enclosed over a box: J[row][column], row an equation, column an unknown.
template <std::size_t N>
using IntervalMatrix = std::array<std::array<Interval, N>, N>;
/// A real N x N matrix (the midpoint inverse Y).
template <std::size_t N>
using DoubleMatrix = Eigen::Matrix<double, int(N), int(N)>;
/// A real N-vector (a Newton correction).
template <std::size_t N>
using DoubleVector = Eigen::Matrix<double, int(N), 1>;

/// The centre of a box (each coordinate a double inside its interval).
template <std::size_t N>
PointN<N> centre(const IntervalBox<N>& x) {
  PointN<N> y{};
  for (std::size_t k = 0; k < N; ++k) y[k] = 0.5 * (x[k].inf() + x[k].sup());
  return y;
}

/// The point y as a box of point intervals.
template <std::size_t N>
IntervalBox<N> point_box(const PointN<N>& y) {
  IntervalBox<N> b;
  for (std::size_t k = 0; k < N; ++k) b[k] = Interval(y[k]);
  return b;
}

/// The box y +- r: coordinate k spans y_k +- r max(1, |y_k|) when `relative`, y_k +- r otherwise.
template <std::size_t N>
IntervalBox<N> box_about(const PointN<N>& y, double r, bool relative) {
  IntervalBox<N> b;
  for (std::size_t k = 0; k < N; ++k) {
    const double rk = relative ? r * std::max(1.0, std::fabs(y[k])) : r;
    b[k] = Interval(y[k] - rk, y[k] + rk);
  }
  return b;
}

/// The widest side of a box.
template <std::size_t N>
double box_width(const IntervalBox<N>& x) {
  double w = 0;
  for (std::size_t k = 0; k < N; ++k) w = std::max(w, x[k].sup() - x[k].inf());
  return w;
}

/// The matrix of the interval matrix's midpoints.
template <std::size_t N>
DoubleMatrix<N> midpoint(const IntervalMatrix<N>& j) {
  DoubleMatrix<N> m;
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t c = 0; c < N; ++c) m(int(r), int(c)) = 0.5 * (j[r][c].inf() + j[r][c].sup());
  return m;
}

/// A real matrix from a double Jacobian J[row][column].
template <std::size_t N>
DoubleMatrix<N> to_matrix(const std::array<std::array<double, N>, N>& j) {
  DoubleMatrix<N> m;
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t c = 0; c < N; ++c) m(int(r), int(c)) = j[r][c];
  return m;
}

/// Y ~ m^-1 in doubles (LU with partial pivoting): the Krawczyk step's preconditioner. Nothing
/// when m is singular or the inverse not finite, or when |det m| <= min_relative_determinant *
/// (max |m_rc|)^N (a caller's floor for near-singular midpoints, whose steps cannot decide).
/// Any Y keeps the step valid: this is an estimate, in the caller's rounding mode.
template <std::size_t N>
std::optional<DoubleMatrix<N>> midpoint_inverse(const DoubleMatrix<N>& m, double min_relative_determinant = 0) {
  const Eigen::PartialPivLU<DoubleMatrix<N>> lu(m);
  const double det = lu.determinant();
  if (!(det != 0.0)) return std::nullopt;
  if (min_relative_determinant > 0) {
    const double scale = m.cwiseAbs().maxCoeff();
    if (!(std::fabs(det) > min_relative_determinant * std::pow(scale, double(N)))) return std::nullopt;
  }
  const DoubleMatrix<N> inverse = lu.inverse();
  if (!inverse.allFinite()) return std::nullopt;
  return inverse;
}

/// Newton's correction J^-1 F at a point, in doubles (partial pivoting): x - correction is the
/// next iterate. Non-finite when J is singular; a poor step on a near-singular J is only a poor
/// start for the interval test, never a wrong verdict.
template <std::size_t N>
DoubleVector<N> newton_correction(const DoubleMatrix<N>& j, const DoubleVector<N>& f) {
  return j.partialPivLu().solve(f);
}

enum class KrawczykVerdict {
  none,      // K(X) misses X: no root in X
  unique,    // K(X) in the interior of X: exactly one root in X, and it lies in K(X)
  narrowed,  // neither: X intersected with K(X) holds every root of X
};

/// The step's outcome and its box: K(X) (unique), X intersected with K(X) (narrowed), X (none).
template <std::size_t N>
struct KrawczykStep {
  KrawczykVerdict verdict = KrawczykVerdict::narrowed;
  IntervalBox<N> box;
};

/// The Krawczyk step on X about y (see header). fy encloses F(y); jx encloses J over X; y_inverse
/// is any real matrix (midpoint_inverse of J at y or of mid J(X)). REQUIRES rounding upward.
template <std::size_t N>
KrawczykStep<N> krawczyk_step(const IntervalBox<N>& x, const PointN<N>& y, const IntervalBox<N>& fy, const IntervalMatrix<N>& jx,
                              const DoubleMatrix<N>& y_inverse) {
  KrawczykStep<N> out;
  out.box = x;
  IntervalBox<N> k;
  bool inside = true;
  for (std::size_t r = 0; r < N; ++r) {
    Interval s(y[r]);
    for (std::size_t m = 0; m < N; ++m) s -= y_inverse(int(r), int(m)) * fy[m];
    for (std::size_t c = 0; c < N; ++c) {
      Interval a(r == c ? 1.0 : 0.0);
      for (std::size_t m = 0; m < N; ++m) a -= y_inverse(int(r), int(m)) * jx[m][c];
      s += a * (x[c] - y[c]);
    }
    if (s.sup() < x[r].inf() || s.inf() > x[r].sup()) {
      out.verdict = KrawczykVerdict::none;
      return out;
    }
    inside = inside && s.inf() > x[r].inf() && s.sup() < x[r].sup();
    k[r] = s;
  }
  if (inside) {
    out.verdict = KrawczykVerdict::unique;
    out.box = k;
    return out;
  }
  for (std::size_t r = 0; r < N; ++r) out.box[r] = Interval(std::max(x[r].inf(), k[r].inf()), std::min(x[r].sup(), k[r].sup()));
  return out;
}

/// Whether ||I - Y J(U)||_inf < 1 (J enclosed over the box U, Y any real matrix): then F has at
/// most one root in U (the mean value theorem makes x -> x - Y F(x) a contraction there), so a
/// root proved inside U is the only one in all of U. REQUIRES rounding upward; the row sums are
/// intervals, an upper bound in any rounding mode.
template <std::size_t N>
bool contracts(const DoubleMatrix<N>& y_inverse, const IntervalMatrix<N>& ju) {
  for (std::size_t r = 0; r < N; ++r) {
    Interval row(0.0);
    for (std::size_t c = 0; c < N; ++c) {
      Interval a(r == c ? 1.0 : 0.0);
      for (std::size_t m = 0; m < N; ++m) a -= y_inverse(int(r), int(m)) * ju[m][c];
      row += Interval(-a.inf() > a.sup() ? -a.inf() : a.sup());  // a NaN end stays NaN: then not < 1
    }
    if (!(row.sup() < 1.0)) return false;
  }
  return true;
}

/// Epsilon-inflation about a point found by Newton: the radii r = first, first * factor, ... while
/// r >= last (0 < factor < 1), each handed to `prove(r)`, which tests the box about the point of
/// radius r and returns a std::optional; the first proof, or nothing when every radius failed.
/// (A root is proved in a box of some radius once the box is small enough for J to vary little
/// and wide enough to hold the root with Newton's and the rounding's error.)
/// A first radius that is not finite, a floor not above 0 or a factor outside (0, 1) tries nothing.
template <class Prove>
auto epsilon_inflation(double first, double factor, double last, const Prove& prove) -> decltype(prove(first)) {
  if (!std::isfinite(first) || !(last > 0) || !(factor > 0 && factor < 1)) return {};
  for (double r = first; r >= last; r *= factor)
    if (auto proof = prove(r)) return proof;
  return {};
}

}  // namespace sphtroch
