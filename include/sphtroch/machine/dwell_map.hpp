// sphtroch/machine/dwell_map.hpp — where a clinostat's gravity spends its time: seconds in each cell
// of an equal-area HEALPix grid (RING order), the share of cells visited and the uniformity.
// Needs the sphtroch::healpix component (Debian's libhealpix-cxx-dev; defines SPHTROCH_HAVE_HEALPIX).
//
//   sphtroch::ClinostatSettings s;
//   s.outer = sphtroch::Rpm(133, 100);
//   s.inner = sphtroch::Rpm(2);
//   const sphtroch::DwellMap d = sphtroch::dwell_map(sphtroch::Clinostat(s), 0.0, 6000.0, 8);
//   d.dwell_s.size();      // 768 cells (12 nside^2), RING order: healpy draws it as it is
//   d.visited_fraction;    // the share of cells the gravity vector entered
//   d.bound_s;             // every cell's time is right to within this many seconds
//
// Method (rigorous up to rounding): the gravity vector g_s moves at most v = |W_o| + |W_i| rad/s
// (its angular velocity in the sample frame has that norm at most), so over a time step
// [t, t + h] it stays within v h / 2 of g_s(t + h / 2). HEALPix's query_disc_inclusive returns
// every cell of a finer grid (cells about the disc's radius across) that the disc may touch,
// a superset; each lies inside one cell of the map (HEALPix's hierarchy). When they all lie in one
// cell, the step's h seconds belong to that cell exactly. Otherwise the step is halved, down to
// tau = h0 / 16384, depth first, while the query budget lasts (each first-level step
// adds its share, kDwellQueryBudget / steps within [4, 4096], to a pool that carries what steps
// leave unused, up to kMaxDwellCarry); a step that is not halved further and still touches several cells gives its time
// to the cell of its midpoint (HEALPix's vec2pix) and adds its length to the uncertainty of each
// cell it may touch. bound_s is the largest uncertainty of a cell (~2 tau per crossing of a cell
// edge; a path that runs along an edge, as a single-axis machine's circle along the polar cells'
// meridians, is uncertain for the time it spends there, and the budget stops the halving that
// cannot help). Steps start at h0 with v h0 / 2 a quarter of a cell's radius. Times are taken
// from the start (the frame angles of start + dt are reduced exactly), so a late start is as
// precise as t = 0. A duration longer than the period is a whole number of periods (the period
// walked once) plus the rest.
// Visited: a cell with time > 0. Uniformity: the coefficient of variation of the dwell times over
// all 12 nside^2 cells (population standard deviation over the mean D / cells; 0 = uniform).
// Cost: refused up front beyond kMaxDwellSteps first-level steps (~ min(D, T) v / cell size);
// each walk makes at most max(kDwellQueryBudget, 4 steps) + kMaxDwellCarry + 64 steps query_disc
// calls (~0.3 us each).
#pragma once

#if !defined(SPHTROCH_HAVE_HEALPIX)
#error "sphtroch/machine/dwell_map.hpp needs the sphtroch::healpix component (libhealpix-cxx-dev)"
#endif

#include "sphtroch/machine/dwell_map_result.hpp"
#include "sphtroch/machine/gravity_series.hpp"

#include <healpix_base.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sphtroch {


namespace detail {

class DwellWalk {
 public:
  DwellWalk(const Clinostat& m, double start_s, int nside)
      : m_(m), start_(start_s), base_(nside, RING, SET_NSIDE), order_(T_Healpix_Base<int>::nside2order(nside)),
        speed_(std::fabs(m.settings().outer.radians_per_second()) + std::fabs(m.settings().inner.radians_per_second())) {
    const double cell_radius = std::sqrt(4 * Constants<double>::pi() / base_.Npix());
    first_step_ = cell_radius / 4 / (speed_ / 2);
    finest_ = first_step_ / 16384;
    for (int o = 0; o <= 29; ++o) fine_.emplace_back(o, RING);
  }
  double first_step() const { return first_step_; }

