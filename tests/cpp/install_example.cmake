# Run as `cmake -P`: installs the build tree BUILD_DIR into a scratch prefix, then
# configures, builds and runs the standalone project EXAMPLE_SOURCE_DIR against
# that prefix only, the way a downstream project would use the package.
foreach(var BUILD_DIR EXAMPLE_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_example.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

set(prefix "${WORK_DIR}/prefix")
set(example_build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")

function(run)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "running: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed with ${rc}: ${ARGN}")
  endif()
endfunction()

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" --config "${BUILD_TYPE}")

# Some system package configs still declare cmake_minimum_required < 3.5, which
# CMake 4 refuses without this.
set(configure_args -S "${EXAMPLE_SOURCE_DIR}" -B "${example_build}"
  "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}" -DCMAKE_POLICY_VERSION_MINIMUM=3.5)
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
if(MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif()
if(CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
run("${CMAKE_COMMAND}" ${configure_args})

# The package must come from the scratch prefix, not from the source or build tree.
file(STRINGS "${example_build}/CMakeCache.txt" fgdwa_dir_line REGEX "^fgdwa_DIR:")
string(REGEX REPLACE "^fgdwa_DIR:[A-Z]+=" "" fgdwa_dir "${fgdwa_dir_line}")
file(REAL_PATH "${prefix}" real_prefix)
file(REAL_PATH "${fgdwa_dir}" real_fgdwa_dir)
string(FIND "${real_fgdwa_dir}" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "fgdwa was found at '${fgdwa_dir}', outside the install prefix '${prefix}'")
endif()

run("${CMAKE_COMMAND}" --build "${example_build}" --config "${BUILD_TYPE}")
run("${example_build}/fgdwa_example")
run("${example_build}/fgdwa_navigate")
