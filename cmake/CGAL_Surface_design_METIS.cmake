# Finds METIS (Debian: libmetis-dev) and defines the imported target CGAL_Surface_design::METIS
# (include directory, library, and the compile definition CGAL_SURFACE_DESIGN_HAS_METIS), which
# enables Metis_ldlt_solver_traits (Eigen SimplicialLDLT with METIS nested-dissection ordering).
# Defines nothing when METIS is absent, or when it was built with 64-bit indices (Eigen's
# MetisOrdering<int> passes int arrays to METIS_NodeND, so idx_t must be 32 bits).
# Debian's METIS 5.1 ships neither a CMake package nor a pkg-config file, hence the search.
if(NOT TARGET CGAL_Surface_design::METIS)
  find_path(CGAL_SURFACE_DESIGN_METIS_INCLUDE_DIR metis.h PATH_SUFFIXES metis)
  find_library(CGAL_SURFACE_DESIGN_METIS_LIBRARY metis)
  if(CGAL_SURFACE_DESIGN_METIS_INCLUDE_DIR AND CGAL_SURFACE_DESIGN_METIS_LIBRARY)
    file(STRINGS "${CGAL_SURFACE_DESIGN_METIS_INCLUDE_DIR}/metis.h" _cgal_sd_metis_width
         REGEX "^#define[ \t]+IDXTYPEWIDTH[ \t]+[0-9]+")
    string(REGEX MATCH "[0-9]+$" _cgal_sd_metis_width "${_cgal_sd_metis_width}")
    if(_cgal_sd_metis_width STREQUAL "32")
      add_library(CGAL_Surface_design::METIS INTERFACE IMPORTED)
      set_target_properties(CGAL_Surface_design::METIS PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${CGAL_SURFACE_DESIGN_METIS_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${CGAL_SURFACE_DESIGN_METIS_LIBRARY}"
        INTERFACE_COMPILE_DEFINITIONS "CGAL_SURFACE_DESIGN_HAS_METIS")
    else()
      message(STATUS "METIS in ${CGAL_SURFACE_DESIGN_METIS_INCLUDE_DIR} has IDXTYPEWIDTH "
                     "'${_cgal_sd_metis_width}', not 32: not used")
    endif()
    unset(_cgal_sd_metis_width)
  endif()
endif()
