// src/cli/urdf_input.hpp — the tool's URDF reader (ChainText::urdf_reader): urdfdom lives in the
// URDF plugin (urdf_plugin.cpp), which the tool opens only when a command reads --urdf
// (plugin_loader.hpp), so that every other call loads neither urdfdom nor its XML parser.
#pragma once

#include "sphtroch/core/rotation_chain.hpp"
#include "sphtroch/core/types.hpp"

#include <string>

namespace sphtroch::cli {

/// chain_from_urdf's contract (io/urdf_chain.hpp), through the plugin. Throws InvalidInput as
/// it does, UsageError ("--urdf = FILE: URDF is read by the plugin ...") when the plugin is
/// missing or broken, InvalidInput("urdf") in a build without urdfdom.
RotationChain urdf_chain_by_plugin(const std::string& xml, const std::string& from, const std::string& to, const Vector3d& axis);

/// For --version: "yes" (the plugin file present), "missing", or "no" (a build without urdfdom).
const char* urdf_plugin_state() noexcept;

}  // namespace sphtroch::cli
