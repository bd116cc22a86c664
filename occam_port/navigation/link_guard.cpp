// The names of link troubles.

#include "marsokhod/occam_port/navigation/link_guard.hpp"

namespace marsokhod::occam_port {

const char* to_string(LinkTrouble trouble) {
  switch (trouble) {
  case LinkTrouble::timeout:
    return "output not acknowledged in time";
  case LinkTrouble::checksum:
    return "message with a wrong checksum";
  }
  return "?";
}

} // namespace marsokhod::occam_port
