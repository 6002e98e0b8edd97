// tests/fuzz/fuzz_scene.cpp — the scene reader of `sphtroch scene`:
// sphtroch::cli::validate_scene_text (src/cli/scene_command.cpp) parses and validates a scene's
// JSON (depth limit, keys, values, gear trains, cost checks) without touching the file system.
//
// Input: the scene file's bytes.
// Expected: sphtroch::cli::UsageError (with a non-empty message) and sphtroch::InvalidInput.
// Anything else thrown (a JSON library exception, std::out_of_range, ...) crashes: the tool
// would report it as an internal error (exit 1) instead of a one-line input error (exit 2).
#include "fuzz_common.hpp"

#include "cli_common.hpp"

#include "sphtroch/core/errors.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const std::size_t trains = sphtroch::cli::validate_scene_text(text);
    FUZZ_CHECK(trains >= 1);  // "trains" must be a non-empty list
  } catch (const sphtroch::cli::UsageError& e) {
    FUZZ_CHECK(!e.message.empty());
  } catch (const sphtroch::InvalidInput& e) {
    FUZZ_CHECK(!e.field().empty() && !e.problem().empty());
  }
  return 0;
}
