# Project-wide compile settings applied to every marsokhod target.
add_library(marsokhod_options INTERFACE)
target_compile_options(marsokhod_options INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                                   -Wold-style-cast -Wimplicit-fallthrough)
if(MARSOKHOD_WERROR)
  target_compile_options(marsokhod_options INTERFACE -Werror)
endif()
if(MARSOKHOD_SANITIZE)
  # GCC's -Wmaybe-uninitialized gives false positives on instrumented code (the GCC manual
  # warns that -fsanitize can cause spurious warnings; with g++ 12 it fires inside
  # <regex>'s std::function), so under the sanitizers it is off: they check the real thing.
  target_compile_options(marsokhod_options INTERFACE -fsanitize=${MARSOKHOD_SANITIZE} -fno-omit-frame-pointer
                                                     -fno-sanitize-recover=all)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(marsokhod_options INTERFACE -Wno-maybe-uninitialized)
  endif()
  target_link_options(marsokhod_options INTERFACE -fsanitize=${MARSOKHOD_SANITIZE})
endif()