  /// Adds the time of [start + a, start + b) to dwell and its uncertainty to unsure (per cell).
  void walk(double a, double b, std::vector<double>& dwell, std::vector<double>& unsure) const {
    if (!(b > a)) return;
    const double steps = std::ceil((b - a) / first_step_);
    const double h = (b - a) / steps;
    const int share = static_cast<int>(std::clamp(kDwellQueryBudget / steps, 4.0, 4096.0));
    int pool = kMaxDwellCarry;  // what the steps so far left unused, up to kMaxDwellCarry
    for (double k = 0; k < steps; ++k) {
      pool = std::min(pool, kMaxDwellCarry) + share;
      step(a + k * h, h, dwell, unsure, pool);
    }
  }

 private:
  /// The cells (RING) that the disc of radius r about p may touch: the fine cells
  /// query_disc_inclusive returns, at a level where a fine cell is ~r across, mapped to their
  /// parent cells (a NESTED cell at order o + k lies inside its parent at order o).
  std::vector<int> cells_touched(const Vector3d& p, double r) const {
    const double fine_cells = std::sqrt(Constants<double>::pi() / 3) / (r * 2);  // nside with cells ~ r across
    const int order = std::clamp(static_cast<int>(std::ceil(std::log2(std::max(1.0, fine_cells)))), order_, 29);
    const T_Healpix_Base<std::int64_t>& grid = fine_[static_cast<std::size_t>(order)];
    const rangeset<std::int64_t> found = grid.query_disc_inclusive(pointing(vec3(p.x(), p.y(), p.z())), r);
    const int shift = 2 * (order - order_);
    std::vector<int> cells;
    for (std::size_t i = 0; i < found.nranges(); ++i)
      for (std::int64_t pixel = found.ivbegin(i); pixel < found.ivend(i); ++pixel) {
        const int ring = base_.nest2ring(static_cast<int>(grid.ring2nest(pixel) >> shift));
        if (std::find(cells.begin(), cells.end(), ring) == cells.end()) cells.push_back(ring);
      }
    return cells;
  }

  /// The step [t, t + h) (seconds after the start); budget: the query_disc calls it may still make.
  void step(double t, double h, std::vector<double>& dwell, std::vector<double>& unsure, int& budget) const {
    const double middle = t + h / 2;
    const Vector3d p = m_.gravity_at(m_.outer_angle(start_, middle), m_.inner_angle(start_, middle));
    const std::vector<int> cells = cells_touched(p, speed_ * h / 2 * (1 + 1e-9) + 1e-12);
    --budget;
    if (cells.size() == 1) {
      dwell[static_cast<std::size_t>(cells[0])] += h;
      return;
    }
    if (h > finest_ && budget >= 2) {
      step(t, h / 2, dwell, unsure, budget);
      step(t + h / 2, h / 2, dwell, unsure, budget);
      return;
    }
    dwell[static_cast<std::size_t>(base_.vec2pix(vec3(p.x(), p.y(), p.z())))] += h;
    for (const int c : cells) unsure[static_cast<std::size_t>(c)] += h;
  }

  const Clinostat& m_;
  double start_;
  T_Healpix_Base<int> base_;
  std::vector<T_Healpix_Base<std::int64_t>> fine_;  // the grids of orders 0 .. 29 (RING: faster queries)
  int order_;
  double speed_, first_step_ = 0, finest_ = 0;
};

inline void check_dwell_request(double start_s, double duration_s, int nside) {
  if (!(nside >= 1 && nside <= kMaxNside && (nside & (nside - 1)) == 0))
    throw InvalidInput("nside", std::to_string(nside), "not a power of two in range", "1, 2, 4, ..., 1024");
  if (!(duration_s > 0 && duration_s <= Clinostat::kMaxTime))
    throw InvalidInput("coverage", report_number(duration_s), "not a positive duration", "0 < seconds <= 1e12");
  if (!(std::fabs(start_s) <= Clinostat::kMaxTime)) throw InvalidInput("start", report_number(start_s), "not a finite time", "|t| <= 1e12 seconds");
}

}  // namespace detail

