// Output plugins found next to the executable and opened with dlopen on first use (see
// plugin_loader.hpp; the ABI: output_plugin.hpp).
#include "plugin_loader.hpp"

#include "cli_common.hpp"
#include "output_plugin.hpp"

#include "sphtroch/core/errors.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef SPHTROCH_PLUGIN_DIR
#define SPHTROCH_PLUGIN_DIR "../lib/sphtroch"  // the plugins' directory relative to the executable's
#endif

namespace sphtroch::cli {

namespace {

/// "<output>: STEP is written by the plugin P (OpenCASCADE), which <why>; valid: ..." (the verb the plugin's).
UsageError unavailable(const OutputPlugin& plugin, const std::string& path, const std::string& output,
                       const std::string& why) {
  return UsageError{output + ": " + plugin.format + " is " + plugin.verb + " by the plugin " + path + " (" + plugin.library +
                    "), which " + why + "; valid: the tool installed with its plugins (cmake --install), or " +
                    plugin.alternative};
}

/// The plugin's run function, opened and checked once.
PluginRunFunction open_plugin(const OutputPlugin& plugin, const std::string& output) {
  static std::mutex mutex;
  static std::map<std::string, PluginRunFunction> opened;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = opened.find(plugin.file); it != opened.end()) return it->second;
  const std::string path = (std::filesystem::path(plugin_directory()) / plugin.file).string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw unavailable(plugin, path, output, "is not there");
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed: its code may be on a stack
  if (!handle) {
    const char* why = dlerror();
    throw unavailable(plugin, path, output, std::string("cannot be opened: ") + (why ? why : "dlopen failed"));
  }
  const auto abi = reinterpret_cast<PluginAbiFunction>(dlsym(handle, kPluginAbiSymbol));
  const auto run = reinterpret_cast<PluginRunFunction>(dlsym(handle, kPluginRunSymbol));
  if (!abi || !run) throw unavailable(plugin, path, output, "is not a sphtroch output plugin");
  if (const int revision = abi(); revision != kOutputPluginAbi)
    throw unavailable(plugin, path, output, "is of plugin ABI revision " + std::to_string(revision) + ", the tool's is " +
                                                std::to_string(kOutputPluginAbi) + " (a tool and a plugin of different builds)");
  return opened[plugin.file] = run;
}

/// The InvalidInput of a kPluginInvalidInput text (field, value, problem, valid range).
InvalidInput invalid_input(const std::string& text) {
  std::vector<std::string> part(1);
  for (const char c : text)
    if (c == kPluginFieldSeparator) part.emplace_back();
    else part.back() += c;
  part.resize(4);
  return InvalidInput(part[0], part[1], part[2], part[3]);
}

}  // namespace

std::string plugin_directory() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw UsageError{"the tool's own path (/proc/self/exe), next to which its plugins lie, cannot be read: " + ec.message()};
  return (exe.parent_path() / SPHTROCH_PLUGIN_DIR).lexically_normal().string();
}

const char* output_plugin_state(const OutputPlugin& plugin) noexcept {
  try {
    const std::string path = plugin_directory() + "/" + plugin.file;
    return ::access(path.c_str(), R_OK) == 0 ? "yes" : "missing";
  } catch (...) {  // the executable's path unreadable, or out of memory
    return "missing";
  }
}

void require_output_plugin(const OutputPlugin& plugin, const std::string& output) { (void)open_plugin(plugin, output); }

std::string run_output_plugin(const OutputPlugin& plugin, const std::string& output, const std::string& request) {
  const PluginRunFunction run = open_plugin(plugin, output);
  char* bytes = nullptr;
  char* error = nullptr;
  std::size_t size = 0;
  const int code = run(request.data(), request.size(), &bytes, &size, &error);
  const std::unique_ptr<char, decltype(&std::free)> own_bytes(bytes, &std::free), own_error(error, &std::free);
  const std::string message = error ? error : "no message";
  switch (code) {
    case kPluginOk: return std::string(bytes, size);
    case kPluginInvalidInput: throw invalid_input(message);
    case kPluginOutOfMemory: throw std::bad_alloc();
    default: throw std::runtime_error(message);
  }
}

}  // namespace sphtroch::cli
