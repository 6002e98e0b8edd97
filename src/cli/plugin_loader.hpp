// src/cli/plugin_loader.hpp — the tool's side of output_plugin.hpp: finds an output plugin next
// to the executable, opens it (dlopen) the first time a command writes its format, and runs it.
// The plugins live in plugin_directory(): the executable's own directory (/proc/self/exe) joined
// with SPHTROCH_PLUGIN_DIR, a relative path fixed at configure time, the same in the build tree
// (<build>/bin/sphtroch, <build>/lib/sphtroch/) and the install tree (<prefix>/bin/sphtroch,
// <prefix>/<libdir>/sphtroch/), so that an installed tree can be moved as a whole. The install
// directories must be relative to the prefix (src/cli/CMakeLists.txt refuses absolute ones). A tool
// started through the dynamic loader (`ld.so ./sphtroch`) sees the loader as /proc/self/exe: its
// plugins are then not found and STEP and PNG are refused (one line, exit 2).
#pragma once

#include <string>

namespace sphtroch::cli {

/// One output plugin, as the messages name it.
struct OutputPlugin {
  const char* file;         // "sphtroch_step.so": the MODULE's file name (src/cli/CMakeLists.txt)
  const char* format;       // "STEP"
  const char* library;      // "OpenCASCADE"
  const char* alternative;  // the valid alternatives a refusal names
  const char* verb = "written";  // what the plugin does with the format: "written", "read", "computed"
};

/// The directory the plugins are looked up in (absolute; see the header). Throws UsageError if
/// the executable's path cannot be read.
std::string plugin_directory();

/// The bytes `plugin` makes of `request`, for the output errors name as `output` ("--output =
/// p.step", "p.png"). Opens the plugin at first use (RTLD_NOW | RTLD_LOCAL; kept open for the
/// life of the process). Throws UsageError (exit 2, one line "<output>: ..." naming the plugin's
/// path and why) if it is not there,
/// cannot be opened or is of another ABI revision; InvalidInput as the plugin reports it;
/// std::bad_alloc if it ran out of memory; std::runtime_error with its message for any other
/// failure. Thread-safe.
std::string run_output_plugin(const OutputPlugin& plugin, const std::string& output, const std::string& request);

/// "yes" when `plugin`'s file is in plugin_directory() and readable (not opened: cheap), else
/// "missing"; for `sphtroch --version`.
const char* output_plugin_state(const OutputPlugin& plugin) noexcept;

/// Opens `plugin` now (as run_output_plugin does at first use), so that a command refuses a
/// missing or broken plugin before its work. Throws as run_output_plugin's opening does.
void require_output_plugin(const OutputPlugin& plugin, const std::string& output);

}  // namespace sphtroch::cli
