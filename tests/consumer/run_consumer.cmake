# Builds and runs tests/consumer against sphtroch; called by ctest:
#   cmake -DSOURCE_DIR=<sphtroch source> -DWORK_DIR=<scratch> -DMODE=find_package|add_subdirectory
#         -DPART=eigen|interval|exact|compiled|exact_unlinked -P run_consumer.cmake
# PART eigen configures the consumer with CGAL hidden (CMAKE_DISABLE_FIND_PACKAGE_CGAL): the
# Eigen-only package must not need it; PART interval too: CGAL's headers, not its package (which
# brings GMP and MPFR); PART compiled too (sphtroch::compiled: the consumer parses no CGAL header
# and links libsphtroch_compiled; also built with pkg-config sphtroch-compiled). PART exact_unlinked must FAIL to build, with the #error
# that names sphtroch::exact.
# find_package:     configure + install sphtroch (tests, CLI, benchmarks off) into WORK_DIR/<mode>/prefix,
#                   then configure, build and run the consumer with CMAKE_PREFIX_PATH = that prefix.
# add_subdirectory: the consumer adds SOURCE_DIR as a subdirectory.
# Any failing step is a FATAL_ERROR (the ctest test fails, with the step's output).
foreach(var SOURCE_DIR WORK_DIR MODE PART)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT MODE STREQUAL "find_package" AND NOT MODE STREQUAL "add_subdirectory")
  message(FATAL_ERROR "run_consumer.cmake: MODE must be find_package or add_subdirectory, not '${MODE}'")
endif()

set(work "${WORK_DIR}/${MODE}-${PART}")
set(prefix "${work}/prefix")
set(consumer_build "${work}/consumer-build")
# Fresh every run: an install left from an earlier run must not hide a broken one.
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}")

