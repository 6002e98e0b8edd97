// Tests of cad/step_export.hpp and `sphtroch trace -o FILE.step`: the file is read back with
// OpenCASCADE's own STEP reader (STEPControl_Reader), and its curve is compared with the exact path
// (the forward model of Eq. 4 in MPFR at 128 bits, times the radius) at 10,000 random parameters
// and by projecting 10,000 path points onto it (GeomAPI_ProjectPointOnCurve): both distances must
// be within the stated tolerance. Seeded.
#include "sphtroch/core/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "sphtroch/cad/step_export.hpp"
#include "sphtroch/core/curve.hpp"

#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_Curve.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <random>
#include <string>

using namespace sphtroch;
using namespace sphtroch::test;

namespace {

const double kPi = Constants<double>::pi();

struct ReadBack {
  Handle(Geom_Curve) curve;
  double first = 0.0, last = 0.0;
  int edges = 0;
};

/// The file's edges through OpenCASCADE's STEP reader; the curve of the last one.
ReadBack read_step(const std::string& path) {
  STEPControl_Reader reader;
  REQUIRE(reader.ReadFile(path.c_str()) == IFSelect_RetDone);
  REQUIRE(reader.TransferRoots() > 0);
  ReadBack r;
  for (TopExp_Explorer e(reader.OneShape(), TopAbs_EDGE); e.More(); e.Next()) {
    r.curve = BRep_Tool::Curve(TopoDS::Edge(e.Current()), r.first, r.last);
    ++r.edges;
  }
  return r;
}

/// radius * P(t) at 128 bits, rounded to double.
Vector3d exact_point(const GearTrain& train, double t, double radius) {
  mpfr::mpreal::set_default_prec(128);
  const TracerCurve<mpfr::mpreal> curve(train);
  const Vector3<mpfr::mpreal> p = curve.point(mpfr::mpreal(t));
  return radius * Vector3d(double(p.x()), double(p.y()), double(p.z()));
}

/// Max over 10,000 random t of |C(t) - radius P(t)| (C keeps theta2 as its parameter: this bounds
/// the distance of C(t) to the path) and of the distance of radius P(t) to C (projection).
std::pair<double, double> deviations(const ReadBack& r, const GearTrain& train, double period, double radius) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, period);
  double along = 0.0, projected = 0.0;
  for (int k = 0; k < 10000; ++k) {
    const double t = u(rng);
    const Vector3d p = exact_point(train, t, radius);
    const gp_Pnt c = r.curve->Value(t), q(p.x(), p.y(), p.z());
    along = std::max(along, c.Distance(q));
    GeomAPI_ProjectPointOnCurve projection(q, r.curve, r.first, r.last);
    REQUIRE(projection.NbPoints() > 0);
    projected = std::max(projected, projection.LowerDistance());
  }
  return {along, projected};
}

}  // namespace

TEST_CASE("STEP: the B-spline read back by OpenCASCADE is within the tolerance of the exact path", "[step]") {
  struct Case {
    GearTrain train;
    double radius, tolerance;
    std::optional<double> turns;
  };
  const double a2 = 1.0, n = 3.0;
  const std::vector<Case> cases = {
      {GearTrain(0.7, 2.5, Ratio(13, 5)), 25.0, 25e-6, {}},                         // the default: 1e-6 * R
      {GearTrain(a2, std::atan2(std::sin(a2), std::cos(a2) + n), Ratio(3), 0.4), 1.0, 1e-4, {}},  // cusps
      {GearTrain(2.0, 0.9, Ratio(-3, 2), 1.0), 7.5, 1e-3, {}},
      {GearTrain(1.2, 1.9, Ratio(1, 3)), 1.0, 1e-7, 2.5}};                           // open, 2.5 turns
  TempDir dir;
  for (const Case& c : cases) {
    StepOptions o;
    o.radius = c.radius;
    o.turns = c.turns;
    if (c.tolerance != 1e-6 * c.radius) o.tolerance = c.tolerance;  // else the default
    const StepPath path = step_path(c.train, o);
    CHECK(path.tolerance == c.tolerance);
    CHECK(path.checked_error <= c.tolerance / 4);
    const std::string file = (dir.path / "p.step").string();
    std::ofstream(file, std::ios::binary) << step_text(path);
    const ReadBack r = read_step(file);
    const double period = c.turns ? 2 * kPi * *c.turns : c.train.period();
    INFO("n = " << c.train.ratio().str() << " a3 = " << c.train.a3() << ": " << path.points << " points");
    REQUIRE(r.edges == 1);
    CHECK(std::abs(r.first) < 1e-12);
    CHECK(std::abs(r.last - period) < 1e-9);
    const auto [along, projected] = deviations(r, c.train, period, c.radius);
    CHECK(along <= c.tolerance);
    CHECK(projected <= c.tolerance);
    const gp_Pnt start = r.curve->Value(r.first), end = r.curve->Value(r.last);
    if (!c.turns) CHECK(start.Distance(end) == 0.0);  // closed: the same point
  }
}

