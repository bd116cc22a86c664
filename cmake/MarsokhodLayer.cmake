# marsokhod_layer(NAME DIR DEPS...): one static library per layer, built from its rooms.
#
# A layer is a folder of rooms, one per subject (DIR/<room>/). Each room holds its sources and
# private headers, and its public headers under DIR/<room>/include/marsokhod/<layer>/<room>/, so
# that `#include "marsokhod/nav/stereo/stereo.hpp"` names the layer and the room. Sources reach
# a private header of any room of their own layer as "<room>/<header>.hpp" (DIR is a private
# include folder); other layers cannot. NAME_internals exposes those private headers to tests
# that pin a private piece on its own, and to nothing else.
function(marsokhod_layer name dir)
  file(GLOB sources CONFIGURE_DEPENDS "${dir}/*.cpp" "${dir}/*/*.cpp")
  file(GLOB room_includes LIST_DIRECTORIES true "${dir}/include" "${dir}/*/include")
  add_library(${name} STATIC ${sources})
  target_include_directories(${name} PUBLIC ${room_includes} PRIVATE "${dir}")
  target_link_libraries(${name} PUBLIC marsokhod_options ${ARGN})

  add_library(${name}_internals INTERFACE)
  target_include_directories(${name}_internals INTERFACE "${dir}")
  target_link_libraries(${name}_internals INTERFACE ${name})
endfunction()
