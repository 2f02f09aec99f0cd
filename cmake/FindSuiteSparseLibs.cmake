# Finds the SuiteSparse pieces the runtime uses (CHOLMOD, UMFPACK) as Debian ships
# them: headers in /usr/include/suitesparse, no CMake config files.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(UMFPACK_LIBRARY umfpack)
find_library(AMD_LIBRARY amd)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparseLibs DEFAULT_MSG
  SUITESPARSE_INCLUDE_DIR CHOLMOD_LIBRARY UMFPACK_LIBRARY AMD_LIBRARY SUITESPARSECONFIG_LIBRARY)
if(SuiteSparseLibs_FOUND AND NOT TARGET SuiteSparse::libs)
  add_library(SuiteSparse::libs INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::libs PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SUITESPARSE_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${UMFPACK_LIBRARY};${AMD_LIBRARY};${SUITESPARSECONFIG_LIBRARY}")
endif()
