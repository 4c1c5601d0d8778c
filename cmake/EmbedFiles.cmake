# ncc_embed_files(<output.cpp> <namespace> [BASE <dir>] <file>...)
#
# Compiles data files (dialect tables, the default profile, ncc view's page) into the
# binary, so ncc runs without an installed data directory. Each file, named relative
# to BASE (default: the calling directory), becomes an entry {"relative/path",
# "contents"} in `embedded_files()`.
function(ncc_embed_files output namespace)
  cmake_parse_arguments(PARSE_ARGV 2 EMBED "" "BASE" "")
  set(base "${CMAKE_CURRENT_SOURCE_DIR}")
  if(EMBED_BASE)
    set(base "${EMBED_BASE}")
  endif()
  set(files ${EMBED_UNPARSED_ARGUMENTS})
  list(TRANSFORM files PREPEND "${base}/" OUTPUT_VARIABLE paths)
  add_custom_command(
    OUTPUT "${output}"
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${namespace}
            -DBASE=${base} "-DFILES=${files}"
            -P "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    DEPENDS ${paths} "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    WORKING_DIRECTORY "${base}"
    COMMENT "Embedding ${namespace} data files"
    VERBATIM)
  # Data, not code: a file's contents are one string literal, longer than -Wpedantic
  # (-Woverlength-strings) likes; every compiler ncc builds with takes them.
  set_source_files_properties("${output}" PROPERTIES COMPILE_OPTIONS -Wno-overlength-strings)
endfunction()
