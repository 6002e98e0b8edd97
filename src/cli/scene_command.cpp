// sphtroch scene FILE [--explain] [--json] [--output-dir DIR] — runs a scene: a list of gear
// trains and, for each, the effects wanted, computing only the stages those effects need
// (sphtroch::Analysis). The second CLI translation unit that includes CGAL.
//
// Order of work (so that a failure anywhere leaves no output at all):
//  1. read and validate the whole scene — JSON syntax (line and column), every key, every value,
//     every output path (distinct, in an existing writable directory) — computing nothing;
//  2. per train, build one Analysis, request each effect in the order written, and write its
//     output to a temporary file next to the target (StagedOutputs);
//  3. rename every temporary into place; only then print the explanation (if asked).
// Every problem is one line on stderr naming the file and the field (or line and column), the
// value and the valid range, exit status 2.
#include "cli_common.hpp"

#include "sphtroch/analysis.hpp"
#include "sphtroch/csv_io.hpp"
#include "sphtroch/report.hpp"
#include "sphtroch/input_file.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/trace_output.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <iterator>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace sphtroch::cli {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keeps the order written: effects run in that order

struct SceneOptions {
  std::string file, output_dir;
  bool explain = false;
  bool json = false;
};

struct EffectRequest {
  Effect effect = Effect::trace;
  std::string path;   // as resolved (output dir applied)
  std::string field;  // "trains[0].effects.trace", for messages
};

struct SceneTrain {
  std::string name;
  TrainOptions text;  // angles as written (a2_text, plot caption)
  GearTrain train;
  AnalysisSettings settings;
  std::vector<EffectRequest> effects;
};

const char* const kTopKeys = "trains, description";
const char* const kTrainKeys = "name, description, a2, a3, n, phase, samples, turns, census_samples, literal, effects";
const char* const kAngleValue = "a string in the command-line forms (pi/2, 2pi/3, 90deg, 1.25) or a number in radians";

/// Collects the one-line error of a scene file.
struct SceneError {
  std::string file;
  [[noreturn]] void field(const std::string& path, const Json* value, const std::string& problem,
                          const std::string& valid) const {
    std::string shown = value ? value->dump() : std::string();  // one line: dump() escapes newlines
    if (shown.size() > 80) shown = shown.substr(0, 77) + "...";
    throw UsageError{file + ": " + path + (value ? " = " + shown : std::string()) + ": " + problem + "; valid: " + valid};
  }
};

/// "line L, column C" of a byte offset (nlohmann's parse_error::byte: 1-based, the last byte read).
std::string line_column(const std::string& text, std::size_t byte) {
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
  explicit DuplicateKeyCheck(const SceneError& err) : err_(err) {}
  bool operator()(int, nlohmann::detail::parse_event_t event, Json& parsed) {
    using E = nlohmann::detail::parse_event_t;
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
    for (const Frame& f : frames_)
      p += f.array ? "[" + std::to_string(f.index) + "]" : (p.empty() ? "" : ".") + f.key;
    return p;
  }
  const SceneError& err_;
  std::vector<Frame> frames_;
};

/// Scenes nest 4 levels (scene, trains, train, effects); anything deeper than this is refused
/// while parsing, before a deep value could exhaust the stack of the code that prints it.
constexpr int kMaxSceneDepth = 16;
/// Scene files are a few kilobytes; a larger file is refused before it is parsed.
constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;

