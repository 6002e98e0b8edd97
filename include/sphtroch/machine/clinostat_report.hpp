// sphtroch/machine/clinostat_report.hpp — the report of `sphtroch clinostat` as one result with its
// formats beside it: what is asked (window, epsilon, resolution, coverage), what is computed (the
// gear train, the period and mean, M(W), the time to epsilon, the dwell map), the JSON object that
// the CLI prints, Python's Clinostat.report returns and the explorer shows, the text for people,
// and the --plot composition. Eigen and nlohmann-json (header-only); the dwell map comes from the
// caller (HEALPix lives in a plugin or an extension module: machine/dwell_map.hpp).
//
//   sphtroch::ClinostatText text;
//   text.outer = "1.33";
//   text.inner = "2";
//   const sphtroch::Clinostat m(text.settings());
//   sphtroch::ClinostatRequest q;
//   q.window = 600;
//   q.epsilon = 0.01;
//   const sphtroch::ClinostatReport r = sphtroch::clinostat_report(m, q);
//   std::string j = sphtroch::clinostat_report_json(r).dump(2);   // `sphtroch clinostat --json`
//
// JSON (docs/clinostat.md): "train" {"n", "a2", "a3", "phase", "theta2_at_0", "theta2_rate",
// "rotation"} or null (then "train_note"); "averaged"; "gravity_g0" (only when not 1); "period_s" (null: none); "mean_over_period";
// with --window "worst_window_mean" {"window_s", "lower", "upper", "start_s", "certified"}; with
// --epsilon "time_to_epsilon" {"epsilon", "resolution_s", "first_s", "stays_below_from_s",
// "above_s", "reason", "certified"}; with --band "window_band" {"window_s", "min": {"lower", "upper",
// "start_s"}, "max": {...}, "certified", "bound": "period" or "torus" (a period too long to search)}; with --target-g "target" {"g",
// "tolerance", "inside" (null: not decided), "start_s" (null unless outside)}; with --running-mean "running_mean" [{"start_s", "t_s", "mean",
// "magnitude"}]; with --coverage "coverage" {"start_s", "duration_s", "nside",
// "order", "fraction", "dwell_cv", "bound_s", "dwell_s"}.
// Cost: M(W) and the time to epsilon are refused up front when the period is too long to search
// (worst_window_mean_cost throws InvalidInput("outer")); the band is then bounded over the motor
// torus (window_band_torus, fixed cost); the rest is closed form.
#pragma once

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/types.hpp"
#include "sphtroch/machine/clinostat.hpp"
#include "sphtroch/machine/clinostat_plot.hpp"
#include "sphtroch/machine/clinostat_train.hpp"
#include "sphtroch/machine/dwell_map_result.hpp"
#include "sphtroch/machine/gravity_series.hpp"
#include "sphtroch/machine/running_mean.hpp"
#include "sphtroch/machine/time_to_epsilon.hpp"
#include "sphtroch/machine/window_band.hpp"
#include "sphtroch/machine/worst_window_mean.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>
#include <string>

