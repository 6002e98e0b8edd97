// explorer/sphtroch_wasm.cpp — the Eigen-only library as a WebAssembly module for the explorer
// page (embind; built by the CMake target `explorer` with emscripten's em++).
//
// Every function takes the CLI's texts ("pi/3", "ap+1e-6", "5/2", teeth "39:15") through the same
// parsers (io/train_text.hpp), so a URL, a scene, the CLI and the page read a train alike. No
// exception reaches JavaScript: a refused input returns {error: "<the CLI's one line>"} (the
// field, the value, the valid range), and the page shows that line instead of any number.
// Where the library writes a format (the trace CSV, the sphere picture SVG), the module returns
// the library's text, so that the page's exports are the bytes of `sphtroch trace` and `sphtroch
// plot` (the picture's grid lines up to a vertex: see plot_svg). Nothing here starts a thread.
// A count is certified by the library's rule, the CLI's (exact/certified_census.hpp: the polyline
// census with CGAL's exact predicates against the root census), compiled header-only without GMP
// (SPHTROCH_EXACT_WITHOUT_GMP, CGAL_NO_GMP: see explorer/CMakeLists.txt).
// A clinostat (machine/) is read by the CLI's reader (ClinostatText) and computed by the library's
// functions that `sphtroch clinostat` runs (its train, period, mean, M(W), time to epsilon); the
// dwell map needs HEALPix, which the module does not have.
// A rotation chain is read by the CLI's reader (ChainText) and drawn with its census as `sphtroch
// chain plot` draws it (chain_picture_svg, the chain census); a gear train is handed to the page.
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/curve_view.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/exact/certified_census.hpp"
#include "sphtroch/census/interval/chain_picture.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/polyline_input.hpp"
#include "sphtroch/io/trace_output.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/map/boundary_events.hpp"
#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"
#include "sphtroch/machine/clinostat_text.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"
#include "sphtroch/synthesis/interval/precision_points.hpp"
#include "sphtroch/synthesis/interval/tolerance_box.hpp"
#include "sphtroch/synthesis/path_fit.hpp"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using emscripten::val;
using sphtroch::GearTrain;
using sphtroch::Ratio;

/// The page's error line: what `sphtroch` prints on stderr for the same texts.
val error_object(const std::string& line) {
  val out = val::object();
  out.set("error", "sphtroch: " + sphtroch::one_line_text(line));
  return out;
}

/// Runs body() and turns every exception into {error: ...}: InvalidInput as the CLI words it
/// ("--a2 = 7: ...; valid: ..."), anything else as an internal error (never thrown to JS).
template <typename Body>
val guarded(Body body) {
  try {
    return body();
  } catch (const sphtroch::InvalidInput& e) {
    return error_object(std::string("--") + e.what());
  } catch (const std::exception& e) {
    return error_object(std::string("internal error: ") + e.what());
  }
}

val float64_array(const std::vector<double>& values) {
  return val::global("Float64Array").new_(emscripten::typed_memory_view(values.size(), values.data()));
}

/// Vectors as x0 y0 z0 x1 ...
std::vector<double> flat(const std::vector<sphtroch::Vector3d>& vectors) {
  std::vector<double> xyz;
  xyz.reserve(vectors.size() * 3);
  for (const sphtroch::Vector3d& v : vectors) xyz.insert(xyz.end(), v.data(), v.data() + 3);
  return xyz;
}

val string_list(const std::vector<std::string>& items) {
  val out = val::array();
  for (const std::string& s : items) out.call<void>("push", s);
  return out;
}

sphtroch::TrainText train_text(const std::string& a2, const std::string& a3, const std::string& n,
                               const std::string& phase, const std::string& teeth) {
  return sphtroch::TrainText{a2, a3, n, phase.empty() ? "0" : phase, teeth};
}

val train_object(const GearTrain& t) {
  val out = val::object();
  out.set("a2", t.a2());
  out.set("a3", t.a3());
  out.set("phase", t.phase());
  out.set("n", t.ratio().str());
  out.set("p", static_cast<double>(t.ratio().p()));
  out.set("q", static_cast<double>(t.ratio().q()));
  out.set("period", t.period());
  out.set("planetCone", t.planet_cone());
  return out;
}

val node_positions(const std::vector<sphtroch::Node>& nodes) {
  std::vector<double> xyz;
  for (const sphtroch::Node& node : nodes) xyz.insert(xyz.end(), node.position.data(), node.position.data() + 3);
  return float64_array(xyz);
}

