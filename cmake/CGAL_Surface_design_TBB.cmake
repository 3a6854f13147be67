# Finds Intel oneTBB (Debian: libtbb-dev) through CGAL's own support: find_package(TBB) (CGAL's
# FindTBB module), then CGAL_TBB_support, which defines the target CGAL::TBB_support with the
# compile definition CGAL_LINKED_WITH_TBB. Defines the imported target CGAL_Surface_design::TBB
# (CGAL::TBB_support and the compile definition CGAL_SURFACE_DESIGN_HAS_TBB), which lets the
# library run its per-vertex loops with tbb::parallel_for. Defines nothing when TBB is absent.
if(NOT TARGET CGAL_Surface_design::TBB)
  find_package(TBB QUIET)
  include(CGAL_TBB_support)
  if(TARGET CGAL::TBB_support)
    add_library(CGAL_Surface_design::TBB INTERFACE IMPORTED)
    set_target_properties(CGAL_Surface_design::TBB PROPERTIES
      INTERFACE_LINK_LIBRARIES CGAL::TBB_support
      INTERFACE_COMPILE_DEFINITIONS "CGAL_SURFACE_DESIGN_HAS_TBB")
  endif()
endif()
