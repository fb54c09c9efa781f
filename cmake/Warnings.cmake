# Warnings as an INTERFACE target: every maxillo target links it, third-party code does not.
add_library(maxillo_warnings INTERFACE)
target_compile_options(maxillo_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor -Wno-deprecated-declarations)

# Sanitizers on request: cmake -DMAXILLO_SANITIZE=address,undefined
set(MAXILLO_SANITIZE "" CACHE STRING "Comma-separated -fsanitize list")
add_library(maxillo_sanitizers INTERFACE)
if(MAXILLO_SANITIZE)
  target_compile_options(maxillo_sanitizers INTERFACE -fsanitize=${MAXILLO_SANITIZE} -fno-omit-frame-pointer)
  target_link_options(maxillo_sanitizers INTERFACE -fsanitize=${MAXILLO_SANITIZE})
endif()
