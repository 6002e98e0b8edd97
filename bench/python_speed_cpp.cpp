// bench/python_speed_cpp.cpp — the C++ side of bench/python_speed.py: the same library calls the
// Python module makes, timed in-process (median of --reps runs, seconds, one line of JSON).
//
//   python_speed_cpp trace A2 A3 N SAMPLES REPS       sample_period(curve, SAMPLES)
//   python_speed_cpp crossings FILE.f64 CLOSED REPS   find_self_crossings of raw float64 x,y,z rows
//
// Built on demand next to the module: cmake --build build --target sphtroch_python_speed_cpp.
#include "sphtroch/core/curve.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/exact/self_crossings.hpp"
#include "sphtroch/core/sampling.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

template <typename F>
double median_seconds(int reps, F&& f) {
  std::vector<double> s;
  for (int r = 0; r < reps; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(s.begin(), s.end());
  return s[s.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  using namespace sphtroch;
  const std::string what = argc > 1 ? argv[1] : "";
  if (what == "trace" && argc == 7) {
    const GearTrain train = make_gear_train(parse_angle(argv[2], "a2"), parse_a3(argv[3]), parse_ratio(argv[4]));
    const TracerCurve<double> curve(train);
    const std::size_t n = std::strtoull(argv[5], nullptr, 10);
    std::size_t sink = 0;
    const double s = median_seconds(std::atoi(argv[6]), [&] { sink += sample_period(curve, n).size(); });
    std::printf("{\"what\": \"trace\", \"samples\": %zu, \"median_seconds\": %.9g, \"sink\": %zu}\n", n, s, sink);
    return 0;
  }
  if (what == "crossings" && argc == 5) {
    std::ifstream in(argv[2], std::ios::binary);
    std::vector<Eigen::Vector3d> v;
    double xyz[3];
    while (in.read(reinterpret_cast<char*>(xyz), sizeof xyz)) v.emplace_back(xyz[0], xyz[1], xyz[2]);
    const bool closed = std::string(argv[3]) == "1";
    std::size_t found = 0;
    const double s = median_seconds(std::atoi(argv[4]), [&] { found = find_self_crossings(v, closed).crossings.size(); });
    std::printf("{\"what\": \"crossings\", \"vertices\": %zu, \"crossings\": %zu, \"median_seconds\": %.9g}\n", v.size(),
                found, s);
    return 0;
  }
  std::fprintf(stderr, "usage: python_speed_cpp trace A2 A3 N SAMPLES REPS | crossings FILE.f64 CLOSED(0|1) REPS\n");
  return 2;
}
