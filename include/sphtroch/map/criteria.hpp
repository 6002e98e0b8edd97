// sphtroch/map/criteria.hpp — the report's analytic results, computed in closed form: the a3
// boundaries, the node criteria (Eq. 24 for n = 1; Eqs. 43 and 46 for n = 2), the pitch-cone cusp
// criterion (every n), the predicted nodes and cusps with their positions and parameters. The z
// extremes and the mirror planes, also closed forms, are in extremes_and_symmetry.hpp.
//
// Nothing here samples or evaluates the curve; every number comes from a formula of the report
// (Lin & Tsai 1990) or one derived below from its Eqs. 3, 4, 8 and 47b. The classification shows
// these predictions side by side with the numeric node census, so they must stay independent of it.
//
//   using namespace sphtroch;
//   const double pi = Constants<double>::pi();
//   GearTrain fig5g(pi / 3, 2 * pi / 3, Ratio(2));             // Table 1 row (g)
//   AnalyticClassification a = classify_analytic(fig5g);       // tolerance kBoundaryTolerance
//   *a.predicted_nodes == 3;  a.predicted_cusps == 0;
//   a.nodes[0].equation;      // "Eq. 39b" or "Eq. 44b"; .position, .params (two theta2), .kind
//   a.criteria;               // Eq. 43 (equality at upper end a3 = pi - a2), Eq. 46 (strict), pitch cone
//   a.boundaries_hit;         // { "a3 = pi - a2 (south pole on the curve)", margin 3.4e-16 }
//
// Conventions
//  (1) Parameters are carrier angles theta2 in [0, period), period = 2 pi q for n = p/q (lowest
//      terms); lists of parameters are ascending. Positions are unit vectors in the base frame.
//  (2) A feature fixed by a planet angle theta3 = n theta2 + theta_p = c (mod 2 pi) (Eq. 3) sits
//      at theta2 = (c - theta_p + 2 pi m) q / p, m = 0 .. |p| - 1: |p| parameters per period.
//  (3) Phase (Eq. 8): P_phase(t) = Rz(-theta_p/n) P_0(t + theta_p/n). A zero-phase node at
//      parameter t and position X therefore appears at t - theta_p/n and Rz(-theta_p/n) X.
//  (4) Boundaries: an input with |a3 - boundary| <= tolerance is treated as lying on the
//      boundary (the report's equality cases: cusps, nodes merged at a pole). tolerance = 0 is the
//      literal reading: only an exact margin of 0 is "on" the boundary. Margins are exact when a3
//      was given relative to that boundary (GearTrain::on_cone): then margin = offset.
#pragma once

#include "sphtroch/map/closed_form_boundaries.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/parameters.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/core/ratio.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {



// ---------------------------------------------------------------------------------------------
// Criteria
// ---------------------------------------------------------------------------------------------

enum class CriterionStatus {
  holds_strictly,     // lower < a3 < upper, both margins > tolerance
  equality_at_lower,  // |a3 - lower| <= tolerance
  equality_at_upper,  // |upper - a3| <= tolerance
  equality_at_both,   // both (only possible when lower ~ upper, e.g. a_p = pi/2 for the cusp criterion)
  fails,              // outside the interval (or the interval is empty)
};

inline const char* to_string(CriterionStatus status);

/// One criterion of the report, written as an interval lower <= a3 <= upper.
struct Criterion {
  std::string equation;   // "Eq. 24", "Eq. 43", "Eq. 46", "pitch cone (Eq. 20b, 47b)"
  std::string statement;  // e.g. "a2/2 <= a3 <= pi - a2/2"
  // For the pitch-cone criterion only the ends carry meaning (cusps there); inside or outside
  // the interval both mean "no cusps".
  CriterionStatus status = CriterionStatus::fails;
  double lower = 0.0;         // interval ends, radians
  double upper = 0.0;
  double lower_margin = 0.0;  // a3 - lower (>= 0 inside)
  double upper_margin = 0.0;  // upper - a3 (>= 0 inside)
  double tolerance = 0.0;     // used to decide equality
  std::size_t predicted_nodes = 0;  // what this criterion alone contributes
  std::size_t predicted_cusps = 0;
  std::string prediction;     // e.g. "1 node at Eq. 25", "2 cusps", "simple curve"
};