Json read_json(const SceneError& err, const std::string& text) {
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw UsageError{err.file + ": " + line_column(text, nul + 1) +
                     ": not valid JSON (a NUL byte); valid: a JSON scene file (README: sphtroch scene)"};
  try {
    DuplicateKeyCheck check(err);
    return Json::parse(text, [&](int depth, nlohmann::detail::parse_event_t event, Json& parsed) {
      if (depth > kMaxSceneDepth)
        throw UsageError{err.file + ": nested deeper than " + std::to_string(kMaxSceneDepth) +
                         " levels; valid: a JSON scene file (README: sphtroch scene; at most " +
                         std::to_string(kMaxSceneDepth) + " levels)"};
      return check(depth, event, parsed);
    });
  } catch (const nlohmann::json::parse_error& e) {
    // what(): "[json.exception.parse_error.101] parse error at line 3, column 9: syntax error ..."
    std::string why = e.what();
    const auto at = why.find(": ", why.find("parse error"));
    if (at != std::string::npos) why = why.substr(at + 2);
    throw UsageError{err.file + ": " + line_column(text, e.byte) + ": not valid JSON (" + why +
                     "); valid: a JSON scene file (README: sphtroch scene)"};
  } catch (const nlohmann::json::out_of_range& e) {
    // what(): "[json.exception.out_of_range.406] number overflow parsing '1e999'" (no position).
    std::string why = e.what();
    if (const auto at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    throw UsageError{err.file + ": not valid JSON (" + why +
                     "); valid: a JSON scene file with finite numbers (README: sphtroch scene)"};
  }
}

/// An angle value: a string in the CLI forms or a JSON number (radians). Returns the text form.
std::string angle_text(const SceneError& err, const std::string& path, const Json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number()) return number(v.get<double>());
  err.field(path, &v, "not an angle", kAngleValue);
}

std::size_t count_value(const SceneError& err, const std::string& path, const Json& v, std::size_t lo, std::size_t hi) {
  const std::string range = "an integer " + std::to_string(lo) + " .. " + std::to_string(hi);
  if (!v.is_number_integer()) err.field(path, &v, "not a whole number", range);
  if (v.is_number_unsigned()) {
    const auto n = v.get<std::uint64_t>();
    if (n >= lo && n <= hi) return static_cast<std::size_t>(n);
  }
  err.field(path, &v, "outside the valid range", range);
}

