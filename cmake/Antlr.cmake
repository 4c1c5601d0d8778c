# Debian's 4.9 umbrella header antlr4-runtime.h includes misc/InterpreterDataReader.h,
# which Clang rejects (its InterpreterData() calls dfa::Vocabulary's deleted default
# constructor). Nothing of ours reads interpreter data, so the generated code and ours
# include a copy of the umbrella header without that one line, written here at configure
# time into a directory searched before the runtime's own.
set(NCC_ANTLR4_SHADOW_DIR "${CMAKE_BINARY_DIR}/antlr4-shadow")
file(READ "${ANTLR4_INCLUDE_DIR}/antlr4-runtime.h" umbrella)
string(REPLACE "#include \"misc/InterpreterDataReader.h\"" "" umbrella "${umbrella}")
file(WRITE "${NCC_ANTLR4_SHADOW_DIR}/antlr4-runtime.h.new" "${umbrella}")
file(COPY_FILE "${NCC_ANTLR4_SHADOW_DIR}/antlr4-runtime.h.new" "${NCC_ANTLR4_SHADOW_DIR}/antlr4-runtime.h" ONLY_IF_DIFFERENT)

# ncc_antlr_grammar(<target> LEXER <file.g4> PARSER <file.g4> NAMESPACE <ns>)
#
# Runs the Debian `antlr4` tool (4.7.2) at build time and builds the generated C++
# into its own static library, linked against Debian's 4.9 runtime. Generated code
# is compiled without our warning flags: it is not ours to fix.
function(ncc_antlr_grammar target)
  cmake_parse_arguments(G "" "LEXER;PARSER;NAMESPACE" "" ${ARGN})
  set(out "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  get_filename_component(lexer_name "${G_LEXER}" NAME_WE)
  get_filename_component(parser_name "${G_PARSER}" NAME_WE)
  set(generated
      "${out}/${lexer_name}.cpp" "${out}/${lexer_name}.h"
      "${out}/${parser_name}.cpp" "${out}/${parser_name}.h"
      "${out}/${parser_name}Visitor.cpp" "${out}/${parser_name}Visitor.h"
      "${out}/${parser_name}BaseVisitor.cpp" "${out}/${parser_name}BaseVisitor.h")
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${ANTLR4_TOOL} -Dlanguage=Cpp -no-listener -visitor -package ${G_NAMESPACE}
            -Xexact-output-dir -o "${out}" "${G_LEXER}" "${G_PARSER}"
    DEPENDS "${G_LEXER}" "${G_PARSER}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
    COMMENT "ANTLR: generating ${target}"
    VERBATIM)
  add_library(${target} STATIC ${generated})
  target_include_directories(${target} SYSTEM PUBLIC "${NCC_ANTLR4_SHADOW_DIR}" "${out}" ${ANTLR4_INCLUDE_DIR})
  target_link_libraries(${target} PUBLIC antlr4_shared)
  # The 4.7.2 generator writes u8"" literals, which are char8_t in C++20.
  set_target_properties(${target} PROPERTIES CXX_STANDARD 17)
  target_compile_options(${target} PRIVATE -w)
endfunction()
