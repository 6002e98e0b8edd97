// Tests of chain/chain_event_roots.hpp and ChainEnclosure::family_jet. Expected values,
// each independent of the code under test: the chain as a product of rotation matrices in long
// double (P, and P' = omega x P with omega = sum N_i Z_i, the model) with difference
// quotients along the family (mean value theorem); a cusp built into a chain at a chosen s0 and
// last twist (P(s0) aimed along omega(s0)); the event equations evaluated in long double at the
// roots reported.
#include "catch2/catch.hpp"
#include "test_support.hpp"

#include "chain_cusp_support.hpp"
#include "sphtroch/chain/chain_event_roots.hpp"
#include "sphtroch/chain/chain_family_events.hpp"

#include <random>

using namespace sphtroch;

namespace {

using V3 = Eigen::Matrix<long double, 3, 1>;
using M3 = Eigen::Matrix<long double, 3, 3>;

struct Direct {
  V3 point, velocity;
};

/// P(s) and P'(s) as a product of rotation matrices in long double.
Direct direct(const std::vector<ChainStage>& stages, long double s) {
  M3 r = M3::Identity();
  V3 omega = V3::Zero();
  for (const ChainStage& st : stages) {
    const long double n = static_cast<long double>(st.rate.p()) / static_cast<long double>(st.rate.q());
    omega += n * r.col(2);
    const long double a = n * s + static_cast<long double>(st.phase), c = std::cos(a), sn = std::sin(a);
    const long double ca = std::cos(static_cast<long double>(st.twist)), sa = std::sin(static_cast<long double>(st.twist));
    M3 z, x;
    z << c, -sn, 0, sn, c, 0, 0, 0, 1;
    x << 1, 0, 0, 0, ca, -sa, 0, sa, ca;
    r = r * z * x;
  }
  return {r.col(2), omega.cross(V3(r.col(2)))};
}

std::vector<ChainStage> moved(std::vector<ChainStage> st, const ChainVary& v, double by) {
  (v.twist ? st[v.stage - 1].twist : st[v.stage - 1].phase) += by;
  return st;
}

bool holds(const Interval& x, long double v, long double slack) { return v >= x.inf() - slack && v <= x.sup() + slack; }

long double residual_norm(const V3& v) { return v.norm(); }

}  // namespace

TEST_CASE("chain event roots: family_jet encloses the difference quotients of P and P' along the family", "[chain_census]") {
  // Mean value theorem, per component: (f(d = h) - f(d = -h)) / 2h = f'(xi) for some xi in (-h, h),
  // so it lies in the enclosure of df/dd over [-h, h]. Slack 1e-12: the long double rounding of
  // the quotient (~1e-16 here), far below a wrong term (a missing stage's term is ~|N_i| h^0).
  std::mt19937_64 rng(4545);
  std::uniform_real_distribution<double> twist(0.2, 2.9), phase(-3.0, 3.0), unit(0.0, 1.0);
  const long double h = 1e-3L;
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t k = 2 + static_cast<std::size_t>(rng() % 3);
    std::vector<ChainStage> st;
    for (std::size_t i = 0; i < k; ++i) st.push_back({twist(rng), ChainRate(static_cast<int>(rng() % 7) - 3, 1 + static_cast<int>(rng() % 3)), phase(rng)});
    if (std::all_of(st.begin(), st.end(), [](const ChainStage& s) { return s.rate.is_zero(); })) st[0].rate = ChainRate(1);
    const ChainVary v{rng() % 2 == 0, 1 + static_cast<std::size_t>(rng() % k), 0, 0};
    const double s = 20 * unit(rng);
    ChainWidening w{std::vector<int>(k, 0), std::vector<int>(k, 0), Interval(0.0)};
    (v.twist ? w.twist_sign : w.phase_sign)[v.stage - 1] = 1;
    FamilyJet j;
    {
      const RoundingGuard upward;
      w.offset = Interval(-double(h), double(h));
      j = ChainEnclosure(RotationChain(st), w).family_jet(Interval(s));
    }
    const Direct plus = direct(moved(st, v, double(h)), s), minus = direct(moved(st, v, -double(h)), s), at = direct(st, s);
    const V3 dp = (plus.point - minus.point) / (2 * h), dv = (plus.velocity - minus.velocity) / (2 * h);
    INFO("trial " << trial << " " << v.name() << " s " << s);
    for (int c = 0; c < 3; ++c) {
      CHECK(holds(j.point_d[c], dp(c), 1e-12L));
      CHECK(holds(j.velocity_d[c], dv(c), 1e-12L));
      CHECK(holds(j.jet.point[c], at.point(c), 1e-12L));
      CHECK(holds(j.jet.velocity[c], at.velocity(c), 1e-12L));
    }
  }
}