/// A node the report predicts: a point the curve passes through at two parameters.
struct AnalyticNode {
  Vector3d position = Vector3d::Zero();  // unit vector, base frame, phase applied (Eq. 8)
  std::vector<double> params;            // the two theta2, ascending in [0, period)
  NodeKind kind = NodeKind::crossing;    // tangency for the merged pole nodes (Table 1 rows d, g)
  std::string equation;                  // "Eq. 25", "Eq. 39b", "Eq. 44b", ...
};

/// A cusp the pitch-cone criterion predicts: P parallel to omega (Eq. 47b).
struct AnalyticCusp {
  Vector3d position = Vector3d::Zero();     // +omega_hat (pitch cone) or -omega_hat (mirror)
  double param = 0.0;                       // theta2 in [0, period)
  BoundaryKind cone = BoundaryKind::pitch_cone;  // pitch_cone or mirror_pitch_cone
};

/// n = 1 only: Eq. 20/24, a2/2 <= a3 <= pi - a2/2. REQUIRES: train.ratio() == Ratio(1).
inline Criterion criterion_eq24(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// n = 2 only: Eq. 43, a_p <= a3 <= pi - a2 (nodes of Eq. 39b on the plane y = 0 at phase 0).
inline Criterion criterion_eq43(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// n = 2 only: Eq. 46, a2 <= a3 <= pi - a_p (nodes of Eq. 44b on the plane x = 0 at phase 0).
inline Criterion criterion_eq46(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// Every n: cusps exactly when a3 = a_p (lower end) or a3 = pi - a_p (upper end), |p| cusps per
/// period for each, 2|p| when a_p = pi/2 (equality at both ends).
inline Criterion pitch_cone_criterion(const GearTrain& train, double tolerance = kBoundaryTolerance);

/// n = 1: the node of Eq. 25, (0, sin a3, cos a3) at phase 0, with theta2 = +-acos(Eq. 22b);
/// empty unless Eq. 24 holds strictly.
inline std::vector<AnalyticNode> nodes_eq25(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// n = 2: the nodes of Eq. 39b (two crossings; one tangency at (0,0,-1) when a3 = pi - a2;
/// none when a3 = a_p, where they are cusps, or when Eq. 43 fails).
inline std::vector<AnalyticNode> nodes_eq39b(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// n = 2: the nodes of Eq. 44b (two crossings; one tangency at (0,0,1) when a3 = a2; none when
/// a3 = pi - a_p or when Eq. 46 fails).
inline std::vector<AnalyticNode> nodes_eq44b(const GearTrain& train, double tolerance = kBoundaryTolerance);
/// Every n: the cusps of the pitch-cone criterion, ascending by parameter; empty off the cones.
/// On a cone within tolerance but not exactly, the positions are those of the exact cone
/// (the curve passes within O(margin) of them).
inline std::vector<AnalyticCusp> pitch_cone_cusps(const GearTrain& train, double tolerance = kBoundaryTolerance);

/// The cusps as every report lists them (classify, plot, nodes, the explorer): pitch_cone_cusps at
/// kCuspResolution, each with its point on the curve and the speed there (which verifies it).
inline std::vector<Cusp> cusp_points(const GearTrain& analysed);

/// Everything above in one result.
struct AnalyticClassification {
  bool applicable = false;  // node criteria exist (n = 1 or n = 2); otherwise only the cusp criterion
  std::optional<std::size_t> predicted_nodes;  // nullopt: the report predicts nothing for this n
  std::size_t predicted_cusps = 0;
  std::vector<AnalyticNode> nodes;             // predicted node positions (empty when unknown)
  std::vector<AnalyticCusp> cusps;
  std::vector<Boundary> boundaries_hit;        // |margin| <= tolerance
  std::vector<Criterion> criteria;             // Eq. 24 | Eqs. 43, 46 (n = 1 | 2), then pitch cone
  double tolerance = kBoundaryTolerance;
  std::string curve_class;  // "simple curve", "nodes", "cusps", "nodes and cusps", or for other n
                            // "cusps (nodes not predicted)" / "no cusps (nodes not predicted)"
};

/// REQUIRES: tolerance >= 0 (0 = literal). Evaluates no point of the curve.
inline AnalyticClassification classify_analytic(const GearTrain& train, double tolerance = kBoundaryTolerance);

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace criteria_detail {

inline double pi() { return Constants<double>::pi(); }

/// Base-frame position of a carrier-frame vector at carrier angle theta2 (parameters.hpp frames).
inline Vector3d base_from_carrier(const GearTrain& train, double theta2, const Vector3d& p_carrier) {
  return Vector3d(base_R_carrier(theta2, train.trig<double>()) * p_carrier);
}

/// The angle a3 is measured from, as GearTrain holds it symbolically.

inline bool is_n(const GearTrain& train, std::int64_t p) { return train.ratio() == Ratio(p); }




inline CriterionStatus decide(double lower_margin, double upper_margin, double tol) {
  const bool on_lower = std::abs(lower_margin) <= tol;
  const bool on_upper = std::abs(upper_margin) <= tol;
  if (on_lower && on_upper) return CriterionStatus::equality_at_both;
  if (on_lower) return CriterionStatus::equality_at_lower;
  if (on_upper) return CriterionStatus::equality_at_upper;
  if (lower_margin > 0 && upper_margin > 0) return CriterionStatus::holds_strictly;
  return CriterionStatus::fails;
}

inline Criterion make_criterion(std::string equation, std::string statement, double lower, double upper,
                                double lower_margin, double upper_margin, double tol) {
  Criterion c;
  c.equation = std::move(equation);
  c.statement = std::move(statement);
  c.lower = lower;
  c.upper = upper;
  c.lower_margin = lower_margin + 0.0;  // + 0.0: print an exact zero margin as 0, not -0
  c.upper_margin = upper_margin + 0.0;
  c.tolerance = tol;
  c.status = decide(lower_margin, upper_margin, tol);
  return c;
}

/// A margin that the criterion treats as "on the boundary" is exactly 0 in the formulas (so the
/// predicted points are those of the boundary case); a negative one never reaches them.
inline double clamp_margin(double m, double tol) { return std::abs(m) <= tol ? 0.0 : std::max(m, 0.0); }

/// Zero-phase node -> node of the actual train (convention 3, Eq. 8).
inline AnalyticNode phased_node(const GearTrain& train, Vector3d position0, std::vector<double> params0,
                                NodeKind kind, const char* equation) {
  const double shift = train.phase() / train.n();
  AnalyticNode node;
  node.position = rotation_z(-shift) * position0;
  for (double t : params0) node.params.push_back(reduce_to_period(t - shift, train.period()));
  std::sort(node.params.begin(), node.params.end());
  node.kind = kind;
  node.equation = equation;
  return node;
}

/// |omega| per unit carrier rate, sqrt(1 + n^2 + 2 n cos a2) (Eq. 47a); also sin a2 / sin a_p.
inline double omega_norm(const GearTrain& train) {
  const double n = train.n(), c2 = std::cos(train.a2());
  return std::sqrt(1.0 + n * n + 2.0 * n * c2);
}

}  // namespace criteria_detail



inline const char* to_string(CriterionStatus status) {
  switch (status) {
    case CriterionStatus::holds_strictly: return "holds strictly";
    case CriterionStatus::equality_at_lower: return "holds with equality at the lower end";
    case CriterionStatus::equality_at_upper: return "holds with equality at the upper end";
    case CriterionStatus::equality_at_both: return "holds with equality at both ends";
    case CriterionStatus::fails: return "fails";
  }
  return "?";
}


inline Criterion criterion_eq24(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 1))
    throw InvalidInput("n", train.ratio().str(), "Eq. 24 is the n = 1 criterion", "n = 1");
  Criterion c = make_criterion("Eq. 24", "a2/2 <= a3 <= pi - a2/2", boundary_value(train, BoundaryKind::half_a2),
                               boundary_value(train, BoundaryKind::pi_minus_half_a2),
                               boundary_margin(train, BoundaryKind::half_a2),
                               -boundary_margin(train, BoundaryKind::pi_minus_half_a2), tol);
  switch (c.status) {
    case CriterionStatus::holds_strictly:
      c.predicted_nodes = 1;
      c.prediction = "1 node at Eq. 25, (0, sin a3, cos a3) at phase 0";
      break;
    case CriterionStatus::equality_at_lower:
    case CriterionStatus::equality_at_upper:
    case CriterionStatus::equality_at_both:  // impossible for a2 < pi; kept total
      c.predicted_cusps = 1;
      c.prediction = "1 cusp at Eq. 25's point (spherical cardioid)";
      break;
    case CriterionStatus::fails: c.prediction = "simple curve"; break;
  }
  return c;
}

inline Criterion criterion_eq43(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 2))
    throw InvalidInput("n", train.ratio().str(), "Eq. 43 is an n = 2 criterion", "n = 2");
  Criterion c = make_criterion("Eq. 43", "a_p <= a3 <= pi - a2", boundary_value(train, BoundaryKind::pitch_cone),
                               boundary_value(train, BoundaryKind::pi_minus_a2),
                               boundary_margin(train, BoundaryKind::pitch_cone),
                               -boundary_margin(train, BoundaryKind::pi_minus_a2), tol);
  switch (c.status) {
    case CriterionStatus::holds_strictly:
      c.predicted_nodes = 2;
      c.prediction = "2 nodes (Eq. 39b, on the plane y = 0 at phase 0)";
      break;
    case CriterionStatus::equality_at_lower:
      c.predicted_cusps = 2;
      c.prediction = "2 cusps (a3 = a_p: the Eq. 39b nodes become cusps)";
      break;
    case CriterionStatus::equality_at_upper:
      c.predicted_nodes = 1;
      c.prediction = "1 node at the pole (0,0,-1), a tangency (a3 = pi - a2: the two Eq. 39b nodes merge)";
      break;
    case CriterionStatus::equality_at_both:  // a_p = pi - a2 needs a2 = pi: impossible; kept total
      c.predicted_cusps = 2;
      c.prediction = "2 cusps";
      break;
    case CriterionStatus::fails: c.prediction = "no nodes from Eq. 39b"; break;
  }
  return c;
}

inline Criterion criterion_eq46(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 2))
    throw InvalidInput("n", train.ratio().str(), "Eq. 46 is an n = 2 criterion", "n = 2");
  Criterion c = make_criterion("Eq. 46", "a2 <= a3 <= pi - a_p", boundary_value(train, BoundaryKind::a2),
                               boundary_value(train, BoundaryKind::mirror_pitch_cone),
                               boundary_margin(train, BoundaryKind::a2),
                               -boundary_margin(train, BoundaryKind::mirror_pitch_cone), tol);
  switch (c.status) {
    case CriterionStatus::holds_strictly:
      c.predicted_nodes = 2;
      c.prediction = "2 nodes (Eq. 44b, on the plane x = 0 at phase 0)";
      break;
    case CriterionStatus::equality_at_lower:
      c.predicted_nodes = 1;
      c.prediction = "1 node at the pole (0,0,1), a tangency (a3 = a2: the two Eq. 44b nodes merge)";
      break;
    case CriterionStatus::equality_at_upper:
      c.predicted_cusps = 2;
      c.prediction = "2 cusps (a3 = pi - a_p: the Eq. 44b nodes become cusps)";
      break;
    case CriterionStatus::equality_at_both:  // a2 = pi - a_p needs a2 = pi: impossible; kept total
      c.predicted_cusps = 2;
      c.prediction = "2 cusps";
      break;
    case CriterionStatus::fails: c.prediction = "no nodes from Eq. 44b"; break;
  }
  return c;
}

