// Tests of sphtroch/exact/scene.hpp: a scene's schema read into trains (every key, defaults, order of
// effects, output paths), its errors as one line naming file, field, value and valid range, each
// effect's output against what the stage gives when computed separately here, and the
// explanation against the Analysis's own record of the stages it ran.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/exact/scene.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace sphtroch;
using nlohmann::json;

namespace {

const double kPi = Constants<double>::pi();

SceneError scene_error(const std::string& text) {
  try {
    parse_scene(text, "f.json");
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("no SceneError for " << text);
  return SceneError("", "", "", "", "");
}

std::string train_with(const std::string& extra) {
  return R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, )" + extra + R"("effects": {"nodes": "n.csv"}}]})";
}


}  // namespace

TEST_CASE("scene: every key read, defaults, effects in the order written, relative paths joined") {
  const std::string text = R"({
    "description": "two trains",
    "trains": [
      {"name": "first", "a2": "pi/3", "a3": 1.25, "n": 2, "samples": 720, "literal": true,
       "census_samples": 2048, "effects": {"plot": "f.svg", "nodes": "/abs/n.csv", "trace": "sub/t.csv"}},
      {"name": "second", "description": "open", "a2": 1, "a3": "ap+1e-6", "n": "5/2", "phase": "pi/4",
       "turns": 1.5, "effects": {"classification": "c.txt"}}
    ]})";
  const std::vector<SceneTrain> s = parse_scene(text, "x.json", "out");
  REQUIRE(s.size() == 2);
  const SceneTrain& a = s[0];
  CHECK(a.name == "first");
  CHECK(a.text.a2 == "pi/3");
  CHECK(a.text.a3 == "1.25");  // a number becomes its shortest round-trip text
  CHECK(a.text.n == "2");
  CHECK(a.text.phase == "0");
  CHECK(a.train.a2() == kPi / 3);
  CHECK(a.train.a3() == 1.25);
  CHECK(a.settings.samples == 720);
  CHECK(a.settings.census_samples == 2048);
  CHECK(a.settings.reading.literal);
  CHECK_FALSE(a.settings.turns);
  REQUIRE(a.effects.size() == 3);
  CHECK(a.effects[0].effect == Effect::plot);  // as written, not alphabetical
  CHECK(a.effects[1].effect == Effect::nodes);
  CHECK(a.effects[2].effect == Effect::trace);
  CHECK(a.effects[0].path == "out/f.svg");
  CHECK(a.effects[1].path == "/abs/n.csv");  // absolute: as written
  CHECK(a.effects[2].path == "out/sub/t.csv");
  CHECK(a.effects[0].field == "trains[0].effects.plot");
  CHECK(a.effects[0].written == "\"f.svg\"");
  const SceneTrain& b = s[1];
  CHECK(b.text.phase == "pi/4");
  CHECK(b.train.phase_given() == Approx(kPi / 4).epsilon(1e-15));
  CHECK(b.train.ratio().p() == 5);
  CHECK(b.train.ratio().q() == 2);
  REQUIRE(b.settings.turns);
  CHECK(*b.settings.turns == 1.5);
  CHECK(b.settings.samples == 0);
  CHECK_FALSE(b.settings.reading.literal);
}

TEST_CASE("scene: teeth instead of n is the train of n = ZS/ZP, kept and echoed next to n") {
  const auto one = [](const std::string& ratio) {
    return parse_scene(R"({"trains": [{"name": "t", "a2": 0.7, "a3": 2.5, )" + ratio +
                           R"(, "effects": {"classification": "c.json"}}]})",
                       "x.json")
        .at(0);
  };
  const SceneTrain teeth = one(R"("teeth": "39:15")"), n = one(R"("n": "13/5")");
  CHECK(teeth.text.teeth == "39:15");
  CHECK(teeth.train.ratio() == n.train.ratio());
  CHECK(teeth.train.a3() == n.train.a3());
  Analysis analysis(teeth.train, teeth.settings);
  std::ostringstream out, explanation;
  write_scene_effect(out, teeth, analysis, teeth.effects.at(0));
  CHECK(json::parse(out.str())["inputs"]["teeth"] == "39:15");
  write_scene_explanation(explanation, teeth, analysis);
  CHECK(explanation.str().find("n = 13/5 (teeth 39:15)") != std::string::npos);
  CHECK(scene_error(train_with(R"("teeth": "39:15", )")).field() == "f.json: trains[0].n");  // both n and teeth
  CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "teeth": 39, "effects": {"nodes": "n"}}]})").field() ==
        "f.json: trains[0].teeth");
  CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "teeth": "39:0", "effects": {"nodes": "n"}}]})").field() ==
        "f.json: trains[0].teeth");
  CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "teeth": "", "effects": {"nodes": "n"}}]})").field() ==
        "f.json: trains[0].teeth");
}

