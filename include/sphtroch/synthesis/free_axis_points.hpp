// sphtroch/synthesis/free_axis_points.hpp — every gear train of ratio n whose tracer passes through
// five given points when the sun axis may be placed anywhere (free axis), certified.
//
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   std::vector<sphtroch::Vector3d> pts;   // five points of the curve, any rotation of it
//   for (double t : {0.5, 2.0, 4.0, 7.0, 10.0}) pts.push_back(curve.point(t));
//   sphtroch::PrecisionPoints r = sphtroch::free_axis_points(pts, sphtroch::Ratio(1, 2));
//   r.solutions[0].frame;      // columns x, y, z of the train's frame (z: the sun axis)
//   r.solutions[0].train;      // a2, a3, n, phase in that frame
//
// Unknowns (derivation ours, from Eqs. 3 and 4). The tracer is P(theta) = R_s(theta) R_w0(n theta +
// theta_p) v (s: sun axis, w0: planet axis at theta = 0, R_a(t): the rotation by t about a). With
// w the planet axis at point 1 and Delta_i = theta_i - theta_1, the points satisfy
//     A_i = R_w(n Delta_i) P_1 = R_s(-Delta_i) P_i = B_i      (i = 2..5),
// eight equations (two per unit-vector equation) in the eight unknowns s, w (unit vectors, two
// each) and Delta_2..Delta_5 in [0, 2 pi q]: no arccos, nothing folds. a2 = angle(s, w), a3 =
// angle(w, P_1). s and w are charted by cube faces: a = c / |c| with c = +-e_f + u e_(f+1) + v
// e_(f+2), u, v in [-1 - 1/512, 1 + 1/512]: every axis has |u|, |v| <= 1 on the face of its
// largest component, so each root lies inside some face pair's domain, off its edges (boxes
// wholly outside [-1, 1] are dropped: those roots are another face pair's). (s, w, Delta) and
// (-s, -w, -Delta) are the same motion (the same train seen with the sun axis reversed: a3
// becomes pi - a3), so s takes the three faces +x, +y, +z and w all six.
// Of A_i - B_i, the component k where |A_i| is largest over a box is dropped (`chart`): the other
// two vanish at every root, and its mirror roots (A_ik = -B_ik) are dropped by solution().
// Point 1 is the reference of free_axis_detail::reference_point (chosen from the points'
// geometry, not their order); params are reported in input order.
//
// Certificate: the branch and bound of root_isolation.hpp over the 18 face pairs (outer unknowns
// s, w; one list per point for Delta_i), as in precision_points.hpp; besides, the four points'
// Delta-free combinations, one slab each in (s, w), drop or narrow outer boxes together
// (narrow_outer: Krawczyk's operator in the four outer unknowns). `certified` means the
// solutions are ALL the trains through the five points with a2, a3 in [1e-6, pi - 1e-6], each
// once (the sun axis up to its sign). Reported: the sun axis with its sign chosen so that z > 0
// (else y > 0, else x > 0; components within 1e-9 of 0 count as 0), the frame's x axis the
// projection of the coordinate axis least aligned with it (ties to 1e-9: X first), the phase in
// that frame. Cost: measured in bench/ and the README.
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/synthesis/free_axis_points.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/parallel_for.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/interval/interval.hpp"
#include "sphtroch/interval/interval_vector.hpp"
#include "sphtroch/interval/root_isolation.hpp"
#include "sphtroch/synthesis/precision_points.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace sphtroch {

/// All trains of ratio n through the five points, the sun axis free. Throws InvalidInput (field
/// "points") for a count other than 5, non-finite or non-unit points, or two points closer than
/// kDistinctPoints.
inline PrecisionPoints free_axis_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options = {});

