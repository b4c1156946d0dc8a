# The lesson parser and the table of step keys it reads values through: the part of rt_lesson that builds
# without md4c or the step runner. The fuzzers (tests/fuzz) and the WebAssembly build (cmake/wasm.cmake) compile
# these alone, so a file split out of the parser is added here once and reaches both.
set(RT_LESSON_PARSER_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/lesson.cpp
  ${CMAKE_CURRENT_LIST_DIR}/lesson_parser.cpp
  ${CMAKE_CURRENT_LIST_DIR}/step_block.cpp
  ${CMAKE_CURRENT_LIST_DIR}/placeholders.cpp
  ${CMAKE_CURRENT_LIST_DIR}/value_parsing.cpp
  ${CMAKE_CURRENT_LIST_DIR}/step_keys.cpp
  ${CMAKE_CURRENT_LIST_DIR}/step_keys_chapters.cpp)
