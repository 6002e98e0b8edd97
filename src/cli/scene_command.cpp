// sphtroch scene FILE [--explain] [--json] [--output-dir DIR] — runs a scene: a list of gear
// trains and, for each, the effects wanted, computing only the stages those effects need
// (sphtroch::Analysis). The scene's schema, outputs and explanation are the library's
// (sphtroch/exact/scene.hpp); this file adds the file system. The second CLI translation unit that
// includes CGAL.
//
// Order of work (so that a failure anywhere leaves no output at all):
//  1. read and validate the whole scene — JSON syntax (line and column), every key, every value
//     (parse_scene), every output path (distinct, in an existing writable directory) — computing
//     nothing;
//  2. per train, build one Analysis, request each effect in the order written, and write its
//     output to a temporary file next to the target (StagedOutputs);
//  3. rename every temporary into place; only then print the explanation (if asked);
//  4. if a train's node count is not certified (certified_census.hpp), one line on stderr and
//     exit status 3 (the outputs are complete and say so).
// Every problem is one line on stderr naming the file and the field (or line and column), the
// value and the valid range, exit status 2.
#include "cli_common.hpp"

#include "sphtroch/exact/analysis.hpp"
#include "sphtroch/io/input_file.hpp"
#include "sphtroch/exact/scene.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <sstream>

namespace sphtroch::cli {

namespace {

struct SceneOptions {
  std::string file, output_dir;
  bool explain = false;
  bool json = false;
};

/// The scene's trains, parsed by the library; its SceneError becomes the tool's one-line error.
std::vector<SceneTrain> parse_scene_text(const std::string& text, const std::string& file, const std::string& output_dir) {
  try {
    return parse_scene(text, file, output_dir);
  } catch (const SceneError& e) {
    throw UsageError{e.what()};
  }
}

std::vector<SceneTrain> read_scene(const SceneOptions& o) {
  namespace fs = std::filesystem;
  std::string text;
  try {
    text = read_whole_input(o.file, "scene", kMaxSceneBytes);
  } catch (const InvalidInput& e) {
    throw UsageError{o.file + ": " + e.problem() + "; valid: a readable scene file (JSON) of at most 16 MiB"};
  }
  if (!o.output_dir.empty() && !fs::is_directory(o.output_dir))
    throw UsageError{"--output-dir = " + o.output_dir + ": not a directory; valid: an existing, writable directory"};
  std::vector<SceneTrain> out = parse_scene_text(text, o.file, o.output_dir);
  std::map<std::string, std::string> paths;  // file identity -> where first used
  paths.emplace(input_key(o.file), "the scene file itself");  // by identity: any alias of it is refused
  for (const SceneTrain& st : out) {
    for (const SceneEffect& e : st.effects) {
      const auto fail = [&](const std::string& problem, const std::string& valid) {
        throw UsageError{SceneError(o.file, e.field, e.written, problem, valid).what()};
      };
      const fs::path abs = fs::absolute(e.path).lexically_normal();
      if (const std::string key = file_key(abs.string()); !key.empty())
        if (const auto [it, fresh] = paths.emplace(key, e.field); !fresh)
          fail("output path reaches the same file as " + it->second, "a distinct path per output, not the scene file");
      const fs::path dir = abs.parent_path();
      std::error_code ec;
      if (!fs::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        fail("its directory " + dir.string() + " is missing or not writable", "a path in an existing, writable directory");
      if (fs::is_directory(abs, ec)) fail("is a directory", "a file path");
    }
  }
  return out;
}

void run_scene(const SceneOptions& o) {
  const std::vector<SceneTrain> scene = read_scene(o);  // 1. validate everything first
  StagedOutputs outputs;
  std::ostringstream text;
  nlohmann::ordered_json trains = nlohmann::ordered_json::array();
  std::vector<std::string> uncertified;
  for (const SceneTrain& st : scene) {  // 2. compute what is asked, into temporaries
    const Analysis a(st.train, st.settings);
    for (const SceneEffect& e : st.effects) {
      a.request(e.effect);
      outputs.stage(e.path, e.field, [&](std::ostream& out) { write_scene_effect(out, st, a, e); }, {});  // read_scene checked it
    }
    if (std::string why = scene_uncertified(st, a); !why.empty()) uncertified.push_back(std::move(why));
    if (o.json) trains.push_back(scene_explanation_json(st, a));
    else if (o.explain) write_scene_explanation(text, st, a);
  }
  outputs.commit();  // 3. every output appears, then the explanation
  std::vector<std::string> written;
  for (const SceneTrain& st : scene)
    for (const SceneEffect& e : st.effects) written.push_back(e.path);
  write_stdout_after_outputs(written, [&](std::ostream& out) {
    if (o.json) out << nlohmann::ordered_json{{"trains", trains}}.dump(2) << "\n";
    else out << text.str();
  });
  if (!uncertified.empty())  // 4. the outputs say so (classification, plot caption); so does the status
    throw UncertifiedResult{uncertified.front() + (uncertified.size() > 1 ? " (and " + std::to_string(uncertified.size() - 1) +
                                                                               " more train(s))" : "") +
                            " (exit status 3; see docs/cli.md: Certified counts)"};
}

}  // namespace

std::size_t validate_scene_text(const std::string& text) { return parse_scene_text(text, "scene", "").size(); }

void register_scene(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto o = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand("scene", "run a scene file: gear trains and the effects wanted from each (JSON)");
  cmd->add_option("FILE", o->file, "the scene (JSON; see docs/cli.md: sphtroch scene)")->type_name("FILE")->required();
  cmd->add_flag("--explain", o->explain, "print, per gear train, the stages each effect needs and the work done");
  cmd->add_flag("--json", o->json, "the explanation as one JSON object (implies --explain)");
  cmd->add_option("--output-dir", o->output_dir, "resolve relative output paths against DIR (default: the current directory)")->type_name("DIR");
  cmd->footer("Example: sphtroch scene data/scenes/paper_figures.json --output-dir /tmp --explain");
  actions.emplace_back(cmd, [o] { run_scene(*o); });
}

}  // namespace sphtroch::cli