TEST_CASE("scene errors: FILE: PATH = VALUE: PROBLEM, valid: RANGE, one line, an InvalidInput") {
  const SceneError e = scene_error(train_with(R"("phase": "x", )"));
  const InvalidInput& base = e;  // callers that know InvalidInput only still get the parts
  CHECK(base.field() == "f.json: trains[0].phase");
  CHECK(base.value() == "\"x\"");
  CHECK(std::string(e.what()) == "f.json: trains[0].phase = \"x\": " + e.problem() + "; valid: " + e.valid_range());
  CHECK_FALSE(e.problem().empty());
  CHECK_FALSE(e.valid_range().empty());

  const SceneError range = scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 7, "n": 2, "effects": {"nodes": "n"}}]})");
  CHECK(range.field() == "f.json: trains[0].a3");  // the range check of the train, named by the scene's key
  CHECK(range.value() == "7");
}

TEST_CASE("scene errors: a problem without a value has no ' = '") {
  const SceneError e = scene_error(R"({"trains": [{"a2": 1}]})");
  CHECK(std::string(e.what()).rfind("f.json: trains[0].name: missing; valid: ", 0) == 0);
  CHECK(e.value().empty());
}

TEST_CASE("scene errors: each hazard named where it is") {
  CHECK(scene_error(R"({"trains": [{"name": "a", "name": "b"}]})").field() == "f.json: trains[0].name");
  CHECK(scene_error(train_with(R"("bogus": 3, )")).field() == "f.json: trains[0].bogus");
  CHECK(scene_error(train_with(R"("samples": 5, "turns": 2, )")).field() == "f.json: trains[0].turns");
  CHECK(scene_error(train_with(R"("samples": 2.5, )")).field() == "f.json: trains[0].samples");
  CHECK(scene_error(R"({"trains": [], "x": 1})").field() == "f.json: x");
  CHECK(scene_error(R"({"trains": []})").field() == "f.json: trains");
  CHECK(scene_error("[1]").field() == "f.json: (top level)");
  CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"bogus": "x"}}]})").field() ==
        "f.json: trains[0].effects.bogus");
  const std::string two = R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"nodes": "a"}},
                                         {"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"nodes": "b"}}]})";
  CHECK(scene_error(two).field() == "f.json: trains[1].name");
  // SVG bytes never go into a file named as another picture format.
  for (const char* name : {"a.png", "dir/A.PNG", "a.pdf", "a.jpeg"})
    CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"plot": ")" + std::string(name) +
                      R"("}}]})").field() == "f.json: trains[0].effects.plot");
  CHECK(parse_scene(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"plot": "p.svg", "trace": "t.png.csv"}}]})",
                    "f.json").size() == 1);
  // A census of a huge ratio is refused up front, before anything is computed.
  CHECK(scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 100001, "effects": {"nodes": "n"}}]})").field() ==
        "f.json: trains[0].effects.nodes");
}

TEST_CASE("scene errors: JSON syntax by line and column, depth, NUL and overflow refused") {
  const SceneError syntax = scene_error("{\n  \"trains\": [,]\n}");
  CHECK(std::string(syntax.what()).rfind("f.json: line 2, column ", 0) == 0);
  const std::string deep = std::string(kMaxSceneDepth + 4, '[') + std::string(kMaxSceneDepth + 4, ']');
  CHECK(std::string(scene_error(R"({"trains": )" + deep + "}").what()).find("nested deeper than") != std::string::npos);
  CHECK(std::string(scene_error(std::string("{\"trains\": [\0]}", 15)).what()).find("NUL") != std::string::npos);
  CHECK(std::string(scene_error(R"({"trains": [1e999]})").what()).find("not valid JSON") != std::string::npos);
}

TEST_CASE("scene errors: a value with a newline or of any length stays on one line of bounded width") {
  const std::string long_name(300, 'x');
  const SceneError e =
      scene_error(R"({"trains": [{"name": "t", "a2": 1, "a3": 1, "n": 2, "effects": {"nodes": "a\nb", "bogus": ")" +
                  long_name + R"("}}]})");
  const std::string what = e.what();
  CHECK(what.find('\n') == std::string::npos);
  CHECK(e.value().size() == 80);
  CHECK(e.value().substr(77) == "...");
}

