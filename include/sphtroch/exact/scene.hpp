// sphtroch/exact/scene.hpp — a scene file: gear trains and, for each, the effects wanted (trace,
// nodes, classification, plot, ...) with the path each is written to; the outputs of those
// effects; and the explanation of which stages ran. The format part of `sphtroch scene` (the
// tool adds the file system: reading the file, checking and writing the outputs).
//
//   const std::string text = R"({"trains": [{"name": "fig3", "a2": "pi/2", "a3": "pi/2", "n": "1", "effects": {"trace": "fig3.csv"}}]})";
//   std::vector<sphtroch::SceneTrain> scene = sphtroch::parse_scene(text, "figs.json");  // SceneError
//   for (const sphtroch::SceneTrain& st : scene) {
//     const sphtroch::Analysis a(st.train, st.settings);
//     for (const sphtroch::SceneEffect& e : st.effects) {
//       std::ofstream out(e.path);
//       sphtroch::write_scene_effect(out, st, a, e);   // the bytes of the single command
//     }
//     sphtroch::write_scene_explanation(std::cout, st, a);
//   }
//
// Schema (docs/cli.md: sphtroch scene). The top level is an object {"trains": [...], "description"?};
// a train is an object with
//   name (non-empty string, distinct per train), description? (string, ignored),
//   a2, a3 (angle strings in the CLI forms of parse.hpp, or numbers in radians), n (a ratio
//   string or an integer; a JSON number 2.5 or 2e0 is refused: write "2.5"), phase? (angle, default "0"), samples? | turns? (trajectory
//   samples per period | open curve over K turns), census_samples?, literal? (bool), and
//   effects: a non-empty object {effect name: output path without NUL bytes}, run in the order
//   written; at most kMaxSceneOutputs outputs in all.
// Contracts:
//  1. parse_scene validates everything (JSON syntax with line and column, no key written twice,
//     at most kMaxSceneDepth levels, every key known, every value in range, the cost bounds of
//     the stages each effect needs) and computes nothing; it touches no file: relative output
//     paths are joined to output_dir, nothing is checked on disk.
//  2. Every problem throws SceneError (an InvalidInput) whose what() is one line
//     "FILE: PATH[ = VALUE]: PROBLEM; valid: RANGE", PATH as "trains[0].effects.plot" or
//     "line L, column C"; VALUE is the JSON value as written, cut to 80 characters.
//  3. write_scene_effect writes exactly what the single command writes for the same train: trace
//     and velocity the trajectory CSV (trace_output.hpp), nodes and cusps the nodes CSV
//     (node_csv.hpp; cusps: cusp rows only), classification the text report when the path ends in
//     ".txt" else the JSON (classification_output.hpp), extrema the z extremes JSON, screw_axis its CSV, plot the
//     SVG.
//  4. The explanation lists, per train, the stages each effect needs, the stages run in order
//     with their work, the stages not run and the total; scene_explanation_json has the keys
//     name, effects, stages, work in that order (nlohmann::ordered_json).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/scene.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/core/cost_bounds.hpp"
#include "sphtroch/io/node_csv.hpp"
#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/io/train_text.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/exact/classification_output.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg.hpp"
#include "sphtroch/io/trace_output.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <map>
#include <ostream>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace sphtroch {

/// Scenes nest 4 levels (scene, trains, train, effects); anything deeper than this is refused
/// while parsing, before a deep value could exhaust the stack of the code that prints it.
constexpr int kMaxSceneDepth = 16;
/// Scene files are a few kilobytes; a larger file is refused before it is parsed (by the reader).
constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;
/// Outputs of one scene (each a file renamed into place at the end); more are refused while
/// parsing, before anything is computed.
constexpr std::size_t kMaxSceneOutputs = 100000;

/// A problem in a scene (contract 2). field() is "FILE[: PATH]", value() the JSON value as
/// written (empty when the problem has none, e.g. a missing key), problem() and valid_range() as
/// named. PATH is empty for problems of the whole file (too deep, a number out of range).
class SceneError : public InvalidInput {
 public:
  SceneError(const std::string& file, const std::string& path, const std::string& written, const std::string& problem,
             const std::string& valid)
      : InvalidInput(path.empty() ? file : file + ": " + path, written, problem, valid),
        line_(file + ": " + (path.empty() ? std::string() : path + (written.empty() ? "" : " = " + written) + ": ") +
              problem + "; valid: " + valid) {}
  /// The one line to print: "FILE: [PATH[ = VALUE]: ]PROBLEM; valid: RANGE".
  const char* what() const noexcept override { return line_.c_str(); }