function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}): ${name} failed (${rc})\n${out}\n${err}")
  endif()
  message(STATUS "consumer (${MODE}): ${name} ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(part_flags -DSPHTROCH_CONSUMER_PART=${PART})
if(PART STREQUAL "eigen" OR PART STREQUAL "interval" OR PART STREQUAL "compiled")
  list(APPEND part_flags -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=TRUE)
endif()
set(build_compiled OFF)  # libsphtroch_compiled: built and installed for PART compiled only
if(PART STREQUAL "compiled")
  set(build_compiled ON)
endif()
set(off -DSPHTROCH_BUILD_TESTS=OFF -DSPHTROCH_BUILD_CLI=OFF -DSPHTROCH_BUILD_BENCH=OFF -DSPHTROCH_BUILD_PYTHON=OFF
    -DSPHTROCH_BUILD_EXPLORER=OFF -DSPHTROCH_BUILD_COMPILED=${build_compiled})
if(MODE STREQUAL "find_package")
  step("configure sphtroch" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${work}/sphtroch-build"
       -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=${prefix} ${off})
  step("install sphtroch" ${CMAKE_COMMAND} --build "${work}/sphtroch-build" --target install)
  if(NOT EXISTS "${prefix}/include/sphtroch/sphtroch.hpp")
    message(FATAL_ERROR "consumer (${MODE}): headers not installed under ${prefix}/include")
  endif()
  step("configure consumer" ${CMAKE_COMMAND} -S "${CMAKE_CURRENT_LIST_DIR}" -B "${consumer_build}"
       -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DSPHTROCH_CONSUMER_MODE=find_package ${part_flags})
  if(PART STREQUAL "eigen")
    # COMPONENTS exact where CGAL cannot be found: a failure that names what is missing.
    execute_process(COMMAND ${CMAKE_COMMAND} -S "${CMAKE_CURRENT_LIST_DIR}" -B "${work}/consumer-exact-no-cgal"
                            -DCMAKE_PREFIX_PATH=${prefix} -DSPHTROCH_CONSUMER_MODE=find_package
                            -DSPHTROCH_CONSUMER_PART=exact -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=TRUE
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES "sphtroch: exact needs CGAL")
      message(FATAL_ERROR "consumer (${MODE}): COMPONENTS exact without CGAL must fail naming CGAL (${rc})\n${out}\n${err}")
    endif()
    message(STATUS "consumer (${MODE}): COMPONENTS exact without CGAL fails naming CGAL")
  endif()
else()
  step("configure consumer" ${CMAKE_COMMAND} -S "${CMAKE_CURRENT_LIST_DIR}" -B "${consumer_build}"
       -DCMAKE_BUILD_TYPE=Release -DSPHTROCH_CONSUMER_MODE=add_subdirectory -DSPHTROCH_SOURCE_DIR=${SOURCE_DIR}
       ${part_flags})
  # As a subproject sphtroch must leave the parent's build type alone and add nothing to the
  # parent's install (SPHTROCH_INSTALL is off under add_subdirectory).
  if(PART STREQUAL "eigen")
    step("configure consumer without a build type" ${CMAKE_COMMAND} -S "${CMAKE_CURRENT_LIST_DIR}"
         -B "${work}/consumer-no-type" -DSPHTROCH_CONSUMER_MODE=add_subdirectory -DSPHTROCH_SOURCE_DIR=${SOURCE_DIR}
         ${part_flags})
    file(STRINGS "${work}/consumer-no-type/CMakeCache.txt" build_type REGEX "^CMAKE_BUILD_TYPE:")
    if(NOT build_type MATCHES "^CMAKE_BUILD_TYPE:[A-Z]+=$")
      message(FATAL_ERROR "consumer (${MODE}): sphtroch set the parent's build type: ${build_type}")
    endif()
    step("install the parent" ${CMAKE_COMMAND} --install "${work}/consumer-no-type" --prefix "${work}/parent-prefix")
    if(EXISTS "${work}/parent-prefix/include/sphtroch")
      message(FATAL_ERROR "consumer (${MODE}): the parent's install installed sphtroch's headers")
    endif()
  endif()
  # As a subproject sphtroch must not build its tests, CLI, benchmarks or Python module by default.
  foreach(dir tests src/cli bench python)
    if(EXISTS "${consumer_build}/sphtroch/${dir}/Makefile" OR EXISTS "${consumer_build}/sphtroch/${dir}/build.ninja")
      message(FATAL_ERROR "consumer (${MODE}): sphtroch built ${dir} as a subproject")
    endif()
  endforeach()
endif()
if(PART STREQUAL "exact_unlinked")
  execute_process(COMMAND ${CMAKE_COMMAND} --build "${consumer_build}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "consumer (${MODE}, ${PART}): built without sphtroch::exact; the #error did not fire")
  endif()
  if(NOT "${out}${err}" MATCHES "self_crossings.hpp needs CGAL, GMP and MPFR: link the CMake target sphtroch::exact")
    message(FATAL_ERROR "consumer (${MODE}, ${PART}): failed, but not with the #error naming sphtroch::exact:\n${out}\n${err}")
  endif()
  message(STATUS "consumer (${MODE}, ${PART}): refused at compile time with the #error naming sphtroch::exact")
  return()
endif()
step("build consumer" ${CMAKE_COMMAND} --build "${consumer_build}")
if(PART STREQUAL "interval")  # CGAL's headers only: no GMP or MPFR on the link line
  file(READ "${consumer_build}/CMakeFiles/consumer.dir/link.txt" link_line)
  if(link_line MATCHES "gmp|mpfr")
    message(FATAL_ERROR "consumer (${MODE}, ${PART}): sphtroch::interval linked GMP or MPFR: ${link_line}")
  endif()
endif()
step("run consumer" "${consumer_build}/consumer")
message(STATUS "consumer (${MODE}): ${step_output}")
if(PART STREQUAL "compiled" AND MODE STREQUAL "find_package")
  # The same example without CMake: pkg-config sphtroch-compiled (in <libdir>/pkgconfig, requiring
  # sphtroch.pc of share/pkgconfig) and one compiler call, run with the library's directory.
  file(GLOB_RECURSE pc_file "${prefix}/sphtroch-compiled.pc")
  if(NOT pc_file)
    message(FATAL_ERROR "consumer (${MODE}, ${PART}): sphtroch-compiled.pc not installed under ${prefix}")
  endif()
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  set(ENV{PKG_CONFIG_PATH} "${pc_dir}:${prefix}/share/pkgconfig")
  step("pkg-config" pkg-config --cflags --libs sphtroch-compiled)
  separate_arguments(flags UNIX_COMMAND "${step_output}")
  step("pkg-config libdir" pkg-config --variable=libdir sphtroch-compiled)
  string(STRIP "${step_output}" libdir)
  find_program(cxx NAMES c++ g++ REQUIRED)
  step("compile with pkg-config" ${cxx} -std=c++17 "${CMAKE_CURRENT_LIST_DIR}/main_compiled.cpp" ${flags}
       -o "${work}/consumer-pkg-config")
  step("run the pkg-config build" ${CMAKE_COMMAND} -E env "LD_LIBRARY_PATH=${libdir}" "${work}/consumer-pkg-config")
  message(STATUS "consumer (pkg-config sphtroch-compiled): ${step_output}")
endif()
