# A consumer without CMake: the library-only install (configure, `cmake --install` to a scratch
# prefix, nothing built), then `pkg-config --cflags sphtroch` (PKG_CONFIG_PATH = the prefix's
# share/pkgconfig; the .pc file finds its prefix from its own place) and a plain compiler call on
# main_eigen.cpp, which must build and print Fig. 3's one node. Called by ctest:
#   cmake -DSOURCE_DIR=<sphtroch source> -DWORK_DIR=<scratch> -DCXX=<c++ compiler> -P run_pkg_config.cmake
foreach(var SOURCE_DIR WORK_DIR CXX)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_pkg_config.cmake: -D${var}=... is required")
  endif()
endforeach()
set(work "${WORK_DIR}/pkg-config")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}")

function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pkg-config consumer: ${name} failed (${rc})\n${out}\n${err}")
  endif()
  set(step_out "${out}" PARENT_SCOPE)
endfunction()

step("configure" ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${work}/build-lib" -DSPHTROCH_BUILD_CLI=OFF
     -DSPHTROCH_BUILD_TESTS=OFF -DSPHTROCH_BUILD_PYTHON=OFF)
step("install" ${CMAKE_COMMAND} --install "${work}/build-lib" --prefix "${work}/prefix")
set(ENV{PKG_CONFIG_PATH} "${work}/prefix/share/pkgconfig")
step("pkg-config" pkg-config --cflags sphtroch)
string(STRIP "${step_out}" cflags)
separate_arguments(cflags UNIX_COMMAND "${cflags}")
if(NOT cflags MATCHES "prefix/share/pkgconfig/\\.\\./\\.\\./include")
  message(FATAL_ERROR "pkg-config consumer: --cflags ${cflags} does not name the installed include folder")
endif()
step("compile" ${CXX} -std=c++17 ${cflags} "${SOURCE_DIR}/tests/consumer/main_eigen.cpp" -o "${work}/consumer")
step("run" "${work}/consumer")
if(NOT step_out MATCHES "1 node\\(s\\), 0 cusp\\(s\\)")
  message(FATAL_ERROR "pkg-config consumer: printed ${step_out}, not Fig. 3's one node and no cusp")
endif()
message(STATUS "pkg-config consumer: ${step_out}")
