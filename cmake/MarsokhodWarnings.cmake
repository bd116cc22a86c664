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
                                                     -fno-sanitize-recover=all -Wno-maybe-uninitialized)
  target_link_options(marsokhod_options INTERFACE -fsanitize=${MARSOKHOD_SANITIZE})
endif()

# marsokhod_layer(NAME DIR DEPS...): a static library from DIR/*.cpp with DIR/include public.
function(marsokhod_layer name dir)
  file(GLOB sources CONFIGURE_DEPENDS "${dir}/*.cpp")
  if(NOT sources)
    # A layer that has only headers so far.
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE "${dir}/include")
    target_link_libraries(${name} INTERFACE marsokhod_options ${ARGN})
    return()
  endif()
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC "${dir}/include")
  target_link_libraries(${name} PUBLIC marsokhod_options ${ARGN})
endfunction()
