# Build-time kernel generation: pdgen (generator library + every laws/*.cpp) writes
# one kernel header/source pair per law file, plus the law table, into the build
# tree. pdgen rewrites a file only when its content changes, so editing one law
# recompiles only that law's kernels.
file(GLOB PD_LAW_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/laws/*.cpp)
add_executable(pdgen ${CMAKE_SOURCE_DIR}/generator/pdgen_main.cpp ${PD_LAW_FILES})
target_link_libraries(pdgen PRIVATE pd_generator)
target_compile_options(pdgen PRIVATE ${PD_WARNINGS})

set(PD_GEN_DIR ${CMAKE_BINARY_DIR}/generated)
set(PD_GEN_FILES ${PD_GEN_DIR}/law_table.cpp)
foreach(law_file ${PD_LAW_FILES})
  get_filename_component(stem ${law_file} NAME_WE)
  list(APPEND PD_GEN_FILES ${PD_GEN_DIR}/${stem}.cpp ${PD_GEN_DIR}/${stem}.hpp)
endforeach()

add_custom_command(
  OUTPUT ${PD_GEN_DIR}/pdgen.stamp
  BYPRODUCTS ${PD_GEN_FILES}
  COMMAND pdgen --out ${PD_GEN_DIR}
  COMMAND ${CMAKE_COMMAND} -E touch ${PD_GEN_DIR}/pdgen.stamp
  DEPENDS pdgen
  COMMENT "Generating law kernels (pdgen)"
  VERBATIM)
add_custom_target(generate_kernels DEPENDS ${PD_GEN_DIR}/pdgen.stamp)

set(PD_GEN_SOURCES ${PD_GEN_FILES})
list(FILTER PD_GEN_SOURCES INCLUDE REGEX "\\.cpp$")
add_library(pd_kernels STATIC ${PD_GEN_SOURCES})
add_dependencies(pd_kernels generate_kernels)
target_include_directories(pd_kernels PUBLIC $<BUILD_INTERFACE:${CMAKE_SOURCE_DIR}/runtime> $<BUILD_INTERFACE:${PD_GEN_DIR}>
                                              $<INSTALL_INTERFACE:include/pdgen>)
# Generated code must compile cleanly: warnings are errors here.
target_compile_options(pd_kernels PRIVATE -Wall -Wextra -Werror)
# The bond loops carry `#pragma omp simd reduction(...)` (generator/emit/emitter.cpp):
# -fopenmp-simd honours it without the OpenMP runtime. -fno-math-errno: a kernel's sqrt
# need not set errno (nothing reads it), so it is one instruction the loop may vectorise;
# IEEE results are unchanged (this is not -ffast-math).
set(PD_KERNEL_FLAGS -fopenmp-simd -fno-math-errno)
target_compile_options(pd_kernels PRIVATE ${PD_KERNEL_FLAGS})
# clang reports every `omp simd` loop it leaves scalar (-Wpass-failed), which -Werror would
# turn into a build failure: the pragma is a permission to vectorise, not a requirement
# (a loop that stays scalar computes the same sums), so that report is not an error.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  target_compile_options(pd_kernels PRIVATE -Wno-pass-failed)
endif()

# `cmake --build build --target refresh_generated` copies the build's kernels into
# the committed snapshot generated/, removing snapshot files no longer emitted.
add_custom_target(refresh_generated
  COMMAND ${CMAKE_COMMAND} -DFROM=${PD_GEN_DIR} -DTO=${CMAKE_SOURCE_DIR}/generated
          -P ${CMAKE_SOURCE_DIR}/cmake/SyncGenerated.cmake
  DEPENDS generate_kernels
  COMMENT "Refreshing the committed snapshot generated/")
