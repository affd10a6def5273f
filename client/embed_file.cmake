# cmake -DIN=<file> -DOUT=<file.cc> -DNAME=<symbol> -P embed_file.cmake
# Writes a .cc defining `const char meshseg::cli::embedded::<NAME>[]` with the
# bytes of IN (as a raw string literal), so the binary needs no files at run
# time.
file(READ "${IN}" content)
set(delimiter "meshseg_embed")
string(FIND "${content}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw string delimiter )${delimiter}\"")
endif()
file(WRITE "${OUT}.tmp"
  "// Generated from ${IN} by client/embed_file.cmake; do not edit.\n"
  "namespace meshseg::cli::embedded {\n"
  "extern const char ${NAME}[];\n"
  "const char ${NAME}[] = R\"${delimiter}(${content})${delimiter}\";\n"
  "}  // namespace meshseg::cli::embedded\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.tmp")
