# The README's from-scratch library install, as a new user runs it (docs/library.md):
#   cmake -S . -B build-lib -DSPHTROCH_BUILD_CLI=OFF -DSPHTROCH_BUILD_TESTS=OFF
#   cmake --install build-lib --prefix PREFIX
# with nothing built in between. Called by ctest:
#   cmake -DSOURCE_DIR=<sphtroch source> -DWORK_DIR=<scratch> -DPYBIND11=present|absent -P run_install.cmake
# present: pybind11 is found (the Python module is then switched on by default: the configure must
#          say so, else the case this test exists for is not tested) and the install must still exit
#          0, installing the headers and the package files but no half Python package.
# absent:  pybind11 hidden (CMAKE_DISABLE_FIND_PACKAGE_pybind11); the same install must exit 0.
foreach(var SOURCE_DIR WORK_DIR PYBIND11)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_install.cmake: -D${var}=... is required")
  endif()
endforeach()
set(work "${WORK_DIR}/install-pybind11-${PYBIND11}")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}")
set(extra "")
if(PYBIND11 STREQUAL "absent")
  set(extra -DCMAKE_DISABLE_FIND_PACKAGE_pybind11=TRUE)
endif()

function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install (pybind11 ${PYBIND11}): ${name} failed (${rc})\n${out}\n${err}")
  endif()
  message(STATUS "install (pybind11 ${PYBIND11}): ${name} ok")
endfunction()

step("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${work}/build-lib" -DSPHTROCH_BUILD_CLI=OFF
     -DSPHTROCH_BUILD_TESTS=OFF ${extra})
file(STRINGS "${work}/build-lib/CMakeCache.txt" python_on REGEX "^SPHTROCH_BUILD_PYTHON:BOOL=ON$")
if(PYBIND11 STREQUAL "present" AND NOT python_on)
  message(FATAL_ERROR "install (pybind11 present): the configure did not switch the Python module on; "
                      "is pybind11-dev installed? (this test needs it)")
endif()
if(PYBIND11 STREQUAL "absent" AND python_on)
  message(FATAL_ERROR "install (pybind11 absent): the Python module is on without pybind11")
endif()
step("install" ${CMAKE_COMMAND} --install "${work}/build-lib" --prefix "${work}/prefix")
foreach(f include/sphtroch/sphtroch.hpp include/sphtroch/core/gear_train.hpp share/cmake/sphtroch/sphtrochConfig.cmake
          share/cmake/sphtroch/sphtrochMpfrLibraries.cmake)
  if(NOT EXISTS "${work}/prefix/${f}")
    message(FATAL_ERROR "install (pybind11 ${PYBIND11}): ${f} not installed")
  endif()
endforeach()
file(GLOB_RECURSE python_files "${work}/prefix/lib/*sphtroch*")
if(python_files)
  message(FATAL_ERROR "install (pybind11 ${PYBIND11}): Python files installed without the module: ${python_files}")
endif()
