# The CMake package (cmake/PdgenInstall.cmake) used as another project would use it:
# install the build into PREFIX, configure and build consumer/ against it with
# find_package(pdgen), run the installed pd and the consumer on SCENE: both must give
# the same probe value. Any failing step fails the test.
# Usage: cmake -DBUILD_DIR=... -DPREFIX=... -DWORK=... -DSOURCE=... -DSCENE=... -DCOMPILER=... -P check_package.cmake
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message("${out}")
endfunction()
file(REMOVE_RECURSE ${PREFIX} ${WORK})
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})
foreach(f bin/pd include/pdgen/run/simulation.hpp include/pdgen/kernel_abi.hpp include/pdgen/silling.hpp share/pdgen/plot_study.py
          lib/cmake/pdgen/pdgenConfig.cmake)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${PREFIX}/${f}")
  endif()
endforeach()
step(${CMAKE_COMMAND} -S ${SOURCE} -B ${WORK} -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_CXX_COMPILER=${COMPILER}
     -DCMAKE_BUILD_TYPE=Release)
step(${CMAKE_COMMAND} --build ${WORK})
# The installed pd solves the scene; the consumer, through the library, gets the same probe.
step(${PREFIX}/bin/pd run ${SCENE} --out ${WORK}/out)
step(${WORK}/consumer ${SCENE} ${WORK}/out/summary.json)