SceneTrain read_train(const SceneError& err, const Json& t, std::size_t index, const std::string& output_dir) {
  const std::string at = "trains[" + std::to_string(index) + "]";
  if (!t.is_object()) err.field(at, &t, "not an object", "an object with the keys " + std::string(kTrainKeys));
  static const char* const known[] = {"name",    "description", "a2",             "a3",      "n",      "phase",
                                      "samples", "turns",       "census_samples", "literal", "effects"};
  for (const auto& [key, value] : t.items())
    if (std::find(std::begin(known), std::end(known), key) == std::end(known))
      err.field(at + "." + key, &value, "unknown key", kTrainKeys);  // a typo must not pass silently
  auto required = [&](const char* key, const std::string& valid) -> const Json& {
    const auto it = t.find(key);
    if (it == t.end()) err.field(at + "." + key, nullptr, "missing", valid);
    return *it;
  };
  SceneTrain st{{}, {}, GearTrain(1.0, 1.0, Ratio(1)), {}, {}};
  const Json& name = required("name", "a non-empty string");
  if (!name.is_string() || name.get<std::string>().empty()) err.field(at + ".name", &name, "not a non-empty string", "a non-empty string");
  st.name = name.get<std::string>();
  if (const auto it = t.find("description"); it != t.end() && !it->is_string())
    err.field(at + ".description", &*it, "not a string", "any string (ignored)");

  const Json& a2 = required("a2", std::string("(0, pi) radians as ") + kAngleValue);
  const Json& a3 = required("a3", std::string("(0, pi) radians as ") + kAngleValue + ", or ap, pi-ap, a2, pi-a2 with an offset");
  const Json& n = required("n", std::string(kRatioForms) + ", as a string or an integer");
  st.text.a2 = angle_text(err, at + ".a2", a2);
  st.text.a3 = angle_text(err, at + ".a3", a3);
  if (n.is_string()) st.text.n = n.get<std::string>();
  else if (n.is_number_integer()) st.text.n = n.dump();
  else if (n.is_number()) st.text.n = number(n.get<double>());
  else err.field(at + ".n", &n, "not a gear ratio", std::string(kRatioForms) + ", as a string or an integer");
  const auto phase = t.find("phase");
  st.text.phase = phase == t.end() ? "0" : angle_text(err, at + ".phase", *phase);
  try {
    st.train = st.text.train();
  } catch (const InvalidInput& e) {
    const Json* raw = e.field() == "a2" ? &a2 : e.field() == "a3" ? &a3 : e.field() == "n" ? &n
                    : phase != t.end() ? &*phase : nullptr;
    err.field(at + "." + e.field(), raw, e.problem(), e.valid_range());
  }

  const auto samples = t.find("samples"), turns = t.find("turns");
  if (samples != t.end() && turns != t.end())
    err.field(at + ".turns", &*turns, "cannot be combined with samples",
              "either samples N (closed curve) or turns K (open curve)");
  if (samples != t.end()) st.settings.samples = count_value(err, at + ".samples", *samples, kMinSamples, kMaxSamples);
  if (turns != t.end()) {
    if (!turns->is_number() || !(turns->get<double>() > 0.0 && turns->get<double>() <= kMaxTurns))
      err.field(at + ".turns", &*turns, "outside the valid range", "a number in (0, 1e6] carrier turns");
    st.settings.turns = turns->get<double>();
  }
  if (const auto it = t.find("census_samples"); it != t.end())
    st.settings.census_samples = count_value(err, at + ".census_samples", *it, kMinCensusSamples, kMaxSamples);
  if (const auto it = t.find("literal"); it != t.end()) {
    if (!it->is_boolean()) err.field(at + ".literal", &*it, "not a boolean", "true or false");
    st.settings.literal = it->get<bool>();
  }

  const std::string effects_valid = "an object {effect: output path} with effects " + effect_names();
  const Json& effects = required("effects", effects_valid);
  if (!effects.is_object() || effects.empty()) err.field(at + ".effects", &effects, "not a non-empty object", effects_valid);
  for (const auto& [key, value] : effects.items()) {
    const std::string field = at + ".effects." + key;
    const auto effect = effect_from_name(key);
    if (!effect) err.field(field, &value, "unknown effect", effect_names());
    if (!value.is_string() || value.get<std::string>().empty())
      err.field(field, &value, "not an output path", "a non-empty string (relative to the current directory or --output-dir)");
    fs::path path = value.get<std::string>();
    if (!output_dir.empty() && path.is_relative()) path = fs::path(output_dir) / path;
    st.effects.push_back({*effect, path.string(), field});
  }
  // Costs, up front: a census of a huge ratio, a default sample count beyond 1e6.
  for (const EffectRequest& e : st.effects) {
    const auto stages = Analysis::stages_for(e.effect);
    const auto needs = [&](Stage s) { return std::find(stages.begin(), stages.end(), s) != stages.end(); };
    try {
      if (needs(Stage::crossings) || needs(Stage::root_census)) check_census_cost(st.train.ratio());
      if ((needs(Stage::trajectory) || needs(Stage::velocities) || needs(Stage::screw_axis)) && !st.settings.samples)
        (void)trace_sample_count(st.train, st.settings.turns);
    } catch (const InvalidInput& ex) {
      err.field(e.field, nullptr, (ex.field() == "n" ? "n = " + ex.value() + ": " : ex.value() + ": ") + ex.problem(),
                ex.valid_range());
    }
  }
  return st;
}

