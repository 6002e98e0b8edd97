// sphtroch/chain/chain_picture.hpp — a rotation chain's curve on the sphere with its
// census: the picture of `sphtroch chain plot`, Python's Chain.svg and the explorer's chain panel
// (draw/svg_plot.hpp's renderer; the census is the caller's: classify_chain's for the CLI).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
//   std::string svg = sphtroch::chain_picture_svg(chain, c);   // chain_plot_sample_count samples
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_picture.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg_plot.hpp"

#include <cstddef>
#include <string>

namespace sphtroch {

/// The caption of `chain plot`: "twists A1,..,Ak, rates N1,..,Nk[, phases ..] — N node(s)
/// (C crossing, T tangency), K cusp(s)", the twists and phases as shortest round-trip doubles,
/// the phases shown when one is not 0; " — NOT CERTIFIED: why" when the census is not certified.
inline std::string chain_plot_caption(const RotationChain& chain, const ChainCensus& c) {
  std::string twists, phases;
  bool any_phase = false;
  for (const ChainStage& s : chain.stages()) {
    twists += (twists.empty() ? "" : ",") + number_text(s.twist);
    phases += (phases.empty() ? "" : ",") + number_text(s.phase);
    any_phase = any_phase || s.phase != 0.0;
  }
  std::size_t crossings = 0;
  for (const Node& n : c.nodes) crossings += n.kind == NodeKind::crossing ? 1 : 0;
  std::string caption = "twists " + twists + ", rates " + chain.rates_text() + (any_phase ? ", phases " + phases : "") + " — " +
                        std::to_string(c.nodes.size()) + " node(s)";
  if (!c.nodes.empty())
    caption += " (" + std::to_string(crossings) + " crossing, " + std::to_string(c.nodes.size() - crossings) + " tangency)";
  caption += ", " + std::to_string(c.cusps.size()) + " cusp(s)";
  return c.certified ? caption : caption + " — NOT CERTIFIED: " + c.why;
}

/// `chain plot`: the sphere picture (draw/svg_plot.hpp) of `trajectory` (the chain's curve) with
/// the census's nodes and cusps and chain_plot_caption, drawn with `options` (its caption replaced).
inline std::string chain_plot_svg(const RotationChain& chain, const Trajectory<double>& trajectory, const ChainCensus& c,
                                  PlotOptions options = {}) {
  options.caption = chain_plot_caption(chain, c);
  return render_sphere_svg(trajectory, c.nodes, c.cusps, options);
}

/// The picture of a chain with its census `c` (classify_chain's): chain_plot_sample_count samples
/// of the period drawn by chain_plot_svg. `chain plot`, Python's Chain.svg and the explorer's
/// chain panel draw it.
inline std::string chain_picture_svg(const RotationChain& chain, const ChainCensus& c, const PlotOptions& options = {}) {
  const ChainCurve<double> curve(chain);
  const std::size_t n = chain_plot_sample_count(chain);
  return chain_plot_svg(chain, sample(curve, UniformSampling<double>{curve.period(), n, n, true}), c, options);
}

}  // namespace sphtroch
