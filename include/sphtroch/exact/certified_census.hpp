// sphtroch/exact/certified_census.hpp — a node census that is certified or says that it is not: the
// polyline census (polyline_census.hpp) checked against the independent root-count census
// (root_census.hpp), escalated while they disagree.
//
//   #include <sphtroch/exact/certified_census.hpp>        // needs sphtroch::exact (CGAL)
//   const sphtroch::RootCensus root = sphtroch::root_census(train);
//   sphtroch::CertifiedCensus c = sphtroch::certified_census(train, {}, root);
//   c.certificate.certified;   // the node points of both censuses agree (node_sets.hpp)
//   c.polyline.nodes;          // the nodes of the last polyline census run
//
// Contract (CGAL's discipline: a printed count is one two methods agree on):
//  1. Run the polyline census at the given settings. While its node points differ from the root
//     census's (same_node_sets), run it again one escalation level higher: 4x the uniform samples
//     and 2x the dense samples around near-cusp parameters, where the loops of a tracer near a
//     pitch cone shrink to ~|a3 - a_p| (PolylineCensusSettings::escalation).
//  2. Stop when they agree (certified), after kMaxCensusEscalations levels, or before a run whose
//     uniform samples would exceed kMaxEscalatedSamples (cost: a census costs about linearly in
//     its samples; the bound keeps an uncertified answer within ~20x the time of the first run).
//     Then the certificate says why it stopped, with every run's sample and node count.
//  3. The returned census is the last one run (the agreeing one when certified).
#pragma once

// Header-only without GMP and MPFR: SPHTROCH_EXACT_WITHOUT_GMP with CGAL_NO_GMP=1 (arc_predicates.hpp).
#if !defined(SPHTROCH_HAVE_EXACT) && \
    !(defined(SPHTROCH_EXACT_WITHOUT_GMP) && defined(CGAL_NO_GMP) && CGAL_NO_GMP)
#error "sphtroch/exact/certified_census.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact (find_package(sphtroch CONFIG REQUIRED COMPONENTS exact)), or define SPHTROCH_HAVE_EXACT and link CGAL, GMP and MPFR yourself, or (header-only, no GMP or MPFR) define SPHTROCH_EXACT_WITHOUT_GMP and CGAL_NO_GMP=1"
#endif

#include "sphtroch/core/gear_train.hpp"
#include "sphtroch/census/node_sets.hpp"
#include "sphtroch/exact/polyline_census.hpp"
#include "sphtroch/census/polyline_census_result.hpp"
#include "sphtroch/census/root_census.hpp"

#include <cmath>
#include <string>

namespace sphtroch {

/// Escalation levels after the first run (each 4x the uniform samples): at most 16x in all.
constexpr unsigned kMaxCensusEscalations = 2;
/// No escalated run takes more uniform samples than this (about 10 s of census on this machine).
constexpr std::size_t kMaxEscalatedSamples = std::size_t{1} << 20;

struct CertifiedCensus {
  PolylineCensus polyline;         // the last run
  PolylineWork earlier_work;       // the work of the runs before it
  CensusCertificate certificate;
};

/// The certified polyline census of `train` (see header). `root` must be root_census(train).
inline CertifiedCensus certified_census(const GearTrain& train, const PolylineCensusSettings& settings,
                                        const RootCensus& root) {
  CertifiedCensus out;
  CensusCertificate& cert = out.certificate;
  cert.root_nodes = root.nodes.size();
  const std::size_t base = settings.samples ? settings.samples : census_sample_count(train);
  PolylineCensusSettings s = settings;
  for (;;) {
    if (cert.runs() > 0) {
      out.earlier_work.points_evaluated += out.polyline.work.points_evaluated;
      out.earlier_work.predicates += out.polyline.work.predicates;
      out.earlier_work.candidate_pairs += out.polyline.work.candidate_pairs;
      out.earlier_work.newton_steps += out.polyline.work.newton_steps;
      out.earlier_work.seeds += out.polyline.work.seeds;
    }
    out.polyline = polyline_census(train, s);
    cert.samples.push_back(escalated_samples(base, s.escalation));
    cert.polyline_nodes.push_back(out.polyline.nodes.size());
    cert.disagreement.clear();
    cert.certified = same_node_sets(out.polyline.nodes, root.nodes, cert.disagreement);
    cert.differences.push_back(cert.certified ? std::string() : cert.disagreement);
    if (cert.certified) return out;
    if (s.escalation - settings.escalation >= kMaxCensusEscalations) {
      cert.stopped = "the censuses still disagree after " + std::to_string(cert.runs()) + " polyline census runs";
      return out;
    }
    if (escalated_samples(base, s.escalation + 1) > kMaxEscalatedSamples) {
      cert.stopped = "a further run would take " + std::to_string(escalated_samples(base, s.escalation + 1)) +
                     " uniform samples, beyond the escalation bound " + std::to_string(kMaxEscalatedSamples);
      return out;
    }
    PolylineWork sampling;  // the next run's polyline, for its cost (polyline_census would refuse it)
    const double pairs = census::close_pair_estimate(
        census::sample_polyline(train, escalated_samples(base, s.escalation + 1), sampling, s.escalation + 1).points);
    if (pairs > census::kMaxCloseVertexPairs) {
      cert.stopped = "a further run would compare ~" + number_text(std::round(pairs)) + " pairs of close edges, beyond the bound " +
                     number_text(census::kMaxCloseVertexPairs);
      return out;
    }
    ++s.escalation;
  }
}

}  // namespace sphtroch