/// The scene's JSON and trains, validated without touching the file system (paths unchecked).
std::vector<SceneTrain> parse_scene(const SceneError& err, const std::string& text, const std::string& output_dir,
                                    Json& scene) {
  scene = read_json(err, text);
  if (!scene.is_object()) err.field("(top level)", nullptr, "not an object", "{\"trains\": [...]}");
  for (const auto& [key, value] : scene.items())
    if (key != "trains" && key != "description") err.field(key, &value, "unknown key", kTopKeys);
  const auto trains = scene.find("trains");
  if (trains == scene.end()) err.field("trains", nullptr, "missing", "a non-empty list of gear trains");
  if (!trains->is_array() || trains->empty()) err.field("trains", &*trains, "not a non-empty list", "a non-empty list of gear trains");
  std::vector<SceneTrain> out;
  std::map<std::string, std::string> names;  // name -> where first used
  for (std::size_t i = 0; i < trains->size(); ++i) {
    SceneTrain st = read_train(err, (*trains)[i], i, output_dir);
    const std::string at = "trains[" + std::to_string(i) + "].name";
    if (const auto [it, fresh] = names.emplace(st.name, at); !fresh)
      err.field(at, &(*trains)[i].at("name"), "used twice (also " + it->second + ")", "a distinct name per gear train");
    out.push_back(std::move(st));
  }
  return out;
}

