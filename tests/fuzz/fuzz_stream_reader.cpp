// libFuzzer target for the .rays reader: any input either reads cleanly or throws InputError;
// never a crash, a hang, an out-of-bounds access or another exception.
#include <cstdint>
#include <cstdio>

#include "traces/error.h"
#include "traces/stream.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;  // fmemopen rejects an empty buffer
  FILE* file = fmemopen(const_cast<uint8_t*>(data), size, "rb");
  if (!file) return 0;
  try {
    rtsim::RayStreamReader reader(file, "fuzz.rays");
    rtsim::Ray ray;
    while (reader.next(ray)) {
    }
  } catch (const rtsim::InputError&) {
  }
  return 0;
}
