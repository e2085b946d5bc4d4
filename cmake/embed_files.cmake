# raystep_embed_files: embeds data files into a library with the assembler's .incbin, and gives
# them a lookup by file name (so the tools work from any folder without the source tree).
#
#   raystep_embed_files(TARGET
#     HEADER "raystep/scene/resources.h"   # declares the two functions below (namespace raystep)
#     LOOKUP embeddedFile                  # std::optional<std::string_view> LOOKUP(name)
#     NAMES embeddedFileNames              # std::vector<std::string> NAMES(), sorted
#     FILES a.json b.obj ...              # each found by its file name ("a.json")
#     [BASE dir])                          # or by its path under dir ("it/core.json")
#
# The table is generated from embedded_files.cpp.in; its symbols carry TARGET's name, so two
# libraries' tables can be linked into one program.
set(RAYSTEP_EMBED_TEMPLATE "${CMAKE_CURRENT_LIST_DIR}/embedded_files.cpp.in")

function(raystep_embed_files target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "HEADER;LOOKUP;NAMES;BASE" "FILES")
  set(_files ${ARG_FILES})
  list(SORT _files)
  set(EMBED_TARGET "${target}")
  set(EMBED_HEADER "${ARG_HEADER}")
  set(EMBED_LOOKUP "${ARG_LOOKUP}")
  set(EMBED_NAMES "${ARG_NAMES}")
  set(EMBED_INCBIN_LINES "")
  set(EMBED_TABLE_LINES "")
  set(_index 0)
  foreach(_file IN LISTS _files)
    if(ARG_BASE)
      file(RELATIVE_PATH _name "${ARG_BASE}" "${_file}")
    else()
      get_filename_component(_name "${_file}" NAME)
    endif()
    set(_symbol "${target}_embedded_${_index}")
    string(APPEND EMBED_INCBIN_LINES "RAYSTEP_INCBIN(${_symbol}, \"${_file}\")\n")
    string(APPEND EMBED_TABLE_LINES "    {\"${_name}\", ${_symbol}_begin, ${_symbol}_end},\n")
    math(EXPR _index "${_index} + 1")
  endforeach()
  set(_out "${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp")
  configure_file("${RAYSTEP_EMBED_TEMPLATE}" "${_out}" @ONLY)
  set_source_files_properties("${_out}" PROPERTIES OBJECT_DEPENDS "${_files}")
  target_sources(${target} PRIVATE "${_out}")
endfunction()
