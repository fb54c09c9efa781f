# maxillo_module(NAME [FEATURE_FOLDERS] PUBLIC_LINKS ... PRIVATE_LINKS ...): a static library from
# every .cpp in the module's folder, and with FEATURE_FOLDERS in its subfolders too (casework
# keeps each feature's workflow in a folder of its own, one library all the same).
# Tests live in tests/<module>/, never beside the sources, so the glob picks up sources only.
function(maxillo_module name)
  cmake_parse_arguments(ARG "FEATURE_FOLDERS" "" "PUBLIC_LINKS;PRIVATE_LINKS" ${ARGN})
  if(ARG_FEATURE_FOLDERS)
    file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  else()
    file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  endif()
  add_library(maxillo_${name} STATIC ${sources})
  target_link_libraries(maxillo_${name}
    PUBLIC maxillo_core ${ARG_PUBLIC_LINKS}
    PRIVATE maxillo_warnings maxillo_sanitizers ${ARG_PRIVATE_LINKS})
  maxillo_keep_itk_apart(maxillo_${name})
endfunction()