val node_list(const std::vector<sphtroch::Node>& nodes) {
  val out = val::array();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const sphtroch::Node& node = nodes[i];
    val item = val::object();
    item.set("id", static_cast<double>(i + 1));
    item.set("kind", std::string(sphtroch::to_string(node.kind)));
    item.set("x", node.position.x());
    item.set("y", node.position.y());
    item.set("z", node.position.z());
    item.set("params", float64_array(node.params));
    out.call<void>("push", item);
  }
  return out;
}

val criteria_list(const std::vector<sphtroch::Criterion>& criteria) {
  val out = val::array();
  for (const sphtroch::Criterion& c : criteria) {
    val item = val::object();
    item.set("equation", c.equation);
    item.set("statement", c.statement);
    item.set("status", std::string(sphtroch::to_string(c.status)));
    item.set("lowerMargin", c.lower_margin);
    item.set("upperMargin", c.upper_margin);
    item.set("prediction", c.prediction);
    out.call<void>("push", item);
  }
  return out;
}

/// The page's census of one train: the root census (classify_roots) of the train read onto its
/// boundaries (`analysed`, as the CLI reads it). Its count is not certified by itself: see
/// page_certificate.
struct PageCensus {
  GearTrain analysed;
  sphtroch::RootClassification roots;
};

PageCensus page_census(const GearTrain& t) {
  return {sphtroch::snap_to_boundaries(t, sphtroch::Reading{}.boundary()).train, sphtroch::classify_roots(t)};
}

/// The certificate of `sphtroch classify` for the analysed train: certified_census (the polyline
/// census against root_census, escalated while they disagree) at the CLI's default settings (the
/// default reading's tangency tolerance, the default samples), as exact/analysis.hpp runs it.
/// When certified, the root census's nodes (PageCensus::roots) are the certified ones: the
/// censuses agree node for node, kind and branches included (census/node_sets.hpp).
sphtroch::CensusCertificate page_certificate(const PageCensus& census) {
  const sphtroch::Reading reading;
  sphtroch::RootCensusSettings rs;
  rs.tangency_tolerance = reading.tangency();
  sphtroch::PolylineCensusSettings ps;
  ps.tangency_tolerance = reading.tangency();
  return sphtroch::certified_census(census.analysed, ps, sphtroch::root_census(census.analysed, rs)).certificate;
}

/// The cusps of the analysed train as `sphtroch plot` and `sphtroch nodes` list them (the cusp
/// stage of exact/analysis.hpp): the pitch-cone criterion's parameters, the point and speed there.
std::vector<sphtroch::Cusp> cusps_of(const GearTrain& analysed) {
  const sphtroch::TracerCurve<double> curve(analysed);
  std::vector<sphtroch::Cusp> out;
  for (const sphtroch::AnalyticCusp& a : sphtroch::pitch_cone_cusps(analysed, sphtroch::kCuspResolution)) {
    sphtroch::Cusp k;
    k.param = a.param;
    k.position = curve.point(a.param);
    k.speed = curve.velocity(a.param).norm();
    out.push_back(k);
  }
  return out;
}

/// The class, counts and node points of one train by the root census (PageCensus): fast enough
/// for every slider step, not certified (certify() is).
val classify(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
             const std::string& teeth) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const PageCensus census = page_census(t);
    const sphtroch::RootClassification& c = census.roots;
    const sphtroch::ZExtremes z = sphtroch::z_extremes(t);
    const sphtroch::AnalyticClassification a = sphtroch::classify_analytic(t);
    val out = train_object(t);
    out.set("class", std::string(sphtroch::to_string(c.curve_class)));
    out.set("nodes", static_cast<double>(c.nodes));
    out.set("crossings", static_cast<double>(c.crossings));
    out.set("tangencies", static_cast<double>(c.tangencies));
    out.set("cusps", static_cast<double>(c.cusps));
    out.set("readOn", string_list(c.boundaries));
    out.set("nodePoints", node_list(c.node_points));
    out.set("nodePositions", node_positions(c.node_points));
    // The cusps where classify_roots finds them: on the train read onto its boundaries.
    std::vector<double> cusp_xyz;
    for (const sphtroch::AnalyticCusp& cusp : sphtroch::pitch_cone_cusps(census.analysed, sphtroch::kCuspResolution))
      cusp_xyz.insert(cusp_xyz.end(), cusp.position.data(), cusp.position.data() + 3);
    out.set("cuspPositions", float64_array(cusp_xyz));
    out.set("zMax", z.z_max);
    out.set("zMin", z.z_min);
    out.set("criteria", criteria_list(a.criteria));
    out.set("reportClass", a.curve_class);
    return out;
  });
}

