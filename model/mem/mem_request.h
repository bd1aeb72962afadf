// The request record of the shared levels (model/sc/shared_levels_module.h): one per read,
// write or victim fill at an instance of a shared level, and one per access its slices' misses
// and evictions send to the DRAM below the last level, from the moment it is sent until it is
// answered (a read) or served (a write, a fill). It knows whom its answer goes to (Answer: a
// unit's last own level, the level above through the calendar, a TLM initiator's transaction),
// where it is (its instance, the requester's port, the slice) and what it waits for since which
// cycle, so that the stall dump can name every waiting request.
#pragma once

#include <cstdint>

#include "model/mem/memory_level.h"

namespace tlm {
class tlm_generic_payload;
}

namespace rtsim {

enum class RequestKind : uint8_t { Read, Write, Fill };

// What a request waits for. Free: the record is not in use.
enum class RequestWait : uint8_t {
  Free,
  Crossbar,  // sent: it crosses to its slice when the calendar reaches its earliest arrival
  Slice,     // crossed: queued for its slice's lookup at its arrival cycle
  Below,     // missed in its slice: waits for an MSHR there and the level below's data
  Dram,      // queued for, or in, the DRAM below the last level
  Data,      // its data's cycle is known: its answer waits in the calendar for that cycle
};

// Whom a read's answer goes to.
enum class Answer : uint8_t {
  Unit,       // a unit's last own level: client->read_done at once, then the port's wake-up
  Level,      // a slice of the level above (or the module, for a memory port): through the
              // calendar at the data's cycle, so that the level above sees answers in time order
  Initiator,  // a TLM initiator bound to `in`: BEGIN_RESP on its transaction
};

inline const char* wait_name(RequestWait wait) {
  switch (wait) {
    case RequestWait::Free: return "nothing";
    case RequestWait::Crossbar: return "the crossbar";
    case RequestWait::Slice: return "its slice";
    case RequestWait::Below: return "the level below";
    case RequestWait::Dram: return "the DRAM";
    case RequestWait::Data: return "its data";
  }
  return "?";
}

struct MemRequest {
  uint64_t addr = 0;
  uint32_t bytes = 0;
  RequestKind kind = RequestKind::Read;
  RequestWait wait = RequestWait::Free;
  Answer answer = Answer::Unit;
  bool to_dram = false;  // an access to the DRAM below `instance`, not a request at it
  uint16_t instance = 0;
  uint32_t port = 0;   // the requester's crossbar port at the instance
  uint32_t slice = 0;  // the slice it goes to
  Cycle since = 0;     // the cycle it has waited for `wait` from
  // The answer's receiver: Unit and Level: client->read_done(token, ...); Initiator: the
  // transaction the initiator owns.
  ReadClient* client = nullptr;
  uint64_t token = 0;
  tlm::tlm_generic_payload* transaction = nullptr;
  ReadCharge charge;  // what the read has cost at and below this instance so far
};

}  // namespace rtsim