inline Criterion pitch_cone_criterion(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  // Written as the interval a_p <= a3 <= pi - a_p (Eq. 20b generalised); only its ends matter:
  // the ends are where P can be parallel to omega. (For a_p > pi/2 the interval is empty and
  // "fails" / "holds strictly" both mean: no cusps.)
  Criterion c = make_criterion("pitch cone (Eq. 20b, 47b)", "a_p <= a3 <= pi - a_p (cusps at either end)",
                               boundary_value(train, BoundaryKind::pitch_cone),
                               boundary_value(train, BoundaryKind::mirror_pitch_cone),
                               boundary_margin(train, BoundaryKind::pitch_cone),
                               -boundary_margin(train, BoundaryKind::mirror_pitch_cone), tol);
  const std::size_t p = static_cast<std::size_t>(train.ratio().abs_p());
  switch (c.status) {
    case CriterionStatus::equality_at_lower:
      c.predicted_cusps = p;
      c.prediction = std::to_string(p) + " cusp(s) per period, tracer on the pitch cone (P = +omega_hat)";
      break;
    case CriterionStatus::equality_at_upper:
      c.predicted_cusps = p;
      c.prediction = std::to_string(p) + " cusp(s) per period, tracer on the mirror pitch cone (P = -omega_hat)";
      break;
    case CriterionStatus::equality_at_both:
      c.predicted_cusps = 2 * p;
      c.prediction = std::to_string(2 * p) + " cusps per period, a_p = pi/2: both cones at once";
      break;
    case CriterionStatus::holds_strictly:
    case CriterionStatus::fails: c.prediction = "no cusps (tracer off both cones)"; break;
  }
  return c;
}