/// The certificate of classify()'s count (page_certificate: the CLI's rule): {certified, rootNodes,
/// runs: [{samples, nodes}] (each polyline census run: uniform samples, node count), stopped (why
/// escalation stopped, "" when certified), disagreement (the last run's first difference)}.
val certify(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
            const std::string& teeth) {
  return guarded([&] {
    const sphtroch::CensusCertificate cert = page_certificate(page_census(train_text(a2, a3, n, phase, teeth).train()));
    val runs = val::array();
    for (std::size_t i = 0; i < cert.runs(); ++i) {
      val run = val::object();
      run.set("samples", static_cast<double>(cert.samples[i]));
      run.set("nodes", static_cast<double>(cert.polyline_nodes[i]));
      runs.call<void>("push", run);
    }
    val out = val::object();
    out.set("certified", cert.certified);
    out.set("rootNodes", static_cast<double>(cert.root_nodes));
    out.set("runs", runs);
    out.set("stopped", cert.stopped);
    out.set("disagreement", cert.disagreement);
    return out;
  });
}

/// Which node and cusp markers a picture of `nodes` nodes and `cusps` cusps draws in `mode` ("auto",
/// "all", "none"; the library's rule, draw/mark_density.hpp, as `sphtroch plot --markers`):
/// {draw, note, dense} (dense: the automatic rule hides them), or {error} naming "markers".
val marks(const std::string& mode, double nodes, double cusps) {
  return guarded([&] {
    const sphtroch::MarkChoice m =
        sphtroch::choose_marks(sphtroch::parse_mark_mode(mode), static_cast<std::size_t>(nodes), static_cast<std::size_t>(cusps));
    val out = val::object();
    out.set("draw", m.draw);
    out.set("note", m.note);
    out.set("dense", sphtroch::dense_curve(static_cast<std::size_t>(nodes), static_cast<std::size_t>(cusps)));
    return out;
  });
}

/// A sample count the page may ask for: an integer 3 .. 1e6 (InvalidInput "samples" otherwise).
std::size_t page_samples(double samples) {
  if (!(samples >= 3 && samples <= 1e6 && samples == static_cast<double>(static_cast<std::int64_t>(samples))))
    throw sphtroch::InvalidInput("samples", sphtroch::number_text(samples), "outside the valid range",
                                 "integer 3 .. 1000000");
  return static_cast<std::size_t>(samples);
}

/// `samples` points of one period (the CLI's trace --samples), as x0 y0 z0 x1 ... (unit vectors),
/// and with `velocity` their velocities dP/dtheta2 = omega x P (Eq. 47a; the CLI's --velocity) as
/// `velocities`, laid out the same; `view`: the direction `sphtroch plot` looks from by default,
/// chosen from these points (draw/curve_view.hpp), [x, y, z].
val trace(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
          const std::string& teeth, double samples, bool velocity) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const sphtroch::TracerCurve<double> curve(t);
    const auto sampled = sphtroch::sample_period(curve, page_samples(samples), velocity);
    val out = val::object();
    out.set("points", float64_array(flat(sampled.points)));
    if (velocity) out.set("velocities", float64_array(flat(sampled.velocities)));
    out.set("params", float64_array(sampled.t));
    const std::vector<sphtroch::Vector3d> points(sampled.points.begin(), sampled.points.end());
    const sphtroch::Vector3d view = sphtroch::view_of_curve(points, true).direction;
    out.set("view", float64_array(std::vector<double>{view.x(), view.y(), view.z()}));
    return out;
  });
}

val text_object(const std::string& text) {
  val out = val::object();
  out.set("text", text);
  return out;
}

/// The trace CSV of `samples` points of one period of the train as given: {text}, the bytes
/// `sphtroch trace --samples N` prints for the same texts (io/trace_output.hpp's writer).
val trace_csv(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
              const std::string& teeth, double samples) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    std::ostringstream out;
    sphtroch::write_trajectory_csv(out, sphtroch::sample_period(sphtroch::TracerCurve<double>(t), page_samples(samples)));
    return text_object(out.str());
  });
}

/// The caption of `sphtroch plot` (draw/svg_plot.hpp's plot_caption_text, the tool's words); a
/// count page_certificate does not certify is said so.
std::string plot_caption(const sphtroch::TrainText& text, const PageCensus& census, std::size_t cusps) {
  const sphtroch::RootClassification& c = census.roots;
  const std::string caption = sphtroch::plot_caption_text(text, census.analysed, c.crossings, c.tangencies, cusps);
  return page_certificate(census).certified ? caption : caption + " — count not certified in the page: run sphtroch plot";
}

