# The WebAssembly build (the wasm preset, Emscripten's em++): the core, portable (no Embree, no TBB), the
# lesson layer's step keys, and the web module, one JavaScript file with the WebAssembly embedded (radiosity-core.js), which the web edition's
# pages load from file:// or any static server. Nothing else of the project is built here.
set(RT_PORTABLE ON CACHE BOOL "" FORCE)
set(RT_CHECKS ON)
# The core reports bad input by exceptions (InputError): Emscripten catches them only when asked.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)
add_library(rt_warnings INTERFACE)
target_compile_options(rt_warnings INTERFACE -Wall -Wextra -Wno-unused-parameter -Wno-missing-field-initializers)
if(RT_WARNINGS_AS_ERRORS)
  target_compile_options(rt_warnings INTERFACE -Werror)
endif()

# The header-only libraries the core uses, from the system's include folder: only their own folders are put on
# the include path (the system folder itself holds the host's C library, which must not shadow Emscripten's).
set(rt_headers ${CMAKE_BINARY_DIR}/system-headers)
file(MAKE_DIRECTORY ${rt_headers})
foreach(entry "Eigen=/usr/include/eigen3/Eigen" "nlohmann=/usr/include/nlohmann" "boost=/usr/include/boost")
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 target)
  if(NOT EXISTS ${target})
    message(FATAL_ERROR "${target} not found: install the header packages (./install-deps.sh)")
  endif()
  file(CREATE_LINK ${target} ${rt_headers}/${name} SYMBOLIC)
endforeach()
foreach(name Eigen3::Eigen nlohmann_json::nlohmann_json Boost::headers Threads::Threads)
  add_library(${name} INTERFACE IMPORTED)
endforeach()
set_target_properties(Eigen3::Eigen nlohmann_json::nlohmann_json Boost::headers PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES ${rt_headers} INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${rt_headers})

add_subdirectory(src/core)
# The lesson layer's table of step keys and its mapping to the pipeline, so that a page's widgets and what a
# change computes come from the same declared table as the app's (src/web/web_step.h). The table's choices
# name the homework topics, hence rt_homework (core only). The rest of the lesson layer (Markdown, the runner)
# stays native.
add_subdirectory(src/homework)
include(${PROJECT_SOURCE_DIR}/src/lesson/parser_sources.cmake)
add_library(rt_lesson STATIC ${RT_LESSON_PARSER_SOURCES} ${PROJECT_SOURCE_DIR}/src/lesson/step_settings.cpp)
target_link_libraries(rt_lesson PUBLIC rt_core rt_homework PRIVATE rt_warnings nlohmann_json::nlohmann_json)
add_subdirectory(src/web)
