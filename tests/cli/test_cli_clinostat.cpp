// `sphtroch clinostat`, run as the real executable: the JSON's train and rotation reproduce the
// gravity (Eq. 4 written here with Eigen's AngleAxis: Rz(theta2) Rx(a2) Rz(n theta2 + phase)
// Rx(a3) z) and both equal --trace's rows and an independent rotation model of the machine; the
// report's keys; the dwell map's size and total; the text's numbers as a person writes them (a
// window of --resolution 0.01 as its decimal, no -0, 0.0001); bad input (exit 2, one stderr line,
// nothing on stdout, no file).
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "svg_support.hpp"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {

using namespace sphtroch::test;
using nlohmann::json;

/// g_s(t) = (Rot(u, phi_o) Rot(v, phi_i))^T (0, 0, -1); the turns rpm t / 60 in long double with
/// the whole turns removed (t up to 1e8 s keeps ~1e-12 rad).
Eigen::Vector3d model_gravity(long double outer_rpm, long double inner_rpm, double tilt_deg, double frame_deg, long double t) {
  const double pi = 3.14159265358979323846, psi = tilt_deg * pi / 180, beta = frame_deg * pi / 180;
  const Eigen::Vector3d u(std::sin(psi), 0, std::cos(psi)), w(-std::cos(psi), 0, std::sin(psi));
  const Eigen::Vector3d v = std::cos(beta) * u + std::sin(beta) * w;
  const auto angle = [](long double rpm, long double time) {
    long double turns = rpm * time / 60;
    turns -= std::floor(turns);
    return static_cast<double>(2 * 3.141592653589793238462643383279502884L * turns);
  };
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(angle(outer_rpm, t), u) * Eigen::AngleAxisd(angle(inner_rpm, t), v)).toRotationMatrix();
  return r.transpose() * Eigen::Vector3d(0, 0, -1);
}

