// The URDF plugin (CMake MODULE sphtroch_urdf, the one binary of the tool that links urdfdom):
// a request of four fields (plugin_fields.hpp: the document, the from and to links, the tool axis
// as three numbers) in, through io/urdf_chain.hpp; out one field per stage, "twist rate phase"
// (twist and phase as round-trip decimals, rate p/q). The C ABI and its error contract:
// output_plugin.hpp (InvalidInput crosses it as field, value, problem, valid range).
#include "output_plugin.hpp"
#include "plugin_fields.hpp"

#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"
#include "sphtroch/io/urdf_chain.hpp"

#include <string>
#include <vector>

namespace {

std::string read_urdf_request(const std::string& text) {
  using namespace sphtroch;
  const std::vector<std::string> f = cli::split_fields(text, 6);
  Vector3d axis;
  for (int k = 0; k < 3; ++k) axis[k] = detail::strict_double(f[3 + static_cast<std::size_t>(k)]).value_or(0.0);
  const RotationChain chain = chain_from_urdf(f[0], f[1], f[2], axis);
  std::vector<std::string> stages;
  for (const ChainStage& s : chain.stages())
    stages.push_back(number_text(s.twist) + " " + std::to_string(s.rate.p()) + "/" + std::to_string(s.rate.q()) + " " + number_text(s.phase));
  return cli::join_fields(stages);
}

}  // namespace

SPHTROCH_OUTPUT_PLUGIN(read_urdf_request)
