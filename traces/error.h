// Errors caused by bad input: a missing or corrupt file, a bad key, an impossible config.
// The CLI prints what() as one line and exits with code 2.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace rtsim {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  InputError(const std::string& message, std::string problem)
      : std::runtime_error(message), problem_(std::move(problem)) {}

  // What is wrong without the file and place, for a caller that names its own place (a sweep
  // spec's line for a setting it passed on); the whole message where no place was given apart.
  std::string problem() const { return problem_.empty() ? what() : problem_; }

 private:
  std::string problem_;
};

// "FILE: offset N: WHAT" or "FILE: line N: WHAT"; place may be empty.
[[noreturn]] void throw_input_error(const std::string& file, const std::string& place,
                                    const std::string& what);

}  // namespace rtsim
