// sphtroch/exact/precision_points_output.hpp — precision points over a set of ratios, each train
// with its census, and the reports: the JSON that `sphtroch synth points --json` and Python's
// synth_points print, and the text that `sphtroch synth points` and Python's synth_points_text print.
//
//   const sphtroch::TracerCurve<double> curve(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
//   std::vector<sphtroch::Vector3d> pts = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
//   auto all = sphtroch::precision_points_with_census(pts, {sphtroch::Ratio(1, 2)});
//   std::string json = sphtroch::precision_points_json(all);   // {"solutions": [...], "complete": true, ...}
//   std::string text = sphtroch::precision_points_text(all);   // "n = 1/2: 4 train(s), all of them (certified)\n..."
//   all[0].margins[0].lower;                                   // the first train's certified margin, radians
//
// JSON: {"solutions": [{"n": "p/q", "teeth": "ZS:ZP" (only with a TeethSpec), "a2", "a3", "phase",
// free axis only: "axis": [x, y, z] (the sun axis), "frame": [X, Y, Z], the train's axes in the
// points' coordinates (point = X P_x(theta2) + Y P_y + Z P_z, P the train's curve; Z = axis),
// "params": [theta2 per point, input order],
// "residual", "certified_margin": {"lower", "upper"} (topology_margin.hpp: how far the train is from a
// change of its census, radians in (a2, a3)), "counts": {"nodes", "crossings", "tangencies", "cusps"},
// "census_certified", "isolated"
// (false: a near-singular root the certificate could not isolate, see PrecisionSolution)}],
// "complete": every ratio's list certified complete, "undecided_boxes": their sum}. Radians.
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/precision_points_output.hpp needs CGAL: link the CMake target sphtroch::exact"
#endif

#include "sphtroch/exact/classification.hpp"  // classify()'s result
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/teeth.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/synthesis/precision_solution.hpp"
#include "sphtroch/tolerance/tolerance_types.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace sphtroch {

/// The trains of one ratio through the points, and the census (classify) of each.
struct RatioPrecisionPoints {
  Ratio ratio;
  PrecisionPoints result;
  std::vector<Classification> census;  // one per solution, same order
  std::vector<TopologyMargin> margins; // topology_margin of each solution's train, same order
  bool free_axis = false;              // five points, the sun axis free (free_axis_points)
};

/// precision_points (or, with free_axis, free_axis_points) for each ratio, then classify() and
/// topology_margin() of every train found (defined in precision_points_analysis.hpp). A function
/// template (Options = PrecisionPointsOptions), like classify(), so that files built with and
/// without SPHTROCH_SEPARATE_EXACT share one program.
template <typename Options = PrecisionPointsOptions>
std::vector<RatioPrecisionPoints> precision_points_with_census(const std::vector<Vector3d>& points, const std::vector<Ratio>& ratios,
                                                               const Options& options = {}, bool free_axis = false);

/// [x, y, z] of a vector, shortest round-trip numbers.
inline std::string vector_json(const Vector3d& v) {
  return "[" + number_text(v.x()) + ", " + number_text(v.y()) + ", " + number_text(v.z()) + "]";
}

