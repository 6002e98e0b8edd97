// Tests of machine/clinostat.hpp, machine/clinostat_text.hpp, machine/clinostat_train.hpp and
// machine/running_mean.hpp (against a Gauss-Legendre quadrature of the model below).
// Expected values come from an independent rotation model written here: the frame angles from the
// exact speed in 128-bit MPFR, the sample frame as a product of Eigen AngleAxis rotations in long
// double (not the library's Rodrigues matrices), and the off-centre acceleration in the lab frame
// from the angular velocity and acceleration (a = alpha x p + omega x (omega x p)), not the
// library's sample-frame formula.
#include "catch2/catch.hpp"
#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "sphtroch/machine/clinostat_text.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/running_mean.hpp"
#include "test_support.hpp"

#include <numeric>
#include <random>

using namespace sphtroch;
using mpfr::mpreal;

namespace {

using Vec3L = Eigen::Matrix<long double, 3, 1>;
using Mat3L = Eigen::Matrix<long double, 3, 3>;

/// The frame angle phi0 + 2 pi w t / 60, reduced mod 2 pi, from MPFR at 160 bits.
long double angle_of(const Rpm& w, double phase_deg, double t) {
  mpreal::set_default_prec(160);
  const mpreal pi = mpfr::const_pi();
  mpreal turns = mpreal(static_cast<long>(w.num())) * mpreal(t) / (60 * mpreal(static_cast<long>(w.den())));
  turns -= mpfr::floor(turns);
  const mpreal a = 2 * pi * turns + mpreal(phase_deg) * pi / 180;
  return static_cast<long double>(mpfr::fmod(a, 2 * pi).toLDouble());
}

/// The convention of docs/clinostat.md written out: u, w, v and R = Rot(u, phi_o) Rot(v, phi_i).
struct Model {
  Vec3L u, v;
  long double phi_o, phi_i, wo, wi;
  Mat3L ro, ri;
  Model(const ClinostatSettings& s, double t) {
    const long double pi = 3.141592653589793238462643383279502884L;
    const long double psi = s.tilt_deg * pi / 180, beta = s.frame_angle_deg * pi / 180;
    u = Vec3L(std::sin(psi), 0, std::cos(psi));
    const Vec3L w(-std::cos(psi), 0, std::sin(psi));
    v = std::cos(beta) * u + std::sin(beta) * w;
    phi_o = angle_of(s.outer, s.phase_outer_deg, t);
    phi_i = angle_of(s.inner, s.phase_inner_deg, t);
    wo = 2 * pi * static_cast<long double>(s.outer.num()) / s.outer.den() / 60;
    wi = 2 * pi * static_cast<long double>(s.inner.num()) / s.inner.den() / 60;
    ro = Eigen::AngleAxis<long double>(phi_o, u).toRotationMatrix();
    ri = Eigen::AngleAxis<long double>(phi_i, v).toRotationMatrix();
  }
  Mat3L frame() const { return ro * ri; }
  Vec3L gravity() const { return frame().transpose() * Vec3L(0, 0, -1); }
  Vec3L effective(const Vector3d& r_sample) const {
    const Vec3L p = frame() * r_sample.cast<long double>();
    const Vec3L omega = wo * u + wi * (ro * v);
    const Vec3L alpha = wo * wi * u.cross(ro * v);  // d/dt (wi Ro v) = wi wo u x Ro v
    const Vec3L a = alpha.cross(p) + omega.cross(omega.cross(p));
    return frame().transpose() * (Vec3L(0, 0, -1) - a / 9.80665L);
  }
};

Rpm random_rpm(std::mt19937_64& rng, bool allow_zero) {
  std::uniform_int_distribution<int> kind(0, 9), num(-6000, 6000), den(1, 1000);
  if (allow_zero && kind(rng) == 0) return Rpm(0);
  for (;;) {
    const int n = num(rng);
    if (n != 0) return Rpm(n, kind(rng) < 5 ? 100 : 100 + den(rng));  // |speed| <= 60 rpm
  }
}

ClinostatSettings random_machine(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(0, 180), phase(-720, 720), offset(-0.2, 0.2);
  std::uniform_int_distribution<int> special(0, 9);
  ClinostatSettings s;
  s.outer = random_rpm(rng, true);
  s.inner = random_rpm(rng, !s.outer.is_zero());
  const double specials[] = {0, 90, 180};
  s.tilt_deg = special(rng) < 2 ? specials[special(rng) % 3] : angle(rng);
  s.frame_angle_deg = special(rng) < 2 ? specials[special(rng) % 3] : angle(rng);
  s.phase_outer_deg = phase(rng);
  s.phase_inner_deg = phase(rng);
  s.offset_m = Vector3d(offset(rng), offset(rng), offset(rng));
  return s;
}

}  // namespace

