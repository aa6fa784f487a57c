# cmake -DINPUT=FILE -DOUTPUT=FILE.cpp -DFUNCTION=NAME -P embed_text.cmake
# Writes a C++ source defining std::string_view iga::NAME() that returns FILE's text (a raw string
# literal), rewritten only when the text changed. Used for docs/configuration.md (app/starter_configs).
file(READ "${INPUT}" IGA_EMBEDDED_TEXT)
string(FIND "${IGA_EMBEDDED_TEXT}" ")igadoc\"" IGA_DELIMITER_AT)
if(NOT IGA_DELIMITER_AT EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )igadoc\" of ${OUTPUT}")
endif()
set(IGA_EMBEDDED_FUNCTION "${FUNCTION}")
get_filename_component(IGA_EMBEDDED_NAME "${INPUT}" NAME)
configure_file(${CMAKE_CURRENT_LIST_DIR}/embedded_text.cpp.in "${OUTPUT}" @ONLY)
