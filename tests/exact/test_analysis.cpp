// Tests of sphtroch/exact/analysis.hpp (issue 5): laziness and memoization proved through the work
// counters, the stage graph, and the stages' results against the report's equations computed
// HERE (Eq. 4/5 for points, Eq. 47a for the velocity and the screw axis, Eqs. 32-35 for the z
// extremes, Table 1 for the node counts) — never against the code's own earlier output.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/exact/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace sphtroch;

namespace {

const double kPi = Constants<double>::pi();

GearTrain fig5f() { return GearTrain(kPi / 3, kPi / 2, Ratio(2)); }           // Table 1 row (f): 4 nodes
GearTrain fig5g() { return GearTrain(kPi / 3, 2 * kPi / 3, Ratio(2)); }       // row (g): 3 nodes (pole tangency)
GearTrain fig4e() { return GearTrain::on_cone(kPi / 2, A3Reference::pitch_cone, 0.0, Ratio(1)); }  // cardioid

/// Eq. 5 expanded (phase 0): P(t) for ratio n.
Vector3d eq5(double a2, double a3, double n, double t) {
  const double c2 = std::cos(t), s2 = std::sin(t), cn = std::cos(n * t), sn = std::sin(n * t);
  const double ca2 = std::cos(a2), sa2 = std::sin(a2), ca3 = std::cos(a3), sa3 = std::sin(a3);
  return {c2 * sn * sa3 + s2 * cn * ca2 * sa3 + s2 * sa2 * ca3, s2 * sn * sa3 - c2 * cn * ca2 * sa3 - c2 * sa2 * ca3,
          -cn * sa2 * sa3 + ca2 * ca3};
}

std::set<Stage> ran_stages(const Analysis& a) {
  std::set<Stage> s;
  for (std::size_t i = 0; i < kStageCount; ++i)
    if (a.work(static_cast<Stage>(i)).ran) s.insert(static_cast<Stage>(i));
  return s;
}

bool same_work(const StageWork& a, const StageWork& b) {
  return a.ran == b.ran && a.points_evaluated == b.points_evaluated && a.predicates == b.predicates &&
         a.newton_steps == b.newton_steps && a.root_evaluations == b.root_evaluations && a.seconds == b.seconds;
}

}  // namespace

TEST_CASE("analysis: a fresh object has run only the input stage, which evaluates no point", "[analysis][lazy]") {
  const Analysis a(fig5g());  // a3 = pi - a2 up to 3.4e-16: snapped, still no point evaluated
  CHECK(ran_stages(a) == std::set<Stage>{Stage::input});
  CHECK(a.total_work().points_evaluated == 0);
  CHECK(!a.snapped().hits.empty());
}

TEST_CASE("analysis: trace only evaluates exactly the samples: no predicate, no Newton step, no crossing search",
          "[analysis][lazy][trace]") {
  AnalysisSettings s;
  s.samples = 720;
  const Analysis a(fig5f(), s);
  const Trajectory<double>& tr = a.trajectory();
  REQUIRE(tr.size() == 720);
  const StageWork total = a.total_work();
  CHECK(total.points_evaluated == 720);
  CHECK(total.predicates == 0);
  CHECK(total.newton_steps == 0);
  CHECK(total.root_evaluations == 0);
  CHECK(!a.work(Stage::polyline_census).ran);
  CHECK(ran_stages(a) == std::set<Stage>{Stage::input, Stage::trajectory});
  // The samples are Eq. 5 at t_i = 2 pi i / 720 (q = 1).
  for (std::size_t i : {std::size_t{0}, std::size_t{97}, std::size_t{719}}) {
    const double t = 2 * kPi * static_cast<double>(i) / 720;
    CHECK(tr.t[i] == Approx(t).margin(1e-15));
    CHECK((tr.points[i] - eq5(kPi / 3, kPi / 2, 2, t)).norm() < 1e-14);
  }
}

TEST_CASE("analysis: default trajectory samples are 360 (q + |p|), turns K give 360 (1 + |n|) K + 1 over [0, 2 pi K]",
          "[analysis][trace]") {
  const Analysis closed(GearTrain(1.0, 0.7, Ratio(5, 2)));
  CHECK(closed.trajectory().size() == 360 * 7);
  AnalysisSettings s;
  s.turns = 1.5;
  const Analysis open(GearTrain(1.0, 0.7, Ratio(2)), s);
  const Trajectory<double>& tr = open.trajectory();
  REQUIRE(tr.size() == 360 * 3 * 3 / 2 + 1);
  CHECK(!tr.closed);
  CHECK(tr.t.back() == Approx(3 * kPi).epsilon(1e-15));
  CHECK(open.work(Stage::trajectory).points_evaluated == tr.size());
}