 private:
  std::string line_;
};

/// One effect of a train: what to compute and where to write it.
struct SceneEffect {
  Effect effect = Effect::trace;
  std::string path;     // output path as resolved (output_dir applied to a relative path)
  std::string field;    // "trains[0].effects.trace", for messages
  std::string written;  // the path's JSON value as written (for messages, contract 2)
};

/// One train of a scene.
struct SceneTrain {
  std::string name;
  TrainText text;       // the angles as written (numbers in the shortest round-trip form)
  GearTrain train;
  AnalysisSettings settings;
  std::vector<SceneEffect> effects;  // in the order written
};

/// The trains of a scene's text (contract 1). `file` names the scene in messages.
/// Throws SceneError.
inline std::vector<SceneTrain> parse_scene(const std::string& text, const std::string& file,
                                           const std::string& output_dir = "");

/// Writes one effect's output (contract 3), computing what it needs through `analysis`.
/// REQUIRES: analysis is of st.train with st.settings.
inline void write_scene_effect(std::ostream& out, const SceneTrain& st, const Analysis& analysis,
                               const SceneEffect& effect);

/// The explanation of one train as text (contract 4), after its effects were requested.
inline void write_scene_explanation(std::ostream& out, const SceneTrain& st, const Analysis& analysis);

/// The same as one JSON object (contract 4).
inline nlohmann::ordered_json scene_explanation_json(const SceneTrain& st, const Analysis& analysis);

// ---------------------------------------------------------------------------------------------
// Implementation details follow.

namespace scene_detail {

using Json = nlohmann::ordered_json;  // keeps the order written: effects run in that order

constexpr const char* kTopKeys = "trains, description";
constexpr const char* kTrainKeys = "name, description, a2, a3, n (or teeth), phase, samples, turns, census_samples, literal, effects";
constexpr const char* kAngleValue = "a string in the command-line forms (pi/2, 2pi/3, 90deg, 1.25) or a number in radians";

/// A value as shown in messages: one line (dump() escapes newlines), at most 80 characters.
inline std::string shown(const Json& value) {
  std::string s = value.dump();
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

/// Raises the SceneErrors of one scene file.
struct Errors {
  std::string file;
  [[noreturn]] void field(const std::string& path, const Json* value, const std::string& problem,
                          const std::string& valid) const {
    throw SceneError(file, path, value ? shown(*value) : std::string(), problem, valid);
  }
};

/// "line L, column C" of a byte offset (nlohmann's parse_error::byte: 1-based, the last byte read).
inline std::string line_column(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte == 0 ? 0 : byte - 1, text.size());
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// Rejects a key written twice in one object (JSON parsers keep one silently): the parse
/// callback tracks the path ("trains[1].effects") of the value being read.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const Errors& err) : err_(err) {}
  bool operator()(int, Json::parse_event_t event, Json& parsed) {
    using E = Json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        element_begins();
        frames_.push_back({event == E::array_start, 0, false, {}, {}});
        break;
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        break;
      case E::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second)
          err_.field(path(), nullptr, "written twice in one object", "each key once (the second would silently win)");
        break;
      }
      case E::value: element_begins(); break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    bool started;
    std::set<std::string> keys;
    std::string key;
  };
  void element_begins() {
    if (frames_.empty() || !frames_.back().array) return;
    Frame& f = frames_.back();
    if (f.started) ++f.index;
    f.started = true;
  }
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) p += f.array ? "[" + std::to_string(f.index) + "]" : (p.empty() ? "" : ".") + f.key;
    return p;
  }
  const Errors& err_;
  std::vector<Frame> frames_;
};

