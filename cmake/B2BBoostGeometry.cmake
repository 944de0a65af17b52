# Boost.Geometry's R-tree (header-only, nothing to link; Debian: libboost-dev)
# for a target that compiles the broad phase (src/model/search.cpp) in: the
# library itself, the scaling benchmark and check_box_tree.
#
# b2b_use_boost_rtree(TARGET VERSION_VAR): when the headers are there, gives
# TARGET their include directory and B2B_HAVE_BOOST_GEOMETRY (the R-tree
# backend compiled in), and sets VERSION_VAR in the caller to Boost's
# version; else VERSION_VAR is empty (false in if()).
function(b2b_use_boost_rtree target version_var)
  find_package(Boost 1.66 QUIET)
  if(Boost_FOUND AND EXISTS "${Boost_INCLUDE_DIRS}/boost/geometry/index/rtree.hpp")
    target_include_directories(${target} SYSTEM PRIVATE ${Boost_INCLUDE_DIRS})
    # (Boost 1.74's geometry headers include a deprecated header of their own.)
    target_compile_definitions(${target} PRIVATE B2B_HAVE_BOOST_GEOMETRY
                                                 BOOST_ALLOW_DEPRECATED_HEADERS)
    set(${version_var} "${Boost_VERSION}" PARENT_SCOPE)
  else()
    set(${version_var} "" PARENT_SCOPE)
  endif()
endfunction()