/// The sphere picture of `sphtroch plot` for the same texts (draw/svg_plot.hpp's renderer, the
/// default view and size): {text}. The curve, the cusps and the caption's train are those of the
/// train read onto its boundaries, as the CLI's; the node marks are the page's census (the root
/// census, the CLI's count when certified; its marks agree with the CLI's at the picture's
/// precision, labelled in the same order, by the first branch parameter), drawn as `markers`
/// says ("auto", "all", "none": `sphtroch plot --markers`). Runs the certified census (the
/// caption says when it does not certify).
val plot_svg(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
             const std::string& teeth, const std::string& markers) {
  return guarded([&] {
    const sphtroch::TrainText text = train_text(a2, a3, n, phase, teeth);
    const PageCensus census = page_census(text.train());
    const std::vector<sphtroch::Cusp> cusps = cusps_of(census.analysed);
    sphtroch::PlotOptions options;
    options.markers = sphtroch::parse_mark_mode(markers);
    options.caption = plot_caption(text, census, cusps.size());
    const sphtroch::Trajectory<double> trajectory =
        sphtroch::sample_period(sphtroch::TracerCurve<double>(census.analysed), sphtroch::plot_sample_count(census.analysed));
    return text_object(sphtroch::render_sphere_svg(trajectory, census.roots.node_points, cusps, options));
  });
}

/// `sphtroch chain plot --twists T --rates R --phases P --markers M` (phases "": all 0) for a
/// chain that is not a gear train: {text: its SVG, the CLI's bytes (chain_picture_svg of the chain
/// census, classify_chain's for such a chain), nodes, cusps, certified, why}. A two-stage chain
/// with both rates not 0 is a gear train, whose census the CLI takes from classify's (MPFR, not in
/// the module): {train: {a2, a3, n, phase}} (gear_train_of), for the page to show as its design.
/// The census runs here, within chain classify's bound (refused up front beyond it).
val chain_plot(const std::string& twists, const std::string& rates, const std::string& phases, const std::string& markers) {
  return guarded([&] {
    sphtroch::ChainText text;
    text.twists = twists;
    text.rates = rates;
    text.phases = phases;
    const sphtroch::RotationChain chain = text.chain();
    sphtroch::PlotOptions options;
    options.markers = sphtroch::parse_mark_mode(markers);
    if (const std::optional<GearTrain> t = sphtroch::gear_train_of(chain)) {
      val train = val::object();
      train.set("a2", sphtroch::number_text(t->a2()));
      train.set("a3", sphtroch::number_text(t->a3()));
      train.set("n", t->ratio().str());
      train.set("phase", sphtroch::number_text(t->phase()));
      val out = val::object();
      out.set("train", train);
      return out;
    }
    const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
    val out = text_object(sphtroch::chain_picture_svg(chain, c, options));
    out.set("nodes", static_cast<double>(c.nodes.size()));
    out.set("cusps", static_cast<double>(c.cusps.size()));
    out.set("certified", c.certified);
    out.set("why", c.why);
    return out;
  });
}