namespace sphtroch {

/// What a report computes beyond the train, period and mean (each checked by the reader).
struct ClinostatRequest {
  std::optional<double> window;    ///< M(W) for this W, seconds
  std::optional<double> epsilon;   ///< the time to epsilon for this bound, units of g0
  double resolution = 1;           ///< the step of W for epsilon, seconds
  std::optional<double> coverage;  ///< the dwell map over this many seconds (supplied by the caller)
  double start = 0;                ///< start of the dwell map and of the running means, seconds
  int nside = 8;                   ///< HEALPix nside of the dwell map
  std::vector<double> running_mean_s;  ///< the running means from start over these durations, seconds
  bool band = false;               ///< the window band of `window` (window_band.hpp)
  std::optional<double> target_g;  ///< with band: whether every window mean lies in target_g +- tolerance, g0
  double tolerance = 0;            ///< units of g0
};

/// A report's numbers, computed once for the text, the JSON and the picture.
struct ClinostatReport {
  ClinostatSettings settings;
  ClinostatRequest request;
  ClinostatTrain train;
  GravitySeries series;  ///< of the effective gravity when the machine has an offset
  bool effective = false;
  std::optional<WorstWindowMean> worst;
  std::optional<TimeToEpsilon> time_to;
  std::optional<DwellMap> dwell;  ///< the caller's, when coverage was asked
  std::vector<RunningMean> running;  ///< of request.running_mean_s (running_mean.hpp)
  std::optional<WindowBand> band;    ///< with request.band
  std::optional<WindowTarget> target;  ///< with request.target_g
};

/// The report of machine m for q; `dwell` is the dwell map of q.coverage when asked (the caller
/// computes it: HEALPix). Throws InvalidInput("outer") before any search when the period is too
/// long, InvalidInput("band") for a band without a window, InvalidInput("target-g") for a target
/// without a band (and window_target's errors for its values).
inline ClinostatReport clinostat_report(const Clinostat& m, const ClinostatRequest& q, std::optional<DwellMap> dwell = std::nullopt) {
  if (q.band && !q.window) throw InvalidInput("band", "true", "a band needs a window", "--window S --band");
  if (q.target_g && !q.band) throw InvalidInput("target-g", report_number(*q.target_g), "a target needs the band", "--window S --band --target-g G --tolerance D");
  ClinostatReport r{m.settings(), q, clinostat_train(m),
                    m.has_offset() ? GravitySeries::of_effective_gravity(m) : GravitySeries::of_gravity(m), m.has_offset(),
                    std::nullopt, std::nullopt, std::move(dwell), {}, std::nullopt, std::nullopt};
  bool torus = false;  // the band of a period too long to search: bounds over the torus
  if (q.band) try {
      worst_window_mean_cost(r.series);
    } catch (const InvalidInput&) {
      torus = true;
    }
  if (q.epsilon || (q.window && !q.band)) worst_window_mean_cost(r.series);  // refuse a period too long up front
  if (q.target_g) check_window_target(*q.target_g, q.tolerance);  // before any search
  if (q.band) {
    r.band = torus ? window_band_torus(r.series, *q.window) : window_band(r.series, *q.window);
    r.worst = r.band->max;  // the band's max is M(W), the same search
    if (q.target_g) r.target = window_target(r.series, *r.band, *q.target_g, q.tolerance);
  } else if (q.window) {
    r.worst = worst_window_mean(r.series, *q.window);
  }
  if (q.epsilon) r.time_to = time_to_epsilon(r.series, *q.epsilon, q.resolution);
  if (!q.running_mean_s.empty()) r.running = running_means(r.series, q.start, q.running_mean_s);
  return r;
}

/// Whether every bracket and comparison of the report is certified (else the CLI exits 3).
inline bool clinostat_report_certified(const ClinostatReport& r) {
  return !(r.worst && !r.worst->certified) && !(r.time_to && !r.time_to->certified) && !(r.band && !r.band->certified) &&
         !(r.target && !r.target->inside);
}

/// Why the report is not certified ("" when it is).
inline std::string clinostat_report_uncertified(const ClinostatReport& r) {
  if (r.band && !r.band->certified)  // before M(W): with the band, M(W) is its max
    return std::string("the window band's brackets are wider than 1e-9") +
           (std::string(r.band->bound) == "torus" ? " (the period is too long to search: bounds over the motor torus)" : "");
  if (r.worst && !r.worst->certified) return "the worst window mean's bracket is wider than 1e-9";
  if (r.time_to && !r.time_to->certified) return r.time_to->reason;
  if (r.target && !r.target->inside) return "the target is not certified: an extreme of the window means is within rounding of its end";
  return "";
}

namespace clinostat_report_detail {

inline nlohmann::json vector_json(const Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }
inline nlohmann::json or_null(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

inline nlohmann::json train_json(const ClinostatTrain& ct) {
  if (!ct.train) return nullptr;
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) rows.push_back(vector_json(ct.rotation.row(i).transpose()));
  return {{"n", ct.train->ratio().str()}, {"a2", ct.train->a2()}, {"a3", ct.train->a3()}, {"phase", ct.train->phase()},
          {"theta2_at_0", ct.theta2_at_0}, {"theta2_rate", ct.theta2_rate}, {"rotation", rows}};
}

inline nlohmann::json band_json(const WindowBand& b) {
  const auto end = [](const WorstWindowMean& m) { return nlohmann::json{{"lower", m.lower}, {"upper", m.upper}, {"start_s", m.start_s}}; };
  return {{"window_s", b.window_s}, {"min", end(b.min)}, {"max", end(b.max)}, {"certified", b.certified}, {"bound", b.bound}};
}

inline nlohmann::json target_json(const WindowTarget& t) {
  return {{"g", t.g}, {"tolerance", t.tolerance}, {"inside", t.inside ? nlohmann::json(*t.inside) : nlohmann::json(nullptr)},
          {"start_s", or_null(t.start_s)}};
}

inline std::string degrees(double radians) { return report_number(radians * 180 / Constants<double>::pi()); }

}  // namespace clinostat_report_detail

/// The report as JSON (the header's schema): one object for the CLI, Python and the explorer.
inline nlohmann::json clinostat_report_json(const ClinostatReport& r) {
  namespace d = clinostat_report_detail;
  nlohmann::json out;
  out["train"] = d::train_json(r.train);
  if (!r.train.train) out["train_note"] = r.train.reason;
  out["averaged"] = r.effective ? "effective gravity at the offset" : "gravity";
  if (r.settings.gravity_g0 != 1) out["gravity_g0"] = r.settings.gravity_g0;
  out["period_s"] = d::or_null(r.series.period_s());
  out["mean_over_period"] = d::vector_json(r.series.period_mean());
  if (r.worst)
    out["worst_window_mean"] = {{"window_s", r.worst->window_s}, {"lower", r.worst->lower}, {"upper", r.worst->upper},
                                {"start_s", r.worst->start_s}, {"certified", r.worst->certified}};
  if (r.band) out["window_band"] = d::band_json(*r.band);
  if (r.target) out["target"] = d::target_json(*r.target);
  if (r.time_to)
    out["time_to_epsilon"] = {{"epsilon", r.time_to->epsilon}, {"resolution_s", r.request.resolution},
                              {"first_s", d::or_null(r.time_to->first_s)}, {"stays_below_from_s", d::or_null(r.time_to->stays_below_from_s)},
                              {"above_s", d::or_null(r.time_to->above_s)},
                              {"reason", r.time_to->reason}, {"certified", r.time_to->certified}};
  if (!r.running.empty()) {
    out["running_mean"] = nlohmann::json::array();
    for (const RunningMean& m : r.running)
      out["running_mean"].push_back({{"start_s", r.request.start}, {"t_s", m.t_s}, {"mean", d::vector_json(m.mean)}, {"magnitude", m.magnitude}});
  }
  if (r.dwell)
    out["coverage"] = {{"start_s", r.dwell->start_s}, {"duration_s", r.dwell->duration_s}, {"nside", r.dwell->nside},
                       {"order", "RING"}, {"fraction", r.dwell->visited_fraction}, {"dwell_cv", r.dwell->dwell_cv},
                       {"bound_s", r.dwell->bound_s}, {"dwell_s", r.dwell->dwell_s}};
  return out;
}

/// The settings and the gravity path (the first lines of the text).
inline void write_clinostat_machine_text(std::ostream& out, const ClinostatReport& r) {
  namespace d = clinostat_report_detail;
  const ClinostatSettings& s = r.settings;
  out << "clinostat: outer " << s.outer.str() << " rpm, inner " << s.inner.str() << " rpm, tilt " << report_number(s.tilt_deg)
      << " deg, frame angle " << report_number(s.frame_angle_deg) << " deg\n";
  if (!r.train.train) {
    out << "gravity path: " << r.train.reason << "\n";
    return;
  }
  const GearTrain& t = *r.train.train;
  out << "gravity path: the spherical trochoid of the gear train n = " << t.ratio().str() << ", a2 = " << d::degrees(t.a2())
      << " deg, a3 = " << d::degrees(t.a3()) << " deg, phase = " << report_number(t.phase()) << " rad\n"
      << "  traced by: sphtroch trace --a2 " << report_number(t.a2()) << " --a3 " << report_number(t.a3()) << " --n "
      << t.ratio().str() << " --phase " << report_number(t.phase()) << "\n"
      << "  g_s(t) = rotation * P(theta2), theta2 = " << report_number(r.train.theta2_at_0)
      << (r.train.theta2_rate < 0 ? " - " : " + ") << report_number(std::fabs(r.train.theta2_rate)) << " t rad (t in s; --json gives the rotation)\n";
}

/// The window band and the target, when asked (lines of the text).
inline void write_clinostat_band_text(std::ostream& out, const ClinostatReport& r) {
  if (r.band) {
    const WindowBand& b = *r.band;
    out << "window band, W = " << report_number(b.window_s) << " s: every window mean's |mean| lies between min in ["
        << report_number(b.min.lower) << ", " << report_number(b.min.upper) << "] g0 (the window starting at "
        << report_number(b.min.start_s) << " s) and max in [" << report_number(b.max.lower) << ", " << report_number(b.max.upper)
        << "] g0 (starting at " << report_number(b.max.start_s) << " s)"
        << (b.certified ? ""
            : std::string(b.bound) == "torus"
                ? " (NOT CERTIFIED to 1e-9: the period is too long to search; each bracket holds its end: the bound over every"
                  " pair of frame angles and the path's sampled starts)"
                : " (NOT CERTIFIED: a bracket is wider than 1e-9)")
        << "\n";
  }
  if (r.target) {
    const WindowTarget& t = *r.target;
    out << "target " << report_number(t.g) << " +- " << report_number(t.tolerance) << " g0: ";
    if (!t.inside) out << "not certified: an extreme of the window means is within rounding of an end of the target\n";
    else if (*t.inside) out << "every window mean lies inside (certified)\n";
    else out << "the window starting at " << report_number(*t.start_s) << " s leaves it (certified)\n";
  }
}

/// The period, the mean, M(W), the band, the time to epsilon and the coverage (the rest of the text).
inline void write_clinostat_numbers_text(std::ostream& out, const ClinostatReport& r) {
  if (r.series.period_s())
    out << "period: " << report_number(*r.series.period_s()) << " s (" << report_number(*r.series.period_s() / 60)
        << " min): both frames back at their start\n";
  else
    out << "period: none (the gravity does not move in the sample)\n";
  if (r.settings.gravity_g0 != 1)
    out << "environment's gravity: " << report_number(r.settings.gravity_g0) << " g0 (every mean and bracket below is of it)\n";
  const Vector3d c = r.series.period_mean();
  out << "mean " << (r.effective ? "effective gravity" : "gravity") << " over a period: (" << report_number(c.x()) << ", "
      << report_number(c.y()) << ", " << report_number(c.z()) << ") g0, |mean| = " << report_number(c.norm()) << " g0\n";
  if (r.worst)
    out << "worst window mean, W = " << report_number(r.worst->window_s) << " s: M(W) in [" << report_number(r.worst->lower) << ", "
        << report_number(r.worst->upper) << "] g0, reached by the window starting at " << report_number(r.worst->start_s) << " s"
        << (r.worst->certified ? "" : " (NOT CERTIFIED: the bracket is wider than 1e-9)") << "\n";
  write_clinostat_band_text(out, r);
  if (r.time_to) {
    out << "time to epsilon = " << report_number(r.time_to->epsilon) << " g0 (windows in steps of " << report_number(r.request.resolution) << " s): ";
    if (r.time_to->first_s)
      out << "the first window below is " << report_number(*r.time_to->first_s) << " s; every window from "
          << report_number(*r.time_to->stays_below_from_s) << " s on, of any length, is below"
          << (r.time_to->above_s ? " (one of " + report_number(*r.time_to->above_s) + " s is above)" : std::string()) << "\n";
    else
      out << (r.time_to->certified ? "none: " : "NOT CERTIFIED: ") << r.time_to->reason << "\n";
  }
  if (r.dwell)
    out << "coverage over [" << report_number(r.dwell->start_s) << ", " << report_number(r.dwell->start_s + r.dwell->duration_s)
        << "] s on " << r.dwell->dwell_s.size() << " HEALPix cells (nside " << r.dwell->nside << "): " << report_number(100 * r.dwell->visited_fraction)
        << "% visited, dwell coefficient of variation " << report_number(r.dwell->dwell_cv) << "; each cell's time within "
        << report_number(r.dwell->bound_s) << " s (--json gives the dwell per cell)\n";
}

/// The running means, one line each.
inline void write_clinostat_running_text(std::ostream& out, const ClinostatReport& r) {
  for (const RunningMean& m : r.running)
    out << "running mean over [" << number_text(r.request.start) << ", " << number_text(r.request.start + m.t_s) << "] s: ("
        << number_text(m.mean.x()) << ", " << number_text(m.mean.y()) << ", " << number_text(m.mean.z()) << ") g0, |mean| = "
        << number_text(m.magnitude) << " g0\n";
}

/// The report as text, for people (`sphtroch clinostat` without --json).
inline void write_clinostat_report_text(std::ostream& out, const ClinostatReport& r) {
  write_clinostat_machine_text(out, r);
  write_clinostat_numbers_text(out, r);
  write_clinostat_running_text(out, r);
}

/// How long the --plot's dwell panel covers when no coverage was asked: one period, at most an hour.
inline double clinostat_plot_dwell_s(const ClinostatReport& r) { return std::min(r.series.period_s().value_or(60.0), 3600.0); }

/// --plot's picture: the dwell map `dwell` (the report's coverage or one of clinostat_plot_dwell_s;
/// none: no dwell panel) on the cells' outlines `cells`, and M(W) at 100 windows up to 1.25 times
/// the time to epsilon (or three periods, at most two hours), by window_curve (searched, or the
/// torus bound when 100 searches would cost more than kMaxCurvePieces: the picture's cost is
/// bounded whatever the period), with the time to epsilon's two answers when it was asked.
inline ClinostatPlot clinostat_report_plot(const ClinostatReport& r, const DwellMap* dwell, std::vector<std::vector<Vector3d>> cells) {
  ClinostatPlot plot;
  const ClinostatSettings& s = r.settings;
  plot.title = "clinostat " + s.outer.str() + " / " + s.inner.str() + " rpm, tilt " + report_number(s.tilt_deg) + " deg, frame angle " +
               report_number(s.frame_angle_deg) + " deg";
  if (dwell) {
    plot.cells = std::move(cells);
    plot.dwell_s = dwell->dwell_s;
    plot.title += "; dwell over " + report_number(dwell->duration_s) + " s";
  }
  plot.epsilon = r.request.epsilon;
  const double period = r.series.period_s().value_or(60.0);
  const double longest = r.time_to && r.time_to->stays_below_from_s ? 1.25 * *r.time_to->stays_below_from_s : std::min(3 * period, 7200.0);
  const WindowCurve curve = window_curve(r.series, longest, 100);
  for (const WorstWindowMean& w : curve.points) plot.windows.push_back({w.window_s, w.lower, w.upper});
  if (curve.torus) plot.window_note = "the period is too long to search: the upper bound over every frame angle";
  if (r.time_to) {
    plot.first_below_s = r.time_to->first_s;
    plot.stays_below_from_s = r.time_to->stays_below_from_s;
  }
  return plot;
}

}  // namespace sphtroch
