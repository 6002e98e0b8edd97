// Tests of cad/step_export.hpp and `sphtroch trace -o FILE.step`: the file is read back with
// OpenCASCADE's own STEP reader (STEPControl_Reader), and its curve is compared with the exact path
// (the forward model of Eq. 4 in MPFR at 128 bits, times the radius) at 10,000 random parameters:
// |C(t) - R P(t)| within the stated tolerance (the curve keeps theta2 as its parameter, so this
// bounds the distance both ways). Seeded.
#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "catch2/catch.hpp"
#include "cli_support.hpp"
#include "sphtroch/cad/step_export.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/version.hpp"

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <STEPControl_Reader.hxx>
#include <StepData_StepModel.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
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

/// Max over 10,000 random t of |C(t) - radius P(t)|. C keeps theta2 as its parameter, so this
/// bounds both distances: of C(t) to the path, and of the path's point radius P(t) to C.
double deviation(const ReadBack& r, const GearTrain& train, double period, double radius) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, period);
  double along = 0.0;
  for (int k = 0; k < 10000; ++k) {
    const double t = u(rng);
    const Vector3d p = exact_point(train, t, radius);
    along = std::max(along, r.curve->Value(t).Distance(gp_Pnt(p.x(), p.y(), p.z())));
  }
  return along;
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
      {GearTrain(1.2, 1.9, Ratio(1, 3)), 1.0, 1e-7, 2.5},                            // open, 2.5 turns
      {GearTrain(1.0, 1.0, Ratio(5, 7)), 1.0, 1e-11, {}},
      {GearTrain(1.0, 1.0, Ratio(1, 20)), 1.0, 1e-10, {}},
      {GearTrain(1.0, 1.0, Ratio(1, 30)), 1.0, 3e-10, {}}};  // tight, long: the file's reals need 16 digits
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
    CHECK(deviation(r, c.train, period, c.radius) <= c.tolerance);
    char uncertainty[40];
    std::snprintf(uncertainty, sizeof uncertainty, kStepRealFormat, c.tolerance);
    CHECK(contains(slurp(file), uncertainty));  // the file's distance accuracy is the tolerance
    const gp_Pnt start = r.curve->Value(r.first), end = r.curve->Value(r.last);
    if (!c.turns) CHECK(start.Distance(end) == 0.0);  // closed: the same point
  }
}

TEST_CASE("STEP: D0 every double, negative with a 3-digit exponent too, fits OpenCASCADE's 24-byte number buffer "
          "and reads back to 16 digits", "[step]") {
  // Send(Real) formats into char[24]: the text may hold at most 23 characters. The widest texts
  // are negative numbers with a 3-digit exponent; subnormals and the extremes have 3 digits too.
  const std::vector<double> widest = {-1.2345678901234567e-100, -1.2345678901234567e-308, -4.9406564584124654e-324,
                                      -1.2345678901234567e300,  -9.9999999999999999e-101, -2.2250738585072014e-308,
                                      1.2345678901234567e-200,  -0.0,                     -123.45678901234567};
  std::mt19937_64 rng(40);
  std::vector<double> values = widest;
  for (int k = 0; k < 100000; ++k) {  // random bit patterns: every exponent, both signs
    std::uint64_t bits = rng();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (std::abs(x) <= 1e300) values.push_back(x);  // a STEP file's reals stay below ~1e112 (radius <= 1e100);
                                                     // 16 digits of DBL_MAX round past it
  }
  for (const double x : values) {
    char text[64];
    const int length = std::snprintf(text, sizeof text, kStepRealFormat, x);
    INFO(text);
    CHECK(length <= kStepRealChars);
    CHECK(kStepRealChars < 24);
    const double back = std::strtod(text, nullptr);
    // 16 significant digits: half a unit of the 16th (5e-16 relative), then strtod's rounding
    // (1.1e-16); a subnormal keeps only its own absolute precision.
    CHECK(std::abs(back - x) <= 6.2e-16 * std::abs(x) + std::numeric_limits<double>::denorm_min());
  }
  char widest_text[64];
  CHECK(std::snprintf(widest_text, sizeof widest_text, "%.17E", widest[0]) > 23);  // the overflowing format
}

