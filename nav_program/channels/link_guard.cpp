// The names of link troubles.

#include "marsokhod/nav_program/channels/link_guard.hpp"

namespace marsokhod::nav_program {

const char* to_string(LinkTrouble trouble) {
  switch (trouble) {
  case LinkTrouble::timeout:
    return "output not acknowledged in time";
  case LinkTrouble::checksum:
    return "message with a wrong checksum";
  }
  return "?";
}

} // namespace marsokhod::nav_program
