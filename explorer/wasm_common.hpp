// explorer/wasm_common.hpp — what the explorer module's topic files share: the error boundary
// (guarded: no exception reaches JavaScript), the conversions to JavaScript values, the train as
// typed, the page's census of a train (defined in wasm_census.cpp) and one register_* function per
// topic file, called by wasm_module.cpp's EMSCRIPTEN_BINDINGS:
//   wasm_train.cpp      trace, traceCsv, plotSvg, marks, numberText: the sphere and its exports
//   wasm_census.cpp     classify, certify: the census of one train and its certificate
//   wasm_map.cpp        events, mapCounts, loci: the a3 ruler and the design map
//   wasm_synthesis.cpp  fit, points: inverse design
//   wasm_tolerance.cpp  tolerance: the certified margin and the tolerance box
//   wasm_chain.cpp      chainPlot: the chain panel
//   wasm_clinostat.cpp  clinostatReport, clinostatPath, clinostatWindows: the clinostat panel
#pragma once

#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/train_text.hpp"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace sphtroch::wasm {

using emscripten::val;

/// The page's error line: what `sphtroch` prints on stderr for the same texts.
inline val error_object(const std::string& line) {
  val out = val::object();
  out.set("error", "sphtroch: " + one_line_text(line));
  return out;
}

/// Runs body() and turns every exception into {error: ...}: InvalidInput as the CLI words it
/// ("--a2 = 7: ...; valid: ..."), anything else as an internal error (never thrown to JS).
template <typename Body>
val guarded(Body body) {
  try {
    return body();
  } catch (const InvalidInput& e) {
    return error_object(std::string("--") + e.what());
  } catch (const std::exception& e) {
    return error_object(std::string("internal error: ") + e.what());
  }
}

inline val float64_array(const std::vector<double>& values) {
  return val::global("Float64Array").new_(emscripten::typed_memory_view(values.size(), values.data()));
}

/// Vectors as x0 y0 z0 x1 ...
inline std::vector<double> flat(const std::vector<Vector3d>& vectors) {
  std::vector<double> xyz;
  xyz.reserve(vectors.size() * 3);
  for (const Vector3d& v : vectors) xyz.insert(xyz.end(), v.data(), v.data() + 3);
  return xyz;
}

/// {text}: a text the library wrote (a CSV, an SVG).
inline val text_object(const std::string& text) {
  val out = val::object();
  out.set("text", text);
  return out;
}

/// The train of the CLI's texts (phase "" is 0), read by the CLI's reader.
inline TrainText train_text(const std::string& a2, const std::string& a3, const std::string& n, const std::string& phase,
                            const std::string& teeth) {
  return TrainText{a2, a3, n, phase.empty() ? "0" : phase, teeth};
}

/// {a2, a3, phase, n, p, q, period, planetCone} of a train.
inline val train_object(const GearTrain& t) {
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

// --- wasm_census.cpp ----------------------------------------------------------------------------
/// The page's census of one train: the root census (classify_roots) of the train read onto its
/// boundaries (`analysed`, as the CLI reads it). Its count is not certified by itself: see
/// page_certified.
struct PageCensus {
  GearTrain analysed;
  RootClassification roots;
};
PageCensus page_census(const GearTrain& t);
/// Whether `sphtroch classify` certifies the census's count (its rule: certified_census at the
/// CLI's default settings, on the analysed train).
bool page_certified(const PageCensus& census);

// --- the topics' exports (wasm_module.cpp calls each once) ---------------------------------------
void register_train();
void register_census();
void register_map();
void register_synthesis();
void register_tolerance();
void register_chain();
void register_clinostat();

}  // namespace sphtroch::wasm
