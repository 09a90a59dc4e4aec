// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/provenance.hpp"

#include <gsl/gsl_version.h>
#include <CLI/Version.hpp>
#include <Eigen/Core>

#include <nlohmann/json.hpp>

namespace dfchaos::kit {

const char* version() { return DFCHAOS_VERSION; }

std::string compiler_id() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

std::vector<std::pair<std::string, std::string>> build_info() {
  return {{"dfchaos", version()},
          {"git", git_hash()},
          {"compiler", compiler_id()},
          {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION)},
          {"GSL", GSL_VERSION},
          {"CLI11", CLI11_VERSION},
          {"nlohmann-json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." + std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                                std::to_string(NLOHMANN_JSON_VERSION_PATCH)}};
}

}  // namespace dfchaos::kit