/// Every cell's outline (RING order): 4 * steps points along its edges, unit vectors, from
/// HEALPix's boundaries(). For pictures (clinostat_plot.hpp). REQUIRES nside a power of two <= 1024.
inline std::vector<std::vector<Vector3d>> cell_outlines(int nside, int steps = 4) {
  detail::check_dwell_request(0, 1, nside);
  const T_Healpix_Base<int> base(nside, RING, SET_NSIDE);
  std::vector<std::vector<Vector3d>> out(static_cast<std::size_t>(base.Npix()));
  std::vector<vec3> edge;
  for (int c = 0; c < base.Npix(); ++c) {
    base.boundaries(c, static_cast<tsize>(steps), edge);
    for (const vec3& v : edge) out[static_cast<std::size_t>(c)].emplace_back(v.x, v.y, v.z);
  }
  return out;
}

/// The dwell map over [start, start + duration] (seconds) on the HEALPix grid of nside. Throws
/// InvalidInput: "nside" not a power of two in [1, 1024]; "coverage" duration not in (0, 1e12];
/// "coverage" when the walk would take more than kMaxDwellSteps first-level steps.
inline DwellMap dwell_map(const Clinostat& m, double start_s, double duration_s, int nside = 8) {
  detail::check_dwell_request(start_s, duration_s, nside);
  const GravitySeries series = GravitySeries::of_gravity(m);
  const detail::DwellWalk walker(m, start_s, nside);
  const std::size_t cells = static_cast<std::size_t>(12) * static_cast<std::size_t>(nside) * static_cast<std::size_t>(nside);
  const double period = series.period_s() ? *series.period_s() : duration_s;
  const double repeats = duration_s > period ? std::floor(duration_s / period) : 0;
  const double rest = duration_s - repeats * period;
  const double walked = repeats > 0 ? period : duration_s;
  if (walked / walker.first_step() > kMaxDwellSteps)
    throw InvalidInput("coverage", report_number(duration_s),
                       "the walk needs " + number_text(std::ceil(walked / walker.first_step())) + " steps (the gravity's period is " +
                           number_text(period) + " s)",
                       "at most 2e6 steps: a shorter duration, slower speeds or a smaller nside");
  DwellMap out;
  out.nside = nside;
  out.start_s = start_s;
  out.duration_s = duration_s;
  std::vector<double> part(cells, 0.0), part_unsure(cells, 0.0), other(cells, 0.0), other_unsure(cells, 0.0);
  walker.walk(0, rest, part, part_unsure);
  if (repeats > 0) walker.walk(rest, period, other, other_unsure);
  out.dwell_s.resize(cells);
  for (std::size_t i = 0; i < cells; ++i) {
    out.dwell_s[i] = part[i] + repeats * (part[i] + other[i]);
    out.bound_s = std::max(out.bound_s, part_unsure[i] + repeats * (part_unsure[i] + other_unsure[i]));
  }
  out.bound_s += duration_s * 1e-12;  // the sums' rounding
  // The CV from each cell's share of the mean, d / (D / cells), so that a duration near the
  // smallest doubles does not underflow: sqrt(sum (share - 1)^2 / cells).
  double square = 0;
  for (const double d : out.dwell_s) {
    out.visited += d > 0 ? 1 : 0;
    const double share = d / duration_s * static_cast<double>(cells);
    square += (share - 1) * (share - 1);
  }
  out.visited_fraction = static_cast<double>(out.visited) / static_cast<double>(cells);
  out.dwell_cv = std::sqrt(square / static_cast<double>(cells));
  return out;
}

}  // namespace sphtroch