// Implementation details follow.
namespace free_axis_detail {

/// {sin, cos} of one angle (interval.hpp).
template <typename T>
using SinCos = std::pair<T, T>;

template <typename T>
using Vec = Vec3<T>;  // interval_vector.hpp, with its cross and dot

inline Vec<double> of_point(const Vector3d& p) { return {p.x(), p.y(), p.z()}; }

template <typename T>
T squared(const T& x) {
  if constexpr (std::is_same_v<T, double>)
    return x * x;
  else
    return CGAL::square(x);
}
template <typename T>
T root(const T& x) {
  if constexpr (std::is_same_v<T, double>)
    return std::sqrt(x);
  else
    return CGAL::sqrt(x);
}

/// A unit axis a(u, v) = c / |c| on cube face f (c = +-e_(f mod 3) + u e_(f+1) + v e_(f+2); faces
/// 3..5 are the negative ones) and (if `derivatives`; else left unset) its partial derivatives
/// (e_k - a a_k) / |c|.
template <typename T>
struct Axis {
  Vec<T> a, du, dv;
};

template <typename T>
Axis<T> face_axis(int face, const T& u, const T& v, bool derivatives = true) {
  const int k = face % 3, ku = (k + 1) % 3, kv = (k + 2) % 3;
  const T inverse = T(1.0) / root(T(1.0) + squared(u) + squared(v));  // one division: 1 / |c|
  Axis<T> x;
  x.a[k] = face < 3 ? inverse : -inverse;
  x.a[ku] = u * inverse;
  x.a[kv] = v * inverse;
  for (int j = 0; j < 3 && derivatives; ++j) {
    x.du[j] = (T(j == ku ? 1.0 : 0.0) - x.a[j] * x.a[ku]) * inverse;
    x.dv[j] = (T(j == kv ? 1.0 : 0.0) - x.a[j] * x.a[kv]) * inverse;
  }
  return x;
}

/// R_a(t) X = c0 + c1 cos t + c2 sin t with c0 = a (a . X), c1 = X - c0, c2 = a x X, and (if
/// `derivatives`; else left unset) the derivatives of c0 and c2 along the axis's chart
/// coordinates u, v (those of c1 are -dc0).
template <typename T>
struct RotationTerms {
  Vec<T> c0, c1, c2;
  std::array<Vec<T>, 2> dc0, dc2;
};

template <typename T>
RotationTerms<T> rotation_terms(const Axis<T>& a, const Vec<double>& x, bool derivatives = true) {
  RotationTerms<T> r;
  const T ax = dot(a.a, x);
  r.c2 = cross(a.a, x);
  const Vec<T>* d[2] = {&a.du, &a.dv};
  for (int k = 0; k < 2 && derivatives; ++k) {
    const T dx = dot(*d[k], x);
    r.dc2[k] = cross(*d[k], x);
    for (int j = 0; j < 3; ++j) r.dc0[k][j] = (*d[k])[j] * ax + a.a[j] * dx;
  }
  for (int j = 0; j < 3; ++j) {
    r.c0[j] = a.a[j] * ax;
    r.c1[j] = x[j] - r.c0[j];
  }
  return r;
}

/// A_i - B_i (see header) and A . B; with `jacobian` the derivatives by (s_u, s_v, w_u, w_v,
/// Delta_i). `a`: the terms of R_w P_1, `b`: those of R_s P_i; `delta` = {sin, cos} of Delta_i,
/// `n_delta` of n Delta_i. B = R_s(-Delta_i) P_i.
template <typename T>
struct PointEquations {
  Vec<T> a, e;
  T dot;
  std::array<Vec<T>, 5> de;
};

/// Component j of A (its terms a, `n_delta` = {sin, cos} of n Delta) and of B (terms b, `delta`).
template <typename T>
T a_component(const RotationTerms<T>& a, const SinCos<T>& n_delta, int j) {
  return a.c0[j] + a.c1[j] * n_delta.second + a.c2[j] * n_delta.first;
}
template <typename T>
T b_component(const RotationTerms<T>& b, const SinCos<T>& delta, int j) {
  return b.c0[j] + b.c1[j] * delta.second - b.c2[j] * delta.first;
}

/// d(A - B)_j / d(s_u, s_v, w_u, w_v, Delta) in `d`, each column from its own terms: s_u's and
/// s_v's from *b_for[0] and *b_for[1], w_u's and w_v's from *a_for[0] and *a_for[1], Delta's from
/// a_delta and b_delta (all alike for the plain gradient; see the recursive form of may_hold).
template <typename T>
void gradient_columns(const std::array<const RotationTerms<T>*, 2>& a_for, const std::array<const RotationTerms<T>*, 2>& b_for,
                      const RotationTerms<T>& a_delta, const RotationTerms<T>& b_delta, const SinCos<T>& delta,
                      const SinCos<T>& n_delta, const T& n, int j, T d[5]) {
  const T &sp = n_delta.first, &cp = n_delta.second, &sd = delta.first, &cd = delta.second;
  for (int k = 0; k < 2; ++k) {
    d[k] = b_for[k]->dc2[k][j] * sd - b_for[k]->dc0[k][j] * (T(1.0) - cd);
    d[2 + k] = a_for[k]->dc0[k][j] * (T(1.0) - cp) + a_for[k]->dc2[k][j] * sp;
  }
  d[4] = n * (a_delta.c2[j] * cp - a_delta.c1[j] * sp) + b_delta.c1[j] * sd + b_delta.c2[j] * cd;  // n w x A + s x B
}

/// d(A - B)_j / d(s_u, s_v, w_u, w_v, Delta) in `d`, every column from the same terms a, b.
template <typename T>
void component_gradient(const RotationTerms<T>& a, const RotationTerms<T>& b, const SinCos<T>& delta,
                        const SinCos<T>& n_delta, const T& n, int j, T d[5]) {
  gradient_columns<T>({&a, &a}, {&b, &b}, a, b, delta, n_delta, n, j, d);
}

/// An axis's rotation terms of one point at three nested places of an outer box, for the
/// recursive mean-value form: at the box's centre (no derivatives), over the box with the axis's
/// chart coordinate v at its centre (`half`), and over the box.
template <typename T>
struct NestedTerms {
  RotationTerms<T> centre, half, box;
};

template <typename T>
PointEquations<T> point_equations(const RotationTerms<T>& a, const RotationTerms<T>& b, const SinCos<T>& delta,
                                  const SinCos<T>& n_delta, const T& n, bool jacobian) {
  PointEquations<T> r;
  Vec<T> bv;
  for (int j = 0; j < 3; ++j) {
    r.a[j] = a_component(a, n_delta, j);
    bv[j] = b_component(b, delta, j);
    r.e[j] = r.a[j] - bv[j];
  }
  r.dot = dot(r.a, bv);
  if (!jacobian) return r;
  for (int j = 0; j < 3; ++j) {
    T d[5];
    component_gradient(a, b, delta, n_delta, n, j, d);
    for (int k = 0; k < 5; ++k) r.de[k][j] = d[k];
  }
  return r;
}

/// The component of A kept out of the equations: the one of largest magnitude over the box, if
/// it stays above 1/2 there (then a mirror root has |A_k - B_k| = 2 |A_k| > 1); else -1.
inline int dropped_component(const Vec<Interval>& a) {
  int best = -1;
  double best_mig = 0.5;
  for (int j = 0; j < 3; ++j) {
    const double mig = may_vanish(a[j]) ? 0.0 : std::min(std::fabs(a[j].inf()), std::fabs(a[j].sup()));
    if (mig > best_mig) best = j, best_mig = mig;
  }
  return best;
}

/// Components this close to 0 (or to each other) count as equal in the two rules below, so that
/// an axis along a coordinate axis or a diagonal is reported the same way whatever its rounding.
constexpr double kAxisTie = 1e-9;

/// The sun axis's sign rule of the header: z > 0, else y > 0, else x > 0 (|component| > kAxisTie).
inline bool canonical_sign(const Vector3d& s) {
  for (int k = 2; k >= 0; --k)
    if (std::fabs(s[k]) > kAxisTie) return s[k] > 0.0;
  return true;
}

/// Columns x, y, z: z = s, x the projection of the coordinate axis least aligned with s (the
/// first of X, Y, Z among those within kAxisTie of the least).
inline Eigen::Matrix3d frame_of(const Vector3d& s) {
  const double least = s.cwiseAbs().minCoeff();
  int k = 0;
  while (std::fabs(s[k]) > least + kAxisTie) ++k;
  Vector3d e = Vector3d::Zero();
  e[k] = 1.0;
  const Vector3d x = (e - e.dot(s) * s).normalized();
  Eigen::Matrix3d f;
  f.col(0) = x;
  f.col(1) = s.cross(x);
  f.col(2) = s;
  return f;
}

constexpr double kFaceOverlap = 1.0 / 512;  // any margin keeps roots off the domain edges; wider only adds boxes

/// The combination nu . (A - B) with nu = A x d(A - B)/dDelta at the box's middle, nu of unit
/// length (a: A at the box's centre; centre: A - B at the centre; gradient: the columns of its
/// derivatives by (s_u, s_v, w_u, w_v, Delta) of a mean-value form over the box, plain or
/// recursive (may_hold); dx: box - centre). nu is tangent to the sphere at A and normal
/// to Delta's direction, so Delta's coefficient is O(width): the components tested apart may
/// vanish for different Deltas, this one only near a Delta where both do. Any nu keeps it valid.
/// Its mean-value form over the box is value + sum_k coefficient_k dx_k (k: the four outer
/// unknowns; Delta's part is in value): a slab in the outer unknowns. None when nu is zero or not
/// finite (no information).
struct DeltaFreeSlab {
  Interval value;
  std::array<Interval, 4> coefficient;
};

inline std::optional<DeltaFreeSlab> delta_free_slab(const Interval a[3], const Interval centre[3], const Interval gradient[3][5],
                                                    const Interval dx[5]) {
  double am[3], dm[3];
  for (int j = 0; j < 3; ++j) am[j] = 0.5 * (a[j].inf() + a[j].sup()), dm[j] = 0.5 * (gradient[j][4].inf() + gradient[j][4].sup());
  double nu[3] = {am[1] * dm[2] - am[2] * dm[1], am[2] * dm[0] - am[0] * dm[2], am[0] * dm[1] - am[1] * dm[0]};
  const double length = std::sqrt(nu[0] * nu[0] + nu[1] * nu[1] + nu[2] * nu[2]);
  if (!(length > 0.0 && std::isfinite(length))) return std::nullopt;
  for (double& x : nu) x /= length;  // rounded: any nu will do
  const auto combined = [&](const auto& term) { return nu[0] * term(0) + nu[1] * term(1) + nu[2] * term(2); };
  DeltaFreeSlab slab;
  slab.value = combined([&](int j) { return centre[j]; }) + combined([&](int j) { return gradient[j][4]; }) * dx[4];
  for (int k = 0; k < 4; ++k) slab.coefficient[k] = combined([&](int j) { return gradient[j][k]; });
  return slab;
}

/// Delta's interval d (centre dc) narrowed by each component's interval Newton step: a root has
/// F_j(c) + sum_k g_k (x_k - c_k) + g_Delta (Delta - dc) = 0 with every g in its column of the
/// mean-value form (the gradient of delta_free_slab), so where g_Delta's column excludes 0, Delta
/// lies in dc - rest_j / G_Delta, rest_j = F_j(c) + sum_k G_k (X_k - c_k) over the outer k.
/// None when the steps leave nothing of d (no root in the box).
inline std::optional<Interval> narrowed_delta(const Interval& d, const Interval& dc, const Interval rest[3],
                                              const Interval gradient[3][5]) {
  double lo = d.inf(), hi = d.sup();
  for (int j = 0; j < 3; ++j) {
    if (may_vanish(gradient[j][4])) continue;
    const Interval step = dc - rest[j] / gradient[j][4];
    lo = std::max(lo, step.inf());
    hi = std::min(hi, step.sup());
  }
  if (!(lo <= hi)) return std::nullopt;
  return Interval(lo, hi);
}

/// The smallest interval holding x and y.
inline Interval hull(const Interval& x, const Interval& y) {
  return Interval(std::min(x.inf(), y.inf()), std::max(x.sup(), y.sup()));
}

/// x widened to hold every y' of y (each interval its hull with y's).
inline void widen_to_hold(DeltaFreeSlab& x, const DeltaFreeSlab& y) {
  x.value = hull(x.value, y.value);
  for (int k = 0; k < 4; ++k) x.coefficient[k] = hull(x.coefficient[k], y.coefficient[k]);
}

/// The point written as point 1 of the header (the reference): the one whose removal leaves the
/// largest smallest chord among the other four; on a tie (the same closest pair left), the one
/// with the smallest sum of chords to the others; then the first. Two close points, neither the
/// reference, give two nearly equal conditions that boxes tell apart only once they are about as
/// narrow as their chord; with one of them the reference, the other's condition scales with the
/// chord. (Measured: docs/cli.md, `synth points --free-axis`.)
inline std::size_t reference_point(const std::vector<Vector3d>& points) {
  const auto chord = [&](std::size_t i, std::size_t j) { return (points[i] - points[j]).norm(); };
  std::size_t best = 0;
  double best_smallest = -1.0, best_sum = 0.0;
  for (std::size_t r = 0; r < points.size(); ++r) {
    double smallest = std::numeric_limits<double>::infinity(), sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i != r) sum += chord(i, r);
      for (std::size_t j = i + 1; j < points.size(); ++j)
        if (i != r && j != r) smallest = std::min(smallest, chord(i, j));
    }
    if (smallest > best_smallest || (smallest == best_smallest && sum < best_sum))
      best = r, best_smallest = smallest, best_sum = sum;
  }
  return best;
}

}  // namespace free_axis_detail

