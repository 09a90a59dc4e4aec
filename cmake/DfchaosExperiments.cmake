# SPDX-License-Identifier: GPL-3.0-or-later
# dfchaos_add_experiments(DIR [OUTPUT_DIR dir] [SMOKE_OUT dir])
#
# One executable per DIR/*.cpp, named after the file: an experiment is its .cpp and nothing else
# (the list is globbed, and re-globbed at build time, so a new or copied file needs no other edit).
# Each is compiled with DFCHAOS_EXPERIMENT_NAME set to its name, linked to the kit and the core, and
# registered with CTest as smoke_NAME (`NAME --fast`, label "smoke"). The names are appended to the
# global property DFCHAOS_EXPERIMENTS.
function(dfchaos_add_experiments dir)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR;SMOKE_OUT" "" ${ARGN})
  if(NOT ARG_OUTPUT_DIR)
    set(ARG_OUTPUT_DIR ${CMAKE_BINARY_DIR}/bin/experiments)
  endif()
  if(NOT ARG_SMOKE_OUT)
    set(ARG_SMOKE_OUT ${CMAKE_BINARY_DIR}/smoke)
  endif()
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  foreach(src IN LISTS sources)
    get_filename_component(name ${src} NAME_WE)
    if(NOT name MATCHES "^[a-z][a-z0-9_]*$")
      message(FATAL_ERROR "experiment file ${src}: the name must be lower case letters, digits and _")
    endif()
    add_executable(${name} ${src})
    target_compile_definitions(${name} PRIVATE DFCHAOS_EXPERIMENT_NAME="${name}")
    target_link_libraries(${name} PRIVATE dfchaos::kit dfchaos::dfchaos)
    # Inside the dfchaos build every experiment may also use the certified layer and the sweep
    # engine (static libraries: what an experiment does not use is not linked in), so that a new
    # experiment is one file whatever it calls.
    foreach(extra IN ITEMS dfchaos_certified dfchaos_certify dfchaos_sweep)
      if(TARGET ${extra})
        target_link_libraries(${name} PRIVATE ${extra})
      endif()
    endforeach()
    set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIR})
    add_test(NAME smoke_${name} COMMAND ${name} --fast --out ${ARG_SMOKE_OUT})
    set_tests_properties(smoke_${name} PROPERTIES TIMEOUT 300 LABELS smoke FIXTURES_SETUP dfchaos_smoke_data)
    set_property(GLOBAL APPEND PROPERTY DFCHAOS_EXPERIMENTS ${name})
  endforeach()
endfunction()
