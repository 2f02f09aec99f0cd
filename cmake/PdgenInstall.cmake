# `cmake --install build --prefix P` installs pd, the runtime and kernel libraries, their
# headers (include/pdgen/, the runtime's own layout: #include "run/simulation.hpp") and a
# CMake package, so another project can use the runtime as a library:
#   find_package(pdgen REQUIRED)      # CMAKE_PREFIX_PATH=P
#   target_link_libraries(app PRIVATE pdgen::runtime)
# tests/package/ builds such a consumer against an installed tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

if(PD_SANITIZE)
  # A sanitizer build's libraries are instrumented: whoever links them needs the sanitizer
  # runtimes too, so the exported targets carry the link option (the consumer test of the
  # sanitizer build failed on undefined __asan_* symbols without it).
  target_link_options(pd_runtime INTERFACE -fsanitize=address,undefined)
  target_link_options(pd_kernels INTERFACE -fsanitize=address,undefined)
endif()
set_target_properties(pd_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(pd_kernels PROPERTIES EXPORT_NAME kernels)
install(TARGETS pd_runtime ${PD_RUNTIME_LAYERS} pd_kernels EXPORT pdgenTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION include/pdgen)
if(TARGET pd)
  install(TARGETS pd RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
# The runtime's headers (the PETSc backend's only with PETSc: they include petsc.h) and the
# generated kernels' headers; pd study's plot script where pd looks for it (share/pdgen/).
set(pd_header_excludes)
if(NOT PD_WITH_PETSC)
  set(pd_header_excludes PATTERN "petsc" EXCLUDE)
endif()
install(DIRECTORY ${CMAKE_SOURCE_DIR}/runtime/ DESTINATION include/pdgen
        FILES_MATCHING PATTERN "*.hpp" ${pd_header_excludes})
install(DIRECTORY ${PD_GEN_DIR}/ DESTINATION include/pdgen FILES_MATCHING PATTERN "*.hpp")
install(FILES ${CMAKE_SOURCE_DIR}/scripts/plot_study.py DESTINATION ${CMAKE_INSTALL_DATADIR}/pdgen)

set(PDGEN_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/pdgen)
install(EXPORT pdgenTargets NAMESPACE pdgen:: DESTINATION ${PDGEN_CMAKE_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/pdgenConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/pdgenConfig.cmake INSTALL_DESTINATION ${PDGEN_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/pdgenConfigVersion.cmake COMPATIBILITY SameMinorVersion)
# FindSuiteSparseLibs.cmake goes along: the exported runtime names SuiteSparse::libs, which
# Debian's SuiteSparse does not provide as a CMake package.
install(FILES ${CMAKE_BINARY_DIR}/pdgenConfig.cmake ${CMAKE_BINARY_DIR}/pdgenConfigVersion.cmake
              ${CMAKE_SOURCE_DIR}/cmake/FindSuiteSparseLibs.cmake
        DESTINATION ${PDGEN_CMAKE_DIR})