/// The boundary events of the a3 ruler at one a2 (`sphtroch boundaries`): ascending a3, each with
/// its shortest round-trip text, kind, name and the node counts on both sides.
val events(const std::string& a2, const std::string& n, const std::string& teeth) {
  return guarded([&] {
    const double a2v = sphtroch::parse_angle(a2, "a2");
    const Ratio ratio = sphtroch::ratio_of(n, teeth);
    const sphtroch::BoundarySet set = sphtroch::boundary_set(a2v, ratio);
    val list = val::array();
    for (const sphtroch::BoundaryEvent& e : set.events) {
      val item = val::object();
      item.set("a3", e.a3);
      item.set("text", sphtroch::number_text(e.a3));
      item.set("kind", std::string(sphtroch::to_string(e.kind)));
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
    return static_cast<std::int32_t>(sphtroch::node_count_off_events(a2, a3, ratio));
  } catch (const sphtroch::InvalidInput&) {
    return -1;
  }
}

/// Node counts off events on a grid of cell centres (the design map): a2 along columns, a3 along
/// rows, row-major from the lowest a3 (Int32Array of nx * ny; -1 where no train exists).
val map_counts(const std::string& n, const std::string& teeth, double a2_lo, double a2_hi, double a3_lo,
               double a3_hi, double nx, double ny) {
  return guarded([&] {
    const Ratio ratio = sphtroch::ratio_of(n, teeth);
    if (!(nx >= 1 && ny >= 1 && nx * ny <= 1 << 22))
      throw sphtroch::InvalidInput("map", sphtroch::number_text(nx) + "x" + sphtroch::number_text(ny),
                                   "outside the valid range", "1 .. 4194304 cells");
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
/// {kind, name, points: Float64Array a2 a3 a2 a3 ...}. One thread (no thread is started).
val loci(const std::string& n, const std::string& teeth, double steps) {
  return guarded([&] {
    const Ratio ratio = sphtroch::ratio_of(n, teeth);
    if (!(steps >= 1 && steps <= static_cast<double>(sphtroch::kMaxLocusSteps) && steps == std::floor(steps)))
      throw sphtroch::InvalidInput("steps", sphtroch::number_text(steps), "outside the valid range", "integer 1 .. 10000");
    const double pi = sphtroch::Constants<double>::pi();
    val list = val::array();
    for (const sphtroch::Locus& locus : sphtroch::boundary_loci(ratio, 0.0, pi, static_cast<std::size_t>(steps), 1)) {
      std::vector<double> xy;
      for (const sphtroch::LocusPoint& p : locus.points) xy.insert(xy.end(), {p.a2, p.a3});
      val item = val::object();
      item.set("kind", std::string(sphtroch::to_string(locus.kind)));
      item.set("name", locus.name);
      item.set("points", float64_array(xy));
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("loci", list);
    return out;
  });
}

/// The points of a text as `sphtroch synth fit/points --input` reads them: the text goes to a file
/// of the module's memory file system named "points" (so errors name it) and the CLI's reader.
std::vector<sphtroch::Vector3d> read_page_points(const std::string& text) {
  FILE* f = std::fopen("points", "wb");
  const bool written = f && std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (!f || std::fclose(f) != 0 || !written) throw std::runtime_error("the points could not be handed to the reader");
  return sphtroch::read_polyline("points", "points", 1).vertices;
}

/// The page's bound on a fit's work (fit_path's unit: points x (2|p| + 30), ~0.5 us each natively):
/// about a second natively, a few in the page, whose main thread waits for it.
constexpr double kPageFitWork = 2e6;

/// Inverse design: the trains of ratio n (or teeth) nearest a path given as the text of `sphtroch
/// synth fit --input` (CSV rows x,y,z, or a header naming x, y, z), best first, optionally with a
/// wanted node count ("" = any). Read by the CLI's reader (the text goes to a file of the module's
/// memory file system named "points": errors name it) and fitted by fit_path, one thread. Each
/// candidate: {n, a2, a3, phase, rms, maxDeviation, margin, rootNodes} (radians); the page then
/// classifies it as any state (its count check). {candidates: [], reason} when none can be.
val fit(const std::string& points, const std::string& n, const std::string& teeth, const std::string& nodes) {
  return guarded([&] {
    const Ratio ratio = sphtroch::ratio_of(n, teeth);
    sphtroch::FitOptions options;
    if (!nodes.empty()) {
      // As `sphtroch synth fit --nodes` reads it.
      const std::size_t k = sphtroch::parse_count(nodes, "nodes", 0, sphtroch::kMaxWantedCount);
      options.nodes = static_cast<std::int64_t>(k);
    }
    const std::vector<sphtroch::Vector3d> path = read_page_points(points);
    const double per_point = 2 * static_cast<double>(ratio.abs_p()) + 30;  // fit_path's work per point
    if (static_cast<double>(path.size()) * per_point > kPageFitWork)
      throw sphtroch::InvalidInput("points", std::to_string(path.size()) + " points",
                                  "more than the page fits at once (points x (2|p| + 30) > 2e6)",
                                  "at most " + std::to_string(static_cast<long long>(kPageFitWork / per_point)) +
                                      " points for n = " + ratio.str() + " (sphtroch synth fit takes more)");
    const sphtroch::PathFit r = sphtroch::fit_path(path, ratio, options);
    val list = val::array();
    for (const sphtroch::FitCandidate& c : r.candidates) {
      val item = train_object(c.train);
      item.set("rms", c.rms);
      item.set("maxDeviation", c.max_deviation);
      item.set("margin", c.margin);
      item.set("rootNodes", static_cast<double>(c.root_nodes));
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("candidates", list);
    out.set("reason", r.reason);
    return out;
  });
}

/// The page's bounds on a precision-points search, which runs on its main thread: the estimated
/// work (|p| + q)^2 (`sphtroch synth points`' unit: the lists of Delta span 2 pi q and turn |n|
/// times faster), refused up front above kPagePointsWork (the CLI allows 20000); and the boxes,
/// beyond which the list is shown as not certified. Measured in the docs (docs/explorer.md).
constexpr double kPagePointsWork = 400;
constexpr std::size_t kPagePointsBoxes = 1000000;

/// Every train of ratio n (or teeth) whose tracer passes through three points (the text of
/// `sphtroch synth points --input`), fixed frame, certified as synthesis/interval/precision_points.hpp says
/// (the module's intervals: CGAL_ALWAYS_ROUND_TO_NEAREST, see explorer/CMakeLists.txt).
/// {solutions: [{n, a2, a3, phase, params, residual, isolated}], certified, undecided, boxes,
/// boxLimit}; the page classifies each solution as any state.
val points(const std::string& text, const std::string& n, const std::string& teeth) {
  return guarded([&] {
    const Ratio ratio = sphtroch::ratio_of(n, teeth);
    const double size = static_cast<double>(ratio.abs_p()) + static_cast<double>(ratio.q());
    if (size * size > kPagePointsWork)
      throw sphtroch::InvalidInput(teeth.empty() ? "n" : "teeth", teeth.empty() ? n : teeth,
                                   "too much work for the page's precision points ((|p| + q)^2 = " +
                                       sphtroch::number_text(size * size) + ")",
                                   "(|p| + q)^2 <= 400, e.g. |p| + q <= 20 (sphtroch synth points allows 20000)");
    sphtroch::PrecisionPointsOptions options;
    options.max_boxes = kPagePointsBoxes;
    const sphtroch::PrecisionPoints r = sphtroch::precision_points(read_page_points(text), ratio, options);
    val list = val::array();
    for (const sphtroch::PrecisionSolution& x : r.solutions) {
      val item = train_object(x.train);
      item.set("params", float64_array(x.params));
      item.set("residual", x.residual);
      item.set("isolated", x.isolated);
      list.call<void>("push", item);
    }
    val out = val::object();
    out.set("solutions", list);
    out.set("certified", r.certified);
    out.set("undecided", static_cast<double>(r.undecided));
    out.set("boxes", static_cast<double>(r.boxes));
    out.set("boxLimit", static_cast<double>(kPagePointsBoxes));
    return out;
  });
}

val witness_object(const std::optional<sphtroch::BoundaryWitness>& w) {
  if (!w) return val::null();
  val out = val::object();
  out.set("kind", std::string(sphtroch::to_string(sphtroch::event_kind(w->boundary))));
  out.set("name", sphtroch::boundary_text(w->boundary));
  out.set("a2", w->a2());
  out.set("a3", w->a3());
  return out;
}

/// The largest proved move of each node (or cusp) over the box, radians; NaN where not proved.
val displacements(const std::vector<sphtroch::NodeTolerance>& points) {
  std::vector<double> d;
  for (const sphtroch::NodeTolerance& p : points) d.push_back(p.max_displacement ? *p.max_displacement : std::nan(""));
  return float64_array(d);
}

/// What `sphtroch tolerance` proves for the box [a2 -+ tolA2] x [a3 -+ tolA3] x [phase -+ tolPhase]
/// (half-widths as angle texts: "1e-3", "0.1deg", "pi/1800"), for the train read onto its boundaries
/// with the page's census (PageCensus: the root census; certify() certifies it): {margin: {lower, upper, converged,
/// nearest: {kind, name, a2, a3} | null}, topology: "holds" | "changes" | "undecided", why, event |
/// null, nodes, cusps: Float64Array of max displacements (NaN: not proved), box: {a2, a3,
/// phase} (the half-widths, radians), a2, a3 (the train analysed)}.
val tolerance(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
              const std::string& teeth, const std::string& tol_a2, const std::string& tol_a3, const std::string& tol_phase) {
  return guarded([&] {
    const GearTrain t = train_text(a2, a3, n, phase, teeth).train();
    const sphtroch::ToleranceBox box{sphtroch::parse_angle(tol_a2, "tol-a2"), sphtroch::parse_angle(tol_a3, "tol-a3"),
                                     sphtroch::parse_angle(tol_phase, "tol-phase")};
    const PageCensus census = page_census(t);
    sphtroch::check_tolerance_box(census.analysed, box, {"tol-a2", "tol-a3", "tol-phase"});
    const sphtroch::BoxTolerance r =
        sphtroch::box_tolerance(census.analysed, census.roots.node_points, cusps_of(census.analysed), box);
    val margin = val::object();
    margin.set("lower", r.margin.lower);
    margin.set("upper", r.margin.upper);
    margin.set("converged", r.margin.converged);
    margin.set("nearest", witness_object(r.margin.nearest));
    val out = val::object();
    out.set("margin", margin);
    out.set("topology", std::string(sphtroch::to_string(r.topology.verdict)));
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

// ---- the clinostat panel -------------------------------------------------------------------------

/// The machine of `sphtroch clinostat --outer O --inner I [--tilt T] [--frame-angle F]` ("" takes
/// the CLI's default), read by the CLI's reader: InvalidInput naming the CLI's option.
sphtroch::Clinostat page_clinostat(const std::string& outer, const std::string& inner, const std::string& tilt,
                                   const std::string& frame_angle) {
  sphtroch::ClinostatText text;
  text.outer = outer;
  text.inner = inner;
  text.tilt = tilt;
  text.frame_angle = frame_angle;
  return sphtroch::Clinostat(text.settings());
}

/// --window or --epsilon as `sphtroch clinostat` reads them: parse_number, then (0, 1e9], refused in
/// the words of src/cli/clinostat_command.cpp's parse_positive. That reader is the CLI's own (not
/// in the library), so this copies its bounds and words; page_test.js checks the lines agree.
double clinostat_positive(const std::string& text, const std::string& field, const std::string& valid) {
  const std::optional<double> v = sphtroch::parse_number(text);
  if (!v || !(*v > 0) || *v > 1e9) throw sphtroch::InvalidInput(field, text, "not a positive number in range", valid);
  return *v;
}

val vector_array(const sphtroch::Vector3d& v) { return float64_array(std::vector<double>{v.x(), v.y(), v.z()}); }

/// --json's "train" (theta2At0, theta2Rate, rotation: Q by rows, 9 numbers), or null.
val clinostat_train_object(const sphtroch::ClinostatTrain& ct) {
  if (!ct.train) return val::null();
  val out = train_object(*ct.train);
  out.set("theta2At0", ct.theta2_at_0);
  out.set("theta2Rate", ct.theta2_rate);
  std::vector<double> rows;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rows.push_back(ct.rotation(i, j));
  out.set("rotation", float64_array(rows));
  return out;
}

/// g_s at `samples` times evenly over one period from t = 0 (x0 y0 z0 x1 ...; one point when the
/// gravity does not move): the machine's gravity(t), the CLI's --trace.
val gravity_path(const sphtroch::Clinostat& m, const std::optional<double>& period, double samples) {
  const std::size_t count = period ? static_cast<std::size_t>(samples) : 1;
  std::vector<sphtroch::Vector3d> points;
  points.reserve(count);
  for (std::size_t k = 0; k < count; ++k)
    points.push_back(m.gravity(period ? *period * static_cast<double>(k) / static_cast<double>(count) : 0.0));
  return float64_array(flat(points));
}

/// The page's samples of the gravity path: 100 per turn of |outer| + |inner| over a period, within
/// [360, maxSamples].
double path_samples(const sphtroch::Clinostat& m, const std::optional<double>& period, double max_samples) {
  if (!period) return 1;
  const double rpm = std::fabs(m.settings().outer.value()) + std::fabs(m.settings().inner.value());
  return std::clamp(std::ceil(100 * *period * rpm / 60), 360.0, std::max(360.0, std::floor(max_samples)));
}

/// What `sphtroch clinostat --json` gives without --window and --epsilon: {outer, inner (the
/// speeds as the CLI prints them), outerRpm, innerRpm, tilt, frameAngle (degrees), train (as
/// clinostat_train_object) | null, trainNote ("" with a train), periodS | null, meanOverPeriod
/// [x, y, z], meanNorm (its length)}, and the gravity path (gravity_path, path_samples points): `path`.
val clinostat(const std::string& outer, const std::string& inner, const std::string& tilt, const std::string& frame_angle,
              double max_samples) {
  return guarded([&] {
    const sphtroch::Clinostat m = page_clinostat(outer, inner, tilt, frame_angle);
    const sphtroch::GravitySeries series = sphtroch::GravitySeries::of_gravity(m);
    const sphtroch::ClinostatTrain ct = sphtroch::clinostat_train(m);
    const sphtroch::ClinostatSettings& s = m.settings();
    val out = val::object();
    out.set("outer", s.outer.str());
    out.set("inner", s.inner.str());
    out.set("outerRpm", s.outer.value());
    out.set("innerRpm", s.inner.value());
    out.set("tilt", s.tilt_deg);
    out.set("frameAngle", s.frame_angle_deg);
    out.set("train", clinostat_train_object(ct));
    out.set("trainNote", ct.reason);
    out.set("periodS", series.period_s() ? val(*series.period_s()) : val::null());
    out.set("meanOverPeriod", vector_array(series.period_mean()));
    out.set("meanNorm", series.period_mean().norm());
    out.set("path", gravity_path(m, series.period_s(), path_samples(m, series.period_s(), max_samples)));
    return out;
  });
}

/// The gravity series of the machine, refused up front as the CLI refuses it when --window or
/// --epsilon is given (worst_window_mean_cost: a period too long for the search, InvalidInput "outer").
sphtroch::GravitySeries searchable_series(const sphtroch::Clinostat& m) {
  sphtroch::GravitySeries series = sphtroch::GravitySeries::of_gravity(m);
  sphtroch::worst_window_mean_cost(series);
  return series;
}

/// --json's "worst_window_mean" for --window W (the text as the CLI reads it): {windowS, lower,
/// upper, startS, certified}; M(W) in [lower, upper], certified when no wider than 1e-9.
val clinostat_window(const std::string& outer, const std::string& inner, const std::string& tilt,
                     const std::string& frame_angle, const std::string& window) {
  return guarded([&] {
    const sphtroch::Clinostat m = page_clinostat(outer, inner, tilt, frame_angle);
    const double w = clinostat_positive(window, "window", "seconds in (0, 1e9]");
    const sphtroch::WorstWindowMean r = sphtroch::worst_window_mean(searchable_series(m), w);
    val out = val::object();
    out.set("windowS", r.window_s);
    out.set("lower", r.lower);
    out.set("upper", r.upper);
    out.set("startS", r.start_s);
    out.set("certified", r.certified);
    return out;
  });
}

/// M(W) at `count` windows W = longest k / count, k = 1 .. count (1 .. 200), each a bracket no
/// wider than 1e-6 (as `sphtroch clinostat --plot` draws it): {windows, lower, upper: Float64Array}.
val clinostat_windows(const std::string& outer, const std::string& inner, const std::string& tilt,
                      const std::string& frame_angle, double longest, double count) {
  return guarded([&] {
    const sphtroch::GravitySeries series = searchable_series(page_clinostat(outer, inner, tilt, frame_angle));
    if (!(longest > 0 && longest <= 1e9))
      throw sphtroch::InvalidInput("window", sphtroch::number_text(longest), "not a positive number in range", "seconds in (0, 1e9]");
    if (!(count >= 1 && count <= 200 && count == std::floor(count)))
      throw sphtroch::InvalidInput("windows", sphtroch::number_text(count), "outside the valid range", "integer 1 .. 200");
    std::vector<double> windows, lower, upper;
    for (double k = 1; k <= count; ++k) {
      const sphtroch::WorstWindowMean r = sphtroch::worst_window_mean(series, longest * k / count, 1e-6);
      windows.push_back(r.window_s);
      lower.push_back(r.lower);
      upper.push_back(r.upper);
    }
    val out = val::object();
    out.set("windows", float64_array(windows));
    out.set("lower", float64_array(lower));
    out.set("upper", float64_array(upper));
    return out;
  });
}

/// --json's "time_to_epsilon" for --epsilon E (the CLI's reader) at the CLI's default resolution,
/// 1 s: {epsilon, resolutionS, firstS | null, staysBelowFromS | null, reason, certified}.
val clinostat_epsilon(const std::string& outer, const std::string& inner, const std::string& tilt,
                      const std::string& frame_angle, const std::string& epsilon) {
  return guarded([&] {
    const sphtroch::Clinostat m = page_clinostat(outer, inner, tilt, frame_angle);
    const double e = clinostat_positive(epsilon, "epsilon", "a bound in units of g0, > 0");
    const sphtroch::TimeToEpsilon r = sphtroch::time_to_epsilon(searchable_series(m), e, 1.0);
    const auto or_null = [](const std::optional<double>& v) { return v ? val(*v) : val::null(); };
    val out = val::object();
    out.set("epsilon", r.epsilon);
    out.set("resolutionS", r.resolution_s);
    out.set("firstS", or_null(r.first_s));
    out.set("staysBelowFromS", or_null(r.stays_below_from_s));
    out.set("aboveS", or_null(r.above_s));
    out.set("reason", r.reason);
    out.set("certified", r.certified);
    return out;
  });
}

/// A shortest round-trip text of a double (what the CLI prints for it).
std::string number_text(double v) { return sphtroch::number_text(v); }

}  // namespace

EMSCRIPTEN_BINDINGS(sphtroch_explorer) {
  emscripten::function("classify", &classify);
  emscripten::function("certify", &certify);
  emscripten::function("marks", &marks);
  emscripten::function("trace", &trace);
  emscripten::function("traceCsv", &trace_csv);
  emscripten::function("plotSvg", &plot_svg);
  emscripten::function("events", &events);
  emscripten::function("mapCounts", &map_counts);
  emscripten::function("loci", &loci);
  emscripten::function("numberText", &number_text);
  emscripten::function("fit", &fit);
  emscripten::function("points", &points);
  emscripten::function("tolerance", &tolerance);
  emscripten::function("chainPlot", &chain_plot);
  emscripten::function("clinostat", &clinostat);
  emscripten::function("clinostatWindow", &clinostat_window);
  emscripten::function("clinostatWindows", &clinostat_windows);
  emscripten::function("clinostatEpsilon", &clinostat_epsilon);
}
