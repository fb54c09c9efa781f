# maxillo_module(NAME ... LINKS ...): a static library from every .cpp in the module's folder.
# Tests live in tests/<module>/, never beside the sources, so the glob picks up sources only.
function(maxillo_module name)
  cmake_parse_arguments(ARG "" "" "PUBLIC_LINKS;PRIVATE_LINKS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_library(maxillo_${name} STATIC ${sources})
  target_link_libraries(maxillo_${name}
    PUBLIC maxillo_core ${ARG_PUBLIC_LINKS}
    PRIVATE maxillo_warnings maxillo_sanitizers ${ARG_PRIVATE_LINKS})
  maxillo_keep_itk_apart(maxillo_${name})
endfunction()