TEST_CASE("clinostat: gravity and effective gravity equal the independent rotation model", "[clinostat]") {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> early(0, 1e4), late(0, 1e6);
  double worst_gravity = 0, worst_effective = 0;
  for (int i = 0; i < 10000; ++i) {
    const ClinostatSettings s = random_machine(rng);
    const Clinostat m(s);
    const double t = i % 2 ? early(rng) : late(rng);
    const Model model(s, t);
    worst_gravity = std::max(worst_gravity, static_cast<double>((m.gravity(t).cast<long double>() - model.gravity()).norm()));
    worst_effective =
        std::max(worst_effective, static_cast<double>((m.effective_gravity(t).cast<long double>() - model.effective(s.offset_m)).norm()));
  }
  CHECK(worst_gravity <= 1e-12);
  CHECK(worst_effective <= 1e-9);
}

TEST_CASE("clinostat: at t = 0 with zero phases the sample frame is the lab frame", "[clinostat]") {
  ClinostatSettings s;
  s.outer = Rpm(133, 100);
  s.inner = Rpm(2);
  s.tilt_deg = 37;
  s.frame_angle_deg = 71;
  const Clinostat m(s);
  CHECK((m.frame(0) - Matrix3d::Identity()).norm() <= 1e-15);
  CHECK((m.gravity(0) - Vector3d(0, 0, -1)).norm() <= 1e-15);
  // The outer axis is fixed in the lab; the inner axis is fixed in the sample (R v = Ro v).
  const Matrix3d r = m.frame(123.0);
  CHECK((r * m.inner_axis() - Eigen::AngleAxisd(m.outer_angle(123.0), m.outer_axis()) * m.inner_axis()).norm() <= 1e-14);
}

TEST_CASE("clinostat: the gear train draws the gravity path, n exact", "[clinostat]") {
  std::mt19937_64 rng(45);
  std::uniform_real_distribution<double> t_early(0, 1e3), t_late(0, 1e6);
  int trains = 0;
  for (int i = 0; i < 2000; ++i) {
    const ClinostatSettings s = random_machine(rng);
    const Clinostat m(s);
    const ClinostatTrain ct = clinostat_train(m);
    const bool single = s.outer.is_zero() || s.inner.is_zero();
    const bool degenerate = s.tilt_deg == 0 || s.tilt_deg == 180 || s.frame_angle_deg == 0 || s.frame_angle_deg == 180;
    if (single || degenerate) {
      CHECK_FALSE(ct.train);
      CHECK_FALSE(ct.reason.empty());
      continue;
    }
    if (!ct.train) {  // only when n's terms exceed the gear train's limit
      const long long p = s.outer.num() * s.inner.den(), q = s.outer.den() * s.inner.num(), g = std::gcd(p, q);
      CHECK(ct.reason.find("1000000") != std::string::npos);
      CHECK(std::max(std::llabs(p / g), std::llabs(q / g)) > 1000000);
      continue;
    }
    ++trains;
    // n = w_o / w_i: p q_i... cross-multiplied in integers.
    const Ratio n = ct.train->ratio();
    CHECK(static_cast<__int128>(n.p()) * s.outer.den() * s.inner.num() ==
          static_cast<__int128>(n.q()) * s.outer.num() * s.inner.den());
    CHECK((ct.rotation * ct.rotation.transpose() - Matrix3d::Identity()).norm() <= 1e-15);
    CHECK(ct.rotation.determinant() == Approx(1).margin(1e-15));
    const double t = t_early(rng);
    const TracerCurve<double> curve(*ct.train);
    const Model model(s, t);
    // In double, theta2 = theta2_at_0 + rate t is rounded (2 ulp) and the planet angle n theta2
    // multiplies that by |n|: the map holds to 1e-12 plus what the double argument carries.
    const double theta2 = ct.theta2_at_0 + ct.theta2_rate * t;
    const double argument_error = (1 + std::fabs(n.value())) * (std::fabs(theta2) * 4.5e-16 + std::fabs(ct.theta2_rate) * t * 4e-16);
    CHECK(static_cast<double>(((ct.rotation * curve.point(theta2)).cast<long double>() - model.gravity()).norm()) <= 1e-12 + argument_error);
    // Late times: theta2 ~ 1e5 rad needs more than a double; the map itself holds in long double.
    const double tl = t_late(rng);
    const TracerCurve<long double> fine(*ct.train);
    const long double theta2_late = static_cast<long double>(ct.theta2_at_0) + static_cast<long double>(ct.theta2_rate) * tl;
    const Model late(s, tl);
    // theta2_rate is a double (3 roundings: 4e-16 relative); the planet angle multiplies its error by |n|.
    const double rate_error = (1 + std::fabs(n.value())) * std::fabs(ct.theta2_rate) * tl * 4e-16;
    CHECK(static_cast<double>((ct.rotation.cast<long double>() * fine.point(theta2_late) - late.gravity()).norm()) <= 1e-12 + rate_error);
  }
  CHECK(trains > 800);
}