TEST_CASE("analysis: the report's criteria, z extremes and symmetry evaluate no point", "[analysis][lazy][analytic]") {
  const Analysis a(fig5g());
  const AnalyticClassification& c = a.analytic();
  REQUIRE(c.predicted_nodes.has_value());
  CHECK(*c.predicted_nodes == 3);  // Table 1 row (g)
  CHECK(c.predicted_cusps == 0);
  const ZExtremes& z = a.extremes();
  CHECK(z.z_max == Approx(std::cos(kPi / 3 - 2 * kPi / 3)));  // Eq. 32/33: cos(a2 - a3)
  CHECK(z.z_min == Approx(-1.0));                              // Eq. 34/35: cos(a2 + a3) = cos(pi)
  CHECK(a.symmetry().rotation_order == 2);
  const StageWork total = a.total_work();
  CHECK(total.points_evaluated == 0);
  CHECK(total.predicates == 0);
  CHECK(total.newton_steps == 0);
  CHECK(total.root_evaluations == 0);
  CHECK(ran_stages(a) == std::set<Stage>{Stage::input, Stage::analytic, Stage::extremes, Stage::symmetry});
}

TEST_CASE("analysis: requesting an effect runs exactly the stages stages_for() lists, in an order respecting dependencies",
          "[analysis][lazy][stages]") {
  for (std::size_t i = 0; i < kEffectCount; ++i) {
    const Effect e = static_cast<Effect>(i);
    INFO("effect " << to_string(e));
    const Analysis a(fig5f());
    a.request(e);
    const std::vector<Stage> needed = Analysis::stages_for(e);
    CHECK(ran_stages(a) == std::set<Stage>(needed.begin(), needed.end()));
    // Every stage ran after each of its dependencies.
    const std::vector<Stage>& order = a.stages_run();
    CHECK(order.size() == needed.size());  // each at most once
    for (std::size_t k = 0; k < order.size(); ++k)
      for (Stage d : Analysis::dependencies(order[k])) {
        const auto at = std::find(order.begin(), order.end(), d);
        CHECK(at != order.end());
        CHECK(static_cast<std::size_t>(at - order.begin()) < k);
      }
  }
  // Spot checks of the graph (docs/design.md data flow).
  CHECK(Analysis::stages_for(Effect::trace) == std::vector<Stage>{Stage::input, Stage::trajectory});
  const auto cls = Analysis::stages_for(Effect::classification);
  for (Stage s : {Stage::polyline_census, Stage::nodes, Stage::cusps, Stage::root_census, Stage::analytic, Stage::classification})
    CHECK(std::count(cls.begin(), cls.end(), s) == 1);
  CHECK(std::count(cls.begin(), cls.end(), Stage::trajectory) == 0);
  const auto ex = Analysis::stages_for(Effect::extrema);
  CHECK(ex == std::vector<Stage>{Stage::input, Stage::extremes});
}

TEST_CASE("analysis: memoized: nodes() twice does no more work, classification() after nodes() reuses the crossing stage",
          "[analysis][memo]") {
  const Analysis a(fig5f());
  const std::vector<Node>& first = a.nodes();
  CHECK(first.size() == 4);  // Table 1 row (f)
  const StageWork crossings = a.work(Stage::polyline_census);
  CHECK(crossings.ran);
  CHECK(crossings.points_evaluated > 0);
  CHECK(crossings.predicates > 0);
  CHECK(crossings.newton_steps > 0);
  const StageWork before = a.total_work();
  const std::vector<Node>& second = a.nodes();
  CHECK(&first == &second);
  CHECK(same_work(a.total_work(), before));

  const Classification& c = a.classification();
  CHECK(c.nodes.size() == 4);
  CHECK(same_work(a.work(Stage::polyline_census), crossings));  // not run again
  CHECK(std::count(a.stages_run().begin(), a.stages_run().end(), Stage::polyline_census) == 1);
  // Its work is the sum of the stages it needed, and a second call changes nothing.
  StageWork sum;
  for (Stage s : Analysis::stages_for(Effect::classification)) sum += a.work(s);
  CHECK(c.work.points_evaluated == sum.points_evaluated);
  CHECK(c.work.predicates == sum.predicates);
  CHECK(c.work.newton_steps == sum.newton_steps);
  CHECK(c.work.root_evaluations == sum.root_evaluations);
  const StageWork after = a.total_work();
  CHECK(&a.classification() == &c);
  CHECK(same_work(a.total_work(), after));
}