TEST_CASE("STEP: the header's example runs (cad/step_export.hpp)", "[step]") {
  const sphtroch::GearTrain train(0.7, 2.5, sphtroch::Ratio(13, 5));
  sphtroch::StepOptions o;  o.radius = 25.0;  o.tolerance = 1e-4;   // mm, say
  const sphtroch::StepPath path = sphtroch::step_path(train, o);   // the B-spline, checked
  std::string file = sphtroch::step_text(path);                     // ISO-10303-21 text
  CHECK(file.rfind("ISO-10303-21;", 0) == 0);
  CHECK(path.tolerance == 1e-4);
  CHECK(sphtroch::step_path(train, sphtroch::StepOptions{}).tolerance == 1e-6);  // the default: 1e-6 * radius
}

TEST_CASE("STEP: a radius or tolerance that cannot be met is refused naming it", "[step][errors]") {
  const GearTrain train(0.7, 2.5, Ratio(13, 5));
  const auto refused_field = [&](double radius, double tolerance) -> std::string {
    StepOptions o;
    o.radius = radius;
    o.tolerance = tolerance;
    try {
      step_path(train, o);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return "accepted";
  };
  CHECK(refused_field(0.0, 1e-3) == "radius");
  CHECK(refused_field(std::nan(""), 1e-3) == "radius");
  CHECK(refused_field(1.0, 1e-13) == "tolerance");
  CHECK(refused_field(1.0, -1.0) == "tolerance");
  CHECK(refused_field(1.0, std::nan("")) == "tolerance");
}

TEST_CASE("cli trace -o FILE.step: scaled by --radius and read back within --tolerance - bad values leave no file",
          "[step][cli]") {
  TempDir dir;
  const Result ok = run("trace --a2 0.7 --a3 2.5 --n 13/5 --radius 25 --tolerance 1e-4 -o p.step", dir, true);
  REQUIRE(ok.status == 0);
  CHECK(ok.out.empty());
  CHECK(ok.err.empty());
  const std::string text = slurp(dir.path / "p.step");
  CHECK(text.rfind("ISO-10303-21;", 0) == 0);
  CHECK(contains(text, "AUTOMOTIVE_DESIGN"));  // AP214
  CHECK(contains(text, "sphtroch a2=0.7 a3=2.5 n=13/5"));
  const GearTrain train(0.7, 2.5, Ratio(13, 5));
  const auto [along, projected] = deviations(read_step((dir.path / "p.step").string()), train, train.period(), 25.0);
  CHECK(along <= 1e-4);
  CHECK(projected <= 1e-4);

  std::ofstream(dir.path / "keep.step") << "old";
  for (const std::string args : {"--tolerance 0", "--tolerance 1e-20", "--radius -1", "--samples 100", "--kinematics"}) {
    const Result bad = run("trace --a2 0.7 --a3 2.5 --n 13/5 " + args + " -o keep.step", dir, true);
    INFO(args << ": " << bad.err);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
    CHECK(count_lines(bad.err) == 1);
    CHECK(slurp(dir.path / "keep.step") == "old");
  }
  const Result csv = run("trace --a2 0.7 --a3 2.5 --n 13/5 --tolerance 1e-3", dir, true);
  CHECK(csv.status == 2);
  CHECK(contains(csv.err, "--tolerance"));
}