namespace criteria_detail {

/// nodes_eq25 with its criterion `c` computed once by the caller (classify_analytic).
inline std::vector<AnalyticNode> nodes_eq25_of(const GearTrain& train, const Criterion& c, double tol) {
  if (c.status != CriterionStatus::holds_strictly) return {};
  const TwistTrig<double> t = train.trig<double>();
  // Eq. 22b: cos theta2 = -sin a2 cos a3 / (sin a3 (1 + cos a2)). With D = sin a3 (1 + cos a2) > 0,
  // D^2 - (sin a2 cos a3)^2 = (sin a3 + sin(a3 - a2)) (sin a3 + sin(a3 + a2))
  //                         = 4 cos^2(a2/2) sin(a3 - a2/2) sin(pi - a2/2 - a3),
  // so sin theta2 = 2 cos(a2/2) sqrt(sin(m_lo) sin(m_hi)) / D with the Eq. 24 margins: the same
  // angle as acos(Eq. 22b), without acos's loss of accuracy near +-1 (near the cusps).
  const double m_lo = clamp_margin(c.lower_margin, tol), m_hi = clamp_margin(c.upper_margin, tol);
  const double sin_part = 2.0 * std::cos(0.5 * train.a2()) * std::sqrt(std::sin(m_lo) * std::sin(m_hi));
  const double theta = std::atan2(sin_part, -t.sin_a2 * t.cos_a3);  // in (0, pi)
  const double two_pi = Constants<double>::two_pi();
  // Eq. 25: y and z of Eq. 9 depend on cos theta2 only, x = 0: the double point (0, sin a3, cos a3).
  return {phased_node(train, Vector3d(0.0, t.sin_a3, t.cos_a3), {theta, two_pi - theta}, NodeKind::crossing,
                      "Eq. 25")};
}

}  // namespace criteria_detail

