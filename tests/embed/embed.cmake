# examples/embed as an integrator builds it: ncc installed into a prefix, the example
# configured and built against the package there (find_package(ncc)), and run; its
# output (stdout, then stderr) must equal EXPECTED. With -DUPDATE=1 it writes it.
#   cmake -DBUILD=<ncc build> -DSOURCE=<repo> -DWORK=<scratch> -DCXX=<compiler> -DEXPECTED=<.out> -P embed.cmake
function(check what)
  execute_process(${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK}")
check("cmake --install" COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix")
check("configuring examples/embed" COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}/examples/embed" -B "${WORK}/build" -G Ninja
      "-DCMAKE_CXX_COMPILER=${CXX}" "-DCMAKE_PREFIX_PATH=${WORK}/prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
      -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
check("building examples/embed" COMMAND "${CMAKE_COMMAND}" --build "${WORK}/build")

# The part as it is, then with a floor the drilling cycle goes below: the host refuses
# the move and the run stops with an error at the block.
set(actual "")
foreach(floor "" "-5")
  execute_process(COMMAND "${WORK}/build/embed" part.nc ${floor} WORKING_DIRECTORY "${SOURCE}/examples/embed"
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(APPEND actual "$ embed part.nc ${floor}\n${out}--- stderr\n${err}--- exit ${status}\n")
endforeach()

if(UPDATE)
  file(WRITE "${EXPECTED}" "${actual}")
  return()
endif()
file(READ "${EXPECTED}" expected)
if(NOT actual STREQUAL expected)
  file(WRITE "${WORK}/actual.out" "${actual}")
  execute_process(COMMAND diff -u "${EXPECTED}" "${WORK}/actual.out")
  message(FATAL_ERROR "examples/embed's output differs from ${EXPECTED}")
endif()
