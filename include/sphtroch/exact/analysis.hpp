// sphtroch/exact/analysis.hpp — one gear train analysed lazily: every stage (trajectory, velocities,
// crossings, nodes, cusps, root-count census, the report's criteria, classification, extremes,
// symmetry, screw axis, plot trajectory) is computed on first request, memoized, and counted.
//
//   #include <sphtroch/exact/analysis.hpp>              // needs sphtroch::exact (CGAL), like classification.hpp
//   sphtroch::Analysis a(train);                  // settings: AnalysisSettings (defaults as on the CLI)
//   a.analytic();                                 // closed forms only: evaluates no point
//   a.trajectory();                               // samples the curve: runs no crossing search
//   a.work(sphtroch::Stage::polyline_census).ran;       // false so far
//   a.classification();                           // crossings, root census, cusps, ... then assembly
//   a.total_work().points_evaluated;              // every TracerCurve call made so far
//
// Contracts:
//  1. Laziness: an accessor runs its stage and the stages it depends on (dependencies()), each
//     at most once per object; a stage that was not needed has work(stage).ran == false and all
//     its counters 0. stages_for(effect) lists, in the order they run, every stage an effect of
//     a scene needs; requesting the effect (request()) runs exactly those.
//  2. Honest counters (StageWork), per stage, counted where the work is done:
//     points_evaluated = calls of TracerCurve::point / velocity / acceleration / screw_axis;
//     predicates = exact CGAL predicates (self_crossings.hpp); newton_steps = Newton
//     iterations (refinement and branch projection); root_evaluations = evaluations of the
//     root-count function g or g'; seconds = wall time of the stage itself (its dependencies
//     are timed in their own stages). Timing is informative only.
//  3. Which train: the input stage snaps the given train onto boundaries within
//     settings.reading.boundary_tolerance (boundary_snap.hpp; no point evaluated), unless
//     settings.reading.literal. The trajectory, velocity and screw-axis stages sample the train AS GIVEN
//     (what `sphtroch trace` prints); every census stage, the criteria, the extremes, the
//     symmetry and the plot trajectory use the ANALYSED (snapped) train (what `sphtroch
//     classify`, `nodes` and `plot` report).
//  4. classification() is the same object classify() returns (classify() is
//     `Analysis(train, settings).classification()`); its `work` is the sum of the work of the
//     stages it needs.
//  5. Screw axis (decision): omega = Z1 + n Z2 (Eq. 47a), the instantaneous screw axis, at the
//     trajectory's sample parameters t_i (the same t_i as trajectory(), without evaluating P).
//     It is not normalised: |omega| = sqrt(1 + n^2 + 2 n cos a2) is constant and its direction
//     sweeps the sun's pitch cone (half-angle a_s) about Z1.
//  6. Dependencies are explicit (dependencies(stage)) and the enum order is a run order; the
//     input stage runs in the constructor, every other stage only when asked for.
//  CAVEAT: the memo is not synchronised; use one Analysis per thread.
//  CAVEAT: this header includes CGAL (through polyline_census.hpp): the object owns the crossing
//  stage, so it lives in exact/. The Eigen-only closed forms stay in map/criteria.hpp, and a user
//  who only wants trajectories still pays for Eigen alone.
//  REQUIRES: settings valid (InvalidInput naming "samples" or "turns" otherwise, from the
//  constructor).
#pragma once

#if !defined(SPHTROCH_HAVE_EXACT)
#error "sphtroch/exact/analysis.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself"
#endif

#include "sphtroch/map/criteria.hpp"
#include "sphtroch/map/extremes_and_symmetry.hpp"
#include "sphtroch/map/boundary_snap.hpp"
#include "sphtroch/exact/classification.hpp"
#include "sphtroch/core/curve.hpp"
#include "sphtroch/core/node.hpp"
#include "sphtroch/census/node_assembly.hpp"
#include "sphtroch/core/pitch_cone.hpp"
#include "sphtroch/exact/certified_census.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/census/root_census.hpp"
#include "sphtroch/census/root_classification.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/core/work.hpp"

#include <array>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace sphtroch {

