// explorer/wasm_tolerance.cpp — what `sphtroch tolerance` proves about a train (tolerance/
// tolerance_box.hpp, the certified engine on CGAL's Interval_nt): the certified margin to the
// nearest boundary of the map and the verdict on a box of tolerances, with the largest proved move
// of each node and cusp.
#include "wasm_common.hpp"

#include "sphtroch/io/parse.hpp"
#include "sphtroch/tolerance/tolerance_box.hpp"

#include <cmath>
#include <optional>

namespace sphtroch::wasm {

namespace {

/// The boundary a margin or a verdict names: {kind, name, a2, a3}, or null.
val witness_object(const std::optional<BoundaryWitness>& w) {
  if (!w) return val::null();
  val out = val::object();
  out.set("kind", std::string(to_string(event_kind(w->boundary))));
  out.set("name", boundary_text(w->boundary));
  out.set("a2", w->a2());
  out.set("a3", w->a3());
  return out;
}

/// The largest proved move of each node (or cusp) over the box, radians; NaN where not proved.
val displacements(const std::vector<NodeTolerance>& points) {
  std::vector<double> d;
  for (const NodeTolerance& p : points) d.push_back(p.max_displacement ? *p.max_displacement : std::nan(""));
  return float64_array(d);
}

/// What `sphtroch tolerance` proves for the box [a2 -+ tolA2] x [a3 -+ tolA3] x [phase -+ tolPhase]
/// (half-widths as angle texts: "1e-3", "0.1deg", "pi/1800"), for the train read onto its boundaries
/// with the page's census (PageCensus: the root census; certify() certifies it): {margin: {lower,
/// upper, converged, nearest: {kind, name, a2, a3} | null}, topology: "holds" | "changes" |
/// "undecided", why, event | null, nodes, cusps: Float64Array of max displacements (NaN: not
/// proved), box: {a2, a3, phase} (the half-widths, radians), a2, a3 (the train analysed)}.
val tolerance(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
              const std::string& teeth, const std::string& tol_a2, const std::string& tol_a3, const std::string& tol_phase) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const ToleranceBox box{parse_angle(tol_a2, "tol-a2"), parse_angle(tol_a3, "tol-a3"), parse_angle(tol_phase, "tol-phase")};
    const PageCensus census = page_census(t);
    check_tolerance_box(census.analysed, box, {"tol-a2", "tol-a3", "tol-phase"});
    const BoxTolerance r = box_tolerance(census.analysed, census.roots.node_points, cusp_points(census.analysed), box);
    val margin = val::object();
    margin.set("lower", r.margin.lower);
    margin.set("upper", r.margin.upper);
    margin.set("converged", r.margin.converged);
    margin.set("nearest", witness_object(r.margin.nearest));
    val out = val::object();
    out.set("margin", margin);
    out.set("topology", std::string(to_string(r.topology.verdict)));
    out.set("why", r.topology.why);
    out.set("event", witness_object(r.topology.event));
    out.set("nodes", displacements(r.nodes));
    out.set("cusps", displacements(r.cusps));
    val half_widths = val::object();
    half_widths.set("a2", box.da2);
    half_widths.set("a3", box.da3);
    half_widths.set("phase", box.dphase);
    out.set("box", half_widths);
    out.set("a2", census.analysed.a2());
    out.set("a3", census.analysed.a3());
    return out;
  });
}

}  // namespace

void register_tolerance() { emscripten::function("tolerance", &tolerance); }

}  // namespace sphtroch::wasm