/// The free-axis system for root_isolation.hpp on one pair of cube faces (s on face sun_face of
/// +x, +y, +z; w on planet_face of all six): outer (s_u, s_v, w_u, w_v), lists Delta_2..Delta_5.
class FreeAxisSystem {
 public:
  using Solution = PrecisionSolution;
  static constexpr int kOuter = 4, kLists = 4, N = 8;
  static constexpr double kIsolateWidth = 1.0 / 64;
  static constexpr double kContractWidth = 1.0 / 16;  // below this, Krawczyk narrows outer boxes
  static constexpr double kMeanValueWidth = 0.5;  // may_hold's mean-value forms on boxes this narrow
  // List items up to twice the outer width: may_hold narrows them (measured on the sweep's seed 7,
  // problems 0, 3, 6, 10, 12, 16: the time against no narrowing: 1x 0.78, 2x 0.74, 3x 0.75).
  static constexpr double kListWidth = 2.0;
  static constexpr double kNarrowItem = 0.7;  // an item is replaced when narrowed below this of its width
  using Outer = std::array<Interval, kOuter>;

  /// REQUIRES: five points checked by checked_precision_points.
  FreeAxisSystem(const std::vector<Vector3d>& checked, const Ratio& n, int sun_face, int planet_face)
      : ratio_(n), n_interval_(ratio_enclosure(n)), sun_face_(sun_face), planet_face_(planet_face) {
    for (int i = 0; i < 5; ++i) p_[i] = checked[i];
  }