inline Json read_json(const Errors& err, const std::string& text) {
  const std::string valid = "a JSON scene file (docs/cli.md: sphtroch scene)";
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw SceneError(err.file, line_column(text, nul + 1), "", "not valid JSON (a NUL byte)", valid);
  try {
    DuplicateKeyCheck check(err);
    return Json::parse(text, [&](int depth, Json::parse_event_t event, Json& parsed) {
      if (depth > kMaxSceneDepth)
        throw SceneError(err.file, "", "", "nested deeper than " + std::to_string(kMaxSceneDepth) + " levels",
                         "a JSON scene file (docs/cli.md: sphtroch scene; at most " + std::to_string(kMaxSceneDepth) +
                             " levels)");
      return check(depth, event, parsed);
    });
  } catch (const nlohmann::json::parse_error& e) {
    // what(): "[json.exception.parse_error.101] parse error at line 3, column 9: syntax error ..."
    std::string why = e.what();
    const auto at = why.find(": ", why.find("parse error"));
    if (at != std::string::npos) why = why.substr(at + 2);
    throw SceneError(err.file, line_column(text, e.byte), "", "not valid JSON (" + why + ")", valid);
  } catch (const nlohmann::json::out_of_range& e) {
    // what(): "[json.exception.out_of_range.406] number overflow parsing '1e999'" (no position).
    std::string why = e.what();
    if (const auto at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    throw SceneError(err.file, "", "", "not valid JSON (" + why + ")",
                     "a JSON scene file with finite numbers (docs/cli.md: sphtroch scene)");
  }
}

/// An angle value: a string in the CLI forms or a JSON number (radians). Returns the text form.
inline std::string angle_text(const Errors& err, const std::string& path, const Json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return number_text(v.get<double>());
  err.field(path, &v, "not an angle", kAngleValue);
}

inline std::size_t count_value(const Errors& err, const std::string& path, const Json& v, std::size_t lo,
                               std::size_t hi) {
  const std::string range = "an integer " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (!v.is_number_integer()) err.field(path, &v, "not a whole number", range);
  if (v.is_number_unsigned()) {
    const auto n = v.get<std::uint64_t>();
    if (n >= lo && n <= hi) return static_cast<std::size_t>(n);
  }
  err.field(path, &v, "outside the valid range", range);
}

/// A train object's keys: every key known, the required ones present.
class TrainObject {
 public:
  TrainObject(const Errors& err, const Json& t, std::size_t index)
      : err_(err), t_(t), at_("trains[" + std::to_string(index) + "]") {
    if (!t.is_object()) err.field(at_, &t, "not an object", "an object with the keys " + std::string(kTrainKeys));
    static const char* const known[] = {"name",    "description", "a2",             "a3",      "n",      "teeth",
                                        "phase",   "samples",     "turns",          "census_samples", "literal", "effects"};
    for (const auto& [key, value] : t.items())
      if (std::find(std::begin(known), std::end(known), key) == std::end(known))
        err.field(at_ + "." + key, &value, "unknown key", kTrainKeys);  // a typo must not pass silently
  }
  const Json& required(const char* key, const std::string& valid) const {
    const auto it = t_.find(key);
    if (it == t_.end()) err_.field(at(key), nullptr, "missing", valid);
    return *it;
  }
  const Json* optional(const char* key) const {
    const auto it = t_.find(key);
    return it == t_.end() ? nullptr : &*it;
  }
  std::string at(const std::string& key) const { return at_ + "." + key; }
  const Errors& err() const { return err_; }

 private:
  const Errors& err_;
  const Json& t_;
  std::string at_;
};

inline void read_name(const TrainObject& t, SceneTrain& st) {
  const Json& name = t.required("name", "a non-empty string");
  if (!name.is_string() || name.get<std::string>().empty())
    t.err().field(t.at("name"), &name, "not a non-empty string", "a non-empty string");
  st.name = name.get<std::string>();
  if (const Json* d = t.optional("description"); d && !d->is_string())
    t.err().field(t.at("description"), d, "not a string", "any string (ignored)");
}

/// n as a ratio, or teeth as tooth counts "ZS:ZP" (kept: the outputs echo them next to n).
inline const Json& read_ratio_text(const TrainObject& t, SceneTrain& st) {
  const Errors& err = t.err();
  const std::string n_valid = std::string(kRatioForms) + ", as a string or an integer";
  if (const Json* teeth = t.optional("teeth")) {
    const char* const teeth_valid = "tooth counts \"ZS:ZP\", sun:planet (\"39:15\" is n = 13/5; ZS < 0: internal)";
    if (const Json* n = t.optional("n"))
      err.field(t.at("n"), n, "given together with teeth", "one of n and teeth");
    if (!teeth->is_string() || teeth->get<std::string>().empty())
      err.field(t.at("teeth"), teeth, "not a non-empty string", teeth_valid);
    st.text.teeth = teeth->get<std::string>();
    return *teeth;
  }
  const Json& n = t.required("n", n_valid + " (or teeth \"ZS:ZP\")");
  if (n.is_string()) st.text.n = n.get<std::string>();
  else if (n.is_number_integer()) st.text.n = n.dump();
  else if (n.is_number()) err.field(t.at("n"), &n, "a JSON number with a fraction or exponent, not a string or an integer", n_valid + " (write \"2.5\" or \"5/2\")");
  else err.field(t.at("n"), &n, "not a gear ratio", n_valid);
  return n;
}

/// a2, a3, n (or teeth), phase: the texts, then the train they make (its errors name the scene's key).
inline void read_gear_train(const TrainObject& t, SceneTrain& st) {
  const Errors& err = t.err();
  const Json& a2 = t.required("a2", std::string("(0, pi) radians as ") + kAngleValue);
  const Json& a3 = t.required("a3", std::string("(0, pi) radians as ") + kAngleValue +
                                        ", or ap, pi-ap, a2, pi-a2 with an offset");
  st.text.a2 = angle_text(err, t.at("a2"), a2);
  st.text.a3 = angle_text(err, t.at("a3"), a3);
  const Json& n = read_ratio_text(t, st);
  const Json* phase = t.optional("phase");
  st.text.phase = phase ? angle_text(err, t.at("phase"), *phase) : "0";
  try {
    st.train = st.text.train();
  } catch (const InvalidInput& e) {
    const Json* raw = e.field() == "a2" ? &a2 : e.field() == "a3" ? &a3 : e.field() == "n" || e.field() == "teeth" ? &n : phase;
    err.field(t.at(e.field()), raw, e.problem(), e.valid_range());
  }
}

/// samples | turns, census_samples, literal.
inline void read_settings(const TrainObject& t, SceneTrain& st) {
  const Errors& err = t.err();
  const Json* samples = t.optional("samples");
  const Json* turns = t.optional("turns");
  if (samples && turns)
    err.field(t.at("turns"), turns, "cannot be combined with samples",
              "either samples N (closed curve) or turns K (open curve)");
  if (samples) st.settings.samples = count_value(err, t.at("samples"), *samples, kMinSamples, kMaxSamples);
  if (turns) {
    if (!turns->is_number() || !turns_in_range(turns->get<double>()))
      err.field(t.at("turns"), turns, "outside the valid range", kTurnsRange);
    st.settings.turns = turns->get<double>();
  }
  if (const Json* c = t.optional("census_samples"))
    st.settings.census_samples = count_value(err, t.at("census_samples"), *c, kMinCensusSamples, kMaxSamples);
  if (const Json* l = t.optional("literal")) {
    if (!l->is_boolean()) err.field(t.at("literal"), l, "not a boolean", "true or false");
    st.settings.reading.literal = l->get<bool>();
  }
}

inline void read_effects(const TrainObject& t, SceneTrain& st, const std::string& output_dir) {
  const Errors& err = t.err();
  const std::string valid = "an object {effect: output path} with effects " + effect_names();
  const Json& effects = t.required("effects", valid);
  if (!effects.is_object() || effects.empty()) err.field(t.at("effects"), &effects, "not a non-empty object", valid);
  for (const auto& [key, value] : effects.items()) {
    const std::string field = t.at("effects." + key);
    const auto effect = effect_from_name(key);
    if (!effect) err.field(field, &value, "unknown effect", effect_names());
    if (!value.is_string() || value.get<std::string>().empty())
      err.field(field, &value, "not an output path", "a non-empty string (relative to the current directory or --output-dir)");
    if (value.get<std::string>().find('\0') != std::string::npos)  // the file system would cut the path there
      err.field(field, &value, "an output path with a NUL byte (\\u0000)", "a path without NUL bytes");
    if (const auto other = other_picture_format(value.get<std::string>()); *effect == Effect::plot && other)
      err.field(field, &value, "a plot is SVG, not ." + *other,
                "a .svg path (or any other name; sphtroch plot -o FILE.png renders a PNG)");
    std::filesystem::path path = value.get<std::string>();
    if (!output_dir.empty() && path.is_relative()) path = std::filesystem::path(output_dir) / path;
    st.effects.push_back({*effect, path.string(), field, shown(value)});
  }
}

/// Costs, up front: a census of a huge ratio, a default sample count beyond 1e6.
inline void check_costs(const Errors& err, const SceneTrain& st) {
  for (const SceneEffect& e : st.effects) {
    const auto stages = Analysis::stages_for(e.effect);
    const auto needs = [&](Stage s) { return std::find(stages.begin(), stages.end(), s) != stages.end(); };
    try {
      if (needs(Stage::polyline_census) || needs(Stage::root_census)) check_census_cost(st.train.ratio());
      if ((needs(Stage::trajectory) || needs(Stage::velocities) || needs(Stage::screw_axis)) && !st.settings.samples)
        (void)trace_sample_count(st.train, st.settings.turns);
    } catch (const InvalidInput& ex) {
      err.field(e.field, nullptr, (ex.field() == "n" ? "n = " + ex.value() + ": " : ex.value() + ": ") + ex.problem(),
                ex.valid_range());
    }
  }
}

inline SceneTrain read_train(const Errors& err, const Json& json, std::size_t index, const std::string& output_dir) {
  const TrainObject t(err, json, index);
  SceneTrain st;
  read_name(t, st);
  read_gear_train(t, st);
  read_settings(t, st);
  read_effects(t, st, output_dir);
  check_costs(err, st);
  return st;
}

inline std::string stage_list(const std::vector<Stage>& stages) {
  std::string s;
  for (Stage x : stages) s += (s.empty() ? "" : ", ") + std::string(to_string(x));
  return s;
}

inline std::string work_text(const Work& w) {
  return std::to_string(w.points_evaluated) + " points evaluated, " + std::to_string(w.predicates) + " predicates, " +
         std::to_string(w.newton_steps) + " Newton steps, " + std::to_string(w.root_evaluations) +
         " root evaluations, " + seconds_text(w.seconds) + " s";
}

inline Json work_json(const Work& w) {
  return {{"ran", w.ran},
          {"points_evaluated", w.points_evaluated},
          {"predicates", w.predicates},
          {"newton_steps", w.newton_steps},
          {"root_evaluations", w.root_evaluations},
          {"seconds", w.seconds}};
}

inline bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace scene_detail

inline std::vector<SceneTrain> parse_scene(const std::string& text, const std::string& file,
                                           const std::string& output_dir) {
  using scene_detail::Json;
  const scene_detail::Errors err{file};
  const Json scene = scene_detail::read_json(err, text);
  if (!scene.is_object()) err.field("(top level)", nullptr, "not an object", "{\"trains\": [...]}");
  for (const auto& [key, value] : scene.items())
    if (key != "trains" && key != "description") err.field(key, &value, "unknown key", scene_detail::kTopKeys);
  const auto trains = scene.find("trains");
  if (trains == scene.end()) err.field("trains", nullptr, "missing", "a non-empty list of gear trains");
  if (!trains->is_array() || trains->empty())
    err.field("trains", &*trains, "not a non-empty list", "a non-empty list of gear trains");
  std::vector<SceneTrain> out;
  std::map<std::string, std::string> names;  // name -> where first used
  std::size_t outputs = 0;
  for (std::size_t i = 0; i < trains->size(); ++i) {
    SceneTrain st = scene_detail::read_train(err, (*trains)[i], i, output_dir);
    outputs += st.effects.size();
    if (outputs > kMaxSceneOutputs)
      err.field("trains[" + std::to_string(i) + "].effects", nullptr,
                "output " + std::to_string(outputs) + " of the scene: more than " + std::to_string(kMaxSceneOutputs),
                "at most " + std::to_string(kMaxSceneOutputs) + " outputs per scene (split the scene)");
    const std::string at = "trains[" + std::to_string(i) + "].name";
    if (const auto [it, fresh] = names.emplace(st.name, at); !fresh)
      err.field(at, &(*trains)[i].at("name"), "used twice (also " + it->second + ")", "a distinct name per gear train");
    out.push_back(std::move(st));
  }
  return out;
}

inline void write_scene_effect(std::ostream& out, const SceneTrain& st, const Analysis& a, const SceneEffect& e) {
  switch (e.effect) {
    case Effect::trace: write_trajectory_csv(out, a.trajectory()); return;
    case Effect::velocity: write_trajectory_csv(out, a.trajectory(), a.velocities()); return;
    case Effect::nodes: write_nodes_csv(out, a.nodes(), a.cusps()); return;
    case Effect::cusps: write_nodes_csv(out, {}, a.cusps()); return;
    case Effect::classification:
      if (scene_detail::ends_with(e.path, ".txt")) write_classification_text(out, st.text, a.classification());
      else out << classification_json(st.text, a.classification()).dump(2) << "\n";
      return;
    case Effect::extrema: out << z_extremes_json(a.extremes()).dump(2) << "\n"; return;
    case Effect::screw_axis: write_screw_axis_csv(out, a.screw_axis().t, a.screw_axis().omega); return;
    case Effect::plot:
      out << plot_svg(st.text, a.analysed(), a.plot_trajectory(), a.nodes(), a.cusps(), &a.certificate());
      return;
  }
}

/// Why what the effects of one train report is not certified, or "" (the node census was not run,
/// or it is certified): nodes, plot and classification print the certified census only.
inline std::string scene_uncertified(const SceneTrain& st, const Analysis& a) {
  if (!a.work(Stage::polyline_census).ran) return "";
  const CensusCertificate& cert = a.certificate();
  const bool analytic_ok = !a.work(Stage::classification).ran || a.classification().agreement.analytic_agrees.value_or(true);
  if (cert.certified && analytic_ok) return "";
  return "train " + st.name + ": the node count is not certified (polyline census " +
         std::to_string(cert.polyline_nodes.back()) + " node(s), root-count census " + std::to_string(cert.root_nodes) +
         (analytic_ok ? "" : ", the report's criteria disagree") + ")";
}

inline void write_scene_explanation(std::ostream& out, const SceneTrain& st, const Analysis& a) {
  using scene_detail::stage_list;
  using scene_detail::work_text;
  out << "train " << st.name << ": a2 = " << st.text.a2 << ", a3 = " << st.text.a3 << ", n = "
      << (st.text.teeth.empty() ? st.text.n : st.train.ratio().str() + st.text.teeth_note()) << ", phase = " << st.text.phase << "\n  effects (stages each needs)\n";
  for (const SceneEffect& e : st.effects)
    out << "    " << to_string(e.effect) << " -> " << e.path << ": " << stage_list(Analysis::stages_for(e.effect)) << "\n";
  out << "  stages run, in order (work)\n";
  for (Stage s : a.stages_run()) {
    std::string name = to_string(s);
    name.resize(16, ' ');
    out << "    " << name << work_text(a.work(s)) << "\n";
  }
  std::vector<Stage> idle;
  for (std::size_t i = 0; i < kStageCount; ++i)
    if (!a.work(static_cast<Stage>(i)).ran) idle.push_back(static_cast<Stage>(i));
  out << "  not run: " << (idle.empty() ? std::string("(none)") : stage_list(idle)) << "\n";
  out << "  total: " << work_text(a.total_work()) << "\n";
}

inline nlohmann::ordered_json scene_explanation_json(const SceneTrain& st, const Analysis& a) {
  using json = nlohmann::ordered_json;  // keys in the order of the shape documented in docs/cli.md
  json effects = json::array();
  for (const SceneEffect& e : st.effects) {
    json stages = json::array();
    for (Stage s : Analysis::stages_for(e.effect)) stages.push_back(to_string(s));
    effects.push_back({{"effect", to_string(e.effect)}, {"output", e.path}, {"stages", stages}});
  }
  json stages = json::object();
  for (std::size_t i = 0; i < kStageCount; ++i)
    stages[to_string(static_cast<Stage>(i))] = scene_detail::work_json(a.work(static_cast<Stage>(i)));
  json work = scene_detail::work_json(a.total_work());
  work.erase("ran");
  json run = json::array();
  for (Stage s : a.stages_run()) run.push_back(to_string(s));
  work["stages_run"] = run;
  return {{"name", st.name}, {"effects", effects}, {"stages", stages}, {"work", work}};
}

}  // namespace sphtroch