/// The stages, in an order in which every stage comes after its dependencies.
enum class Stage {
  input,            // validated train, snapped onto boundaries (no point)
  trajectory,       // P(t_i) of the given train (sampling.hpp)
  velocities,       // dP/dtheta2 (t_i) (Eq. 47a)
  screw_axis,       // omega(t_i) = Z1 + n Z2 (Eq. 47a)
  root_census,      // one-dimensional root count (root_census.hpp)
  polyline_census,  // exact polyline crossings + near misses, Newton refinement, assembly,
                    // certified against the root census (certified_census.hpp); named
                    // "crossings" in reports and scenes (kept for compatibility)
  nodes,            // the node points of the crossing stage
  cusps,            // pitch-cone criterion, each verified by point and speed
  analytic,         // the report's criteria (Eqs. 20/24, 43/46, pitch cone): closed forms only
  extremes,         // z extremes (Eqs. 14/15, 32-35 generalised): closed forms only
  symmetry,         // mirror planes and rotation order: closed forms only
  classification,   // assembly of the above, with the agreement check
  plot_trajectory,  // P(t_i) of the analysed train at plot_sample_count(train) samples
};
constexpr std::size_t kStageCount = 13;

/// What a scene may ask of a gear train (scene files, `sphtroch scene`).
enum class Effect { trace, velocity, nodes, cusps, classification, extrema, screw_axis, plot };
constexpr std::size_t kEffectCount = 8;

inline const char* to_string(Stage s);
inline const char* to_string(Effect e);
/// The effect of this name ("trace", "velocity", ..., "plot"), or nothing.
inline std::optional<Effect> effect_from_name(const std::string& name);
/// Every effect name, comma separated (for error messages).
inline std::string effect_names();

/// Work of one stage (see contract 2; work.hpp).
using StageWork = Work;

struct AnalysisSettings {
  // Census (as ClassifySettings).
  Reading reading;  // default, or literal: the doubles as given (core/reading.hpp)
  std::size_t census_samples = 0;  // polyline census samples; 0 = census_sample_count, else >= kMinCensusSamples
  // Trajectory (trace, velocity, screw axis).
  std::size_t samples = 0;       // closed curve: samples per period; 0 = trace_sample_count
  std::optional<double> turns;   // open curve over K carrier turns instead (K in (0, kMaxTurns])
};

/// omega(t_i) along the trajectory's parameters (contract 5).
struct ScrewAxisSamples {
  std::vector<double> t;
  std::vector<Vector3d> omega;
};

class Analysis {
 public:
  explicit Analysis(const GearTrain& train, const AnalysisSettings& settings = {});

  const GearTrain& input() const noexcept { return input_; }
  const SnappedTrain& snapped() const noexcept { return snapped_; }
  const GearTrain& analysed() const noexcept { return snapped_.train; }
  const AnalysisSettings& settings() const noexcept { return settings_; }

  const Trajectory<double>& trajectory() const;
  const std::vector<Vector3d>& velocities() const;  // at trajectory().t
  const ScrewAxisSamples& screw_axis() const;
  /// The certified polyline census (certified_census.hpp): the last run, and its certificate.
  const PolylineCensus& polyline_census() const;
  const CensusCertificate& certificate() const;
  const std::vector<Node>& nodes() const;
  const std::vector<Cusp>& cusps() const;
  const RootCensus& root_census() const;
  const AnalyticClassification& analytic() const;
  const ZExtremes& extremes() const;
  const Symmetry& symmetry() const;
  const Classification& classification() const;
  const Trajectory<double>& plot_trajectory() const;

  /// Runs one stage (and its dependencies) / every stage of an effect.
  void compute(Stage stage) const;
  void request(Effect effect) const;

  const StageWork& work(Stage stage) const { return work_[static_cast<std::size_t>(stage)]; }
  StageWork total_work() const;
  /// The stages that ran, in the order they finished.
  const std::vector<Stage>& stages_run() const noexcept { return order_; }

  /// The stages one stage needs directly.
  static std::vector<Stage> dependencies(Stage stage);
  /// Every stage an effect needs (transitively), in run order, ending with the effect's own.
  static std::vector<Stage> stages_for(Effect effect);

 private:
  template <typename F>
  void run_stage(Stage stage, F&& body) const;
  std::size_t trajectory_samples() const;
  double trajectory_span() const;
  std::size_t trajectory_divisor() const;

  GearTrain input_;
  AnalysisSettings settings_;
  SnappedTrain snapped_;
  mutable std::array<StageWork, kStageCount> work_{};
  mutable std::vector<Stage> order_;
  mutable std::optional<Trajectory<double>> trajectory_, plot_trajectory_;
  mutable std::optional<std::vector<Vector3d>> velocities_;
  mutable std::optional<ScrewAxisSamples> screw_axis_;
  mutable std::optional<CertifiedCensus> polyline_census_;
  mutable std::optional<std::vector<Cusp>> cusps_;
  mutable std::optional<RootCensus> root_;
  mutable std::optional<AnalyticClassification> analytic_;
  mutable std::optional<ZExtremes> extremes_;
  mutable std::optional<Symmetry> symmetry_;
  mutable std::optional<Classification> classification_;
};