  std::vector<Outer> domains() const {
    const Interval d(-1.0 - free_axis_detail::kFaceOverlap, 1.0 + free_axis_detail::kFaceOverlap);
    return {{d, d, d, d}};
  }
  bool outside(const Outer& x) const {
    return std::any_of(x.begin(), x.end(), [](const Interval& c) { return c.sup() < -1.0 || c.inf() > 1.0; });
  }
  double list_max() const { return 2 * Constants<double>::pi() * double(ratio_.q()); }
  double list_scale() const { return 1.0 + std::fabs(ratio_.value()); }

  /// The rotation terms of every point on an outer box (NestedTerms): a for R_w P_1, b[i] for
  /// R_s P_(i+2). For a box wider than kMeanValueWidth, only a.box and b[i].box, without
  /// derivatives.
  struct View {
    free_axis_detail::NestedTerms<Interval> a;
    std::array<free_axis_detail::NestedTerms<Interval>, kLists> b;
    Outer box, centre;
    double width;  // of the widest outer unknown
    // Noted by may_hold on boxes no wider than kMeanValueWidth: per list, the hull of the
    // Delta-free slabs of the items that passed (for narrow_outer).
    std::array<std::optional<free_axis_detail::DeltaFreeSlab>, kLists> slabs;
    bool slabs_known = true;  // false once an item's slab gave no information
  };

