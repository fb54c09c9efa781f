# Warnings as an INTERFACE target: every maxillo target links it, third-party code does not.
add_library(maxillo_warnings INTERFACE)
target_compile_options(maxillo_warnings INTERFACE -Wall -Wextra -Wpedantic -Wnon-virtual-dtor -Wno-deprecated-declarations)
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(maxillo_warnings INTERFACE -Wshadow=local)
else()
  target_compile_options(maxillo_warnings INTERFACE -Wshadow-uncaptured-local)
endif()

# Sanitizers on request: cmake -DMAXILLO_SANITIZE=address,undefined (scripts/sanitize). Undefined
# behaviour stops the program (no recovery), so a test that meets it fails.
set(MAXILLO_SANITIZE "" CACHE STRING "Comma-separated -fsanitize list")
add_library(maxillo_sanitizers INTERFACE)
if(MAXILLO_SANITIZE)
  target_compile_options(maxillo_sanitizers INTERFACE -fsanitize=${MAXILLO_SANITIZE} -fno-omit-frame-pointer)
  target_link_options(maxillo_sanitizers INTERFACE -fsanitize=${MAXILLO_SANITIZE})
  if(MAXILLO_SANITIZE MATCHES "undefined")
    target_compile_options(maxillo_sanitizers INTERFACE -fno-sanitize-recover=undefined)
    target_link_options(maxillo_sanitizers INTERFACE -fno-sanitize-recover=undefined)
  endif()
endif()
