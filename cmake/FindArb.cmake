# SPDX-License-Identifier: GPL-3.0-or-later
# FindArb.cmake — Arb (ball arithmetic) as packaged by Debian 12: libflint-arb-dev installs
# /usr/include/arb.h and libflint-arb.so, with no pkg-config file or CMake config.
#
# Defines the imported target Arb::Arb (headers, libflint-arb, and its dependencies FLINT, MPFR, GMP)
# and Arb_FOUND, Arb_INCLUDE_DIR, Arb_LIBRARY, Arb_VERSION.
include(FindPackageHandleStandardArgs)

find_path(Arb_INCLUDE_DIR NAMES arb.h PATH_SUFFIXES arb flint)
find_library(Arb_LIBRARY NAMES flint-arb arb)
find_path(Flint_INCLUDE_DIR NAMES flint/flint.h flint.h)
find_library(Flint_LIBRARY NAMES flint)
find_library(Mpfr_LIBRARY NAMES mpfr)
find_library(Gmp_LIBRARY NAMES gmp)

if(Arb_INCLUDE_DIR AND EXISTS "${Arb_INCLUDE_DIR}/arb.h")
  file(STRINGS "${Arb_INCLUDE_DIR}/arb.h" _arb_version_line REGEX "^#define ARB_VERSION \"[0-9.]+\"")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" Arb_VERSION "${_arb_version_line}")
endif()

find_package_handle_standard_args(Arb
  REQUIRED_VARS Arb_LIBRARY Arb_INCLUDE_DIR Flint_LIBRARY Mpfr_LIBRARY Gmp_LIBRARY
  VERSION_VAR Arb_VERSION)

if(Arb_FOUND AND NOT TARGET Arb::Arb)
  add_library(Arb::Arb UNKNOWN IMPORTED)
  set_target_properties(Arb::Arb PROPERTIES
    IMPORTED_LOCATION "${Arb_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Arb_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${Flint_LIBRARY};${Mpfr_LIBRARY};${Gmp_LIBRARY}")
endif()
mark_as_advanced(Arb_INCLUDE_DIR Arb_LIBRARY Flint_INCLUDE_DIR Flint_LIBRARY Mpfr_LIBRARY Gmp_LIBRARY)