Eigen::Vector3d eq4(const json& train, double theta2) {
  const std::string n = train["n"];
  const auto slash = n.find('/');
  const double ratio = slash == std::string::npos ? std::stod(n) : std::stod(n.substr(0, slash)) / std::stod(n.substr(slash + 1));
  const Eigen::Matrix3d m = (Eigen::AngleAxisd(theta2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(train["a2"].get<double>(), Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(ratio * theta2 + train["phase"].get<double>(), Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(train["a3"].get<double>(), Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  return m * Eigen::Vector3d::UnitZ();
}

}  // namespace

TEST_CASE("clinostat --json: the train and rotation draw the gravity, as --trace and a rotation model do", "[cli][clinostat]") {
  TempDir dir;
  for (const auto& [outer, inner, tilt, frame] : {std::tuple{1.33, 2.0, 90.0, 90.0}, std::tuple{-0.7, 1.3, 60.0, 100.0},
                                                  std::tuple{3.5, -2.25, 135.0, 45.0}}) {
    const std::string machine = "--outer " + shortest_g(outer) + " --inner " + shortest_g(inner) + " --tilt " + shortest_g(tilt) +
                                " --frame-angle " + shortest_g(frame);
    const Result r = run("clinostat " + machine + " --json", dir);
    REQUIRE(r.status == 0);
    const json j = json::parse(r.out);
    REQUIRE(j["train"].is_object());
    Eigen::Matrix3d rotation;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) rotation(i, k) = j["train"]["rotation"][i][k];
    const Result trace = run("clinostat " + machine + " --trace --duration 300 --samples 31", dir);
    REQUIRE(trace.status == 0);
    std::istringstream rows(trace.out);
    std::string line;
    std::getline(rows, line);
    CHECK(line == "t,gx,gy,gz");
    int count = 0;
    while (std::getline(rows, line)) {
      double t, x, y, z;
      char c;
      std::istringstream(line) >> t >> c >> x >> c >> y >> c >> z;
      const Eigen::Vector3d traced(x, y, z), model = model_gravity(outer, inner, tilt, frame, t);
      const Eigen::Vector3d mapped = rotation * eq4(j["train"], j["train"]["theta2_at_0"].get<double>() + j["train"]["theta2_rate"].get<double>() * t);
      CHECK((traced - model).norm() <= 1e-12);
      CHECK((mapped - model).norm() <= 1e-12);
      ++count;
    }
    CHECK(count == 31);
    CHECK(j["period_s"].is_number());
    CHECK(j["mean_over_period"].size() == 3);
  }
}

TEST_CASE("clinostat --json: worst window mean, time to epsilon and coverage keys", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat --outer 1.33 --inner 2 --window 600 --epsilon 0.01 --coverage 600 --nside 4 --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  CHECK(j["period_s"] == 6000.0);
  CHECK(j["train"]["n"] == "133/200");
  const json& m = j["worst_window_mean"];
  CHECK(m["window_s"] == 600.0);
  CHECK(m["upper"].get<double>() - m["lower"].get<double>() <= 1e-9);
  CHECK(m["lower"].get<double>() > 0.01);  // M(600 s) is above 0.01 g0 for these speeds
  const json& e = j["time_to_epsilon"];
  CHECK(e["first_s"].get<double>() <= e["stays_below_from_s"].get<double>());
  CHECK(e["stays_below_from_s"].get<double>() > 600);
  const json& c = j["coverage"];
  REQUIRE(c["dwell_s"].size() == 192);
  double total = 0;
  for (const auto& d : c["dwell_s"]) total += d.get<double>();
  CHECK(total == Approx(600).epsilon(1e-12));
  CHECK(c["fraction"].get<double>() > 0);
  CHECK(c["fraction"].get<double>() <= 1);
}

TEST_CASE("clinostat: tilted frames never average out, and the report says why", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat --outer 1.33 --inner 2 --tilt 60 --frame-angle 70 --epsilon 0.01 --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  CHECK(j["time_to_epsilon"]["first_s"].is_null());
  CHECK(j["time_to_epsilon"]["stays_below_from_s"].is_null());
  const double pi = 3.14159265358979323846;
  CHECK(std::hypot(j["mean_over_period"][0].get<double>(), j["mean_over_period"][1].get<double>(), j["mean_over_period"][2].get<double>()) ==
        Approx(std::cos(60 * pi / 180) * std::cos(70 * pi / 180)).epsilon(1e-12));
  // Machines whose train GearTrain refuses: the report goes on, without the train, saying why.
  for (const char* args : {"--outer 1 --inner 1 --frame-angle 179.99", "--outer 1 --inner -1 --frame-angle 0.01", "--outer 1 --inner 2 --tilt 1e-300"}) {
    const Result r2 = run(std::string("clinostat ") + args + " --json", dir);
    INFO(args << ": " << r2.err);
    REQUIRE(r2.status == 0);
    CHECK(json::parse(r2.out)["train"].is_null());
    CHECK(contains(json::parse(r2.out)["train_note"].get<std::string>(), "no gear train"));
  }
  // The inner axis vertical and the outer frame still: the gravity never moves in the sample, so
  // there is no period and the mean is the gravity itself, a unit vector exactly.
  const Result still = run("clinostat --outer 0 --inner 2.5 --json", dir);
  REQUIRE(still.status == 0);
  const json s = json::parse(still.out);
  CHECK(s["train"].is_null());
  CHECK(contains(s["train_note"].get<std::string>(), "does not move"));
  CHECK(s["period_s"].is_null());
  CHECK(std::hypot(s["mean_over_period"][0].get<double>(), s["mean_over_period"][1].get<double>(), s["mean_over_period"][2].get<double>()) == 1.0);
  // One speed 0 with the turning axis horizontal: a circle, the period the turning frame's.
  const Result single = run("clinostat --outer 2.5 --inner 0 --json", dir);
  REQUIRE(single.status == 0);
  CHECK(json::parse(single.out)["period_s"] == 24.0);
}

TEST_CASE("clinostat --plot: the dwell map's cells and the M(W) curve, the report unchanged", "[cli][clinostat]") {
  TempDir dir;
  const Result plain = run("clinostat --outer 1.33 --inner 2 --epsilon 0.01 --coverage 600 --nside 2", dir);
  const Result r = run("clinostat --outer 1.33 --inner 2 --epsilon 0.01 --coverage 600 --nside 2 --plot map.svg", dir, true);
  REQUIRE(r.status == 0);
  CHECK(r.out == plain.out);
  const std::string svg = slurp(dir.path / "map.svg");
  CHECK(contains(svg.substr(0, 200), "<svg"));
  CHECK(contains(svg, "epsilon = 0.01 g0"));
  std::set<std::string> cells;  // 48 cells at nside 2, each drawn once or twice (across the date line)
  for (const svg_test::Element& e : svg_test::elements(svg))
    if (e.name == "path" && e.in_group("cells")) cells.insert(e.attributes.at("class"));
  CHECK(cells.size() == 48);
  const Result bad = run("clinostat --outer 1.33 --inner 2 --plot map.pdf", dir, true);
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK(contains(bad.err, "--plot"));
}

TEST_CASE("clinostat --plot: the visited cells spread over the colour scale and the unvisited ones are one grey", "[cli][clinostat]") {
  // The picture of the issue: 1.33 / 2 rpm over an hour, nside 8 (768 cells). The rule, from the
  // picture's contract (clinostat_plot.hpp), computed here from the JSON's dwell: ratio r = dwell /
  // (total / 768); L = max(1, |log2 r| at the 5th and 95th percentile of the visited cells);
  // position 1/2 + log2 r / (2 L), clamped; the colour there on the legend's own gradient stops.
  TempDir dir;
  const std::string machine = "clinostat --outer 1.33 --inner 2 --coverage 3600 --epsilon 0.01";
  const Result r = run(machine + " --plot map.svg", dir, true);
  REQUIRE(r.status == 0);
  const json report = json::parse(run(machine + " --json", dir).out);
  const std::vector<double> dwell = report["coverage"]["dwell_s"].get<std::vector<double>>();
  REQUIRE(dwell.size() == 768);
  const std::vector<svg_test::Element> svg = svg_test::elements(slurp(dir.path / "map.svg"));
  std::vector<std::string> fills(dwell.size()), stops;  // each cell's fill, by its class "cell-<index>"
  std::size_t paths = 0;
  for (const svg_test::Element& e : svg) {
    if (e.name == "path" && e.in_group("cells")) {
      const std::size_t c = std::stoul(e.attributes.at("class").substr(5));
      REQUIRE(c < dwell.size());
      CHECK((fills[c].empty() || fills[c] == *svg_test::style(e, "fill")));  // a cell's copies alike
      fills[c] = *svg_test::style(e, "fill");
      ++paths;
    }
    if (e.name == "stop") stops.push_back(e.attributes.at("stop-color"));
  }
  CHECK(std::count(fills.begin(), fills.end(), std::string()) == 0);  // every cell drawn
  CHECK(paths < 2 * dwell.size());  // copies that miss the ellipse are left out
  REQUIRE(stops.size() >= 3);
  // Unvisited cells: one colour, which no visited cell has and the gradient does not contain.
  std::set<std::string> unvisited, visited;
  std::vector<double> visited_dwell, visited_luminance;
  double total = 0;
  for (const double d : dwell) total += d;
  std::size_t zeros = 0;
  for (std::size_t c = 0; c < dwell.size(); ++c) {
    (dwell[c] > 0 ? visited : unvisited).insert(fills[c]);
    if (dwell[c] == 0) ++zeros;
    else visited_dwell.push_back(dwell[c]), visited_luminance.push_back(svg_test::luminance(fills[c]));
  }
  CHECK(zeros == 68);  // the count
  REQUIRE(unvisited.size() == 1);
  CHECK(visited.count(*unvisited.begin()) == 0);
  CHECK(std::find(stops.begin(), stops.end(), *unvisited.begin()) == stops.end());
  bool swatch = false, swatch_text = false;
  for (const svg_test::Element& e : svg) {
    swatch = swatch || (e.name == "rect" && svg_test::style(e, "fill") == *unvisited.begin());
    swatch_text = swatch_text || (e.name == "text" && e.text == "not visited (68)");
  }
  CHECK(swatch);
  CHECK(swatch_text);
  // The acceptance: the interquartile range of the visited cells' luminance is at least 20% of the
  // scale's range of luminance (its stops: the map is piecewise linear between them).
  double lo = 1, hi = 0;
  for (const std::string& s : stops) lo = std::min(lo, svg_test::luminance(s)), hi = std::max(hi, svg_test::luminance(s));
  const double iqr = svg_test::quantile(visited_luminance, 0.75) - svg_test::quantile(visited_luminance, 0.25);
  INFO("luminance IQR " << iqr << " of a scale range " << hi - lo);
  CHECK(iqr >= 0.2 * (hi - lo));
  // Each visited cell's colour is the rule's, within one unit of rounding per component.
  std::vector<double> sorted = visited_dwell;
  std::sort(sorted.begin(), sorted.end());
  const double mean = total / static_cast<double>(dwell.size());
  const std::size_t k = static_cast<std::size_t>(std::floor(0.05 * static_cast<double>(sorted.size() - 1)));
  const double half = std::max({1.0, std::fabs(std::log2(sorted[k] / mean)), std::fabs(std::log2(sorted[sorted.size() - 1 - k] / mean))});
  std::size_t wrong = 0;
  for (std::size_t c = 0; c < dwell.size(); ++c) {
    if (dwell[c] == 0) continue;
    const double f = std::clamp(0.5 + std::log2(dwell[c] / mean) / (2 * half), 0.0, 1.0) * static_cast<double>(stops.size() - 1);
    const std::size_t i = std::min(stops.size() - 2, static_cast<std::size_t>(f));
    const auto a = svg_test::rgb(stops[i]), b = svg_test::rgb(stops[i + 1]), got = svg_test::rgb(fills[c]);
    for (int ch = 0; ch < 3; ++ch)
      if (std::fabs(got[ch] - ((1 - (f - i)) * a[ch] + (f - i) * b[ch])) > 1.01) ++wrong;
  }
  CHECK(wrong == 0);
  // Every text is readable: at least 9.5 px.
  for (const svg_test::Element& e : svg)
    if (e.name == "text") CHECK(svg_test::font_px(e) >= 9.5);
}

TEST_CASE("clinostat --plot: M(W) has intermediate ticks and marks the time to epsilon", "[cli][clinostat]") {
  TempDir dir;
  const std::string machine = "clinostat --outer 1.33 --inner 2 --epsilon 0.01";
  REQUIRE(run(machine + " --coverage 600 --nside 2 --plot map.svg", dir, true).status == 0);
  const json t = json::parse(run(machine + " --json", dir).out)["time_to_epsilon"];
  const std::string text = slurp(dir.path / "map.svg");
  const auto whole = [](double v) { return std::to_string(static_cast<long long>(v)); };
  REQUIRE(t["first_s"].get<double>() == std::floor(t["first_s"].get<double>()));  // 1 s resolution: whole seconds
  const std::vector<svg_test::Element> svg = svg_test::elements(text);
  std::string words;  // the texts in order, lines joined by spaces (a wrapped sentence read back)
  for (const svg_test::Element& e : svg)
    if (e.name == "text") words += e.text + " ";
  CHECK(contains(words, "first window below epsilon: " + whole(t["first_s"].get<double>()) + " s"));
  CHECK(contains(words, "every window from " + whole(t["stays_below_from_s"].get<double>()) + " s on is below"));
  // The panel (the rect with no fill after the dwell map): a dotted vertical line inside it and a
  // shaded band from stays_below_from_s to its right edge; tick labels along W between its ends.
  const svg_test::Element* panel = nullptr;
  for (const svg_test::Element& e : svg)
    if (e.name == "rect" && svg_test::style(e, "fill") == std::string("none")) panel = &e;
  REQUIRE(panel != nullptr);
  const double x0 = panel->number("x"), w = panel->number("width"), y0 = panel->number("y"), h = panel->number("height");
  int dotted = 0, shaded = 0, w_ticks = 0, m_ticks = 0;
  for (const svg_test::Element& e : svg) {
    if (e.name == "line" && svg_test::style(e, "stroke-dasharray") == std::string("2,3") && e.number("x1") == e.number("x2") &&
        e.number("x1") > x0 && e.number("x1") < x0 + w)
      ++dotted;
    if (e.name == "rect" && svg_test::style(e, "fill-opacity") && std::fabs(e.number("x") + e.number("width") - (x0 + w)) < 0.02) ++shaded;
    if (e.name == "text" && e.number("y") > y0 + h && e.number("y") < y0 + h + 25 && e.number("x") >= x0 && e.number("x") <= x0 + w &&
        e.text.find_first_not_of("0123456789.") == std::string::npos)
      ++w_ticks;  // a number under the panel
    if (e.name == "line" && e.number("y1") == e.number("y2") && e.number("x2") == x0 && x0 - e.number("x1") > 0 &&
        x0 - e.number("x1") < 5)
      ++m_ticks;  // a short tick left of the panel
  }
  CHECK(dotted == 1);
  CHECK(shaded == 1);
  CHECK(w_ticks >= 4);
  CHECK(m_ticks >= 8);  // 2 .. 9 times at least one decade
}

TEST_CASE("clinostat: bad input is refused with one line naming the option, nothing on stdout", "[cli][clinostat]") {
  TempDir dir;
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--outer 0 --inner 0", "--inner"}, {"--outer nan --inner 1", "--outer"}, {"--outer 1 --inner 1e3", "--inner"},
           {"--outer 1001 --inner 1", "--outer"}, {"--outer 1 --inner 2 --coverage 60 --nside 3", "--nside"},
           {"--outer 1 --inner 2 --window 0", "--window"}, {"--outer 1 --inner 2 --window -5", "--window"},
           {"--outer 1 --inner 2 --offset 1,2", "--offset"}, {"--outer 1 --inner 2 --tilt 190", "--tilt"},
           {"--outer 1 --inner 2 --frame-angle nan", "--frame-angle"}, {"--outer 1 --inner 2 --epsilon 0", "--epsilon"},
           {"--outer 1 --inner 2 --trace --duration 0 -o out.csv", "--duration"},
           {"--outer 1 --inner 2 --trace --duration 10 --samples 1 -o out.csv", "--samples"},
           {"--outer 1.33 --inner 2 --coverage 60 --nside 64 --plot map.svg", "--nside"}, {"--outer 1.33 --inner 2 --plot -", "--plot"},
           {"--outer 1.33 --inner 2 --plot map.txt", "--plot"}, {"--outer 1 --inner 2 --start 5", "--start"},
           {"--outer 1 --inner 2 --trace --duration 10 --plot map.svg", "--plot"}}) {
    const Result r = run("clinostat " + args, dir, true);
    INFO(args << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, option));
    CHECK(dir.entries().empty());
  }
}

