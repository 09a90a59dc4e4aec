// SPDX-License-Identifier: GPL-3.0-or-later
/// @file provenance.hpp
/// @brief What a result was computed with: dfchaos version, git hash of the source tree (refreshed
/// at every build, not only at configure time), compiler and library versions.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace dfchaos::kit {

/// The dfchaos version (CMake project version).
const char* version();
/// `git describe --always --dirty` of the source tree at the last build ("unknown" outside a checkout).
const char* git_hash();
/// The compiler that built the kit, e.g. "g++ 12.2.0".
std::string compiler_id();
/// Versions of everything that went into the build (dfchaos, git hash, compiler, Eigen, GSL,
/// CLI11, nlohmann-json), as (name, version) pairs, for the report's provenance appendix.
std::vector<std::pair<std::string, std::string>> build_info();

}  // namespace dfchaos::kit
