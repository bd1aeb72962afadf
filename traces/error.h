// Errors caused by bad input: a missing or corrupt file, a bad key, an impossible config.
// The CLI prints what() as one line and exits with code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace rtsim {

class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// "FILE: offset N: WHAT" or "FILE: line N: WHAT"; place may be empty.
[[noreturn]] void throw_input_error(const std::string& file, const std::string& place,
                                    const std::string& what);

}  // namespace rtsim
