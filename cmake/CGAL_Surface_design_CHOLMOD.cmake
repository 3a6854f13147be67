# Finds SuiteSparse CHOLMOD (Debian: libsuitesparse-dev) and defines the imported target
# CGAL_Surface_design::CHOLMOD (include directory, library, and the compile definition
# CGAL_SURFACE_DESIGN_HAS_CHOLMOD). Defines nothing when CHOLMOD is absent.
# Debian's SuiteSparse 5.12 ships neither a CMake package nor a pkg-config file, hence the search.
if(NOT TARGET CGAL_Surface_design::CHOLMOD)
  find_path(CGAL_SURFACE_DESIGN_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(CGAL_SURFACE_DESIGN_CHOLMOD_LIBRARY cholmod)
  if(CGAL_SURFACE_DESIGN_CHOLMOD_INCLUDE_DIR AND CGAL_SURFACE_DESIGN_CHOLMOD_LIBRARY)
    add_library(CGAL_Surface_design::CHOLMOD INTERFACE IMPORTED)
    set_target_properties(CGAL_Surface_design::CHOLMOD PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${CGAL_SURFACE_DESIGN_CHOLMOD_INCLUDE_DIR}"
      INTERFACE_LINK_LIBRARIES "${CGAL_SURFACE_DESIGN_CHOLMOD_LIBRARY}"
      INTERFACE_COMPILE_DEFINITIONS "CGAL_SURFACE_DESIGN_HAS_CHOLMOD")
  endif()
endif()