// =============================================================================================
// Implementation details follow.
// =============================================================================================

namespace analysis_detail {

/// One row per stage, in enum order: its name and the stages it needs. With the enum and the
/// member that computes it (dispatched in Analysis::compute), adding a stage is these three edits.
struct StageRow {
  Stage stage;
  const char* name;
  std::array<Stage, 6> needs;  // the first `need_count` entries
  std::size_t need_count;
};

inline const std::array<StageRow, kStageCount>& stage_table() {
  using S = Stage;
  static const std::array<StageRow, kStageCount> table{{
      {S::input, "input", {}, 0},
      {S::trajectory, "trajectory", {S::input}, 1},
      {S::velocities, "velocities", {S::input}, 1},
      {S::screw_axis, "screw_axis", {S::input}, 1},
      {S::root_census, "root_census", {S::input}, 1},
      {S::polyline_census, "crossings", {S::root_census}, 1},
      {S::nodes, "nodes", {S::polyline_census}, 1},
      {S::cusps, "cusps", {S::input}, 1},
      {S::analytic, "analytic", {S::input}, 1},
      {S::extremes, "extremes", {S::input}, 1},
      {S::symmetry, "symmetry", {S::input}, 1},
      {S::classification, "classification", {S::nodes, S::cusps, S::root_census, S::analytic, S::extremes, S::symmetry}, 6},
      {S::plot_trajectory, "plot_trajectory", {S::input}, 1},
  }};
  return table;
}
static_assert(static_cast<std::size_t>(Stage::plot_trajectory) + 1 == kStageCount,
              "kStageCount must count every Stage, and stage_table() must have a row for each");

}  // namespace analysis_detail

inline const char* to_string(Stage s) {
  const std::size_t i = static_cast<std::size_t>(s);
  return i < kStageCount ? analysis_detail::stage_table()[i].name : "?";
}

inline const char* to_string(Effect e) {
  switch (e) {
    case Effect::trace: return "trace";
    case Effect::velocity: return "velocity";
    case Effect::nodes: return "nodes";
    case Effect::cusps: return "cusps";
    case Effect::classification: return "classification";
    case Effect::extrema: return "extrema";
    case Effect::screw_axis: return "screw_axis";
    case Effect::plot: return "plot";
  }
  return "?";
}

inline std::optional<Effect> effect_from_name(const std::string& name) {
  for (std::size_t i = 0; i < kEffectCount; ++i)
    if (name == to_string(static_cast<Effect>(i))) return static_cast<Effect>(i);
  return std::nullopt;
}

inline std::string effect_names() {
  std::string s;
  for (std::size_t i = 0; i < kEffectCount; ++i) s += (i ? ", " : "") + std::string(to_string(static_cast<Effect>(i)));
  return s;
}

inline std::vector<Stage> Analysis::dependencies(Stage stage) {
  const analysis_detail::StageRow& row = analysis_detail::stage_table()[static_cast<std::size_t>(stage)];
  return std::vector<Stage>(row.needs.begin(), row.needs.begin() + static_cast<std::ptrdiff_t>(row.need_count));
}

inline std::vector<Stage> Analysis::stages_for(Effect effect) {
  std::vector<Stage> direct;
  switch (effect) {
    case Effect::trace: direct = {Stage::trajectory}; break;
    case Effect::velocity: direct = {Stage::trajectory, Stage::velocities}; break;
    case Effect::nodes: direct = {Stage::nodes, Stage::cusps}; break;  // the CSV lists cusps too
    case Effect::cusps: direct = {Stage::cusps}; break;
    case Effect::classification: direct = {Stage::classification}; break;
    case Effect::extrema: direct = {Stage::extremes}; break;
    case Effect::screw_axis: direct = {Stage::screw_axis}; break;
    case Effect::plot: direct = {Stage::nodes, Stage::cusps, Stage::plot_trajectory}; break;
  }
  // Transitive closure; the enum order is a valid run order.
  std::array<bool, kStageCount> need{};
  std::vector<Stage> todo = direct;
  while (!todo.empty()) {
    const Stage s = todo.back();
    todo.pop_back();
    if (need[static_cast<std::size_t>(s)]) continue;
    need[static_cast<std::size_t>(s)] = true;
    for (Stage d : dependencies(s)) todo.push_back(d);
  }
  std::vector<Stage> out;
  for (std::size_t i = 0; i < kStageCount; ++i)
    if (need[i]) out.push_back(static_cast<Stage>(i));
  return out;
}

