// sphtroch/core/work.hpp — what a computation did, counted exactly where it is done: the counters of
// one Analysis stage (analysis.hpp) and of a whole classification (classification.hpp) are one
// struct, summed with +=.
//
//   sphtroch::Work w = sphtroch::Analysis(train).work(sphtroch::Stage::polyline_census);
//   w.ran, w.points_evaluated, w.predicates, w.seconds;   // did it run, what it cost
#pragma once

#include <cstddef>

namespace sphtroch {

struct Work {
  bool ran = false;                   // the stage ran (for a sum: any of them)
  std::size_t points_evaluated = 0;   // TracerCurve calls: point, velocity, acceleration
  std::size_t predicates = 0;         // exact orientation predicates
  std::size_t newton_steps = 0;       // refinement iterations
  std::size_t root_evaluations = 0;   // evaluations of the root census's g
  double seconds = 0.0;               // wall clock
  Work& operator+=(const Work& o) {
    ran = ran || o.ran;
    points_evaluated += o.points_evaluated;
    predicates += o.predicates;
    newton_steps += o.newton_steps;
    root_evaluations += o.root_evaluations;
    seconds += o.seconds;
    return *this;
  }
};

}  // namespace sphtroch
