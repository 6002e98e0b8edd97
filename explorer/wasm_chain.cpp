// explorer/wasm_chain.cpp — the chain panel: a rotation chain read by the CLI's reader (ChainText),
// its census (chain/chain_census.hpp) as the object `sphtroch chain classify --json` prints
// (chain/chain_census_output.hpp) and its picture as `sphtroch chain plot` draws it
// (chain/chain_picture.hpp); a two-stage chain that is a gear train is handed to the page.
#include "wasm_common.hpp"

#include "sphtroch/chain/chain_census_output.hpp"
#include "sphtroch/chain/chain_picture.hpp"
#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/draw/mark_density.hpp"
#include "sphtroch/draw/svg_plot.hpp"
#include "sphtroch/io/chain_text.hpp"

#include <optional>

namespace sphtroch::wasm {

namespace {

/// `sphtroch chain plot --twists T --rates R --phases P --markers M` (phases "": all 0) for a
/// chain that is not a gear train: {text: its SVG, the CLI's bytes (chain_picture_svg of the chain
/// census, classify_chain's for such a chain), json: the JSON text of `sphtroch chain classify
/// --json` (chain_census_json; parsed by the page)}. A two-stage chain with both rates not 0 is a
/// gear train, whose census the CLI takes from classify's (MPFR, not in the module): {train: {a2,
/// a3, n, phase}} (gear_train_of), for the page to show as its design. The census runs here,
/// within chain classify's bound (refused up front beyond it).
val chain_plot(const std::string& twists, const std::string& rates, const std::string& phases, const std::string& markers) {
  return guarded([&] {
    ChainText text;
    text.twists = twists;
    text.rates = rates;
    text.phases = phases;
    const RotationChain chain = text.chain();
    PlotOptions options;
    options.markers = parse_mark_mode(markers);
    if (const std::optional<GearTrain> t = gear_train_of(chain)) {
      val train = val::object();
      train.set("a2", number_text(t->a2()));
      train.set("a3", number_text(t->a3()));
      train.set("n", t->ratio().str());
      train.set("phase", number_text(t->phase()));
      val out = val::object();
      out.set("train", train);
      return out;
    }
    const ChainCensus c = chain_census(chain);
    val out = text_object(chain_picture_svg(chain, c, options, &text));
    out.set("json", chain_census_json(chain, c).dump());
    return out;
  });
}

}  // namespace

void register_chain() { emscripten::function("chainPlot", &chain_plot); }

}  // namespace sphtroch::wasm