  View view(const Outer& x) const {
    Outer c;
    for (int k = 0; k < kOuter; ++k) c[k] = centre_of(x[k]);
    View v;
    v.box = x;
    v.centre = c;
    v.width = 0.0;
    for (const Interval& xk : x) v.width = std::max(v.width, xk.sup() - xk.inf());
    const bool forms = v.width <= kMeanValueWidth;  // wider, may_hold needs no centre or derivatives
    terms(x, v, &free_axis_detail::NestedTerms<Interval>::box, forms);
    if (!forms) return v;
    terms(c, v, &free_axis_detail::NestedTerms<Interval>::centre, false);
    terms({x[0], c[1], x[2], c[3]}, v, &free_axis_detail::NestedTerms<Interval>::half, true);
    return v;
  }

  /// An interval of Delta_(i+2) with {sin, cos} of Delta and n Delta over it and at its centre,
  /// computed once for every outer box it meets.
  struct ListItem {
    Interval d, centre;  // the centre the trig at the middle and the mean-value forms both use
    std::array<free_axis_detail::SinCos<Interval>, 4> trig;
  };
  ListItem list_item(const Interval& d, int /*i*/) const {
    const Interval dc = centre_of(d);
    return {d, dc, interval_sincos_all<4>({d, n_interval_ * d, dc, n_interval_ * dc})};
  }

  /// Whether point i + 2 may satisfy its equations on the outer box x item.d: on boxes wider than
  /// kMeanValueWidth plain_test, else the recursive mean-value form F(c) + sum_k J_k(X_k) (X_k - c_k) of each component of
  /// A - B and of the combination in which Delta's coefficient vanishes at the box's middle
  /// (noted in the view for narrow_outer when the item passes). Column k is enclosed with the
  /// unknowns before it (order Delta, s_u, s_v, w_u, w_v) over the box and those after it at the
  /// centre c (the mean value theorem one unknown at a time): Delta's with the axes at c, s_u's
  /// with s_v at c. Measured against J(X) for every column: 0.70x the boxes on the sweep's problem
  /// 6 (seed 7); Delta first beat Delta last (0.75x). The item is then narrowed to Delta's
  /// interval Newton step of each component (narrowed_delta), and replaced when that takes off
  /// more than 1 - kNarrowItem of its width.
  bool may_hold(View& v, ListItem& item, int i) const {
    using free_axis_detail::a_component;
    using free_axis_detail::b_component;
    const auto& t = item.trig;
    if (v.width > kMeanValueWidth) return plain_test(v, item, i);
    Interval dx[5];
    double r[5];  // dx_k within [-r_k, r_k]: the forms' terms without interval products (centred_sum)
    for (int k = 0; k < kOuter; ++k) dx[k] = v.box[k] - v.centre[k], r[k] = radius(dx[k]);
    dx[4] = item.d - item.centre, r[4] = radius(dx[4]);
    Interval a[3], centre[3], rest[3], gradient[3][5];  // a: A at the centre (the slab's direction)
    for (int j = 0; j < 3; ++j) {
      a[j] = a_component(v.a.centre, t[3], j);
      centre[j] = a[j] - b_component(v.b[i].centre, t[2], j);
      free_axis_detail::gradient_columns<Interval>({&v.a.half, &v.a.box}, {&v.b[i].half, &v.b[i].box}, v.a.centre,
                                                   v.b[i].centre, t[0], t[1], n_interval_, j, gradient[j]);
      rest[j] = centre[j] + centred_sum<kOuter>(gradient[j], r);  // the form but Delta's term
      if (!may_vanish(rest[j] + centred_sum<1>(&gradient[j][4], &r[4]))) return false;
    }
    const std::optional<Interval> narrowed = free_axis_detail::narrowed_delta(item.d, item.centre, rest, gradient);
    if (!narrowed) return false;
    dx[4] = *narrowed - item.centre;  // the slab's Delta term on what is left of the item
    const auto slab = free_axis_detail::delta_free_slab(a, centre, gradient, dx);
    if (slab) {
      if (!may_vanish(slab->value + centred_sum<kOuter>(slab->coefficient.data(), r))) return false;
      if (v.slabs[i])
        free_axis_detail::widen_to_hold(*v.slabs[i], *slab);
      else
        v.slabs[i] = slab;
    } else {
      v.slabs_known = false;
    }
    if (narrowed->sup() - narrowed->inf() < kNarrowItem * (item.d.sup() - item.d.inf())) item = list_item(*narrowed, i);
    return true;
  }

