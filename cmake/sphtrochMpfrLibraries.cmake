# Imported targets for MPFR and GMP (no CMake package of their own on Debian 12):
# sphtroch_deps::mpfr and sphtroch_deps::gmp, with their headers and libraries, when both are
# found. Included by the build (CMakeLists.txt) and by the installed package (COMPONENTS mpfr).
find_path(SPHTROCH_MPFR_INCLUDE_DIR mpfr.h)
find_path(SPHTROCH_GMP_INCLUDE_DIR gmp.h)
find_library(SPHTROCH_MPFR_LIBRARY mpfr)
find_library(SPHTROCH_GMP_LIBRARY gmp)
foreach(_sphtroch_lib mpfr gmp)
  string(TOUPPER ${_sphtroch_lib} _sphtroch_upper)
  if(SPHTROCH_${_sphtroch_upper}_LIBRARY AND SPHTROCH_${_sphtroch_upper}_INCLUDE_DIR
     AND NOT TARGET sphtroch_deps::${_sphtroch_lib})
    add_library(sphtroch_deps::${_sphtroch_lib} UNKNOWN IMPORTED)
    set_target_properties(sphtroch_deps::${_sphtroch_lib} PROPERTIES
      IMPORTED_LOCATION "${SPHTROCH_${_sphtroch_upper}_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${SPHTROCH_${_sphtroch_upper}_INCLUDE_DIR}")
  endif()
endforeach()
if(TARGET sphtroch_deps::mpfr AND TARGET sphtroch_deps::gmp)
  set_property(TARGET sphtroch_deps::mpfr APPEND PROPERTY INTERFACE_LINK_LIBRARIES sphtroch_deps::gmp)
endif()