inline std::vector<AnalyticNode> nodes_eq25(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 1))
    throw InvalidInput("n", train.ratio().str(), "Eq. 25 is the n = 1 node", "n = 1");
  return criteria_detail::nodes_eq25_of(train, criterion_eq24(train, tol), tol);
}

namespace criteria_detail {

/// nodes_eq39b with its criterion `c` computed once by the caller (classify_analytic).
inline std::vector<AnalyticNode> nodes_eq39b_of(const GearTrain& train, const Criterion& c, double tol) {
  const double pi_ = pi();
  if (c.status == CriterionStatus::equality_at_upper) {
    // a3 = pi - a2: sin theta2 = 0 in Eq. 39b; theta2 = 0 and pi both reach z = cos(a2 + a3) = -1.
    return {phased_node(train, Vector3d(0.0, 0.0, -1.0), {0.0, pi_}, NodeKind::tangency,
                        "Eq. 39b (a3 = pi - a2: merged at the south pole)")};
  }
  if (c.status != CriterionStatus::holds_strictly) return {};
  const TwistTrig<double> t = train.trig<double>();
  // Eq. 39b: sin^2 theta2 = S = sin(a2 + a3) / (2 sin a3 (1 + cos a2)). Its complement, using
  // n = sin a_s / sin a_p = 2 and a2 = a_s + a_p (Eq. 2):
  //   1 - S = (2 sin a3 - sin(a2 - a3)) / (2 sin a3 (1 + cos a2))
  //         = sin(a3 - a_p) (sin a2 / sin a_p) / (2 sin a3 (1 + cos a2)),
  // and sin a2 / sin a_p = |omega| (Eq. 47b). With sin(a2 + a3) = sin(pi - a2 - a3) both are
  // margins of Eq. 43, so theta = atan2(sqrt(S), sqrt(1 - S)) is accurate up to the boundary.
  const double m_lo = clamp_margin(c.lower_margin, tol), m_hi = clamp_margin(c.upper_margin, tol);
  const double theta = std::atan2(std::sqrt(std::sin(m_hi)), std::sqrt(std::sin(m_lo) * omega_norm(train)));
  const double s = std::sin(theta);  // +sqrt(S)
  const double k = t.sin_a3 * (1.0 + t.cos_a2);
  const double sin_a2_minus_a3 = t.sin_a2 * t.cos_a3 - t.cos_a2 * t.sin_a3;
  // Eq. 28 with sin theta2 = +-s: x = sin theta2 [2 (1 - sin^2) sin a3 (1 + cos a2) + sin(a2 - a3)],
  // y = 0 (Eq. 39b), z = -cos(2 theta2) sin a2 sin a3 + cos a2 cos a3, cos 2 theta2 = 1 - 2 sin^2.
  const double x = s * (2.0 * (1.0 - s * s) * k + sin_a2_minus_a3);
  const double z = -(1.0 - 2.0 * s * s) * t.sin_a2 * t.sin_a3 + t.cos_a2 * t.cos_a3;
  // x and z depend on sin theta2 only: theta and pi - theta meet at one point, -theta and pi + theta
  // at its mirror image in the plane x = 0.
  return {phased_node(train, Vector3d(x, 0.0, z), {theta, pi_ - theta}, NodeKind::crossing, "Eq. 39b"),
          phased_node(train, Vector3d(-x, 0.0, z), {2.0 * pi_ - theta, pi_ + theta}, NodeKind::crossing,
                      "Eq. 39b")};
}

}  // namespace criteria_detail