TEST_CASE("clinostat: the map's angles are those of the derivation", "[clinostat]") {
  ClinostatSettings s;
  s.outer = Rpm(133, 100);
  s.inner = Rpm(-2);
  s.tilt_deg = 60;
  s.frame_angle_deg = 100;
  const ClinostatTrain ct = clinostat_train(Clinostat(s));
  REQUIRE(ct.train);
  const double pi = Constants<double>::pi();
  CHECK(ct.train->a2() == Approx(100 * pi / 180).epsilon(1e-15));  // the angle between the axes
  CHECK(ct.train->a3() == Approx(pi - 60 * pi / 180).epsilon(1e-15));  // outer axis to gravity
  CHECK(ct.train->ratio() == Ratio(-133, 200));
  CHECK(ct.theta2_rate == Approx(2 * pi * 2 / 60).epsilon(1e-15));  // -w_i
}

TEST_CASE("clinostat: speeds are read exactly, bad settings are refused naming the option", "[clinostat]") {
  CHECK(parse_rpm("1.33", "outer").num() == 133);
  CHECK(parse_rpm("1.33", "outer").den() == 100);
  CHECK(parse_rpm("-2.50", "inner").num() == -5);
  CHECK(parse_rpm("4/3", "inner").den() == 3);
  CHECK(parse_rpm("0", "inner").is_zero());
  CHECK(parse_rpm("1.33", "outer").str() == "1.33");
  CHECK(Rpm(1, 4).str() == "0.25");
  CHECK(Rpm(1, 3).str() == "1/3");
  for (const char* bad : {"", "nan", "inf", "1e2", "1.2345678", "1001", "2/0", "x", "1.", "--1", "1,5"})
    CHECK(test::expect_invalid([&] { parse_rpm(bad, "outer"); }).field() == "outer");
  ClinostatText text;
  text.outer = "0";
  text.inner = "0";
  CHECK(test::expect_invalid([&] { Clinostat{text.settings()}; }).field() == "inner");
  text.inner = "2";
  for (const auto& [field, value] : std::vector<std::pair<std::string, std::string>>{
           {"tilt", "nan"}, {"tilt", "181"}, {"tilt", "-1"}, {"frame-angle", "200"}, {"phase-outer", "inf"},
           {"phase-inner", "2e6"}, {"offset", "1,2"}, {"offset", "nan,0,0"}, {"offset", "20,0,0"}}) {
    ClinostatText t = text;
    if (field == "tilt") t.tilt = value;
    if (field == "frame-angle") t.frame_angle = value;
    if (field == "phase-outer") t.phase_outer = value;
    if (field == "phase-inner") t.phase_inner = value;
    if (field == "offset") t.offset = value;
    CHECK(test::expect_invalid([&] { Clinostat{t.settings()}; }).field() == field);
  }
  const Clinostat m(text.settings());
  CHECK(test::expect_invalid([&] { m.gravity(std::nan("")); }).field() == "t");
}