TEST_CASE("clinostat: the time to epsilon holds for every window length, not only the grid (60 rpm, one axis)", "[cli][clinostat]") {
  // M(W) = |sin(pi W)| / (pi W) for gravity turning once a second in a great circle: every grid
  // window (whole seconds) averages to 0, yet M(31.5 s) = 1 / (31.5 pi) > 0.01.
  TempDir dir;
  const Result r = run("clinostat --outer 60 --inner 0 --epsilon 0.01 --json", dir);
  REQUIRE(r.status == 0);
  const nlohmann::json t = nlohmann::json::parse(r.out)["time_to_epsilon"];
  const double stays = t["stays_below_from_s"].get<double>();
  const auto m = [](double w) { return std::fabs(std::sin(3.141592653589793 * w)) / (3.141592653589793 * w); };
  CHECK(stays > 31.5);
  for (double w = stays; w < stays + 100; w += 0.0071) CHECK(m(w) <= 0.01);
  REQUIRE(t["above_s"].is_number());
  CHECK(m(t["above_s"].get<double>()) > 0.01);
  CHECK(t["above_s"].get<double>() >= stays - 2);
}

TEST_CASE("clinostat: numbers and refusals as typed (leading zeros, epsilon below rounding, a still gravity)", "[cli][clinostat]") {
  TempDir dir;
  const Result zeros = run("clinostat --outer 00001 --inner 2", dir);  // 00001 is 1 rpm
  CHECK(zeros.status == 0);
  CHECK(contains(zeros.out, "outer 1 rpm"));
  const Result tiny = run("clinostat --outer 1 --inner 2 --epsilon 1e-16", dir);  // refused (2), not "not certified" (3)
  CHECK(tiny.status == 2);
  CHECK(tiny.out.empty());
  CHECK(count_lines(tiny.err) == 1);
  CHECK(contains(tiny.err, "epsilon"));
  const Result design = run("clinostat design --outer 1:2 --inner 1:2 --step 0.5 --window 600 --epsilon 0.01 --resolution 1e-300", dir);
  CHECK(design.status == 2);  // every pair refuses the option: the option is out of range
  CHECK(design.out.empty());
  CHECK(count_lines(design.err) == 1);
  CHECK(contains(design.err, "resolution"));
}