inline std::vector<AnalyticNode> nodes_eq39b(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 2))
    throw InvalidInput("n", train.ratio().str(), "Eq. 39b is an n = 2 node", "n = 2");
  return criteria_detail::nodes_eq39b_of(train, criterion_eq43(train, tol), tol);
}

namespace criteria_detail {

/// nodes_eq44b with its criterion `c` computed once by the caller (classify_analytic).
inline std::vector<AnalyticNode> nodes_eq44b_of(const GearTrain& train, const Criterion& c, double tol) {
  const double pi_ = pi();
  if (c.status == CriterionStatus::equality_at_lower) {
    // a3 = a2: cos theta2 = 0 in Eq. 44b; theta2 = pi/2 and 3 pi/2 both reach z = cos(a2 - a3) = 1.
    return {phased_node(train, Vector3d(0.0, 0.0, 1.0), {0.5 * pi_, 1.5 * pi_}, NodeKind::tangency,
                        "Eq. 44b (a3 = a2: merged at the north pole)")};
  }
  if (c.status != CriterionStatus::holds_strictly) return {};
  const TwistTrig<double> t = train.trig<double>();
  // Eq. 44b: cos^2 theta2 = C = sin(a3 - a2) / (2 sin a3 (1 + cos a2)); by the mirror a3 -> pi - a3
  // of the Eq. 39b identity, 1 - C = sin(pi - a_p - a3) |omega| / (2 sin a3 (1 + cos a2)).
  // Both numerators are margins of Eq. 46.
  const double m_lo = clamp_margin(c.lower_margin, tol), m_hi = clamp_margin(c.upper_margin, tol);
  const double theta = std::atan2(std::sqrt(std::sin(m_hi) * omega_norm(train)), std::sqrt(std::sin(m_lo)));
  const double co = std::cos(theta);  // +sqrt(C)
  const double k = t.sin_a3 * (1.0 + t.cos_a2);
  const double sin_a2_plus_a3 = t.sin_a2 * t.cos_a3 + t.cos_a2 * t.sin_a3;
  // Eq. 28 with cos theta2 = +-co: y = cos theta2 [2 (1 - cos^2) sin a3 (1 + cos a2) - sin(a2 + a3)],
  // x = 0 (Eq. 44b), z = -(2 cos^2 - 1) sin a2 sin a3 + cos a2 cos a3.
  const double y = co * (2.0 * (1.0 - co * co) * k - sin_a2_plus_a3);
  const double z = -(2.0 * co * co - 1.0) * t.sin_a2 * t.sin_a3 + t.cos_a2 * t.cos_a3;
  // y and z depend on cos theta2 only: theta and -theta meet at one point, pi -+ theta at its
  // mirror image in the plane y = 0.
  return {phased_node(train, Vector3d(0.0, y, z), {theta, 2.0 * pi_ - theta}, NodeKind::crossing, "Eq. 44b"),
          phased_node(train, Vector3d(0.0, -y, z), {pi_ - theta, pi_ + theta}, NodeKind::crossing, "Eq. 44b")};
}

}  // namespace criteria_detail

