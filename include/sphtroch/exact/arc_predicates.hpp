// sphtroch/exact/arc_predicates.hpp — exact predicates for great-circle arcs given by double vertices.
//
// What it is for: deciding, without any tolerance, whether two edges of a spherical polyline
// cross, touch or overlap. Every answer is the exact answer for the double-precision vertices
// as given (CGAL's Exact_predicates_inexact_constructions_kernel: a floating-point filter with
// an exact fallback), so the combinatorics of the polyline never depend on rounding.
//
//   #include <sphtroch/exact/arc_predicates.hpp>   // needs the sphtroch::exact target (CGAL)
//   Eigen::Vector3d a(1, 0, 0), b(0, 1, 0), c(1, 1, -1), d(1, 1, 1);
//   sphtroch::ArcContact k = sphtroch::classify_arcs(a, b, c, d);   // ArcContact::crossing
//   sphtroch::orientation_sign(a, b, Eigen::Vector3d(0, 0, 1));     // +1 = sign det[a, b, c]
//
// Vertices are directions: a vertex v stands for the point v/|v| of the unit sphere, and
// need not be normalised. An arc AB is the shorter great-circle arc from A to B, i.e. the set
// of directions {alpha A + beta B : alpha, beta >= 0, not both 0}. Nothing here normalises a
// vertex or constructs a point, so normalisation can never change an answer.
//
// The API, with contracts:
//
//   int orientation_sign(a, b, c)
//     The exact sign (-1, 0, +1) of det[a, b, c] = (a x b) . c, i.e. on which side of the
//     plane through the origin, a and b the point c lies (+1: the side a x b points to).
//     Implemented as CGAL::orientation(O, a, b, c) on Epick points.
//
//   VertexRelation relate_vertices(a, b)
//     distinct, same_direction (a = lambda b, lambda > 0: the same point of the sphere) or
//     antipodal (lambda < 0). Exact. REQUIRES a, b finite and nonzero (else InvalidInput).
//
//   bool point_on_arc(p, a, b)
//     Whether the direction p lies on the closed arc AB (endpoints included). Exact.
//     REQUIRES p nonzero; a, b nonzero, not the same direction, not antipodal.
//
//   ArcContact classify_arcs(a, b, c, d, std::size_t* predicates = nullptr)
//     How the closed arcs AB and CD meet:
//       none      they have no point in common;
//       crossing  they meet in exactly one point, interior to both arcs, and the arcs pass
//                 from one side of the other's great circle to the other (transversal);
//       touching  they meet in exactly one point, which is an endpoint of at least one arc
//                 (an endpoint of one lies exactly on the other arc, or a shared vertex);
//       overlap   they lie on one great circle and share a sub-arc of positive length.
//     The answer is symmetric: classify(a,b,c,d) == classify(c,d,a,b) == classify(b,a,d,c).
//     If predicates is not null, the number of exact predicates evaluated is added to it.
//     REQUIRES: a, b, c, d nonzero and finite; a and b neither the same direction nor
//     antipodal; likewise c and d (every arc shorter than pi). Checked: throws InvalidInput
//     (field "vertices"), as do relate_vertices and point_on_arc; classify_arcs_unchecked skips
//     the checks but throws the same instead of failing where a degenerate arc is detected.
//     CAVEAT: two arcs that share an endpoint are `touching` (or `overlap` if one folds back
//     along the other); a polyline search skips the pairs of adjacent edges for that reason.
//
// Derivation (the conventions of S2's CrossingSign, which returns +1 for a crossing interior
// to both edges, 0 when two vertices from different edges coincide, -1 otherwise, re-derived
// here with four orientation signs and extended to classify the degenerate cases).
//   Let N1 = A x B, N2 = C x D (both nonzero since the arcs are shorter than pi and nondegenerate),
//   sc = sign det[A,B,C] = sign(N1.C), sd = sign(N1.D), sa = sign det[C,D,A] = sign(N2.A), sb = sign(N2.B).
//   1. If sc = sd != 0, the whole arc CD (positive combinations of C and D) lies strictly on one
//      side of the plane of AB: none. Likewise if sa = sb != 0.
//   2. All four signs nonzero (so sc = -sd and sa = -sb after step 1). The planes differ, and the
//      great circles meet in the two antipodal points +-X, X = N1 x N2. Arc AB meets the plane of
//      CD exactly once, at Q = |N2.B| A + |N2.A| B (the unique positive combination with N2.Q = 0);
//      arc CD meets the plane of AB exactly once, at P = |N1.D| C + |N1.C| D. By the identity
//      X = (A x B) x N2 = (N2.A) B - (N2.B) A, Q is a positive multiple of sa * X; by
//      X = -(C x D) x N1 = (N1.D) C - (N1.C) D, P is a positive multiple of sd * X.
//      The arcs share a point iff P and Q are the same point, i.e. iff sa = sd: then it is a
//      transversal crossing interior to both (every sign is nonzero, so it is no endpoint);
//      otherwise they meet the other's circle at antipodal points: none. (S2 writes the same
//      test as -sign(A,B,C) = sign(A,B,D) = -sign(C,D,B) = sign(C,D,A).)
//   3. sc = sd = 0: C and D lie in the plane of AB, so (C x D != 0) the two planes coincide and
//      sa = sb = 0 too: the arcs lie on one great circle. Each endpoint is located on the other
//      arc (below). Two arcs shorter than pi on one circle intersect in one connected piece, whose
//      ends are endpoints of the arcs; it has positive length iff some endpoint of one arc lies in
//      the open interior of the other, or the two arcs have the same pair of endpoints: overlap.
//      Otherwise, if some endpoint lies on the other arc it is a shared vertex: touching. Else none.
//   4. Otherwise the planes differ and some sign is zero, say sc = 0 with sd != 0: C is one of
//      +-X. If the arcs met at a point interior to CD it would also be one of +-X, distinct from
//      C, hence -C, and an arc shorter than pi cannot contain two antipodal points; so any common
//      point is an endpoint lying on the other arc. touching iff some endpoint with a zero sign
//      lies on the other closed arc; else none.
//   Locating a point P known to lie in the plane of AB on the arc AB: P = alpha A + beta B
//   uniquely; P is on the closed arc iff alpha, beta >= 0 (interior iff both > 0, at A iff
//   beta = 0). From P x B = alpha (A x B) and A x P = beta (A x B), taking a component k with
//   (A x B)_k != 0 (one exists): sign alpha = sign((P x B)_k) sign((A x B)_k), and likewise beta.
//   Each component of a cross product is a 2x2 determinant of the double coordinates, whose
//   sign CGAL::orientation(O2, p, q) on Epick Point_2 gives exactly (the projection along axis
//   k is a bijection of the plane of AB, because e_k . (A x B) != 0).
//
// Cost: the common answer `none` needs 2 predicates (4 at most); a crossing needs 4; degenerate
// configurations need at most 24 (3D and 2D orientations together; exact arithmetic only when a
// floating-point filter cannot decide: for the 3D signs our own semi-static filter, whose error
// bound is derived at kDetFilterError, then CGAL's filtered predicate; for the 2D signs CGAL's).
//
// Implementation details follow.
#pragma once

