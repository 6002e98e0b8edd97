// The tool's side of the URDF plugin (urdf_input.hpp): the request's fields out, the stages back.
#include "urdf_input.hpp"

#include "plugin_fields.hpp"
#include "plugin_loader.hpp"

#include "sphtroch/core/errors.hpp"
#include "sphtroch/core/number_text.hpp"
#include "sphtroch/io/parse.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

namespace sphtroch::cli {

#if defined(SPHTROCH_HAVE_URDF_PLUGIN)
namespace {

/// The MODULE sphtroch_urdf (file name set in src/cli/CMakeLists.txt).
constexpr OutputPlugin kUrdfPlugin{"sphtroch_urdf.so", "URDF", "urdfdom", "--twists, --rates and --phases", "read"};

/// One stage of the plugin's reply: "twist p/q phase".
ChainStage stage_of(const std::string& field) {
  std::istringstream in(field);
  std::string twist, rate, phase;
  in >> twist >> rate >> phase;
  const std::optional<double> a = detail::strict_double(twist), f = detail::strict_double(phase);
  const std::size_t slash = rate.find('/');
  const std::optional<std::int64_t> p = detail::strict_int(rate.substr(0, slash)), q = detail::strict_int(rate.substr(slash + 1));
  if (!a || !f || slash == std::string::npos || !p || !q) throw std::runtime_error("the URDF plugin's reply: a bad stage \"" + field + "\"");
  return ChainStage{*a, ChainRate(*p, *q), *f};
}

}  // namespace

RotationChain urdf_chain_by_plugin(const std::string& xml, const std::string& from, const std::string& to, const Vector3d& axis) {
  const std::string request = join_fields({xml, from, to, number_text(axis.x()), number_text(axis.y()), number_text(axis.z())});
  const std::string reply = run_output_plugin(kUrdfPlugin, "--urdf", request);
  std::vector<ChainStage> chain;
  for (const std::string& f : split_fields(reply)) chain.push_back(stage_of(f));
  return RotationChain(chain);
}

const char* urdf_plugin_state() noexcept { return output_plugin_state(kUrdfPlugin); }
#else
RotationChain urdf_chain_by_plugin(const std::string&, const std::string&, const std::string&, const Vector3d&) {
  throw InvalidInput("urdf", "the document", "this build of sphtroch has no urdfdom", "a build with sphtroch::urdf (Debian's liburdfdom-dev)");
}

const char* urdf_plugin_state() noexcept { return "no"; }
#endif

}  // namespace sphtroch::cli
