// src/compiled/sphtroch_compiled.cpp — the one translation unit of sphtroch::compiled: the exact
// entry points defined and instantiated here (exact_implementation.hpp), so that a consumer built
// with SPHTROCH_SEPARATE_EXACT (the target's interface and sphtroch-compiled.pc define it) parses
// no CGAL header and links this library instead (the pattern of fmt's and spdlog's compiled
// libraries). What it holds: classify() for ClassifySettings, with everything it runs (both
// censuses, the certificate, cusps, criteria), tolerance_report(), precision_points_with_census()
// and fit_with_census() (exact_implementation.hpp). The library stays header-only for everyone else.
#include <sphtroch/exact_implementation.hpp>
