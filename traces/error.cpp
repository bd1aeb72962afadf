#include "traces/error.h"

namespace rtsim {

void throw_input_error(const std::string& file, const std::string& place, const std::string& what) {
  std::string msg = file;
  if (!place.empty()) msg += ": " + place;
  msg += ": " + what;
  throw InputError(msg, what);
}

}  // namespace rtsim
