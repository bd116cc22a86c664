// The kinds of fault and what each touches.

#include "marsokhod/overswitch/fault.hpp"

namespace marsokhod::overswitch {

const char* to_string(Fault::Kind kind) {
  switch (kind) {
  case Fault::Kind::hang:
    return "hang";
  case Fault::Kind::power_loss:
    return "power";
  case Fault::Kind::leak:
    return "leak";
  case Fault::Kind::upset:
    return "seu";
  case Fault::Kind::stuck:
    return "stuck";
  case Fault::Kind::link_down:
    return "link";
  case Fault::Kind::link_bit:
    return "linkbit";
  case Fault::Kind::ack_lost:
    return "ackloss";
  }
  return "?";
}

bool is_memory_fault(Fault::Kind kind) {
  return kind == Fault::Kind::upset || kind == Fault::Kind::stuck;
}

bool is_link_fault(Fault::Kind kind) {
  return kind == Fault::Kind::link_down || kind == Fault::Kind::link_bit ||
         kind == Fault::Kind::ack_lost;
}

bool stops_module(Fault::Kind kind) {
  return kind == Fault::Kind::hang || kind == Fault::Kind::power_loss;
}

} // namespace marsokhod::overswitch
