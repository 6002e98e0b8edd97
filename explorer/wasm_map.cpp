// explorer/wasm_map.cpp — the a3 ruler (the boundary events at one a2, `sphtroch boundaries`) and
// the design map for one n (node counts off the events on a grid of cells, the boundary curves).
// One thread: nothing here starts one (the page runs the map in a worker).
#include "wasm_common.hpp"

#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/map/boundary_events.hpp"

#include <cmath>
#include <cstdint>

namespace sphtroch::wasm {

namespace {

/// The boundary events of the a3 ruler at one a2 (`sphtroch boundaries`): ascending a3, each with
/// its shortest round-trip text, kind, name and the node counts on both sides.
val events(const std::string& a2, const std::string& n, const std::string& teeth) {
  return guarded([&] {
    const double a2v = parse_angle(a2, "a2");
    const Ratio ratio = ratio_of(n, teeth);
    const BoundarySet set = boundary_set(a2v, ratio);
    val list = val::array();
    for (const BoundaryEvent& e : set.events) {
      val item = val::object();
      item.set("a3", e.a3);
      item.set("text", number_text(e.a3));
      item.set("kind", std::string(to_string(e.kind)));
      item.set("name", e.name);
      item.set("nodesBelow", static_cast<double>(e.nodes_below));
      item.set("nodesAbove", static_cast<double>(e.nodes_above));
      item.set("cuspsAbove", static_cast<double>(e.cusps_above));
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("a2", a2v);
    out.set("n", ratio.str());
    out.set("events", list);
    return out;
  });
}

/// The node count of one map cell (-1 if the library ever refused a cell: none is refused today,
/// every cell centre lies inside (0, pi)^2; the page greys such a cell).
std::int32_t cell_count(double a2, double a3, const Ratio& ratio) {
  try {
    return static_cast<std::int32_t>(node_count_off_events(a2, a3, ratio));
  } catch (const InvalidInput&) {
    return -1;
  }
}

/// Node counts off events on a grid of cell centres (the design map): a2 along columns, a3 along
/// rows, row-major from the lowest a3 (Int32Array of nx * ny; -1 where no train exists).
val map_counts(const std::string& n, const std::string& teeth, double a2_lo, double a2_hi, double a3_lo, double a3_hi,
               double nx, double ny) {
  return guarded([&] {
    const Ratio ratio = ratio_of(n, teeth);
    if (!(nx >= 1 && ny >= 1 && nx * ny <= 1 << 22))
      throw InvalidInput("map", number_text(nx) + "x" + number_text(ny), "outside the valid range", "1 .. 4194304 cells");
    const auto columns = static_cast<std::size_t>(nx), rows = static_cast<std::size_t>(ny);
    std::vector<std::int32_t> counts(columns * rows);
    for (std::size_t j = 0; j < rows; ++j)
      for (std::size_t i = 0; i < columns; ++i) {
        const double a2 = a2_lo + (a2_hi - a2_lo) * (static_cast<double>(i) + 0.5) / nx;
        const double a3 = a3_lo + (a3_hi - a3_lo) * (static_cast<double>(j) + 0.5) / ny;
        counts[j * columns + i] = cell_count(a2, a3, ratio);
      }
    val out = val::object();
    out.set("counts", val::global("Int32Array").new_(emscripten::typed_memory_view(counts.size(), counts.data())));
    return out;
  });
}

/// The boundary curves of the map for one n (`sphtroch boundaries --a2 0:pi --steps S`): each
/// {kind, name, points: Float64Array a2 a3 a2 a3 ...}.
val loci(const std::string& n, const std::string& teeth, double steps) {
  return guarded([&] {
    const Ratio ratio = ratio_of(n, teeth);
    if (!(steps >= 1 && steps <= static_cast<double>(kMaxLocusSteps) && steps == std::floor(steps)))
      throw InvalidInput("steps", number_text(steps), "outside the valid range", "integer 1 .. 10000");
    const double pi = Constants<double>::pi();
    val list = val::array();
    for (const Locus& locus : boundary_loci(ratio, 0.0, pi, static_cast<std::size_t>(steps), 1)) {
      std::vector<double> xy;
      for (const LocusPoint& p : locus.points) xy.insert(xy.end(), {p.a2, p.a3});
      val item = val::object();
      item.set("kind", std::string(to_string(locus.kind)));
      item.set("name", locus.name);
      item.set("points", float64_array(xy));
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("loci", list);
    return out;
  });
}

}  // namespace

void register_map() {
  emscripten::function("events", &events);
  emscripten::function("mapCounts", &map_counts);
  emscripten::function("loci", &loci);
}

}  // namespace sphtroch::wasm