namespace {

/// k hundredths as a person writes them (8760 -> "87.6", 3755 -> "37.55", 100 -> "1"), k >= 0.
std::string hundredths(long long k) {
  std::string s = std::to_string(k / 100);
  const long long cents = k % 100;
  if (cents != 0) s += (cents % 10 == 0 ? "." + std::to_string(cents / 10) : (cents < 10 ? ".0" : ".") + std::to_string(cents));
  return s;
}

/// A window in the JSON that lies on the grid of 0.01 s: the double nearest the decimal k / 100.
long long on_hundredths_grid(const nlohmann::json& v) {
  const long long k = std::llround(v.get<double>() * 100);
  CHECK(v.get<double>() == std::strtod((std::to_string(k) + "e-2").c_str(), nullptr));
  return k;
}

}  // namespace

TEST_CASE("clinostat text: a window of --resolution 0.01 prints as its decimal (87.6 s not 87.60000000000001 s)", "[cli][clinostat]") {
  TempDir dir;
  // 1.33 / 2 rpm at epsilon 0.03 (and 0.05): windows of 8760 x 0.01 s (39140 x 0.01 s), whose
  // products of doubles are 87.60000000000001 (391.40000000000003).
  CHECK(8760 * 0.01 != 87.6);
  for (const char* epsilon : {"0.03", "0.05"}) {
    INFO(epsilon);
    const std::string args = std::string("clinostat --outer 1.33 --inner 2 --epsilon ") + epsilon + " --resolution 0.01";
    const Result text = run(args, dir), json = run(args + " --json", dir);
    REQUIRE(text.status == 0);
    REQUIRE(json.status == 0);
    const nlohmann::json t = nlohmann::json::parse(json.out)["time_to_epsilon"];
    const long long first = on_hundredths_grid(t["first_s"]), stays = on_hundredths_grid(t["stays_below_from_s"]);
    CHECK(contains(text.out, std::string("time to epsilon = ") + epsilon + " g0 (windows in steps of 0.01 s): the first window below is " +
                                 hundredths(first) + " s; every window from " + hundredths(stays) + " s on, of any length, is below"));
  }
}

