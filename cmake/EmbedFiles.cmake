# ncc_embed_files(<output.cpp> <namespace> <file>...)
#
# Compiles data files (dialect tables, the default profile) into the binary, so ncc
# runs without an installed data directory. Each file becomes an entry
# {"relative/path", "contents"} in `embedded_files()`.
function(ncc_embed_files output namespace)
  set(files ${ARGN})
  add_custom_command(
    OUTPUT "${output}"
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${namespace}
            -DBASE=${CMAKE_CURRENT_SOURCE_DIR} "-DFILES=${files}"
            -P "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    DEPENDS ${files} "${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
    COMMENT "Embedding ${namespace} data files"
    VERBATIM)
endfunction()