TEST_CASE("chain event roots: a cusp built at a chosen s0 and last twist is certified there", "[chain_census]") {
  // As the chain census's test: P(s0) aimed along omega(s0) by the last twist and phase
  // (chain_cusp_support.hpp). With that phase fixed, the family A3 has a cusp at A3* = that twist,
  // at s0.
  std::mt19937_64 rng(7745);
  std::uniform_real_distribution<double> twist(0.2, 2.9), phase(-3.0, 3.0), where(0.1, 6.0);
  int certified = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const int last_rates[] = {-2, -1, 1, 2, 3};
    std::vector<ChainStage> st = {{twist(rng), ChainRate(1), phase(rng)}, {twist(rng), ChainRate(1 + static_cast<int>(rng() % 3)), phase(rng)},
                                  {1.0, ChainRate(last_rates[rng() % 5]), 0.0}};
    const double s0 = where(rng);
    st = sphtroch_test::with_cusp_at(st, s0);
    if (st[2].twist < 0.05 || st[2].twist > 3.09) continue;
    const RotationChain chain(st);
    const ChainVary a3{true, 3, st[2].twist - 1e-3, st[2].twist + 1e-3};
    const EventRoot root = event_root(chain, a3, BoundaryEventKind::cusp, a3.lo, a3.hi);
    INFO("trial " << trial << " s0 " << s0 << " A3* " << st[2].twist << " rates " << chain.rates_text());
    REQUIRE(root.certified);
    REQUIRE(root.params.size() == 1);
    CHECK(root.lo <= st[2].twist + 1e-13);
    CHECK(root.hi >= st[2].twist - 1e-13);
    CHECK(root.hi - root.lo < 1e-12);
    // At s0, or at a copy of it under the curve's symmetry: a shift d of s with N_i d a multiple of
    // 2 pi for i = 2, 3 turns the whole curve about z by N_1 d (a cusp there too).
    const double shift = root.params[0] - s0;
    for (std::size_t i = 1; i < 3; ++i) CHECK(std::fabs(std::remainder(st[i].rate.value() * shift, 2 * Constants<double>::pi())) < 1e-8);
    CHECK(residual_norm(direct(st, root.params[0]).velocity) < 1e-10L);
    ++certified;
  }
  CHECK(certified >= 15);
}

TEST_CASE("chain event roots: every event of three families is a certified root whose equations hold in long double", "[chain_census]") {
  // Tangencies, triple points and cusp births along phases and twists of three- and four-stage
  // chains. At each root: the value inside the bracket where the census changes; a tangency's two
  // points equal and their tangents parallel, a triple point's three points equal (three distinct
  // parameters), a cusp's velocity 0, all within 1e-10 (the roots are enclosed to ~1e-13; the
  // equations' derivatives are a few units). A tangency changes the pairs by an even number.
  struct Family {
    std::vector<ChainStage> stages;
    std::string vary;
  };
  const std::vector<Family> families = {
      {{{0.646, ChainRate(1, 2), -1.599}, {0.613, ChainRate(1, 2), -2.955}, {0.948, ChainRate(3), 0.172}, {2.372, ChainRate(2), 0.005}}, "P4:1.83:1.86"},
      {{{2.226, ChainRate(-1), -0.937}, {1.649, ChainRate(1, 2), 2.085}, {2.451, ChainRate(-2, 3), -0.88}}, "P2:1.6:1.85"},
      {{{1.2, ChainRate(1), 0.0}, {0.9, ChainRate(2), 0.0}, {0.7, ChainRate(-3), 0.0}}, "A3:0.8:0.94"},
  };
  std::size_t seen[3] = {0, 0, 0};
  for (const Family& f : families) {
    const RotationChain chain(f.stages);
    const ChainVary vary = parse_chain_vary(f.vary, chain.size());
    const ChainEvents e = chain_family_events(chain, vary);
    INFO(f.vary << " rates " << chain.rates_text());
    CHECK(e.certified);
    REQUIRE(e.roots.size() == e.events.size());
    CHECK(!e.events.empty());
    for (std::size_t i = 0; i < e.events.size(); ++i) {
      const EventRoot& r = e.roots[i];
      const BoundaryEvent& b = e.events[i];
      INFO("event " << b.a3 << " " << to_string(b.kind));
      REQUIRE(r.certified);
      CHECK(r.lo <= r.bracket_hi);
      CHECK(r.hi >= r.bracket_lo);
      CHECK(b.a3 >= r.lo);
      CHECK(b.a3 <= r.hi);
      const std::vector<ChainStage> at = chain_at(chain, vary, b.a3).stages();
      std::vector<Direct> p;
      for (const double s : r.params) p.push_back(direct(at, s));
      if (b.kind == BoundaryEventKind::cusp) {
        REQUIRE(p.size() == 1);
        CHECK(residual_norm(p[0].velocity) < 1e-10L);
        ++seen[0];
      } else if (b.kind == BoundaryEventKind::tangency) {
        REQUIRE(p.size() == 2);
        CHECK(residual_norm(p[0].point - p[1].point) < 1e-10L);
        CHECK(std::fabs(p[0].point.dot(p[0].velocity.cross(p[1].velocity))) < 1e-10L);
        CHECK(std::fabs(std::remainder(r.params[0] - r.params[1], chain.period())) > 1e-3);
        CHECK((b.nodes_above - b.nodes_below) % 2 == 0);
        CHECK(b.nodes_above != b.nodes_below);
        ++seen[1];
      } else {
        REQUIRE(p.size() == 3);
        CHECK(residual_norm(p[0].point - p[1].point) < 1e-10L);
        CHECK(residual_norm(p[0].point - p[2].point) < 1e-10L);
        for (std::size_t a = 0; a < 3; ++a)
          CHECK(std::fabs(std::remainder(r.params[a] - r.params[(a + 1) % 3], chain.period())) > 1e-3);
        ++seen[2];
      }
    }
  }
  CHECK(seen[0] >= 2);
  CHECK(seen[1] >= 4);
  CHECK(seen[2] >= 4);
}
