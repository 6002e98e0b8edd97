// sphtroch/chain/chain_picture.hpp — a rotation chain's curve on the sphere with its
// census: the picture of `sphtroch chain plot`, Python's Chain.svg and the explorer's chain panel
// (draw/svg_plot.hpp's renderer; the census is the caller's: classify_chain's for the CLI).
//
//   const sphtroch::RotationChain chain({{1.0, sphtroch::ChainRate(1), 0.0}, {2.0, sphtroch::ChainRate(2, 3), 0.0}});
//   const sphtroch::ChainCensus c = sphtroch::chain_census(chain);
//   std::string svg = sphtroch::chain_picture_svg(chain, c);   // chain_plot_sample_count samples
//
//   sphtroch::ChainText typed;                                  // the chain as the user typed it
//   typed.twists = "pi/2,1.0471975511965976";
//   typed.rates = "1,2/3";
//   const sphtroch::RotationChain wrist = typed.chain();
//   sphtroch::chain_plot_caption(wrist, sphtroch::chain_census(wrist), &typed);
//   // "twists pi/2,1.0472, rates 1,2/3 — ...": an expression as typed, a long decimal to 6 digits
#pragma once

#if !defined(SPHTROCH_HAVE_INTERVAL)
#error "sphtroch/chain/chain_picture.hpp needs CGAL's headers: link the CMake target sphtroch::interval"
#endif

#include "sphtroch/chain/chain_census.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/sampling.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/draw/text_layout.hpp"
#include "sphtroch/io/chain_text.hpp"
#include "sphtroch/io/parse.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace sphtroch {

/// A twist or phase as the chain caption writes it: `typed` (trimmed) when it is an expression
/// ("pi/2", "30deg") or a decimal of at most 6 significant digits; a longer decimal, or no text
/// (`typed` empty: the caller has only the double `value`), to 6 significant digits (picture_number).
inline std::string chain_caption_angle(const std::string& typed, double value) {
  const std::string_view text = detail::trim(typed);
  if (text.empty()) return picture_number(value);
  if (const std::optional<double> plain = detail::strict_double(text)) return picture_number(*plain);
  return std::string(text);
}

/// The caption of `chain plot`: "twists A1,..,Ak, rates N1,..,Nk[, phases ..] — N node(s)
/// (C crossing, T tangency), K cusp(s)", the twists and phases by chain_caption_angle (as typed in
/// `typed`, the ChainText the chain was read from, when given with one item per stage), the
/// phases shown when one is not 0; " — NOT CERTIFIED: why" when the census is not certified. The
/// picture wraps it to its width (svg_plot.hpp contract 8).
inline std::string chain_plot_caption(const RotationChain& chain, const ChainCensus& c, const ChainText* typed = nullptr) {
  const std::size_t k = chain.size();
  std::vector<std::string> twist_text, phase_text;
  if (typed != nullptr && typed->urdf.empty()) {
    twist_text = split_list(typed->twists);
    phase_text = split_list(typed->phases);
  }
  twist_text.resize(twist_text.size() == k ? k : 0);
  phase_text.resize(phase_text.size() == k ? k : 0);
  std::string twists, phases;
  bool any_phase = false;
  for (std::size_t i = 0; i < k; ++i) {
    const ChainStage& s = chain.stages()[i];
    twists += (i == 0 ? "" : ",") + chain_caption_angle(twist_text.empty() ? "" : twist_text[i], s.twist);
    phases += (i == 0 ? "" : ",") + chain_caption_angle(phase_text.empty() ? "" : phase_text[i], s.phase);
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
/// the census's nodes and cusps and chain_plot_caption (of `typed` when given), drawn with
/// `options` (its caption replaced).
inline std::string chain_plot_svg(const RotationChain& chain, const Trajectory<double>& trajectory, const ChainCensus& c,
                                  PlotOptions options = {}, const ChainText* typed = nullptr) {
  options.caption = chain_plot_caption(chain, c, typed);
  return render_sphere_svg(trajectory, c.nodes, c.cusps, options);
}

/// The picture of a chain with its census `c` (classify_chain's): chain_plot_sample_count samples
/// of the period drawn by chain_plot_svg, its caption's angles as in `typed` when given. `chain
/// plot`, Python's Chain.svg (a float as its shortest decimal, so written to 6 digits) and the
/// explorer's chain panel pass the text they read.
inline std::string chain_picture_svg(const RotationChain& chain, const ChainCensus& c, const PlotOptions& options = {},
                                     const ChainText* typed = nullptr) {
  const ChainCurve<double> curve(chain);
  const std::size_t n = chain_plot_sample_count(chain);
  return chain_plot_svg(chain, sample(curve, UniformSampling<double>{curve.period(), n, n, true}), c, options, typed);
}

}  // namespace sphtroch