inline std::vector<AnalyticNode> nodes_eq44b(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!is_n(train, 2))
    throw InvalidInput("n", train.ratio().str(), "Eq. 44b is an n = 2 node", "n = 2");
  return criteria_detail::nodes_eq44b_of(train, criterion_eq46(train, tol), tol);
}

namespace criteria_detail {

/// pitch_cone_cusps with its criterion `c` computed once by the caller (classify_analytic).
inline std::vector<AnalyticCusp> pitch_cone_cusps_of(const GearTrain& train, const Criterion& c) {
  // Derivation. dP/dtheta2 = omega x P (Eq. 47a) vanishes iff P is parallel to omega. In the
  // carrier frame omega ~ (0, sin a2, cos a2 + n) = |omega| (0, sin a_p, cos a_p) (Eq. 47b) and
  // the tracer is (sin th3 sin a3, -cos th3 sin a3, cos a3) (Eq. 4). Since sin a3 > 0, parallel
  // needs sin th3 = 0, and then:
  //   th3 = pi (mod 2 pi): tracer (0, sin a3, cos a3)  = +omega_hat  iff a3 = a_p;
  //   th3 = 0  (mod 2 pi): tracer (0, -sin a3, cos a3) = -omega_hat  iff a3 = pi - a_p;
  // (the other two sign pairings need cos a_p = 0, i.e. a_p = pi/2, which is both cases at once).
  // Each planet angle is reached at |p| carrier angles per period (convention 2). In the base
  // frame omega_hat = Rz(th2) Rx(a2) (0, sin a_p, cos a_p) = (sin a_s sin th2, -sin a_s cos th2,
  // cos a_s): the sun's pitch cone.
  const bool on_pitch = c.status == CriterionStatus::equality_at_lower || c.status == CriterionStatus::equality_at_both;
  const bool on_mirror = c.status == CriterionStatus::equality_at_upper || c.status == CriterionStatus::equality_at_both;
  const double a_s = train.sun_cone();
  std::vector<AnalyticCusp> out;
  auto add = [&](double th3, double sign, BoundaryKind cone) {
    for (double t2 : params_at_planet_angle(train, th3)) {
      const Vector3d omega_hat(std::sin(a_s) * std::sin(t2), -std::sin(a_s) * std::cos(t2), std::cos(a_s));
      out.push_back(AnalyticCusp{Vector3d(sign * omega_hat), t2, cone});
    }
  };
  if (on_pitch) add(pi(), 1.0, BoundaryKind::pitch_cone);
  if (on_mirror) add(0.0, -1.0, BoundaryKind::mirror_pitch_cone);
  std::sort(out.begin(), out.end(), [](const AnalyticCusp& a, const AnalyticCusp& b) { return a.param < b.param; });
  return out;
}

}  // namespace criteria_detail