std::vector<SceneTrain> read_scene(const SceneOptions& o) {
  const SceneError err{o.file};
  std::string text;
  try {
    text = read_whole_input(o.file, "scene", kMaxSceneBytes);
  } catch (const InvalidInput& e) {
    throw UsageError{o.file + ": " + e.problem() + "; valid: a readable scene file (JSON) of at most 16 MiB"};
  }
  if (!o.output_dir.empty() && !fs::is_directory(o.output_dir))
    throw UsageError{"--output-dir = " + o.output_dir + ": not a directory; valid: an existing, writable directory"};
  Json scene;
  std::vector<SceneTrain> out = parse_scene(err, text, o.output_dir, scene);
  const Json& trains = scene.at("trains");
  std::map<std::string, std::string> paths;  // file identity -> where first used
  paths.emplace(file_key(o.file), "the scene file itself");  // by identity: any alias of it is refused
  for (std::size_t i = 0; i < out.size(); ++i) {
    const SceneTrain& st = out[i];
    for (const EffectRequest& e : st.effects) {
      const fs::path abs = fs::absolute(e.path).lexically_normal();
      const Json& shown = trains[i].at("effects").at(to_string(e.effect));
      if (const std::string key = file_key(abs.string()); !key.empty())
        if (const auto [it, fresh] = paths.emplace(key, e.field); !fresh)
          err.field(e.field, &shown, "output path reaches the same file as " + it->second,
                    "a distinct path per output, not the scene file");
      const fs::path dir = abs.parent_path();
      std::error_code ec;
      if (!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        err.field(e.field, &shown, "its directory " + dir.string() + " is missing or not writable",
                  "a path in an existing, writable directory");
      if (fs::is_directory(abs, ec)) err.field(e.field, &shown, "is a directory", "a file path");
    }
  }
  return out;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// Writes one effect's output: the same printer, hence the same bytes, as the single command.
void write_effect(std::ostream& out, const SceneTrain& st, const Analysis& a, const EffectRequest& e) {
  switch (e.effect) {
    case Effect::trace: write_trajectory_csv(out, a.trajectory()); return;
    case Effect::velocity: write_trajectory_csv(out, a.trajectory(), a.velocities()); return;
    case Effect::nodes: write_nodes_csv(out, a.nodes(), a.cusps()); return;
    case Effect::cusps: write_nodes_csv(out, {}, a.cusps()); return;
    case Effect::classification:
      if (ends_with(e.path, ".txt")) write_classification_text(out, st.text, a.classification());
      else out << classification_json(st.text, a.classification()).dump(2) << "\n";
      return;
    case Effect::extrema: out << z_extremes_json(a.extremes()).dump(2) << "\n"; return;
    case Effect::screw_axis: write_screw_axis_csv(out, a.screw_axis().t, a.screw_axis().omega); return;
    case Effect::plot: out << plot_svg(st.text, a.analysed(), a.plot_trajectory(), a.nodes(), a.cusps()); return;
  }
}

std::string stage_list(const std::vector<Stage>& stages) {
  std::string s;
  for (Stage x : stages) s += (s.empty() ? "" : ", ") + std::string(to_string(x));
  return s;
}

std::string work_text(const StageWork& w) {
  return std::to_string(w.points_evaluated) + " points evaluated, " + std::to_string(w.predicates) + " predicates, " +
         std::to_string(w.newton_steps) + " Newton steps, " + std::to_string(w.root_evaluations) +
         " root evaluations, " + seconds_text(w.seconds) + " s";
}

nlohmann::ordered_json work_json(const StageWork& w) {
  return {{"ran", w.ran},
          {"points_evaluated", w.points_evaluated},
          {"predicates", w.predicates},
          {"newton_steps", w.newton_steps},
          {"root_evaluations", w.root_evaluations},
          {"seconds", w.seconds}};
}

void explain_text(std::ostream& out, const SceneTrain& st, const Analysis& a) {
  out << "train " << st.name << ": a2 = " << st.text.a2 << ", a3 = " << st.text.a3 << ", n = " << st.text.n
      << ", phase = " << st.text.phase << "\n  effects (stages each needs)\n";
  for (const EffectRequest& e : st.effects)
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

nlohmann::ordered_json explain_json(const SceneTrain& st, const Analysis& a) {
  using json = nlohmann::ordered_json;  // keys in the order of the shape documented in README
  json effects = json::array();
  for (const EffectRequest& e : st.effects) {
    json stages = json::array();
    for (Stage s : Analysis::stages_for(e.effect)) stages.push_back(to_string(s));
    effects.push_back({{"effect", to_string(e.effect)}, {"output", e.path}, {"stages", stages}});
  }
  json stages = json::object();
  for (std::size_t i = 0; i < kStageCount; ++i)
    stages[to_string(static_cast<Stage>(i))] = work_json(a.work(static_cast<Stage>(i)));
  json work = work_json(a.total_work());
  work.erase("ran");
  json run = json::array();
  for (Stage s : a.stages_run()) run.push_back(to_string(s));
  work["stages_run"] = run;
  return {{"name", st.name}, {"effects", effects}, {"stages", stages}, {"work", work}};
}

void run_scene(const SceneOptions& o) {
  const std::vector<SceneTrain> scene = read_scene(o);  // 1. validate everything first
  StagedOutputs outputs;
  std::ostringstream text;
  nlohmann::ordered_json trains = nlohmann::ordered_json::array();
  for (const SceneTrain& st : scene) {  // 2. compute what is asked, into temporaries
    const Analysis a(st.train, st.settings);
    for (const EffectRequest& e : st.effects) {
      a.request(e.effect);
      outputs.stage(e.path, e.field, [&](std::ostream& out) { write_effect(out, st, a, e); });
    }
    if (o.json) trains.push_back(explain_json(st, a));
    else if (o.explain) explain_text(text, st, a);
  }
  outputs.commit();  // 3. every output appears, then the explanation
  write_output("-", [&](std::ostream& out) {
    if (o.json) out << nlohmann::ordered_json{{"trains", trains}}.dump(2) << "\n";
    else out << text.str();
  });
}

}  // namespace

std::size_t validate_scene_text(const std::string& text) {
  Json scene;
  return parse_scene(SceneError{"scene"}, text, "", scene).size();
}

void register_scene(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand("scene", "run a scene file: gear trains and the effects wanted from each (JSON)");
  cmd->add_option("FILE", o->file, "the scene (JSON; see README: sphtroch scene)")->required();
  cmd->add_flag("--explain", o->explain, "print, per gear train, the stages each effect needs and the work done");
  cmd->add_flag("--json", o->json, "the explanation as one JSON object (implies --explain)");
  cmd->add_option("--output-dir", o->output_dir, "resolve relative output paths against DIR (default: the current directory)");
  cmd->footer("Example: sphtroch scene data/scenes/paper_figures.json --output-dir /tmp --explain");
  actions.emplace_back(cmd, [o] { run_scene(*o); });
}

}  // namespace sphtroch::cli
