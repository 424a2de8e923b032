# Consumer test driver:  cmake -DMODE=... -D... -P run.cmake
#   MODE             find_package | add_subdirectory
#   CTGA_SOURCE_DIR  ctga checkout
#   CTGA_BINARY_DIR  configured ctga build tree (find_package mode: installed from)
#   WORK_DIR         scratch dir (wiped)
#   CONFIG           build configuration (may be empty)
#   GENERATOR, MAKE_PROGRAM, CXX_COMPILER, BOOST_DIR   optional, forwarded
cmake_minimum_required(VERSION 3.21)

foreach(_v MODE CTGA_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${_v} OR "${${_v}}" STREQUAL "")
    message(FATAL_ERROR "run.cmake: -D${_v}=... is required")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE out)
  message("---- ${what}\n${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "run.cmake (${MODE}): ${what} failed (${rc})")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

set(consumer_src "${CMAKE_CURRENT_LIST_DIR}")
set(build "${WORK_DIR}/build")
set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(config_args)
if(NOT "${CONFIG}" STREQUAL "")
  set(config_args --config "${CONFIG}")
endif()

set(configure_args -S "${consumer_src}" -B "${build}" -DCTGA_CONSUMER_MODE=${MODE}
  "-DCTGA_CONSUMER_URDF=${CTGA_SOURCE_DIR}/tests/data/legged.urdf"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
if(BOOST_DIR)
  list(APPEND configure_args "-DBoost_DIR=${BOOST_DIR}")
endif()
# No build type (no optimisation, no debug information): the strict warnings are the front end's,
# and the project's own tests compile optimised under -Wall -Wextra -Werror. (Release doubles the
# consumer's 10 s compile.)
list(APPEND configure_args "-DCMAKE_BUILD_TYPE=")

if(MODE STREQUAL "find_package")
  if(NOT CTGA_BINARY_DIR)
    message(FATAL_ERROR "run.cmake: find_package mode needs -DCTGA_BINARY_DIR=...")
  endif()
  run("install ctga into ${prefix}"
    "${CMAKE_COMMAND}" --install "${CTGA_BINARY_DIR}" --prefix "${prefix}" ${config_args})
  file(GLOB_RECURSE _cfg "${prefix}/*/ctgaConfig.cmake")
  if(NOT _cfg OR NOT IS_DIRECTORY "${prefix}/include/ctga")
    message(FATAL_ERROR "run.cmake: install did not produce ctgaConfig.cmake and include/ctga")
  endif()
  if(NOT EXISTS "${prefix}/bin/ctga-urdf")
    message(FATAL_ERROR "run.cmake: install did not produce bin/ctga-urdf")
  endif()
  run("the installed converter" "${prefix}/bin/ctga-urdf" --help)
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${prefix}")
elseif(MODE STREQUAL "add_subdirectory")
  list(APPEND configure_args "-DCTGA_SOURCE_DIR=${CTGA_SOURCE_DIR}")
else()
  message(FATAL_ERROR "run.cmake: unknown MODE '${MODE}'")
endif()

run("configure consumer" "${CMAKE_COMMAND}" ${configure_args})
if(MODE STREQUAL "find_package")
  # must be the installed package, not the build or source tree
  string(FIND "${run_output}" "from ${prefix}/" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "run.cmake: ctga was not found under ${prefix}")
  endif()
  string(FIND "${run_output}" "converter ${prefix}/bin/ctga-urdf" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "run.cmake: ctga_urdf_header() does not use the installed ${prefix}/bin/ctga-urdf")
  endif()
endif()
run("build consumer" "${CMAKE_COMMAND}" --build "${build}" ${config_args})

set(app "${build}/app")
if(NOT EXISTS "${app}" AND NOT "${CONFIG}" STREQUAL "")
  set(app "${build}/${CONFIG}/app") # multi-config generators
endif()
run("run consumer app" "${app}")
if(NOT run_output MATCHES "(^|\n)ok\n?$")
  message(FATAL_ERROR "run.cmake: app printed '${run_output}', expected 'ok'")
endif()
message("consumer test (${MODE}): passed")
