// A consumer of COMPONENTS interval (sphtroch::interval: CGAL's headers, no GMP or MPFR; configured
// with CGAL's CMake package hidden): the certified precision points through three points of a
// known train find that train, and the list is certified complete.
#include <sphtroch/synthesis/precision_points.hpp>

#include <cmath>
#include <cstdio>

int main() {
  const sphtroch::GearTrain hidden(1.0, 2.0, sphtroch::Ratio(1, 2), 0.3);
  const sphtroch::TracerCurve<double> curve(hidden);
  const std::vector<sphtroch::Vector3d> points = {curve.point(0.5), curve.point(2.0), curve.point(7.0)};
  const sphtroch::PrecisionPoints r = sphtroch::precision_points(points, sphtroch::Ratio(1, 2));
  bool found = false;
  for (const auto& s : r.solutions)
    found = found || (std::fabs(s.train.a2() - 1.0) < 1e-9 && std::fabs(s.train.a3() - 2.0) < 1e-9);
  std::printf("precision points: %zu train(s), certified %d, hidden train found %d\n", r.solutions.size(),
              r.certified ? 1 : 0, found ? 1 : 0);
  return r.certified && found ? 0 : 1;
}