TEST_CASE("analysis: classify() is the classification stage: same nodes, cusps, class and work counts", "[analysis][classify]") {
  for (const GearTrain& train : {fig5f(), fig5g(), fig4e()}) {
    const Classification c = classify(train);
    const Analysis a(train);
    const Classification& d = a.classification();
    CHECK(c.curve_class == d.curve_class);
    REQUIRE(c.nodes.size() == d.nodes.size());
    for (std::size_t i = 0; i < c.nodes.size(); ++i) CHECK(c.nodes[i].position == d.nodes[i].position);
    CHECK(c.cusps.size() == d.cusps.size());
    CHECK(c.work.points_evaluated == d.work.points_evaluated);
    CHECK(c.work.predicates == d.work.predicates);
    CHECK(c.work.newton_steps == d.work.newton_steps);
  }
}

TEST_CASE("analysis: cusp stage counts one point and one velocity per cusp, root census its assembly velocities",
          "[analysis][counters]") {
  const Analysis a(fig4e());
  REQUIRE(a.cusps().size() == 1);  // Fig. 4(e): the cardioid's one cusp
  CHECK(a.cusps()[0].speed < 1e-15);
  CHECK(a.work(Stage::cusps).points_evaluated == 2);
  const Analysis b(fig5f());
  const RootCensus& r = b.root_census();
  std::size_t branches = 0;
  for (const Node& n : r.nodes) branches += n.branches;
  CHECK(branches == 8);  // 4 nodes of 2 branches (Table 1 row f)
  CHECK(b.work(Stage::root_census).points_evaluated == branches);
  CHECK(b.work(Stage::root_census).root_evaluations == r.evaluations);
  CHECK(b.work(Stage::root_census).root_evaluations > 0);
  CHECK(b.work(Stage::root_census).predicates == 0);
}

TEST_CASE("analysis: refinement counts its curve evaluations exactly: 2 to start, then 2 velocities + 2 points per step",
          "[analysis][counters][refinement]") {
  // Fig. 3's node (Eq. 25) at theta2 = pi/2, 3pi/2; seeds nearby.
  const TracerCurve<long double> curve(GearTrain(kPi / 2, kPi / 2, Ratio(1)));
  const auto r = refine_branch_pair(curve, 1.5L, 4.8L);
  REQUIRE(r.status == RefineStatus::converged);
  CHECK(r.evaluations == 2 + 4 * r.iterations);
}

TEST_CASE("analysis: velocities are omega x P (Eq. 47a) at the trajectory's parameters, computed without the points",
          "[analysis][velocity]") {
  AnalysisSettings s;
  s.samples = 90;
  const Analysis a(fig5f(), s);
  const std::vector<Vector3d>& v = a.velocities();
  CHECK(!a.work(Stage::trajectory).ran);
  CHECK(a.work(Stage::velocities).points_evaluated == 90);
  const Trajectory<double>& tr = a.trajectory();
  REQUIRE(v.size() == tr.size());
  const double a2 = kPi / 3, n = 2;
  for (std::size_t i = 0; i < tr.size(); i += 7) {
    const double t = tr.t[i];
    const Vector3d omega(n * std::sin(t) * std::sin(a2), -n * std::cos(t) * std::sin(a2), 1 + n * std::cos(a2));
    CHECK((v[i] - omega.cross(eq5(a2, kPi / 2, n, t))).norm() < 1e-14);
  }
}