TEST_CASE("STEP: D0 radius 1e-100 and 1e100: the file is written whole, every real within 23 characters, the "
          "points R times the path", "[step]") {
  // Reading such files back through OpenCASCADE is not asked: its own Precision::Confusion (1e-7)
  // treats a 1e-100 edge as degenerate. The reals of the text are checked instead.
  const GearTrain train(0.7, 2.5, Ratio(13, 5));
  for (const double radius : {1e-100, 1e100}) {
    StepOptions o;
    o.radius = radius;
    const StepPath path = step_path(train, o);
    const std::string text = step_text(path);
    INFO("radius " << radius);
    CHECK(text.rfind("ISO-10303-21;", 0) == 0);
    CHECK(contains(text, "END-ISO-10303-21;"));
    std::size_t reals = 0, scaled = 0;
    for (std::size_t i = 0; (i = text.find('E', i)) != std::string::npos; ++i) {  // d.dddE+ddd tokens
      if (i == 0 || !std::isdigit(static_cast<unsigned char>(text[i - 1])) || i + 1 >= text.size() ||
          (text[i + 1] != '+' && text[i + 1] != '-'))
        continue;
      std::size_t start = i;
      while (start > 0 && (std::isdigit(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '.' ||
                           text[start - 1] == '-'))
        --start;
      std::size_t end = i + 2;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
      CHECK(end - start <= std::size_t(kStepRealChars));
      const double value = std::strtod(text.c_str() + start, nullptr);
      ++reals;
      if (std::abs(value) > 1e-3 * radius && std::abs(value) <= 1.0000001 * radius) ++scaled;  // a coordinate
    }
    CHECK(reals > 3 * path.points);   // every pole's three coordinates at least
    CHECK(scaled > 2 * path.points);  // most of them of the radius' size
  }
}

TEST_CASE("STEP: the header names sphtroch as the originating system, the product, no placeholder author, and millimetres", "[step]") {
  TempDir dir;
  StepOptions o;
  o.radius = 25;
  const StepPath path = step_path(GearTrain(0.7, 2.5, Ratio(13, 5)), o);
  const std::string file = (dir.path / "h.step").string();
  std::ofstream(file, std::ios::binary) << step_text(path, std::string("sphtroch ") + SPHTROCH_VERSION_STRING);
  STEPControl_Reader reader;  // OpenCASCADE's reader: the header as a STEP reader sees it
  REQUIRE(reader.ReadFile(file.c_str()) == IFSelect_RetDone);
  APIHeaderSection_MakeHeader header(reader.StepModel());
  REQUIRE(header.IsDone());
  CHECK(std::string(header.OriginatingSystem()->ToCString()) == std::string("sphtroch ") + SPHTROCH_VERSION_STRING);
  CHECK(std::string(header.Name()->ToCString()) == path.product);
  CHECK(std::string(header.AuthorValue(1)->ToCString()).empty());
  CHECK(std::string(header.OrganizationValue(1)->ToCString()).empty());
  TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
  reader.FileUnits(lengths, angles, solid_angles);
  REQUIRE(lengths.Length() >= 1);
  for (int k = 1; k <= lengths.Length(); ++k) CHECK(std::string(lengths.Value(k).ToCString()) == "millimetre");
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
  CHECK(refused_field(1e101, 1e95) == "radius");  // beyond 1e100 products of positions overflow
  CHECK(refused_field(9.9e-101, 1e-106) == "radius");  // below 1e-100 (core/cone_distance.hpp)
  CHECK(refused_field(1e-310, 1e-316) == "radius");    // subnormal
  CHECK(refused_field(std::nan(""), 1e-3) == "radius");
  CHECK(refused_field(1.0, 1e-13) == "tolerance");
  CHECK(refused_field(1.0, -1.0) == "tolerance");
  CHECK(refused_field(1.0, std::nan("")) == "tolerance");
  CHECK(refused_field(1.0, 1e-12) == "tolerance");  // would need more than kMaxStepPoints points
  const auto turns_field = [&](const GearTrain& t, double turns) -> std::string {
    StepOptions o;
    o.turns = turns;
    try {
      check_step_options(t, o);
      step_path(t, o);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return "accepted";
  };
  for (const double bad : {0.0, -1.0, 1e-300, std::nan(""), HUGE_VAL, 1e30, 1e5})
    CHECK(turns_field(train, bad) == "turns");
  CHECK(turns_field(train, 1.0) == "accepted");
  try {  // a closed path too long for the point bound names n
    step_path(GearTrain(1.0, 1.0, Ratio(999, 1000)), StepOptions{});
    FAIL("accepted n = 999/1000");
  } catch (const InvalidInput& e) {
    CHECK(e.field() == "n");
  }
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
  CHECK(contains(text, std::string("'sphtroch ") + SPHTROCH_VERSION_STRING + "'"));  // the originating system
  CHECK(!contains(text, "'Author'"));
  const GearTrain train(0.7, 2.5, Ratio(13, 5));
  CHECK(deviation(read_step((dir.path / "p.step").string()), train, train.period(), 25.0) <= 1e-4);

  std::ofstream(dir.path / "keep.step") << "old";
  for (const std::string args : {"--tolerance 0", "--tolerance 1e-20", "--radius -1", "--radius 1e305", "--radius 1e-101",
                                  "--radius 1e-310", "--samples 100",
                                  "--kinematics", "--threads 2", "--turns 1e5"}) {
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
