# Finds the dependencies of CGAL::Quad_remeshing and defines qr_link_dependencies(target).
# Used both by the source tree and by the installed package configuration.
include(CMakeFindDependencyMacro)
find_package(CGAL 5.5 REQUIRED)
find_package(Eigen3 3.3 REQUIRED)
include(CGAL_Eigen3_support)
find_package(GLPK QUIET)
include(CGAL_GLPK_support)
find_package(Boost 1.66 REQUIRED)   # Boost.Graph is header-only

function(qr_link_dependencies target)
  target_link_libraries(${target} INTERFACE CGAL::CGAL CGAL::Eigen3_support)
  if(TARGET CGAL::GLPK_support)
    target_link_libraries(${target} INTERFACE CGAL::GLPK_support)
  endif()
endfunction()