inline Analysis::Analysis(const GearTrain& train, const AnalysisSettings& settings)
    : input_(train), settings_(settings), snapped_{train, {}, false, 0.0, 0.0} {
  if (settings.samples != 0) check_sample_count(settings.samples);
  settings.reading.validate();
  if (settings.census_samples != 0 &&
      (settings.census_samples < kMinCensusSamples || settings.census_samples > kMaxSamples))
    throw InvalidInput("census_samples", std::to_string(settings.census_samples), "outside the valid range",
                       "0 (default) or integer " + std::to_string(kMinCensusSamples) + " .. " +
                           std::to_string(kMaxSamples));
  if (settings.turns) check_turns(*settings.turns, number_text(*settings.turns));
  run_stage(Stage::input, [&](StageWork&) {
    snapped_ = snap_to_boundaries(input_, settings_.reading.boundary());
  });
}

template <typename F>
void Analysis::run_stage(Stage stage, F&& body) const {
  StageWork& w = work_[static_cast<std::size_t>(stage)];
  const auto start = std::chrono::steady_clock::now();
  body(w);
  w.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  w.ran = true;
  order_.push_back(stage);
}

inline std::size_t Analysis::trajectory_samples() const {
  return settings_.samples ? settings_.samples : trace_sample_count(input_, settings_.turns);
}
inline double Analysis::trajectory_span() const {
  return settings_.turns ? Constants<double>::two_pi() * *settings_.turns : TracerCurve<double>(input_).period();
}
inline std::size_t Analysis::trajectory_divisor() const {
  const std::size_t n = trajectory_samples();
  return settings_.turns ? n - 1 : n;
}

inline const Trajectory<double>& Analysis::trajectory() const {
  if (!trajectory_)
    run_stage(Stage::trajectory, [&](StageWork& w) {
      const TracerCurve<double> curve(input_);
      const std::size_t n = trajectory_samples();
      trajectory_ = settings_.turns ? sample_turns(curve, *settings_.turns, n) : sample_period(curve, n);
      w.points_evaluated = n;
    });
  return *trajectory_;
}

inline const std::vector<Vector3d>& Analysis::velocities() const {
  if (!velocities_)
    run_stage(Stage::velocities, [&](StageWork& w) {
      const TracerCurve<double> curve(input_);
      const std::size_t n = trajectory_samples(), divisor = trajectory_divisor();
      const double span = trajectory_span();
      std::vector<Vector3d> v;
      v.reserve(n);
      for (std::size_t i = 0; i < n; ++i) v.push_back(curve.velocity(uniform_parameter(span, i, divisor)));
      w.points_evaluated = n;
      velocities_ = std::move(v);
    });
  return *velocities_;
}

inline const ScrewAxisSamples& Analysis::screw_axis() const {
  if (!screw_axis_)
    run_stage(Stage::screw_axis, [&](StageWork& w) {
      const TracerCurve<double> curve(input_);
      const std::size_t n = trajectory_samples(), divisor = trajectory_divisor();
      const double span = trajectory_span();
      ScrewAxisSamples s;
      s.t.reserve(n);
      s.omega.reserve(n);
      for (std::size_t i = 0; i < n; ++i) {
        s.t.push_back(uniform_parameter(span, i, divisor));
        s.omega.push_back(curve.screw_axis(s.t.back()));  // Eq. 47a
      }
      w.points_evaluated = n;
      screw_axis_ = std::move(s);
    });
  return *screw_axis_;
}

inline const PolylineCensus& Analysis::polyline_census() const {
  if (!polyline_census_) {
    root_census();
    run_stage(Stage::polyline_census, [&](StageWork& w) {
      const PolylineCensusSettings ps = polyline_census_settings(settings_.reading, settings_.census_samples);
#if defined(SPHTROCH_FAULT_INJECTION)
      // Test seam, compiled only into tests' sphtroch_fault (tests/CMakeLists.txt), never into the
      // tool or the library's users: a root census missing its last node stands for a disagreement
      // that no escalation removes, so that the uncertified path is tested end to end.
      RootCensus faulty = *root_;
      if (!faulty.nodes.empty()) faulty.nodes.pop_back();
      polyline_census_ = certified_census(analysed(), ps, faulty);
#else
      polyline_census_ = certified_census(analysed(), ps, *root_);
#endif
      // Every run of the escalation counts (its own counters hold the last run only).
      const PolylineWork& last = polyline_census_->polyline.work;
      w.points_evaluated = last.points_evaluated;
      w.predicates = last.predicates;
      w.newton_steps = last.newton_steps;
      w.points_evaluated += polyline_census_->earlier_work.points_evaluated;
      w.predicates += polyline_census_->earlier_work.predicates;
      w.newton_steps += polyline_census_->earlier_work.newton_steps;
    });
  }
  return polyline_census_->polyline;
}