TEST_CASE("clinostat text: no -0 (a single-axis machine's window starts at 0 s) and epsilon 0.0001 as typed", "[cli][clinostat]") {
  TempDir dir;
  // One axis: every start is as bad as any other; the start reported is 0, not -0 (fmod of -30 s
  // by the 30 s period), in the text and in the JSON.
  const Result one = run("clinostat --outer 2 --inner 0 --window 60", dir);
  REQUIRE(one.status == 0);
  CHECK(contains(one.out, "reached by the window starting at 0 s\n"));
  CHECK_FALSE(contains(one.out, "-0 "));
  CHECK_FALSE(contains(one.out, "-0,"));
  CHECK_FALSE(contains(one.out, "(-0"));
  const nlohmann::json j = nlohmann::json::parse(run("clinostat --outer 2 --inner 0 --window 60 --json", dir).out);
  CHECK(j["worst_window_mean"]["start_s"].get<double>() == 0.0);
  CHECK_FALSE(std::signbit(j["worst_window_mean"]["start_s"].get<double>()));
  const Result small = run("clinostat --outer 1.33 --inner 2 --epsilon 0.0001", dir);
  REQUIRE(small.status == 0);
  CHECK(contains(small.out, "time to epsilon = 0.0001 g0 (windows in steps of 1 s): "));
  CHECK_FALSE(contains(small.out, "e-0"));
}

TEST_CASE("clinostat --plot of a machine with a very long period is bounded (the torus bound) and says so", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat --outer 1.00001 --inner 1 --plot long.svg", dir, true);  // period 6e6 s
  REQUIRE(r.status == 0);
  const std::string svg = slurp(dir.path / "long.svg");
  CHECK(contains(svg, "the period is too long to search"));
}