  /// may_hold on boxes wider than kMeanValueWidth, where the forms hardly ever prune: the plain
  /// enclosure of A - B over the box, then A . B > 0. (Narrower, the forms replace both: A . B
  /// pruned nothing there, measured over the sweep's problem 7; A - B left 0.08% more boxes and
  /// took 0.97x the time on six of seed 7's problems.)
  bool plain_test(const View& v, const ListItem& item, int i) const {
    Interval a[3], b[3];
    for (int j = 0; j < 3; ++j) {
      a[j] = free_axis_detail::a_component(v.a.box, item.trig[1], j);
      b[j] = free_axis_detail::b_component(v.b[i].box, item.trig[0], j);
      if (!may_vanish(a[j] - b[j])) return false;
    }
    return (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]).sup() > 0.0;
  }

  /// After every list was filtered on the view's box x: the four lists' Delta-free slabs must
  /// vanish together at a root x*. So 0 = v + C (x* - c) for some v, C within the slabs, and with
  /// Y ~ mid(C)^-1 (any Y keeps it valid) x* - c = -Y v + (I - Y C) (x* - c) lies in
  /// K = -Y v + (I - Y C) (X - c): Krawczyk's operator in the outer unknowns alone. False when
  /// c + K misses x (no root in x); else x narrowed to c + K. Boxes without slabs: x unchanged.
  /// REQUIRES: x is the view's box, and every list was filtered on the view.
  bool narrow_outer(const View& v, Outer& x) const {
    if (v.width > kMeanValueWidth || !v.slabs_known) return true;
    static_assert(kLists == kOuter, "one slab per outer unknown");
    IntervalMatrix<kOuter> slope;
    IntervalBox<kOuter> value;
    for (int i = 0; i < kLists; ++i) {
      if (!v.slabs[i]) return true;  // (every list kept an item, so each has one)
      value[i] = v.slabs[i]->value;
      for (int k = 0; k < kOuter; ++k) slope[i][k] = v.slabs[i]->coefficient[k];
    }
    const std::optional<DoubleMatrix<kOuter>> y = midpoint_inverse<kOuter>(midpoint<kOuter>(slope));
    if (!y) return true;
    const KrawczykStep<kOuter> k = krawczyk_step<kOuter>(x, centre<kOuter>(v.centre), value, slope, *y);  // krawczyk.hpp
    if (k.verdict == KrawczykVerdict::none) return false;
    x = k.box;  // K (unique) or x meeting K: every root of x
    return true;
  }

  /// Per point, the dropped component of A - B (see header), as base-3 digits; -1 when for some
  /// point no component of A stays above 1/2 over the box.
  template <typename Box>
  int chart(const Box& x) const {
    const auto a = free_axis_detail::rotation_terms(free_axis_detail::face_axis(planet_face_, x[2], x[3], false),
                                                    free_axis_detail::of_point(p_[0]), false);
    int code = 0;
    for (int i = 3; i >= 0; --i) {
      const auto t = interval_sincos(n_interval_ * x[4 + i]);
      free_axis_detail::Vec<Interval> ai;
      for (int j = 0; j < 3; ++j) ai[j] = a.c0[j] + a.c1[j] * t.second + a.c2[j] * t.first;
      const int k = free_axis_detail::dropped_component(ai);
      if (k < 0) return -1;  // no component fits the whole box
      code = 3 * code + k;
    }
    return code;
  }

  /// F(x) and, if `jac`, J(x) in type T (double at a point, Interval over a box), in `chart`.
  template <typename T>
  void equations(const std::array<T, N>& x, std::array<T, N>& f, std::array<std::array<T, N>, N>* jac, int chart) const {
    using free_axis_detail::of_point;
    const T n = ratio_as<T>(ratio_, n_interval_);
    const auto s = free_axis_detail::face_axis(sun_face_, x[0], x[1]);
    const auto a = free_axis_detail::rotation_terms(free_axis_detail::face_axis(planet_face_, x[2], x[3]), of_point(p_[0]));
    const auto trig = interval_sincos_all(std::array<T, 8>{x[4], T(n * x[4]), x[5], T(n * x[5]), x[6], T(n * x[6]), x[7], T(n * x[7])});
    for (int i = 0; i < 4; ++i, chart /= 3) {
      const auto b = free_axis_detail::rotation_terms(s, of_point(p_[i + 1]));
      const auto e = free_axis_detail::point_equations(a, b, trig[2 * i], trig[2 * i + 1], n, jac != nullptr);
      const int k = chart % 3;
      for (int r = 0; r < 2; ++r) {
        const int j = (k + 1 + r) % 3;
        f[2 * i + r] = e.e[j];
        if (!jac) continue;
        auto& row = (*jac)[2 * i + r];
        row.fill(T(0.0));
        for (int c = 0; c < 4; ++c) row[c] = e.de[c][j];
        row[4 + i] = e.de[4][j];
      }
    }
  }

  /// The train of a root in its canonical frame (see header), unless it is a mirror root of a
  /// chart, fails A . B > 0, or has a2 or a3 outside the range.
  std::optional<PrecisionSolution> solution(const std::array<double, N>& y, bool isolated) const {
    Vector3d s = to_vector(free_axis_detail::face_axis(sun_face_, y[0], y[1]).a);
    Vector3d w = to_vector(free_axis_detail::face_axis(planet_face_, y[2], y[3]).a);
    std::array<double, 4> delta{y[4], y[5], y[6], y[7]};
    for (int i = 0; i < 4; ++i) {
      const double nd = ratio_.value() * delta[i];
      const free_axis_detail::Vec<double> zero{0.0, 0.0, 0.0};
      const auto e = free_axis_detail::point_equations(
          free_axis_detail::rotation_terms(free_axis_detail::Axis<double>{to_array(w), zero, zero}, to_array(p_[0])),
          free_axis_detail::rotation_terms(free_axis_detail::Axis<double>{to_array(s), zero, zero}, to_array(p_[i + 1])),
          interval_sincos(delta[i]), interval_sincos(nd), ratio_.value(), false);
      // A mirror root has |A_k - B_k| = 2 |A_k| > 1 (chart: |A_k| > 1/2 over its box); a true root ~0.
      if (!(e.dot > 0.0) || !(std::max({std::fabs(e.e[0]), std::fabs(e.e[1]), std::fabs(e.e[2])}) < 0.5)) return std::nullopt;
    }
    const double a2 = std::acos(std::clamp(s.dot(w), -1.0, 1.0));
    if (!(a2 >= kMinCarrierTwist && a2 <= Constants<double>::pi() - kMinCarrierTwist)) return std::nullopt;
    if (!free_axis_detail::canonical_sign(s)) {
      s = -s, w = -w;
      for (double& d : delta) d = -d;
    }
    const Eigen::Matrix3d frame = free_axis_detail::frame_of(s);
    const Vector3d wf = frame.transpose() * w, p1 = frame.transpose() * p_[0];
    const double theta1 = std::atan2(wf.x(), -wf.y());
    // Point 1 seen from the carrier: Q_1 = Rx(-a2) Rz(-theta_1) P_1 (in the frame).
    const Vector3d r = Eigen::AngleAxisd(-theta1, Vector3d::UnitZ()) * p1;
    const double q1[3] = {r.x(), std::cos(a2) * r.y() + std::sin(a2) * r.z(), std::cos(a2) * r.z() - std::sin(a2) * r.y()};
    auto sol = train_through_points(ratio_, a2, q1,
                                                  {theta1, theta1 + delta[0], theta1 + delta[1], theta1 + delta[2], theta1 + delta[3]}, isolated);
    if (!sol) return sol;
    sol->frame = frame;
    const TracerCurve<double> curve(sol->train);
    for (int i = 0; i < 5; ++i) sol->residual = std::max(sol->residual, (frame * curve.point(sol->params[i]) - p_[i]).norm());
    return sol;
  }

  /// The same train: the same motion (the sun axis, the planet axis at point 1 and the carrier
  /// angles between the points agree to 1e-9, directly or with the sun axis reversed: solution()
  /// fixed the sign of s, but two copies of one root near a tie of the sign rule may differ), or
  /// the same frame and train with other carrier angles (a point at a node of the curve).
  bool same(const PrecisionSolution& a, const PrecisionSolution& b) const {
    if ((a.frame - b.frame).cwiseAbs().maxCoeff() < 1e-9 && same_train_in_frame(a.train, b.train)) return true;
    return same_motion(a, b, false) || same_motion(a, b, true);
  }

 private:
  /// The rotation terms over x (with their derivatives if `derivatives`) into the member `place`
  /// of the view's NestedTerms.
  void terms(const Outer& x, View& v, free_axis_detail::RotationTerms<Interval> free_axis_detail::NestedTerms<Interval>::*place,
             bool derivatives) const {
    using free_axis_detail::of_point;
    v.a.*place = free_axis_detail::rotation_terms(free_axis_detail::face_axis(planet_face_, x[2], x[3], derivatives),
                                                  of_point(p_[0]), derivatives);
    const auto s = free_axis_detail::face_axis(sun_face_, x[0], x[1], derivatives);
    for (int i = 0; i < kLists; ++i) v.b[i].*place = free_axis_detail::rotation_terms(s, of_point(p_[i + 1]), derivatives);
  }

  static Vector3d to_vector(const free_axis_detail::Vec<double>& a) { return {a[0], a[1], a[2]}; }
  static free_axis_detail::Vec<double> to_array(const Vector3d& a) { return {a.x(), a.y(), a.z()}; }

  /// The planet axis at point 1 (params[0]) in the points' coordinates.
  static Vector3d planet_axis(const PrecisionSolution& x) {
    const double a2 = x.train.a2(), t = x.params[0];
    return x.frame * Vector3d(std::sin(a2) * std::sin(t), -std::sin(a2) * std::cos(t), std::cos(a2));
  }

  bool same_motion(const PrecisionSolution& a, const PrecisionSolution& b, bool flipped) const {
    const double sign = flipped ? -1.0 : 1.0;
    if ((a.frame.col(2) - sign * b.frame.col(2)).norm() > 1e-9) return false;
    if ((planet_axis(a) - sign * planet_axis(b)).norm() > 1e-9) return false;
    const double period = list_max();
    for (int i = 1; i < 5; ++i) {
      const double da = a.params[i] - a.params[0], db = sign * (b.params[i] - b.params[0]);
      if (std::fabs(std::remainder(da - db, period)) > 1e-9 * list_scale()) return false;
    }
    return true;
  }

  Vector3d p_[5];
  Ratio ratio_;
  Interval n_interval_;
  int sun_face_, planet_face_;
};