namespace {

/// The mean of the model's gravity (or effective gravity) over [a, a + T]: composite 8-point
/// Gauss-Legendre on panels of at most 0.25 s (at <= 12 rpm a panel holds at most 1/10 of a turn
/// of either frame: the rule's error is far below 1e-13).
Vec3L quadrature_mean(const ClinostatSettings& s, double a, double T, bool effective) {
  static const long double x[4] = {0.183434642495649804939476142360184L, 0.525532409916328985817739049189246L,
                                   0.796666477413626739591553936475830L, 0.960289856497536231683560868569473L};
  static const long double w[4] = {0.362683783378361982965150449277196L, 0.313706645877887287337962201986601L,
                                   0.222381034453374470544355994426241L, 0.101228536290376259152531354309962L};
  const int panels = static_cast<int>(std::ceil(T / 0.25));
  const long double h = static_cast<long double>(T) / panels;
  Vec3L sum = Vec3L::Zero();
  for (int k = 0; k < panels; ++k) {
    const long double mid = a + (k + 0.5L) * h;
    for (int j = 0; j < 4; ++j)
      for (const int sign : {-1, 1}) {
        const Model m(s, static_cast<double>(mid + sign * x[j] * h / 2));
        sum += w[j] * (h / 2) * (effective ? m.effective(s.offset_m) : m.gravity());
      }
  }
  return sum / static_cast<long double>(T);
}

}  // namespace

TEST_CASE("clinostat: running means are the quadrature of the independent model", "[clinostat][running]") {
  std::mt19937_64 rng(62);
  std::uniform_int_distribution<int> num(-1200, 1200);
  std::uniform_real_distribution<double> start(-500, 500), length(0.5, 120), offset(-0.2, 0.2), angle(0, 180);
  double worst = 0;
  for (int i = 0; i < 40; ++i) {
    ClinostatSettings s;
    s.outer = Rpm(num(rng), 100);  // |speed| <= 12 rpm
    s.inner = Rpm(num(rng) == 0 ? 1 : num(rng), 100);
    if (s.outer.is_zero() && s.inner.is_zero()) s.inner = Rpm(1);
    s.tilt_deg = angle(rng);
    s.frame_angle_deg = angle(rng);
    s.phase_outer_deg = start(rng);
    const bool effective = i % 2 == 1;
    if (effective) s.offset_m = Vector3d(offset(rng), offset(rng), offset(rng));
    const Clinostat m(s);
    const GravitySeries g = effective ? GravitySeries::of_effective_gravity(m) : GravitySeries::of_gravity(m);
    const double a = start(rng);
    const std::vector<double> times = {length(rng), length(rng)};
    const std::vector<RunningMean> means = running_means(g, a, times);
    REQUIRE(means.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
      const Vec3L q = quadrature_mean(s, a, times[k], effective);
      CHECK(means[k].t_s == times[k]);
      worst = std::max(worst, static_cast<double>((means[k].mean.cast<long double>() - q).norm()));
      CHECK(means[k].magnitude == means[k].mean.norm());
    }
  }
  INFO("largest difference from the quadrature: " << worst << " g0");
  CHECK(worst < 1e-12);
}

TEST_CASE("clinostat: running means refuse no time a bad time and a start past the clock", "[clinostat][running]") {
  ClinostatSettings s;
  s.outer = Rpm(1);
  s.inner = Rpm(2);
  const GravitySeries g = GravitySeries::of_gravity(Clinostat(s));
  const auto field = [&](double a, std::vector<double> t) {
    try {
      running_means(g, a, t);
    } catch (const InvalidInput& e) {
      return e.field();
    }
    return std::string("none");
  };
  CHECK(field(0, {}) == "running-mean");
  CHECK(field(0, {0.0}) == "running-mean");
  CHECK(field(0, {-1.0}) == "running-mean");
  CHECK(field(0, {std::nan("")}) == "running-mean");
  CHECK(field(0, {2e12}) == "running-mean");
  CHECK(field(9.9e11, {2e11}) == "start");
  CHECK(field(0, {60.0}) == "none");
}
