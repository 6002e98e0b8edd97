// The one file of the program that includes exact_implementation.hpp (SPHTROCH_SEPARATE_EXACT).
// See test_separate_compilation.cpp.
#include "sphtroch/exact_implementation.hpp"
