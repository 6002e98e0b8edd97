// sphtroch/interval/isolated_roots.hpp — what a certified root search returns (root_isolation.hpp):
// the roots found, whether the list is proved complete, and the work. A plain type (no CGAL), so
// that a result can be read where the search is not compiled (sphtroch::compiled).
//
//   struct Root { double x = 0; bool isolated = true; double residual = 0; };
//   sphtroch::IsolatedRoots<Root> r;
//   r.certified;   // true: r.solutions are all the roots, each proved alone in its box
#pragma once

#include <cstddef>
#include <vector>

namespace sphtroch {

/// What a search returns: the System's solutions (its `Solution` type, which has the members
/// `isolated` and `residual`), in the order found, whether the list is certified complete, and the work.
template <class Solution>
struct IsolatedRoots {
  std::vector<Solution> solutions;
  bool certified = true;      // every box was excluded or isolated one root (see header)
  std::size_t undecided = 0;  // boxes left undecided (0 when certified)
  std::size_t boxes = 0;      // boxes examined (the work)
};

}  // namespace sphtroch