TEST_CASE("clinostat design merge: a row whose period or mean over a period was edited is refused", "[cli][clinostat]") {
  TempDir dir;
  const std::string args = "clinostat design --outer 1:2 --inner 1:2 --step 1 --window 600 --epsilon 0.01 --json";
  REQUIRE(run(args + " --shard 1/2 -o p1.json", dir, true).status == 0);
  REQUIRE(run(args + " --shard 2/2 -o p2.json", dir, true).status == 0);
  REQUIRE(run("clinostat merge p1.json p2.json -o whole.json", dir, true).status == 0);
  // Edit the 1/1 rpm row's mean, then compute the digest again as the part's own rule says:
  // FNV-1a 64 of the bytes with the digest's 16 digits written as 0.
  nlohmann::json part = nlohmann::json::parse(slurp(dir.path / "p1.json"));
  std::string text = slurp(dir.path / "p1.json");
  const std::string digest = part["digest"].get<std::string>();
  const std::string zero(16, '0');
  const auto at_mean = text.find("\"mean_over_period\": ");
  REQUIRE(at_mean != std::string::npos);
  const auto end = text.find_first_of(",\n", at_mean);
  text.replace(at_mean, end - at_mean, "\"mean_over_period\": 0.25");
  text.replace(text.find(digest), 16, zero);
  std::uint64_t h = 14695981039346656037ull;
  for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  text.replace(text.find(zero), 16, hex);
  std::ofstream(dir.path / "p1.json", std::ios::binary) << text;
  const Result merged = run("clinostat merge p1.json p2.json -o edited.json", dir, true);
  INFO(merged.err);
  CHECK(merged.status == 2);
  CHECK(contains(merged.err, "mean over a period"));
  CHECK(!fs::exists(dir.path / "edited.json"));
}

TEST_CASE("clinostat --running-mean: the mean over [start, start + T] as --trace integrates it, and its refusals", "[cli][clinostat]") {
  TempDir dir;
  const Result r = run("clinostat --outer 1.5 --inner -2 --tilt 70 --running-mean 40,100 --start 7 --json", dir);
  REQUIRE(r.status == 0);
  const json d = json::parse(r.out);
  REQUIRE(d["running_mean"].size() == 2);
  for (const json& m : d["running_mean"]) {
    const double t = m["t_s"];
    CHECK(m["start_s"] == 7.0);
    // The trace's samples of the same machine, integrated here by Simpson's rule (4000 panels: the
    // frames turn at most 2 rpm, so the rule's error is below 1e-12 g0).
    const Result tr = run("clinostat --outer 1.5 --inner -2 --tilt 70 --trace --start 7 --duration " + std::to_string(t) +
                              " --samples 8001", dir);
    REQUIRE(tr.status == 0);
    std::istringstream lines(tr.out);
    std::string line;
    std::getline(lines, line);  // header
    double sum[3] = {0, 0, 0};
    for (int k = 0; std::getline(lines, line); ++k) {
      double tt, g[3];
      REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &tt, &g[0], &g[1], &g[2]) == 4);
      const double weight = (k == 0 || k == 8000) ? 1 : (k % 2 ? 4 : 2);
      for (int c = 0; c < 3; ++c) sum[c] += weight * g[c];
    }
    double norm2 = 0;
    for (int c = 0; c < 3; ++c) {
      const double mean = sum[c] * (t / 8000 / 3) / t;
      CHECK(std::fabs(m["mean"][c].get<double>() - mean) < 1e-12);
      norm2 += m["mean"][c].get<double>() * m["mean"][c].get<double>();
    }
    CHECK(m["magnitude"].get<double>() == Approx(std::sqrt(norm2)).epsilon(1e-15));
  }
  const Result text = run("clinostat --outer 1.5 --inner -2 --tilt 70 --running-mean 40 --start 7", dir);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "running mean over [7, 47] s: ("));
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--running-mean 0", "--running-mean"}, {"--running-mean 10,-1", "--running-mean"}, {"--running-mean 10,", "--running-mean"},
           {"--running-mean 1e13", "--running-mean"}, {"--trace --duration 10 --running-mean 5", "--running-mean"}}) {
    const Result bad = run("clinostat --outer 1 --inner 2 " + args, dir);
    INFO(args << " -> " << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(contains(bad.err, option));
    CHECK(count_lines(bad.err) == 1);
  }
}

namespace {

/// |mean over [t0, t0 + W]| of model_gravity by composite 4-point Gauss-Legendre (panels of at
/// most 0.2 s: the frames turn at most 5.05 rpm, 0.11 rad per panel, so the rule's error is
/// ~1e-17 of the mean).
double model_window_mean(long double outer, long double inner, double tilt, long double t0, double w, double frame = 90) {
  const double x[2] = {0.3399810435848563, 0.8611363115940526}, c[2] = {0.6521451548625461, 0.3478548451374538};
  const int panels = static_cast<int>(std::ceil(w / 0.2));
  const double h = w / panels;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < panels; ++k) {
    const long double mid = t0 + (k + 0.5L) * h;  // long double: a start of 3e7 s keeps its nodes to ~1e-12 s
    for (int i = 0; i < 2; ++i)
      sum += c[i] * (model_gravity(outer, inner, tilt, frame, mid - x[i] * h / 2) + model_gravity(outer, inner, tilt, frame, mid + x[i] * h / 2));
  }
  return (sum * h / 2 / w).norm();
}

}  // namespace

