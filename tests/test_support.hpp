// tests/test_support.hpp — small helpers shared by the Catch2 tests.
#pragma once

#include "catch2/catch.hpp"
#include "sphtroch/errors.hpp"

namespace sphtroch::test {

/// Runs f, expects sphtroch::InvalidInput, and returns it for inspection (fails the test otherwise).
template <typename F>
InvalidInput expect_invalid(F&& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e;
  }
  FAIL("no InvalidInput thrown");
  return InvalidInput("", "", "", "");
}

}  // namespace sphtroch::test