inline const CensusCertificate& Analysis::certificate() const {
  polyline_census();
  return polyline_census_->certificate;
}

inline const std::vector<Node>& Analysis::nodes() const {
  if (!work(Stage::nodes).ran) {
    polyline_census();
    run_stage(Stage::nodes, [](StageWork&) {});  // the crossing stage's nodes, as they are
  }
  return polyline_census_->polyline.nodes;
}

inline const std::vector<Cusp>& Analysis::cusps() const {
  if (!cusps_)
    run_stage(Stage::cusps, [&](StageWork& w) {
      // Cusps from the pitch-cone criterion, verified by the velocity (map/criteria.hpp).
      std::vector<Cusp> out = cusp_points(analysed());
      w.points_evaluated = 2 * out.size();
      cusps_ = std::move(out);
    });
  return *cusps_;
}

inline const RootCensus& Analysis::root_census() const {
  if (!root_)
    run_stage(Stage::root_census, [&](StageWork& w) {
      const RootCensusSettings rs = root_census_settings(settings_.reading);
      root_ = sphtroch::root_census(analysed(), rs);
      w.root_evaluations = root_->evaluations;
      w.points_evaluated = assembly_evaluations(root_->nodes);  // velocities of node assembly
    });
  return *root_;
}

inline const AnalyticClassification& Analysis::analytic() const {
  if (!analytic_)
    run_stage(Stage::analytic, [&](StageWork&) {
      analytic_ = classify_analytic(analysed(), settings_.reading.boundary());
    });
  return *analytic_;
}

inline const ZExtremes& Analysis::extremes() const {
  if (!extremes_) run_stage(Stage::extremes, [&](StageWork&) { extremes_ = z_extremes(analysed()); });
  return *extremes_;
}

inline const Symmetry& Analysis::symmetry() const {
  if (!symmetry_) run_stage(Stage::symmetry, [&](StageWork&) { symmetry_ = sphtroch::symmetry(analysed()); });
  return *symmetry_;
}

inline const Trajectory<double>& Analysis::plot_trajectory() const {
  if (!plot_trajectory_)
    run_stage(Stage::plot_trajectory, [&](StageWork& w) {
      const std::size_t n = plot_sample_count(analysed());
      plot_trajectory_ = sample_period(TracerCurve<double>(analysed()), n);
      w.points_evaluated = n;
    });
  return *plot_trajectory_;
}

inline const Classification& Analysis::classification() const {
  if (classification_) return *classification_;
  // Dependencies first, so that the assembly's own time excludes theirs.
  for (Stage d : dependencies(Stage::classification)) compute(d);
  run_stage(Stage::classification, [&](StageWork&) {
    classification_ = assemble_classification(
        {input_, snapped_, settings_.reading.literal, polyline_census_->polyline, polyline_census_->certificate, *root_, *cusps_, *analytic_, *extremes_, *symmetry_});
  });
  // The work of everything the classification needed (contract 4).
  StageWork sum;
  for (Stage s : stages_for(Effect::classification)) sum += work(s);
  classification_->work = sum;
  return *classification_;
}

inline void Analysis::compute(Stage stage) const {
  switch (stage) {
    case Stage::input: return;  // done by the constructor
    case Stage::trajectory: trajectory(); return;
    case Stage::velocities: velocities(); return;
    case Stage::screw_axis: screw_axis(); return;
    case Stage::polyline_census: polyline_census(); return;
    case Stage::nodes: nodes(); return;
    case Stage::cusps: cusps(); return;
    case Stage::root_census: root_census(); return;
    case Stage::analytic: analytic(); return;
    case Stage::extremes: extremes(); return;
    case Stage::symmetry: symmetry(); return;
    case Stage::classification: classification(); return;
    case Stage::plot_trajectory: plot_trajectory(); return;
  }
}

inline void Analysis::request(Effect effect) const {
  for (Stage s : stages_for(effect)) compute(s);
}

inline StageWork Analysis::total_work() const {
  StageWork sum;
  for (const StageWork& w : work_) sum += w;
  return sum;
}

/// classification.hpp's entry point (declared there): the classification stage of an Analysis.
template <typename Settings>
Classification classify(const GearTrain& input, const Settings& settings) {
  static_assert(std::is_same<Settings, ClassifySettings>::value, "classify(train, ClassifySettings)");
  AnalysisSettings s;
  s.reading = settings.reading;
  s.census_samples = settings.samples;
  return Analysis(input, s).classification();
}

}  // namespace sphtroch