TEST_CASE("clinostat --band: the Mars preset's window band and target against a scan of the rotation model", "[cli][clinostat]") {
  TempDir dir;
  const std::string mars = "clinostat --tilt 67.7901 --outer 5 --inner 0.05 --window 600 --band";
  // The scan: every 5 s of the period of 1200 s (|d mean / d t0| <= 2 / W: within 1/60 g0 of the extremes).
  double low = 1, high = 0;
  for (double t0 = 0; t0 < 1200; t0 += 5) {
    const double m = model_window_mean(5, 0.05, 67.7901, t0, 600);
    low = std::min(low, m), high = std::max(high, m);
  }
  const Result r = run(mars + " --target-g 0.241 --tolerance 0.008 --json", dir);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  const json& b = j["window_band"];
  CHECK(b["window_s"] == 600.0);
  CHECK(b["certified"] == true);
  CHECK(b["bound"] == "period");
  for (const char* end : {"min", "max"}) {
    CHECK(b[end]["upper"].get<double>() - b[end]["lower"].get<double>() <= 1e-9);
    CHECK(b[end]["lower"].get<double>() <= b[end]["upper"].get<double>());
  }
  CHECK(b["min"]["lower"].get<double>() <= low + 1e-12);
  CHECK(b["max"]["upper"].get<double>() >= high - 1e-12);
  // The starts reached: the model's window there is at the bracket's found end.
  CHECK(model_window_mean(5, 0.05, 67.7901, b["min"]["start_s"], 600) <= b["min"]["upper"].get<double>() + 1e-12);
  CHECK(model_window_mean(5, 0.05, 67.7901, b["max"]["start_s"], 600) >= b["max"]["lower"].get<double>() - 1e-12);
  CHECK(j["worst_window_mean"]["upper"] == b["max"]["upper"]);  // the max is M(W)
  // Inside: the scan's extremes within [0.233, 0.249] by more than the scan's step allows.
  REQUIRE(low > 0.233 + 0.02 / 60);
  REQUIRE(high < 0.249 - 0.02 / 60);
  CHECK(j["target"] == json{{"g", 0.241}, {"tolerance", 0.008}, {"inside", true}, {"start_s", nullptr}});
  // Outside: the scan's max is above 0.245 by more than its step.
  REQUIRE(high > 0.245 + 0.02 / 60);
  const Result out = run(mars + " --target-g 0.241 --tolerance 0.004 --json", dir);
  REQUIRE(out.status == 0);
  const json t = json::parse(out.out)["target"];
  CHECK(t["inside"] == false);
  const double leaves = model_window_mean(5, 0.05, 67.7901, t["start_s"], 600);
  CHECK((leaves > 0.245 || leaves < 0.237));
  // The text says both.
  const Result text = run(mars + " --target-g 0.241 --tolerance 0.004", dir);
  REQUIRE(text.status == 0);
  CHECK(contains(text.out, "window band, W = 600 s: every window mean's |mean| lies between min in [0.2347"));
  CHECK(contains(text.out, "target 0.241 +- 0.004 g0: the window starting at "));
  CHECK(contains(text.out, " s leaves it (certified)"));
  const Result in_text = run(mars + " --target-g 0.241 --tolerance 0.008", dir);
  CHECK(contains(in_text.out, "target 0.241 +- 0.008 g0: every window mean lies inside (certified)"));
}

TEST_CASE("clinostat --band and --target-g: refusals name the option, exit 2, nothing on stdout", "[cli][clinostat]") {
  TempDir dir;
  for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
           {"--band", "--band"}, {"--window 60 --target-g 0.1 --tolerance 0.1", "--target-g"},
           {"--window 60 --band --target-g 0.1 --tolerance -0.1", "--tolerance"},
           {"--window 60 --band --target-g 0.1 --tolerance nan", "--tolerance"},
           {"--window 60 --band --target-g nan --tolerance 0.1", "--target-g"},
           {"--window 60 --band --target-g 0.1", "--tolerance"}, {"--window 60 --band --tolerance 0.1", "--tolerance"},
           {"--trace --duration 10 --band", "--band"}}) {
    const Result bad = run("clinostat --outer 1 --inner 2 " + args, dir, true);
    INFO(args << " -> " << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
    CHECK(contains(bad.err, option));
  }
  // M(W) alone of a period too long to search (decimal speeds): refused up front, naming the cost.
  const Result wide = run("clinostat --outer 1.414214 --inner 1 --window 600", dir, true);
  CHECK(wide.status == 2);
  CHECK(wide.out.empty());
  CHECK(count_lines(wide.err) == 1);
  CHECK(contains(wide.err, "pieces to search"));
}

