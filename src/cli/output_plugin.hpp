// The C ABI between the tool and its output plugins (sphtroch_step, sphtroch_png: CMake MODULE
// libraries that hold OpenCASCADE and librsvg, opened by plugin_loader.cpp only when a command
// writes STEP or PNG). A plugin exports two C functions:
//
//   int sphtroch_plugin_abi(void);   // kOutputPluginAbi of the plugin's build
//   int sphtroch_plugin_run(const char* request, size_t request_size,
//                           char** output, size_t* output_size, char** error);
//
// sphtroch_plugin_run turns the request bytes (the plugin's own format: step_request.hpp, or an
// SVG) into the output bytes. It returns kPluginOk with *output set (*error null), or
// kPluginInvalidInput / kPluginOutOfMemory / kPluginFailed with *error set (a NUL-terminated
// text; *output null). For kPluginInvalidInput the text is the InvalidInput's field, value,
// problem and valid range joined by kPluginFieldSeparator; otherwise it is the message. Both
// buffers are allocated with std::malloc and owned by the caller, who frees them with std::free
// (one C library serves the process). Never throws across the boundary. A plugin defines both
// functions with SPHTROCH_OUTPUT_PLUGIN(convert).
#pragma once

#include "sphtroch/core/errors.hpp"

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>

namespace sphtroch::cli {

/// The ABI revision: the tool opens only a plugin that reports the same number.
constexpr int kOutputPluginAbi = 1;
constexpr int kPluginOk = 0;
constexpr int kPluginInvalidInput = 1;
constexpr int kPluginFailed = 2;
constexpr int kPluginOutOfMemory = 3;
constexpr char kPluginFieldSeparator = '\x1f';  // ASCII unit separator: in no field's text

using PluginAbiFunction = int (*)();
using PluginRunFunction = int (*)(const char*, std::size_t, char**, std::size_t*, char**);
constexpr const char* kPluginAbiSymbol = "sphtroch_plugin_abi";
constexpr const char* kPluginRunSymbol = "sphtroch_plugin_run";

/// A malloc'd copy of `bytes` with a NUL after them (null if out of memory).
inline char* plugin_buffer(const std::string& bytes) {
  char* p = static_cast<char*>(std::malloc(bytes.size() + 1));
  if (p) {
    std::memcpy(p, bytes.data(), bytes.size());
    p[bytes.size()] = '\0';
  }
  return p;
}

/// The body of a plugin's sphtroch_plugin_run: `convert(request)` (std::string -> std::string)
/// with its exceptions turned into the return codes and error texts above.
template <typename Convert>
int serve_plugin_run(Convert convert, const char* request, std::size_t request_size, char** output,
                     std::size_t* output_size, char** error) noexcept {
  *output = nullptr;
  *output_size = 0;
  *error = nullptr;
  int code = kPluginFailed;
  std::string text;
  try {
    const std::string bytes = convert(std::string(request, request_size));
    if ((*output = plugin_buffer(bytes))) {
      *output_size = bytes.size();
      return kPluginOk;
    }
    code = kPluginOutOfMemory;
    text = "out of memory";
  } catch (const std::bad_alloc&) {
    code = kPluginOutOfMemory;
    text = "out of memory";
  } catch (const InvalidInput& e) {
    code = kPluginInvalidInput;
    const char sep = kPluginFieldSeparator;
    text = e.field() + sep + e.value() + sep + e.problem() + sep + e.valid_range();
  } catch (const std::exception& e) {
    text = e.what();
  } catch (...) {
    text = "an unknown exception";
  }
  *error = plugin_buffer(text);
  return code;
}

}  // namespace sphtroch::cli

/// Defines the plugin's two exported C functions around `convert` (std::string -> std::string).
#define SPHTROCH_OUTPUT_PLUGIN(convert)                                                                     \
  extern "C" __attribute__((visibility("default"))) int sphtroch_plugin_abi() {                            \
    return sphtroch::cli::kOutputPluginAbi;                                                                \
  }                                                                                                       \
  extern "C" __attribute__((visibility("default"))) int sphtroch_plugin_run(                               \
      const char* request, std::size_t request_size, char** output, std::size_t* output_size, char** error) { \
    return sphtroch::cli::serve_plugin_run(convert, request, request_size, output, output_size, error);   \
  }
