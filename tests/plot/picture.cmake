# The README's picture is what ncc plot draws today: the plot of examples/iso/pocket.nc
# equals docs/images/pocket-iso.svg (regenerate it with the command below on a change).
execute_process(COMMAND "${NCC}" plot --dialect iso iso/pocket.nc --view iso --size 800 -o -
                WORKING_DIRECTORY "${ROOT}/examples" OUTPUT_VARIABLE drawn RESULT_VARIABLE rc)
file(READ "${ROOT}/docs/images/pocket-iso.svg" committed)
if(NOT rc EQUAL 0 OR NOT drawn STREQUAL committed)
  message(FATAL_ERROR "docs/images/pocket-iso.svg is not what 'ncc plot --dialect iso iso/pocket.nc --view iso --size 800' draws in examples/ (exit ${rc})")
endif()