// Which exact number type: CGAL's choice. Built with SPHTROCH_HAVE_EXACT (the sphtroch::exact
// target), CGAL finds <gmp.h> and uses GMP's rationals, so GMP and MPFR are linked. Header-only,
// without GMP and MPFR (what the explorer's WebAssembly module compiles, explorer/CMakeLists.txt):
// define SPHTROCH_EXACT_WITHOUT_GMP and CGAL_NO_GMP=1; CGAL's configuration
// (CGAL/Installation/internal/enable_third_party_libraries.h) then leaves GMP out and its exact
// fallback is header-only (Exact_type_selector.h: Boost.Multiprecision's cpp_int quotients, or
// CGAL's MP_Float): the same exact signs, slower where the filter cannot decide.
#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/arc_predicates.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself, or (header-only, no GMP or MPFR) define SPHTROCH_EXACT_WITHOUT_GMP and CGAL_NO_GMP=1"
#endif

#include "sphtroch/core/errors.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Core>

#include <cfloat>
#include <cmath>
#include <cstddef>

namespace sphtroch {

/// How two closed great-circle arcs meet. See classify_arcs.
enum class ArcContact { none, crossing, touching, overlap };

inline const char* to_string(ArcContact k) {
  switch (k) {
    case ArcContact::none: return "none";
    case ArcContact::crossing: return "crossing";
    case ArcContact::touching: return "touching";
    case ArcContact::overlap: return "overlap";
  }
  return "?";
}

/// How two vertices relate as points of the sphere. See relate_vertices.
enum class VertexRelation { distinct, same_direction, antipodal };

namespace detail {

using EpickKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

inline EpickKernel::Point_3 epick_point(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

inline void count_predicates(std::size_t* counter, std::size_t n) {
  if (counter != nullptr) *counter += n;
}

/// Error bound of the double evaluation of det[a, b, c] in det_sign, as a multiple of the
/// permanent P = |a0| (|b1 c2| + |b2 c1|) + |a1| (|b2 c0| + |b0 c2|) + |a2| (|b0 c1| + |b1 c0|).
/// Derivation (u = 2^-53, each operation rounds with relative error <= u): a 2x2 minor
/// m0 = b1 c2 - b2 c1 is computed with error <= (2u + u^2)(|b1 c2| + |b2 c1|); the product a0 m0
/// adds u |a0 m0|, so each term errs by <= (3u + 3u^2 + u^3) |a0| (|b1 c2| + |b2 c1|); the two
/// additions of the three terms add <= 2u (1 + u)(1 + 3u) P. Total <= 5u P + O(u^2) P. We use
/// 8u P = 4 DBL_EPSILON P, which also absorbs the rounding of P and of the bound itself.
constexpr double kDetFilterError = 4 * DBL_EPSILON;
/// Below this permanent the filter is not used: products may underflow (their absolute error,
/// at most a few 2^-1074, is far below 3u P only when P is not tiny).
constexpr double kDetFilterMinPermanent = 1e-250;

/// Exact sign of det[a, b, c]: a semi-static floating-point filter (the sign of the double
/// determinant when it exceeds its error bound, see kDetFilterError), else CGAL's exact
/// orientation predicate. Inputs with overflowing products give inf/NaN and fall through to CGAL.
inline int det_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double p0 = b.y() * c.z(), q0 = b.z() * c.y();
  const double p1 = b.z() * c.x(), q1 = b.x() * c.z();
  const double p2 = b.x() * c.y(), q2 = b.y() * c.x();
  const double det = a.x() * (p0 - q0) + a.y() * (p1 - q1) + a.z() * (p2 - q2);
  const double perm = std::fabs(a.x()) * (std::fabs(p0) + std::fabs(q0)) +
                      std::fabs(a.y()) * (std::fabs(p1) + std::fabs(q1)) +
                      std::fabs(a.z()) * (std::fabs(p2) + std::fabs(q2));
  if (perm >= kDetFilterMinPermanent) {  // false for NaN
    const double bound = kDetFilterError * perm;
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  static const EpickKernel::Point_3 origin(0, 0, 0);
  return static_cast<int>(CGAL::orientation(origin, epick_point(a), epick_point(b), epick_point(c)));
}

/// Exact sign of (p x q)_k = p_i q_j - p_j q_i with (i, j) = (k+1, k+2) mod 3.
inline int cross_component_sign(const Eigen::Vector3d& p, const Eigen::Vector3d& q, int k) {
  static const EpickKernel::Point_2 origin(0, 0);
  const int i = (k + 1) % 3;
  const int j = (k + 2) % 3;
  return static_cast<int>(
      CGAL::orientation(origin, EpickKernel::Point_2(p[i], p[j]), EpickKernel::Point_2(q[i], q[j])));
}

/// Where a point known to lie in the plane of arc AB is, relative to the arc.
enum class OnArc { outside, at_first, at_second, interior };

/// A projection axis k with (a x b)_k != 0 and that component's sign. REQUIRES a x b != 0.
struct ArcPlaneAxis {
  int k = 0;
  int sign = 0;
};

/// The refusal of an arc whose endpoints are equal or antipodal (or a vertex zero / not finite).
[[noreturn]] inline void throw_bad_arc(const char* problem) {
  throw InvalidInput("vertices", "an arc's endpoints", problem,
                     "finite nonzero vertices; the two endpoints of an arc distinct and not antipodal");
}

inline ArcPlaneAxis arc_plane_axis(const Eigen::Vector3d& a, const Eigen::Vector3d& b, std::size_t* predicates) {
  for (int k = 0; k < 3; ++k) {
    count_predicates(predicates, 1);
    const int s = cross_component_sign(a, b, k);
    if (s != 0) return {k, s};
  }
  throw_bad_arc("the same direction or antipodal (no arc plane)");
}

/// Locates p on arc AB. REQUIRES det[a, b, p] = 0, p nonzero, axis = arc_plane_axis(a, b).
inline OnArc locate_in_arc_plane(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 ArcPlaneAxis axis, std::size_t* predicates) {
  count_predicates(predicates, 2);
  const int alpha = cross_component_sign(p, b, axis.k) * axis.sign;  // p = alpha a + beta b
  const int beta = cross_component_sign(a, p, axis.k) * axis.sign;
  if (alpha < 0 || beta < 0) return OnArc::outside;
  if (alpha > 0 && beta > 0) return OnArc::interior;
  return beta == 0 ? OnArc::at_first : OnArc::at_second;  // not both zero since p != 0
}

inline bool finite_nonzero(const Eigen::Vector3d& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()) &&
         (v.x() != 0.0 || v.y() != 0.0 || v.z() != 0.0);
}

/// A fast filter for relate_vertices: true only if a x b != 0 for certain. Each component
/// c = a_i b_j - a_j b_i is computed with error <= 1.01 eps (|a_i b_j| + |a_j b_i|) plus
/// underflow terms below 1e-322; |c| > 4 eps s with s > 1e-290 therefore proves c != 0. An
/// overflow gives inf or NaN, which fails the test (the exact predicate decides then).
inline bool surely_distinct(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double p = a[i] * b[j], q = a[j] * b[i];
    const double s = std::fabs(p) + std::fabs(q);
    if (std::fabs(p - q) > 4.0 * DBL_EPSILON * s && s > 1e-290) return true;
  }
  return false;
}

/// Case 3 of the derivation: all four points on one great circle.
inline ArcContact classify_cocircular(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                      const Eigen::Vector3d& d, std::size_t* predicates) {
  const ArcPlaneAxis ab = arc_plane_axis(a, b, predicates);
  const ArcPlaneAxis cd = arc_plane_axis(c, d, predicates);
  const OnArc lc = locate_in_arc_plane(c, a, b, ab, predicates);
  const OnArc ld = locate_in_arc_plane(d, a, b, ab, predicates);
  const OnArc la = locate_in_arc_plane(a, c, d, cd, predicates);
  const OnArc lb = locate_in_arc_plane(b, c, d, cd, predicates);
  if (lc == OnArc::interior || ld == OnArc::interior || la == OnArc::interior || lb == OnArc::interior)
    return ArcContact::overlap;
  const bool c_end = lc == OnArc::at_first || lc == OnArc::at_second;
  const bool d_end = ld == OnArc::at_first || ld == OnArc::at_second;
  if (c_end && d_end) return ArcContact::overlap;  // the same pair of endpoints: the same arc
  if (c_end || d_end || la != OnArc::outside || lb != OnArc::outside) return ArcContact::touching;
  return ArcContact::none;
}

/// classify_arcs without the precondition checks (the polyline search validates its input once).
inline ArcContact classify_arcs_unchecked(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c, const Eigen::Vector3d& d,
                                          std::size_t* predicates) {
  // Step 1: one arc strictly on one side of the other's great circle.
  count_predicates(predicates, 2);
  const int sc = det_sign(a, b, c);
  const int sd = det_sign(a, b, d);
  if (sc == sd && sc != 0) return ArcContact::none;
  count_predicates(predicates, 2);
  const int sa = det_sign(c, d, a);
  const int sb = det_sign(c, d, b);
  if (sa == sb && sa != 0) return ArcContact::none;
  // Step 2: the generic case, sc = -sd != 0 and sa = -sb != 0.
  if (sc != 0 && sd != 0 && sa != 0 && sb != 0) return sa == sd ? ArcContact::crossing : ArcContact::none;
  // Step 3: one great circle.
  if (sc == 0 && sd == 0) {
    if (sa != 0 || sb != 0) throw_bad_arc("the same direction or antipodal (c x d = 0)");
    return classify_cocircular(a, b, c, d, predicates);
  }
  // Step 4: distinct circles, an endpoint on the other circle.
  const auto on_arc = [predicates](const Eigen::Vector3d& p, const Eigen::Vector3d& e0, const Eigen::Vector3d& e1) {
    return locate_in_arc_plane(p, e0, e1, arc_plane_axis(e0, e1, predicates), predicates) != OnArc::outside;
  };
  if ((sc == 0 && on_arc(c, a, b)) || (sd == 0 && on_arc(d, a, b)) || (sa == 0 && on_arc(a, c, d)) ||
      (sb == 0 && on_arc(b, c, d)))
    return ArcContact::touching;
  return ArcContact::none;
}

}  // namespace detail

