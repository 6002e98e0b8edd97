// A consumer of sphtroch::compiled (COMPONENTS compiled, or pkg-config sphtroch-compiled), built
// with CGAL hidden: the README's C++ example, whose classify() is declared by the umbrella in
// separate mode and defined in libsphtroch_compiled. Report Fig. 5(f) (a2 = pi/3, a3 = pi/2,
// n = 2) has four nodes (the report's n = 2 criteria); the sampled trajectory has its 720 points
// on the unit sphere. Its tolerance report, also compiled in the library, counts the same nodes,
// and the compiled precision points find a known train back from three of its points.
#include <sphtroch/sphtroch.hpp>

#if !defined(SPHTROCH_SEPARATE_EXACT)
#error "this consumer must build in separate mode (sphtroch::compiled's interface defines it)"
#endif
#if defined(CGAL_VERSION_NR)
#error "a consumer of sphtroch::compiled must parse no CGAL header"
#endif

#include <cmath>
#include <cstdio>

int main() {
  const double pi = sphtroch::Constants<double>::pi();
  const sphtroch::GearTrain fig5f(pi / 3, pi / 2, sphtroch::Ratio(2));    // report Fig. 5(f)
  const sphtroch::Classification c = sphtroch::classify(fig5f);           // c.nodes.size() == 4
  const auto trajectory = sphtroch::sample_period(sphtroch::TracerCurve<double>(fig5f), 720);
  bool on_sphere = trajectory.points.size() == 720;
  for (const auto& p : trajectory.points) on_sphere = on_sphere && std::abs(p.norm() - 1.0) < 1e-14;
  // tolerance_report() is compiled in the library too: its census is classify's, and a box
  // narrower than the certified margin cannot change the census.
  const sphtroch::ToleranceReport t = sphtroch::tolerance_report(fig5f, {1e-4, 1e-4, 0.0});
  const bool tolerance_ok = t.node_count == c.nodes.size() && t.margin.lower <= t.margin.upper &&
                            (t.margin.lower <= 1e-4 || t.topology.verdict == sphtroch::BoxTopology::Verdict::holds);
  std::printf("%s, %zu node(s), certified %d; margin %g .. %g rad, box topology %s\n", sphtroch::to_string(c.curve_class),
              c.nodes.size(), c.certified(), t.margin.lower, t.margin.upper, sphtroch::to_string(t.topology.verdict));
  // precision_points_with_census() is compiled in the library too: three points of a known train
  // (a2 = 1, a3 = 2, n = 1/2, phase 0.3) must give that train back among the certified solutions.
  const sphtroch::TracerCurve<double> hidden(sphtroch::GearTrain(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3));
  const auto found = sphtroch::precision_points_with_census({hidden.point(0.5), hidden.point(2.0), hidden.point(7.0)}, {sphtroch::Ratio(1, 2)});
  bool hidden_found = false;
  for (const sphtroch::PrecisionSolution& s : found.at(0).result.solutions)
    hidden_found = hidden_found || (std::abs(s.train.a2() - 1.0) < 1e-9 && std::abs(s.train.a3() - 2.0) < 1e-9);
  const bool synthesis_ok = found.at(0).result.certified && hidden_found && found.at(0).census.size() == found.at(0).result.solutions.size();
  std::printf("precision points: %zu train(s), the hidden one found %d\n", found.at(0).result.solutions.size(), hidden_found);
  return c.nodes.size() == 4 && c.certified() && on_sphere && tolerance_ok && synthesis_ok ? 0 : 1;
}