TEST_CASE("analysis: the screw axis omega = Z1 + n Z2 (Eq. 47a) has constant length and sweeps the sun's pitch cone",
          "[analysis][screw_axis]") {
  AnalysisSettings s;
  s.samples = 64;
  const GearTrain train(2 * kPi / 3, 5 * kPi / 6, Ratio(2));  // Table 1 row (e)
  const Analysis a(train, s);
  const ScrewAxisSamples& w = a.screw_axis();
  REQUIRE(w.omega.size() == 64);
  CHECK(a.total_work().points_evaluated == 64);
  CHECK(!a.work(Stage::trajectory).ran);
  const double a2 = 2 * kPi / 3, n = 2;
  const double norm = std::sqrt(1 + n * n + 2 * n * std::cos(a2));
  const double a_p = std::atan2(std::sin(a2), std::cos(a2) + n), a_s = a2 - a_p;  // n = sin a_s / sin a_p
  for (std::size_t i = 0; i < 64; ++i) {
    CHECK(w.t[i] == Approx(2 * kPi * static_cast<double>(i) / 64).margin(1e-15));
    CHECK(w.omega[i].norm() == Approx(norm).epsilon(1e-14));
    CHECK(std::acos(w.omega[i].z() / w.omega[i].norm()) == Approx(a_s).epsilon(1e-12));
  }
}

TEST_CASE("analysis: the trajectory is the train as given, the census the snapped train", "[analysis][snap]") {
  // Row (g) typed as doubles: a2 + a3 = pi - 3.4e-16; snapped onto a3 = pi - a2 for the census only.
  AnalysisSettings s;
  s.samples = 16;
  const Analysis a(fig5g(), s);
  CHECK(a.analysed().a3_reference() != A3Reference::given);
  const TracerCurve<double> given(fig5g());
  for (std::size_t i = 0; i < 16; ++i) CHECK(a.trajectory().points[i] == given.point(a.trajectory().t[i]));
  CHECK(a.nodes().size() == 3);  // Table 1 row (g), on the boundary
}

TEST_CASE("analysis: invalid trajectory settings throw InvalidInput naming samples or turns", "[analysis][errors]") {
  AnalysisSettings s;
  s.samples = 2;
  CHECK(test::expect_invalid([&] { Analysis a(fig5f(), s); }).field() == "samples");
  AnalysisSettings t;
  t.turns = 0.0;
  CHECK(test::expect_invalid([&] { Analysis a(fig5f(), t); }).field() == "turns");
}

TEST_CASE("analysis and classify: bad census settings throw InvalidInput, never abort", "[analysis][errors]") {
  for (double bad : {-1.0, std::nan(""), 1.0}) {
    INFO(bad);
    AnalysisSettings s;
    s.reading.boundary_tolerance = bad;
    CHECK(test::expect_invalid([&] { Analysis a(fig5f(), s); }).field() == "boundary_tolerance");
    ClassifySettings c;
    c.reading.boundary_tolerance = bad;
    CHECK(test::expect_invalid([&] { classify(fig5f(), c); }).field() == "boundary_tolerance");
  }
  AnalysisSettings few;
  few.census_samples = 8;  // the CLI's --samples floor (kMinCensusSamples) holds in the library too
  const InvalidInput e = test::expect_invalid([&] { Analysis a(fig5f(), few); });
  CHECK(e.field() == "census_samples");
  CHECK(e.valid_range() == "0 (default) or integer 1024 .. 10000000");
  ClassifySettings c;
  c.samples = 8;
  CHECK(test::expect_invalid([&] { classify(fig5f(), c); }).field() == "census_samples");
}

TEST_CASE("Classification is a regular value type: default-constructible, copyable", "[analysis][api]") {
  std::vector<Classification> many(200);
  CHECK(many[0].nodes.empty());
  CHECK(many[0].curve_class == CurveClass::simple_curve);
  many[5] = classify(fig5f());
  const Classification copy = many[5];
  CHECK(copy.nodes.size() == many[5].nodes.size());
  CHECK(copy.input.a2() == fig5f().a2());
}

TEST_CASE("stage table: one row per stage in enum order, dependencies earlier, names unique", "[analysis][stages]") {
  std::set<std::string> names;
  for (std::size_t i = 0; i < kStageCount; ++i) {
    const Stage s = static_cast<Stage>(i);
    INFO(to_string(s));
    CHECK(std::string(to_string(s)) != "?");
    CHECK(names.insert(to_string(s)).second);
    for (Stage d : Analysis::dependencies(s)) CHECK(static_cast<std::size_t>(d) < i);
    if (s != Stage::input) CHECK_FALSE(Analysis::dependencies(s).empty());
  }
  CHECK(Analysis::dependencies(Stage::nodes) == std::vector<Stage>{Stage::polyline_census});
  // The crossing stage is certified against the independent root census (certified_census.hpp).
  CHECK(Analysis::dependencies(Stage::polyline_census) == std::vector<Stage>{Stage::root_census});
  CHECK(Analysis::dependencies(Stage::classification).size() == 6);
}
