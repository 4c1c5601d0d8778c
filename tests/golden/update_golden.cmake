# Rewrites every golden case under DIR from the current ncc (see run_golden.cmake).
file(GLOB_RECURSE cases "${DIR}/*.out")
foreach(case IN LISTS cases)
  execute_process(COMMAND ${CMAKE_COMMAND} -DNCC=${NCC} -DPYTHON=${PYTHON} -DCASE=${case} -DUPDATE=1
                  -P ${CMAKE_CURRENT_LIST_DIR}/run_golden.cmake)
endforeach()