inline PrecisionPoints free_axis_points(const std::vector<Vector3d>& points, const Ratio& n,
                                        const PrecisionPointsOptions& options) {
  const std::vector<Vector3d> checked = checked_precision_points(points, 5, "a free-axis problem");
  std::vector<std::size_t> order{free_axis_detail::reference_point(checked)};  // input index of each point
  for (std::size_t i = 0; i < checked.size(); ++i)
    if (i != order[0]) order.push_back(i);
  std::vector<Vector3d> ordered;
  for (const std::size_t i : order) ordered.push_back(checked[i]);
  std::vector<FreeAxisSystem> systems;
  for (int sun = 0; sun < 3; ++sun)
    for (int planet = 0; planet < 6; ++planet) systems.emplace_back(ordered, n, sun, planet);
  std::vector<PrecisionPoints> parts(systems.size());
  parallel_for(systems.size(), options.threads,
               [&](std::size_t k) { parts[k] = RootIsolation<FreeAxisSystem>(systems[k], options.max_boxes).run(); });
  PrecisionPoints all;
  for (std::size_t k = 0; k < parts.size(); ++k) {  // in face order: the result does not depend on threads
    all.boxes += parts[k].boxes;
    all.undecided += parts[k].undecided;
    for (auto& s : parts[k].solutions) {
      const auto copy = std::find_if(all.solutions.begin(), all.solutions.end(),
                                     [&](const PrecisionSolution& t) { return systems[k].same(t, s); });
      if (copy == all.solutions.end())
        all.solutions.push_back(std::move(s));
      else if (!copy->isolated && s.isolated)  // the copy certified by another face pair
        *copy = std::move(s);
    }
  }
  for (auto& s : all.solutions) {  // params back in input order
    std::vector<double> params(s.params.size());
    for (std::size_t k = 0; k < order.size(); ++k) params[order[k]] = s.params[k];
    s.params = std::move(params);
  }
  sort_solutions(all);
  all.certified = all.undecided == 0;
  return all;
}

}  // namespace sphtroch