TEST_CASE("scene effects: each output is what the stage gives, computed separately here") {
  const std::string text =
      R"({"trains": [{"name": "f", "a2": "pi/3", "a3": "pi/2", "n": 2, "samples": 360, "effects": {
        "nodes": "n.csv", "cusps": "k.csv", "classification": "c.json", "extrema": "z.json", "screw_axis": "w.csv",
        "trace": "t.csv"}}]})";
  const SceneTrain st = parse_scene(text, "s.json").front();
  const Analysis a(st.train, st.settings);
  auto output = [&](Effect which) {
    for (const SceneEffect& e : st.effects)
      if (e.effect == which) {
        std::ostringstream out;
        a.request(e.effect);
        write_scene_effect(out, st, a, e);
        return out.str();
      }
    FAIL("no such effect");
    return std::string();
  };
  const Analysis separate(GearTrain(kPi / 3, kPi / 2, Ratio(2)));
  std::ostringstream nodes;
  write_nodes_csv(nodes, separate.nodes(), separate.cusps());
  CHECK(output(Effect::nodes) == nodes.str());
  CHECK(sphtroch::test::split_lines(output(Effect::nodes)).size() == 1 + 4);  // Table 1 row (f): 4 nodes, no cusp
  CHECK(sphtroch::test::split_lines(output(Effect::cusps)).size() == 1);      // no cusp: the header alone

  const json c = json::parse(output(Effect::classification));
  CHECK(c["inputs"]["a2_text"] == "pi/3");
  CHECK(c["counts"]["nodes"] == 4);
  const json z = json::parse(output(Effect::extrema));
  CHECK(z["z_max"].get<double>() == Approx(std::cos(kPi / 3 - kPi / 2)).epsilon(1e-14));

  // Screw axis: |omega| = sqrt(1 + n^2 + 2 n cos a2) at every sample (Eq. 47a).
  const auto w = sphtroch::test::split_lines(output(Effect::screw_axis));
  REQUIRE(w.size() == 1 + 360);
  CHECK(w[0] == "t,wx,wy,wz");
  const double norm = std::sqrt(1.0 + 4.0 + 4.0 * std::cos(kPi / 3));
  for (std::size_t i = 1; i < w.size(); i += 37) {
    double t, x, y, zz;
    REQUIRE(std::sscanf(w[i].c_str(), "%lf,%lf,%lf,%lf", &t, &x, &y, &zz) == 4);
    CHECK(std::sqrt(x * x + y * y + zz * zz) == Approx(norm).epsilon(1e-14));
  }
  CHECK(sphtroch::test::split_lines(output(Effect::trace)).size() == 1 + 360);
}

TEST_CASE("scene effects: a classification path ending in .txt is the text report") {
  const SceneTrain st = parse_scene(
      R"({"trains": [{"name": "f", "a2": "pi/3", "a3": "pi/2", "n": 2, "effects": {"classification": "c.txt"}}]})",
      "s.json").front();
  const Analysis a(st.train, st.settings);
  std::ostringstream out;
  write_scene_effect(out, st, a, st.effects.front());
  CHECK(out.str().rfind("sphtroch classify", 0) == 0);
  CHECK_THROWS_AS(json::parse(out.str()), json::parse_error);
}

TEST_CASE("scene explanation: the effects' stages, the stages run in order, the rest not run") {
  const SceneTrain st =
      parse_scene(R"({"trains": [{"name": "only nodes", "a2": 1, "a3": 2, "n": 2, "effects": {"nodes": "n.csv"}}]})",
                  "s.json").front();
  const Analysis a(st.train, st.settings);
  a.request(Effect::nodes);
  const nlohmann::ordered_json ordered = scene_explanation_json(st, a);  // keys in the documented order
  std::vector<std::string> keys;
  for (const auto& item : ordered.items()) keys.push_back(item.key());
  const json j = json::parse(ordered.dump());
  CHECK(keys == std::vector<std::string>{"name", "effects", "stages", "work"});
  CHECK(j["name"] == "only nodes");
  CHECK(j["stages"].size() == kStageCount);
  REQUIRE(j["work"]["stages_run"].size() == a.stages_run().size());
  for (std::size_t k = 0; k < a.stages_run().size(); ++k) CHECK(j["work"]["stages_run"][k] == to_string(a.stages_run()[k]));
  CHECK(j["stages"][to_string(Stage::root_census)]["ran"] == true);  // nodes are certified by the root census
  CHECK(j["stages"][to_string(Stage::classification)]["ran"] == false);
  CHECK(j["stages"][to_string(Stage::polyline_census)]["ran"] == true);
  CHECK(j["work"]["points_evaluated"].get<std::size_t>() == a.total_work().points_evaluated);

  std::ostringstream out;
  write_scene_explanation(out, st, a);
  const auto l = sphtroch::test::split_lines(out.str());
  REQUIRE(!l.empty());
  CHECK(l[0] == "train only nodes: a2 = 1, a3 = 2, n = 2, phase = 0");
  bool classification_not_run = false;
  for (const auto& s : l)
    if (s.rfind("  not run: ", 0) == 0) classification_not_run = s.find(to_string(Stage::classification)) != std::string::npos;
  CHECK(classification_not_run);
}