/// One solution as a JSON object (see header); with free_axis also "axis" and "frame".
inline std::string precision_solution_json(const PrecisionSolution& s, const Classification& c, const TopologyMargin& margin,
                                           const TeethSpec& teeth = {}, bool free_axis = false) {
  std::ostringstream out;
  out << "{\"n\": \"" << s.train.ratio().str() << "\", ";
  if (const auto t = teeth.of(s.train.ratio())) out << "\"teeth\": \"" << t->str() << "\", ";
  out << "\"a2\": " << number_text(s.train.a2())
      << ", \"a3\": " << number_text(s.train.a3()) << ", \"phase\": " << number_text(s.train.phase_given());
  if (free_axis)
    out << ", \"axis\": " << vector_json(s.frame.col(2)) << ", \"frame\": [" << vector_json(s.frame.col(0)) << ", "
        << vector_json(s.frame.col(1)) << ", " << vector_json(s.frame.col(2)) << "]";
  out << ", \"params\": [";
  for (std::size_t i = 0; i < s.params.size(); ++i) out << (i ? ", " : "") << number_text(s.params[i]);
  out << "], \"residual\": " << number_text(s.residual) << ", \"certified_margin\": {\"lower\": " << number_text(margin.lower)
      << ", \"upper\": " << number_text(margin.upper) << "}, \"counts\": {\"nodes\": " << c.nodes.size()
      << ", \"crossings\": " << c.crossings << ", \"tangencies\": " << c.tangencies << ", \"cusps\": " << c.cusps.size()
      << "}, \"census_certified\": " << (c.certified() ? "true" : "false")
      << ", \"isolated\": " << (s.isolated ? "true" : "false") << "}";
  return out.str();
}

/// The whole result as JSON (see header), one solution per line. `fields`, if any, are more
/// members written first (e.g. "\"ratios\": \"7,7\", " for a ratio set).
inline std::string precision_points_json(const std::vector<RatioPrecisionPoints>& all, const std::string& fields = "",
                                         const TeethSpec& teeth = {}) {
  std::string out = "{" + fields + "\"solutions\": [";
  bool first = true, complete = true;
  std::size_t undecided = 0;
  for (const auto& rs : all) {
    complete = complete && rs.result.certified;
    undecided += rs.result.undecided;
    for (std::size_t k = 0; k < rs.result.solutions.size(); ++k) {
      out += (first ? "\n  " : ",\n  ") + precision_solution_json(rs.result.solutions[k], rs.census[k], rs.margins[k], teeth, rs.free_axis);
      first = false;
    }
  }
  out += std::string(first ? "" : "\n") + "], \"complete\": " + (complete ? "true" : "false") +
         ", \"undecided_boxes\": " + std::to_string(undecided) + "}\n";
  return out;
}

/// The whole result as text for people (what `sphtroch synth points` prints): per ratio a line
/// with its train count and whether the list is certified complete, then each train with its
/// angles, theta2 at the points, residual, census and the command that plots it.
inline std::string precision_points_text(const std::vector<RatioPrecisionPoints>& all, const TeethSpec& teeth = {}) {
  std::ostringstream out;
  std::size_t index = 0;
  for (const auto& rs : all) {
    out << "n = " << rs.ratio.str() << teeth_text(teeth, rs.ratio) << ": " << rs.result.solutions.size() << " train(s)"
        << (rs.result.certified ? ", all of them (certified)" : ", NOT certified complete") << "\n";
    for (std::size_t k = 0; k < rs.result.solutions.size(); ++k) {
      const PrecisionSolution& s = rs.result.solutions[k];
      const Classification& c = rs.census[k];
      out << "  " << ++index << ". a2 = " << report_number(s.train.a2()) << ", a3 = " << report_number(s.train.a3())
          << ", phase = " << report_number(s.train.phase_given());
      if (rs.free_axis)
        out << "; sun axis " << vector_json(s.frame.col(2)) << ", frame x " << vector_json(s.frame.col(0)) << ", y "
            << vector_json(s.frame.col(1));
      out << "; theta2 at the points:";
      for (const double t : s.params) out << " " << report_number(t);
      out << "; residual " << report_number(s.residual) << "; " << c.nodes.size() << " node(s), " << c.cusps.size()
          << " cusp(s)" << (c.certified() ? "" : " (census NOT certified)") << "; certified margin "
          << report_number(rs.margins[k].lower) << " .. " << report_number(rs.margins[k].upper) << " rad"
          << (s.isolated ? "" : " (root NOT isolated: near-singular)") << "\n"
          << "     plot it: sphtroch plot " << train_arguments(s.train) << " -o train" << index << ".svg"
          << (rs.free_axis ? " (in the train's frame above)" : "") << "\n";
    }
  }
  return out.str();
}

}  // namespace sphtroch
