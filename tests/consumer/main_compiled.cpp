// A consumer of sphtroch::compiled (COMPONENTS compiled, or pkg-config sphtroch-compiled), built
// with CGAL hidden: the README's C++ example, whose classify() is declared by the umbrella in
// separate mode and defined in libsphtroch_compiled. Report Fig. 5(f) (a2 = pi/3, a3 = pi/2,
// n = 2) has four nodes (the report's n = 2 criteria); the sampled trajectory has its 720 points
// on the unit sphere.
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
  std::printf("%s, %zu node(s), certified %d\n", sphtroch::to_string(c.curve_class), c.nodes.size(), c.certified());
  return c.nodes.size() == 4 && c.certified() && on_sphere ? 0 : 1;
}
