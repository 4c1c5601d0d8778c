# One golden test: runs the command on the first line of CASE (an .out file) and
# compares what ncc prints with the rest of the file.
#   cmake -DNCC=path/to/ncc -DCASE=path/to/case.out [-DUPDATE=1] -P run_golden.cmake
# The first line reads "$ ncc ARGS"; ARGS run in the directory of CASE. The expected
# text is stdout, then "--- stderr" and stderr if there is any, then "--- exit N".
# UPDATE=1 rewrites the file instead (review every changed line before committing).
file(STRINGS "${CASE}" lines LIMIT_COUNT 1)
list(GET lines 0 command_line)
if(NOT command_line MATCHES "^\\$ ncc (.*)$")
  message(FATAL_ERROR "${CASE}: the first line must be '$ ncc ARGS'")
endif()
separate_arguments(args UNIX_COMMAND "${CMAKE_MATCH_1}")
get_filename_component(dir "${CASE}" DIRECTORY)
execute_process(COMMAND "${NCC}" ${args}
                WORKING_DIRECTORY "${dir}"
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
set(actual "${command_line}\n${out}")
if(NOT err STREQUAL "")
  string(APPEND actual "--- stderr\n${err}")
endif()
string(APPEND actual "--- exit ${rc}\n")
if(UPDATE)
  file(WRITE "${CASE}" "${actual}")
  return()
endif()
file(READ "${CASE}" expected)
if(NOT actual STREQUAL expected)
  file(WRITE "${CASE}.actual" "${actual}")
  execute_process(COMMAND diff -u "${CASE}" "${CASE}.actual")
  message(FATAL_ERROR "${CASE}: output differs (actual output in ${CASE}.actual)")
endif()
file(REMOVE "${CASE}.actual")
