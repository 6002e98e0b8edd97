// sphtroch/version.hpp — the library version.
#pragma once

#define SPHTROCH_VERSION_MAJOR 0
#define SPHTROCH_VERSION_MINOR 1
#define SPHTROCH_VERSION_PATCH 0
#define SPHTROCH_VERSION_STRING "0.1.0"
