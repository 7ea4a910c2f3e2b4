#include "core/events/event.h"

namespace vibro {

std::string_view event_kind_name(EventKind kind) {
  switch (kind) {
    case EventKind::limiter:
      return "limiter";
    case EventKind::collision:
      return "collision";
    case EventKind::reversal:
      return "reversal";
    case EventKind::stick:
      return "stick";
    case EventKind::release:
      return "release";
    case EventKind::chatter:
      return "chatter";
  }
  return "?";
}

}  // namespace vibro
