// explorer/wasm_module.cpp — the library as a WebAssembly module for the explorer page (embind;
// built by the CMake target `explorer` with emscripten's em++): the exports' names, one
// register_* function per topic file (wasm_common.hpp lists them).
//
// Every function takes the CLI's texts ("pi/3", "ap+1e-6", "5/2", teeth "39:15") through the same
// parsers (io/train_text.hpp, machine/clinostat_text.hpp, io/chain_text.hpp), so a URL, a scene,
// the CLI and the page read a train alike. No exception reaches JavaScript: a refused input
// returns {error: "<the CLI's one line>"} (the field, the value, the valid range), and the page
// shows that line instead of any number. Where the library writes a format (the trace CSV, the
// sphere picture SVG, the clinostat report's and the chain census's JSON, the chain picture), the
// module returns the library's text, so that the page's exports and objects are those of the
// tool. Nothing here starts a thread.
// A count is certified by the library's rule, the CLI's (exact/certified_census.hpp: the polyline
// census with CGAL's exact predicates against the root census), compiled header-only without GMP
// (SPHTROCH_EXACT_WITHOUT_GMP, CGAL_NO_GMP: see explorer/CMakeLists.txt).
#include "wasm_common.hpp"

EMSCRIPTEN_BINDINGS(sphtroch_explorer) {
  using namespace sphtroch::wasm;
  register_train();
  register_census();
  register_map();
  register_synthesis();
  register_tolerance();
  register_chain();
  register_clinostat();
}