TEST_CASE("clinostat --band of a period too long to search: bounds over the motor torus, not certified to 1e-9 (exit 3)", "[cli][clinostat]") {
  TempDir dir;
  const std::string machine = "clinostat --outer 1.414214 --inner 1 --tilt 75 --frame-angle 80 --window 600 --band";
  const Result r = run(machine + " --json", dir);
  CHECK(r.status == 3);
  CHECK(contains(r.err, "motor torus"));
  const json b = json::parse(r.out)["window_band"];
  CHECK(b["bound"] == "torus");
  CHECK(b["certified"] == false);
  const double min_lower = b["min"]["lower"], max_upper = b["max"]["upper"];
  // The rotation model at starts over a day lies within the proven ends; the starts reach theirs.
  for (double t0 = 0; t0 < 86400; t0 += 86400.0 / 60) {
    const double m = model_window_mean(1.414214L, 1, 75, t0, 600, 80);
    CHECK(m >= min_lower - 1e-12);
    CHECK(m <= max_upper + 1e-12);
  }
  CHECK(model_window_mean(1.414214L, 1, 75, b["min"]["start_s"], 600, 80) <= b["min"]["upper"].get<double>() + 1e-12);
  CHECK(model_window_mean(1.414214L, 1, 75, b["max"]["start_s"], 600, 80) >= b["max"]["lower"].get<double>() - 1e-12);
  // A target with a margin around the proven ends is certified inside (the band itself still exits 3).
  const double mid = (min_lower + max_upper) / 2, tolerance = (max_upper - min_lower) / 2 + 1e-3;
  const Result t = run(machine + " --target-g " + shortest_g(mid) + " --tolerance " + shortest_g(tolerance) + " --json", dir);
  CHECK(t.status == 3);
  CHECK(json::parse(t.out)["target"]["inside"] == true);
  const Result text = run(machine, dir);
  CHECK(text.status == 3);
  CHECK(contains(text.out, "NOT CERTIFIED to 1e-9: the period is too long to search"));
}

TEST_CASE("clinostat --gravity G: every mean and bracket is G times the unit one, and its refusals", "[cli][clinostat]") {
  TempDir dir;
  const std::string mars = "clinostat --tilt 67.7901 --outer 5 --inner 0.05 --window 600 --band --running-mean 300 --json";
  const Result unit = run(mars, dir), half = run(mars + " --gravity 0.5", dir);
  REQUIRE(unit.status == 0);
  REQUIRE(half.status == 0);
  const json u = json::parse(unit.out), h = json::parse(half.out);
  CHECK(!u.contains("gravity_g0"));
  CHECK(h["gravity_g0"] == 0.5);
  // The brackets of G g_s hold half the unit brackets (each within 1e-9 of the truth).
  for (const char* end : {"min", "max"})
    for (const char* side : {"lower", "upper"})
      CHECK(std::fabs(h["window_band"][end][side].get<double>() - 0.5 * u["window_band"][end][side].get<double>()) <= 1e-9);
  CHECK(std::fabs(h["running_mean"][0]["magnitude"].get<double>() - 0.5 * u["running_mean"][0]["magnitude"].get<double>()) <= 1e-15);
  // The running mean against the model: G times the Simpson mean of the unit gravity.
  CHECK(std::fabs(h["running_mean"][0]["magnitude"].get<double>() - 0.5 * model_window_mean(5, 0.05, 67.7901, 0, 300)) <= 1e-12);
  const Result text = run("clinostat --tilt 67.7901 --outer 5 --inner 0.05 --gravity 0.5", dir);
  CHECK(contains(text.out, "environment's gravity: 0.5 g0"));
  for (const std::string& bad : {"--gravity 0", "--gravity -1", "--gravity nan", "--gravity 1001", "--gravity 0.0009", "--gravity 1e-160", "--gravity 0.5 --trace --duration 10"}) {
    const Result r = run("clinostat --outer 1 --inner 2 " + bad, dir, true);
    INFO(bad << " -> " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
    CHECK(contains(r.err, "--gravity"));
  }
}

TEST_CASE("clinostat --target-g: an end within rounding of an extreme is not decided: exit 3, and the output says so", "[cli][clinostat]") {
  // One horizontal axis at 10 rpm, the sample at 7.395464443117222 m on y: the centripetal term
  // w^2 r / g0 equals sinc(w W / 2) for W = 2 s, so some window mean is 0 (within rounding); the
  // target's lower end 0.9 - 0.8999999999999999 = 1.1e-16 cannot be told from it.
  TempDir dir;
  const std::string machine = "clinostat --outer 10 --inner 0 --offset 0,7.395464443117222,0 --window 2 --band";
  const Result j = run(machine + " --target-g 0.9 --tolerance 0.8999999999999999 --json", dir);
  CHECK(j.status == 3);
  const json t = json::parse(j.out);
  CHECK(t["window_band"]["min"]["lower"] == 0.0);
  CHECK(t["window_band"]["min"]["upper"].get<double>() <= 1e-9);
  CHECK(t["target"]["inside"].is_null());
  CHECK(contains(j.err, "not certified"));
  const Result text = run(machine + " --target-g 0.9 --tolerance 0.8999999999999999", dir);
  CHECK(text.status == 3);
  CHECK(contains(text.out, "target 0.9 +- 0.8999999999999999 g0: not certified"));
}
