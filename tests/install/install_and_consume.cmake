# Run by ctest (label install): installs the gsdot3 build's `fixed` package into a fresh prefix,
# then configures, builds and runs tests/install/consumer against that installed copy only.
# Inputs: -DBUILD_DIR= -DCONSUMER_SOURCE= -DWORK_DIR= -DGENERATOR= -DCXX_COMPILER=
foreach(var BUILD_DIR CONSUMER_SOURCE WORK_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_and_consume.cmake: -D${var}= is required")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")

function(step name)
  message(STATUS "[install test] ${name}: ${ARGN}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(step_rc "${rc}" PARENT_SCOPE)
  set(step_out "${out}" PARENT_SCOPE)
endfunction()

function(must_succeed name)
  step(${name} ${ARGN})
  if(NOT step_rc EQUAL 0)
    message(FATAL_ERROR "[install test] ${name} failed (${step_rc}):\n${step_out}")
  endif()
  set(step_out "${step_out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")

# (a) Component-less install: the gsdot3 project installs only the fixed package.
must_succeed(install ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
list(SORT installed)
message(STATUS "[install test] installed: ${installed}")
foreach(expected include/fixed/fixed.hpp fixedConfig.cmake fixedConfigVersion.cmake fixedTargets.cmake)
  if(NOT installed MATCHES "(^|;)[^;]*${expected}(;|$)")
    message(FATAL_ERROR "[install test] ${expected} was not installed")
  endif()
endforeach()

# (b) Configure the consumer against the prefix only (no package registry, no system fixed).
set(configure_args -G "${GENERATOR}" -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
must_succeed(configure ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build" ${configure_args})
file(STRINGS "${WORK_DIR}/build/CMakeCache.txt" fixed_dir REGEX "^fixed_DIR:")
string(FIND "${fixed_dir}" "${prefix}/" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "[install test] the consumer found fixed outside the install prefix: ${fixed_dir}")
endif()

# The version file must reject an incompatible request (SameMajorVersion: 1.0 is not 0.x); CMake
# then lists the installed config with the version its version file reports.
step(configure-version-1.0 ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE}" -B "${WORK_DIR}/build-v1" ${configure_args}
     -DFIXED_VERSION=1.0)
if(step_rc EQUAL 0 OR NOT step_out MATCHES "version: 0\\.1\\.0")
  message(FATAL_ERROR "[install test] find_package(fixed 1.0) should fail on the version file:\n${step_out}")
endif()

# (c) Build and (d) run.
must_succeed(build ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
must_succeed(run "${WORK_DIR}/build/consumer")
message(STATUS "[install test] consumer output: ${step_out}")
if(NOT step_out MATCHES "fixed consumer OK")
  message(FATAL_ERROR "[install test] unexpected consumer output")
endif()
