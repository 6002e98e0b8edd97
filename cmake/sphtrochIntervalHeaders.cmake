# An imported target for the headers the interval component needs: CGAL's Interval_nt (header-only,
# no GMP or MPFR: CGAL's own CGAL::CGAL target links both) and the Boost headers it includes.
# sphtroch_deps::cgal_headers, when both are found. Included by the build (CMakeLists.txt) and by
# the installed package (COMPONENTS interval).
find_path(SPHTROCH_CGAL_INCLUDE_DIR CGAL/Interval_nt.h)
find_path(SPHTROCH_BOOST_INCLUDE_DIR boost/config.hpp)
if(SPHTROCH_CGAL_INCLUDE_DIR AND SPHTROCH_BOOST_INCLUDE_DIR AND NOT TARGET sphtroch_deps::cgal_headers)
  add_library(sphtroch_deps::cgal_headers INTERFACE IMPORTED)
  set_target_properties(sphtroch_deps::cgal_headers PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SPHTROCH_CGAL_INCLUDE_DIR};${SPHTROCH_BOOST_INCLUDE_DIR}")
endif()
