// Every Scalar type through the same templates: float, double, long double and mpfr::mpreal at
// 256 bits. The MPFR chain is first checked against Eq. 4 expanded in MPFR (agreement to ~1e-70
// shows it computes in full precision), then serves as the reference for the other three, each
// of which must agree to its own precision.
//
// Inputs (a2, a3, theta2, phase) are chosen exactly representable in float, so every type
// evaluates the same curve at the same parameters and the differences are each type's own
// rounding. Error model (per component of P, V, A): theta2 is exact in every type, so sin/cos of
// theta2 are within an ulp; the products add a few ulp of O(1) terms (<= 4 eps); theta3 =
// p theta2 / q + theta_p takes three roundings (<= 1.5 u |theta3| = 0.75 eps |theta3|) and P
// moves by <= 1 per radian of theta3; each derivative multiplies by |omega| <= 1 + |n|:
//   tol(T) = eps_T (4 + |theta3|) (1 + |n|)^order
// i.e. float ~1e-6, double ~1e-15, long double ~1e-18 for |theta3| of a few radians. Measured
// worst case: ~0.25 of this bound for each type.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "sphtroch/exact/mpreal_support.hpp"  // first: Eigen's MPRealSupport
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/sampling.hpp"

#include <cmath>
#include <random>
#include <thread>
#include <utility>
#include <limits>
#include <vector>

using namespace sphtroch;
using mpfr::mpreal;

namespace {
constexpr double kPi = 3.14159265358979323846;

long double to_ld(float v) { return v; }
long double to_ld(double v) { return v; }
long double to_ld(long double v) { return v; }
long double to_ld(const mpreal& v) { return v.toLDouble(); }

struct Sample {
  long double p[3], v[3], a[3];
};

template <typename Scalar>
Sample evaluate(const GearTrain& train, double t2) {
  const TracerCurve<Scalar> curve(train);
  const Scalar t(t2);
  const Vector3<Scalar> p = curve.point(t);
  const Vector3<Scalar> v = curve.velocity(t);
  const Vector3<Scalar> a = curve.acceleration(t);
  Sample s{};
  for (int i = 0; i < 3; ++i) {
    s.p[i] = to_ld(p[i]);
    s.v[i] = to_ld(v[i]);
    s.a[i] = to_ld(a[i]);
  }
  return s;
}

/// Float-representable inputs.
double f(double x) { return static_cast<double>(static_cast<float>(x)); }

struct Case {
  double a2, a3;
  Ratio n;
  double phase;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (double a2 : {0.25, f(kPi / 3), f(kPi / 2), 2.0, 3.0})
    for (double a3 : {0.125, f(kPi / 2), 2.5})
      for (Ratio n : {Ratio(1), Ratio(2), Ratio(-3, 2), Ratio(5, 2), Ratio(1, 3)})
        for (double phase : {0.0, 0.75}) out.push_back({a2, a3, n, phase});
  return out;
}

const double kThetas[] = {-6.5, -3.0, -1.25, 0.0, 0.375, 1.0, 2.75, 4.0, 6.25};

void set_mpfr_precision() { mpreal::set_default_prec(256); }

template <typename Scalar>
void check_against_mpfr(long double eps) {
  set_mpfr_precision();
  double worst_rel = 0;  // worst error relative to the bound, for the record
  for (const Case& c : cases()) {
    const GearTrain train(c.a2, c.a3, c.n, c.phase);
    const long double nabs = std::fabs(static_cast<long double>(c.n.value()));
    for (double t2 : kThetas) {
      const Sample ref = evaluate<mpreal>(train, t2);
      const Sample got = evaluate<Scalar>(train, t2);
      const long double t3 = std::fabs(nabs * t2) + std::fabs(static_cast<long double>(c.phase));
      const long double base = eps * (4 + t3);
      INFO("a2 = " << c.a2 << " a3 = " << c.a3 << " n = " << c.n.str() << " phase = " << c.phase << " theta2 = " << t2);
      for (int i = 0; i < 3; ++i) {
        const long double ep = std::fabs(got.p[i] - ref.p[i]);
        const long double ev = std::fabs(got.v[i] - ref.v[i]);
        const long double ea = std::fabs(got.a[i] - ref.a[i]);
        CHECK(ep <= base);
        CHECK(ev <= base * (1 + nabs));
        CHECK(ea <= base * (1 + nabs) * (1 + nabs));
        worst_rel = std::max(worst_rel, static_cast<double>(ep / base));
      }
    }
  }
  INFO("worst |P error| / bound = " << worst_rel);
  CHECK(worst_rel <= 1.0);
}
}  // namespace