inline std::vector<AnalyticCusp> pitch_cone_cusps(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  return criteria_detail::pitch_cone_cusps_of(train, pitch_cone_criterion(train, tol));
}

inline AnalyticClassification classify_analytic(const GearTrain& train, double tol) {
  using namespace criteria_detail;
  if (!(tol >= 0.0))
    throw InvalidInput("boundary_tolerance", report_number(tol), "not a number >= 0", ">= 0 radians");
  AnalyticClassification a;
  a.tolerance = tol;
  a.boundaries_hit = boundaries_hit(train, tol);
  if (is_n(train, 1)) {  // each criterion computed once, its nodes read from it
    a.applicable = true;
    a.criteria.push_back(criterion_eq24(train, tol));
    a.nodes = nodes_eq25_of(train, a.criteria.back(), tol);
  } else if (is_n(train, 2)) {
    a.applicable = true;
    a.criteria.push_back(criterion_eq43(train, tol));
    a.nodes = nodes_eq39b_of(train, a.criteria.back(), tol);
    a.criteria.push_back(criterion_eq46(train, tol));
    const std::vector<AnalyticNode> more = nodes_eq44b_of(train, a.criteria.back(), tol);
    a.nodes.insert(a.nodes.end(), more.begin(), more.end());
  }
  a.criteria.push_back(pitch_cone_criterion(train, tol));
  a.cusps = pitch_cone_cusps_of(train, a.criteria.back());
  a.predicted_cusps = a.cusps.size();
  if (a.applicable) {
    a.predicted_nodes = a.nodes.size();
    const bool nodes = !a.nodes.empty(), cusps = !a.cusps.empty();
    a.curve_class = nodes && cusps ? "nodes and cusps" : nodes ? "nodes" : cusps ? "cusps" : "simple curve";
  } else {
    a.curve_class = a.cusps.empty() ? "no cusps (nodes not predicted)" : "cusps (nodes not predicted)";
  }
  return a;
}

inline std::vector<Cusp> cusp_points(const GearTrain& analysed) {
  const TracerCurve<double> curve(analysed);
  std::vector<Cusp> out;
  for (const AnalyticCusp& a : pitch_cone_cusps(analysed, kCuspResolution)) {
    Cusp k;
    k.param = a.param;
    k.position = curve.point(a.param);
    k.speed = curve.velocity(a.param).norm();
    out.push_back(k);
  }
  return out;
}

}  // namespace sphtroch
