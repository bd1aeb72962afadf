#include "model/sched/event_queue.h"

#include <stdexcept>

namespace rtsim {

void throw_event_in_past() {
  throw std::logic_error("EventQueue: event scheduled in the past");
}

}  // namespace rtsim