TEST_CASE("MPFR 256-bit chain equals Eq. 4 expanded in MPFR to 1e-70", "[scalar][mpfr][eq4]") {
  set_mpfr_precision();
  const mpreal tol("1e-70");
  for (const Case& c : cases()) {
    const GearTrain train(c.a2, c.a3, c.n, c.phase);
    const TracerCurve<mpreal> curve(train);
    const mpreal a2(c.a2), a3(c.a3);
    const mpreal ca2 = cos(a2), sa2 = sin(a2), ca3 = cos(a3), sa3 = sin(a3);
    for (double t2d : kThetas) {
      const mpreal t2(t2d);
      const mpreal t3 = mpreal(static_cast<long>(c.n.p())) * t2 / mpreal(static_cast<long>(c.n.q())) + mpreal(c.phase);
      const mpreal c2 = cos(t2), s2 = sin(t2), c3 = cos(t3), s3 = sin(t3);
      const mpreal ex = c2 * s3 * sa3 + s2 * c3 * ca2 * sa3 + s2 * sa2 * ca3;
      const mpreal ey = s2 * s3 * sa3 - c2 * c3 * ca2 * sa3 - c2 * sa2 * ca3;
      const mpreal ez = -c3 * sa2 * sa3 + ca2 * ca3;
      const Vector3<mpreal> p = curve.point(t2);
      INFO("a2 = " << c.a2 << " a3 = " << c.a3 << " n = " << c.n.str() << " theta2 = " << t2d);
      CHECK(abs(p.x() - ex) <= tol);
      CHECK(abs(p.y() - ey) <= tol);
      CHECK(abs(p.z() - ez) <= tol);
      CHECK(abs(p.norm() - 1) <= tol);
    }
  }
}

TEST_CASE("double agrees with the MPFR reference to ~1e-15 (its own precision)", "[scalar][double]") {
  check_against_mpfr<double>(std::numeric_limits<double>::epsilon());
}

TEST_CASE("long double agrees with the MPFR reference to ~1e-18 (its own precision)", "[scalar][long_double]") {
  check_against_mpfr<long double>(std::numeric_limits<long double>::epsilon());
}

TEST_CASE("float agrees with the MPFR reference to ~1e-6 (its own precision)", "[scalar][float]") {
  check_against_mpfr<float>(std::numeric_limits<float>::epsilon());
}

namespace {
/// The tracer on the pitch cone (a3 = a_p, kept symbolic) has zero speed at theta3 = pi in every
/// Scalar, to that Scalar's rounding: the symbolic reference gives sin a_p and cos a_p as the
/// normalised screw axis components, so P and omega are parallel to the last bit.
template <typename Scalar>
void check_pitch_cone_cusp(const Scalar& tol_per_unit) {
  set_mpfr_precision();
  for (double a2 : {0.25, f(kPi / 2), 2.0})
    for (Ratio n : {Ratio(1), Ratio(2), Ratio(5, 2), Ratio(-3, 2)}) {
      const GearTrain train = GearTrain::on_cone(a2, A3Reference::pitch_cone, 0.0, n);
      const TracerCurve<Scalar> curve(train);
      // theta3 = n theta2 = pi  =>  theta2 = pi q / p.
      const Scalar t = Constants<Scalar>::pi() * Scalar(static_cast<double>(n.q())) / Scalar(static_cast<double>(n.p()));
      const Scalar speed = curve.velocity(t).norm();
      const double nabs = std::abs(n.value());
      INFO("a2 = " << a2 << " n = " << n.str() << " speed = " << to_ld(speed));
      CHECK(speed <= tol_per_unit * Scalar((1 + nabs) * (1 + nabs) * 8));
      // ... and half a planet turn later it is far from zero.
      const Scalar t_far = Scalar(2) * t;
      CHECK(curve.velocity(t_far).norm() > Scalar(1e-3));
    }
}
}  // namespace

TEST_CASE("tracer_on_pitch_cone: zero speed at theta3 = pi in float, double, long double and MPFR",
          "[scalar][cusp]") {
  check_pitch_cone_cusp<float>(std::numeric_limits<float>::epsilon());
  check_pitch_cone_cusp<double>(std::numeric_limits<double>::epsilon());
  check_pitch_cone_cusp<long double>(std::numeric_limits<long double>::epsilon());
  set_mpfr_precision();
  check_pitch_cone_cusp<mpreal>(mpreal("1e-75"));
}

