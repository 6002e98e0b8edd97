// sphtroch/io/node_csv.hpp — the CSV tables of the analysis commands that are not trajectories (for
// those see trace_output.hpp): nodes and cusps, the screw axis, and the edge pairs of a polyline
// crossing search. Eigen only (the edge-pair writer is a template over the pair type, so this
// header needs no CGAL). The polyline reader is polyline_input.hpp.
//
//   sphtroch::write_nodes_csv(std::cout, analysis.nodes(), analysis.cusps());
//   sphtroch::write_screw_axis_csv(std::cout, samples.t, samples.omega);
//   sphtroch::write_edge_pairs_csv(file, sc.crossings, sc.touchings);   // file: OutputFile; sc = find_self_crossings(...)
//
// Formats (one header line, then one row per item; numbers in the shortest round-trip form of
// number_text.hpp, so every value reads back as the same double):
//   nodes:      kind,x,y,z,t1,t2,branches,id
//               a node row per node (kind crossing | tangency; t1, t2 its first two branch
//               parameters theta2, t2 = t1 when it has one; branches its branch count; id N1, N2,
//               ...), then a cusp row per cusp (kind cusp, t1 = t2 = its parameter, branches 1,
//               id C1, C2, ...). The ids are the labels of `sphtroch plot` and the "id" of the
//               JSON; last, so that readers of the columns before it are unchanged.
//   screw axis: t,wx,wy,wz       omega = Z1 + n Z2 (Eq. 47a) at theta2 = t, base frame.
//   edge pairs: i,j,kind         crossings and touchings together, ascending (i, j); edge e
//               joins vertex e to e + 1; kind as to_string(pair.kind) gives it.
#pragma once

#include "sphtroch/core/cone_distance.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/output_file.hpp"
#include "sphtroch/core/types.hpp"

#include <algorithm>
#include <charconv>
#include <ostream>
#include <string_view>
#include <vector>

namespace sphtroch {

/// Header lines (without newline).
constexpr const char* kNodesCsvHeader = "kind,x,y,z,t1,t2,branches,id";
constexpr const char* kScrewAxisCsvHeader = "t,wx,wy,wz";
constexpr const char* kEdgePairsCsvHeader = "i,j,kind";

/// How the nodes table is written: positions times `radius` (the cone distance, any unit, in
/// [1e-100, 1e100]: core/cone_distance.hpp, else InvalidInput; 1: the unit sphere), parameters in degrees (header t1_deg,t2_deg) when `degrees`.
struct NodesCsvOptions {
  double radius = 1.0;
  bool degrees = false;
};

/// The nodes table: header, node rows, cusp rows (see top). REQUIRES: every node has a parameter.
inline void write_nodes_csv(std::ostream& out, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                            const NodesCsvOptions& options = {});

/// The screw-axis table. REQUIRES: t.size() == omega.size().
inline void write_screw_axis_csv(std::ostream& out, const std::vector<double>& t, const std::vector<Vector3d>& omega);

/// The edge-pair table of a crossing search: `crossings` and `touchings` merged, sorted by (i, j).
/// Pair: any type with members i, j (integers) and kind, and a to_string(kind) found by ADL
/// (sphtroch::EdgePair of self_crossings.hpp). Throws what `out` throws.
template <typename Pair>
void write_edge_pairs_csv(OutputFile& out, const std::vector<Pair>& crossings, const std::vector<Pair>& touchings);

/// The same table streamed: the header, then one row per pair as the search finds it.
inline void write_edge_pairs_header(OutputFile& out);
template <typename Pair>
void write_edge_pair_row(OutputFile& out, const Pair& e);

// ---------------------------------------------------------------------------------------------
// Implementation details follow.

namespace csv_io_detail {
inline void write_vector(std::ostream& out, const Vector3d& v) {
  out << number_text(v.x()) << ',' << number_text(v.y()) << ',' << number_text(v.z());
}
inline Vector3d scaled(const Vector3d& v, double radius) { return radius == 1.0 ? v : Vector3d(radius * v); }
}  // namespace csv_io_detail

inline void write_nodes_csv(std::ostream& out, const std::vector<Node>& nodes, const std::vector<Cusp>& cusps,
                            const NodesCsvOptions& options) {
  namespace d = csv_io_detail;
  check_cone_distance(options.radius);  // before the first byte
  const auto angle = [&](double t) { return number_text(options.degrees ? degrees(t) : t); };
  out << (options.degrees ? "kind,x,y,z,t1_deg,t2_deg,branches,id" : kNodesCsvHeader) << '\n';
  std::size_t id = 0;
  for (const Node& n : nodes) {
    SPHTROCH_ASSERT(!n.params.empty(), "a node has at least one branch parameter");
    out << to_string(n.kind) << ',';
    d::write_vector(out, d::scaled(n.position, options.radius));
    out << ',' << angle(n.params.front()) << ',' << angle(n.params.size() > 1 ? n.params[1] : n.params.front()) << ','
        << n.branches << ",N" << ++id << '\n';
  }
  id = 0;
  for (const Cusp& k : cusps) {
    out << "cusp,";
    d::write_vector(out, d::scaled(k.position, options.radius));
    out << ',' << angle(k.param) << ',' << angle(k.param) << ",1,C" << ++id << '\n';
  }
}

inline void write_screw_axis_csv(std::ostream& out, const std::vector<double>& t, const std::vector<Vector3d>& omega) {
  SPHTROCH_ASSERT(t.size() == omega.size(), "one screw axis per parameter");
  out << kScrewAxisCsvHeader << '\n';
  for (std::size_t i = 0; i < t.size(); ++i) {
    out << number_text(t[i]) << ',';
    csv_io_detail::write_vector(out, omega[i]);
    out << '\n';
  }
}

template <typename Pair>
void write_edge_pairs_csv(OutputFile& out, const std::vector<Pair>& crossings, const std::vector<Pair>& touchings) {
  std::vector<Pair> all = crossings;
  all.insert(all.end(), touchings.begin(), touchings.end());
  std::sort(all.begin(), all.end(), [](const Pair& x, const Pair& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; });
  write_edge_pairs_header(out);
  for (const Pair& e : all) write_edge_pair_row(out, e);
}

inline void write_edge_pairs_header(OutputFile& out) {
  out.write(kEdgePairsCsvHeader);
  out.write("\n");
}

template <typename Pair>
void write_edge_pair_row(OutputFile& out, const Pair& e) {
  const std::string_view kind = to_string(e.kind);
  char* p = out.reserve(2 * 20 + 3 + kind.size());  // two 64-bit integers, two commas, newline
  p = std::to_chars(p, p + 20, e.i).ptr;
  *p++ = ',';
  p = std::to_chars(p, p + 20, e.j).ptr;
  *p++ = ',';
  p = std::copy(kind.begin(), kind.end(), p);
  *p++ = '\n';
  out.advance(p);
}

}  // namespace sphtroch