/// Exact sign of det[a, b, c] (+1, 0, -1): the side of the plane through O, a, b that c is on.
inline int orientation_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return detail::det_sign(a, b, c);
}

/// Exact relation of two directions. REQUIRES a, b nonzero (checked).
inline VertexRelation relate_vertices(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (!detail::finite_nonzero(a) || !detail::finite_nonzero(b)) detail::throw_bad_arc("a vertex is zero or not finite");
  if (detail::surely_distinct(a, b)) return VertexRelation::distinct;
  static const detail::EpickKernel::Point_3 origin(0, 0, 0);
  if (!CGAL::collinear(origin, detail::epick_point(a), detail::epick_point(b))) return VertexRelation::distinct;
  // b = lambda a exactly with lambda != 0: its sign is sign(a_k) sign(b_k) for any k with a_k != 0.
  for (int k = 0; k < 3; ++k) {
    if (a[k] != 0.0) return ((a[k] > 0.0) == (b[k] > 0.0)) ? VertexRelation::same_direction : VertexRelation::antipodal;
  }
  return VertexRelation::same_direction;  // unreachable: a != 0
}

/// Whether direction p lies on the closed arc AB. Exact.
/// REQUIRES p, a, b finite and nonzero; a, b neither the same direction nor antipodal (checked).
inline bool point_on_arc(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  if (!detail::finite_nonzero(p)) detail::throw_bad_arc("the point is zero or not finite");
  if (relate_vertices(a, b) != VertexRelation::distinct) detail::throw_bad_arc("the same direction or antipodal");
  if (detail::det_sign(a, b, p) != 0) return false;
  return detail::locate_in_arc_plane(p, a, b, detail::arc_plane_axis(a, b, nullptr), nullptr) != detail::OnArc::outside;
}

/// How the closed arcs AB and CD meet; see the header comment for the contract and derivation.
/// REQUIRES a, b, c, d finite, nonzero; a, b and c, d neither the same direction nor antipodal (checked).
inline ArcContact classify_arcs(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                const Eigen::Vector3d& d, std::size_t* predicates = nullptr) {
  if (relate_vertices(a, b) != VertexRelation::distinct || relate_vertices(c, d) != VertexRelation::distinct)
    detail::throw_bad_arc("the same direction or antipodal");
  return detail::classify_arcs_unchecked(a, b, c, d, predicates);
}

/// classify_arcs without its precondition checks, for callers that validated every vertex once
/// (self_crossings.hpp). REQUIRES: the four vertices finite and nonzero, a != +-b, c != +-d.
inline ArcContact classify_arcs_unchecked(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                          const Eigen::Vector3d& d, std::size_t* predicates = nullptr) {
  return detail::classify_arcs_unchecked(a, b, c, d, predicates);
}

}  // namespace sphtroch