TEST_CASE("sampling instantiates for every Scalar type", "[scalar][sampling]") {
  set_mpfr_precision();
  const GearTrain train(f(kPi / 2), f(kPi / 2), Ratio(1));
  const auto tf = sample_period(TracerCurve<float>(train), 8, true);
  const auto td = sample_period(TracerCurve<double>(train), 8, true);
  const auto tl = sample_turns(TracerCurve<long double>(train), 1.0, 9, true);
  const auto tm = sample_period(TracerCurve<mpreal>(train), 8, true);
  REQUIRE(tf.size() == 8);
  REQUIRE(tl.size() == 9);
  REQUIRE(tm.size() == 8);
  for (std::size_t i = 0; i < 8; ++i) {
    CHECK(std::fabs(to_ld(tm.t[i]) - to_ld(td.t[i])) <= 1e-15L * 8);
    for (int k = 0; k < 3; ++k) {
      CHECK(std::fabs(to_ld(tf.points[i][k]) - to_ld(tm.points[i][k])) <= 1e-6L);
      CHECK(std::fabs(to_ld(td.points[i][k]) - to_ld(tm.points[i][k])) <= 1e-15L);
    }
  }
}

TEST_CASE("MPFR precision is per thread: a worker gets 256-bit results only with MpfrPrecision", "[scalar][mpfr]") {
  const GearTrain train(kPi / 3, kPi / 2, Ratio(5, 2));
  // The reference at 1000 bits, on this thread: |P| = 1 to far below 1e-70.
  auto norm_error = [&](const char* label) {
    const TracerCurve<mpreal> curve(train);
    const auto p = curve.point(mpreal("0.7"));
    INFO(label << ": precision " << p.x().get_prec());
    return std::make_pair(static_cast<long>(p.x().get_prec()), abs(p.norm() - 1).toLDouble());
  };
  std::pair<long, long double> plain, guarded, after;
  std::thread worker([&] {
    plain = norm_error("worker, default");  // a new thread starts at MPFR's 53 bits
    {
      const sphtroch::MpfrPrecision bits(256);
      guarded = norm_error("worker, MpfrPrecision(256)");
    }
    after = norm_error("worker, after the guard");
    mpfr_free_cache();  // MPFR's per-thread caches (e.g. of pi) outlive the thread otherwise
  });
  worker.join();
  CHECK(plain.first == 53);
  CHECK(guarded.first == 256);
  CHECK(guarded.second < 1e-70L);
  CHECK(after.first == 53);  // restored
  const InvalidInput e = sphtroch::test::expect_invalid([] { sphtroch::MpfrPrecision bad(0); });
  CHECK(e.field() == "precision");
  CHECK_THROWS_AS(sphtroch::MpfrPrecision(2000000), InvalidInput);
}

TEST_CASE("reduce_phase: within an ulp of the true phase mod 2 pi (1e-23 rad next to 2 pi k), by IEEE operations alone below 2^30", "[scalar][phase]") {
  // The reduction must not depend on the C library (the WebAssembly build's musl and glibc give
  // the same double only for IEEE operations): checked here against MPFR at 256 bits.
  mpfr::mpreal::set_default_prec(256);
  const mpfr::mpreal two_pi = 2 * mpfr::const_pi();
  std::mt19937_64 rng(20261125);
  // Next to odd multiples of pi the rounded quotient p / 2 pi can land on the wrong side (found by
  // a review: these gave -pi for a phase just below pi mod 2 pi); next to multiples of 2 pi the
  // result is tiny and only 1e-23 rad absolute is promised.
  std::vector<double> phases = {3.1415926535897936, -3.1415926535897936, 2 * sphtroch::Constants<double>::pi(), 4.029605,
                                -4.029605, 1e3, 123456.789, 0x1p30 - 1, -(0x1p30 - 1), 1068141511.6453075,
                                135.0884841043611, -135.0884841043611, 57844706.681113519};
  for (int k = 1; k < 2000; k += 2) {  // around odd multiples of pi, and multiples of 2 pi
    const double odd = k * sphtroch::Constants<double>::pi(), even = (k + 1) * sphtroch::Constants<double>::pi();
    for (const double c : {odd, even})
      phases.insert(phases.end(), {std::nextafter(c, 0.0), c, std::nextafter(c, 1e9), -c});
  }
  std::uniform_real_distribution<double> log_scale(std::log(3.2), std::log(0x1p30));
  for (int i = 0; i < 20000; ++i) phases.push_back((i % 2 ? -1 : 1) * std::exp(log_scale(rng)));
  for (const double p : phases) {
    const double got = sphtroch::reduce_phase(p);
    mpfr::mpreal exact = mpfr::mpreal(p) - two_pi * mpfr::round(mpfr::mpreal(p) / two_pi);
    const double want = exact.toDouble();
    INFO("phase " << sphtroch::number_text(p) << ": " << sphtroch::number_text(got) << " vs " << sphtroch::number_text(want));
    REQUIRE(std::fabs(got) <= sphtroch::Constants<double>::pi());
    // pi and -pi are one angle: compare on the circle.
    const double gap = std::fabs(got - want) > 6 ? 2 * sphtroch::Constants<double>::pi() - std::fabs(got - want)
                                                 : std::fabs(got - want);
    REQUIRE(gap <= std::max(std::nextafter(std::fabs(want), 4.0) - std::fabs(want), 1e-23));
  }
}
