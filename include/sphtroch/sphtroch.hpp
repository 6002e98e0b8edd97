// sphtroch/sphtroch.hpp — umbrella header: everything that needs Eigen only.
// The crossing search and node census (CGAL) have their own headers; see README.
#pragma once

#include "sphtroch/curve.hpp"
#include "sphtroch/errors.hpp"
#include "sphtroch/gear_train.hpp"
#include "sphtroch/parse.hpp"
#include "sphtroch/ratio.hpp"
#include "sphtroch/sampling.hpp"
#include "sphtroch/types.hpp"
#include "sphtroch/version.hpp"
