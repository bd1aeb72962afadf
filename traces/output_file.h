// Where an output file is written so that it appears whole or not at all. A regular file, or a
// path that does not exist yet, is written to PATH.tmp-PID beside it and renamed over it when
// done. A symbolic link is followed: the file it names is replaced, and the link stays. A
// character or block device, a FIFO or a socket is written in place: renaming over it would
// replace the device itself (as root, `-o /dev/null` would replace /dev/null).
#pragma once

#include <string>

namespace rtsim {

// Creates the output folder `dir` (and its parents) and checks that files can be written in
// it; InputError naming the folder otherwise. Commands call it before any work, so a bad -o
// is one line and exit 2 at once, not an error after hours of simulation.
void create_output_folder(const std::string& dir);

class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  // The path to open for writing now.
  const std::string& write_path() const { return write_path_; }
  // Whether it is a temporary file renamed by commit() (false: the target itself).
  bool renames() const { return renames_; }
  // Whether the target is a FIFO or socket: written in order only, no seeking back.
  bool sequential() const { return sequential_; }
  // Makes the written file the output (renames it over the target). False if that failed.
  bool commit();
  // Removes what was written, if it went to a temporary file.
  void discard();

 private:
  std::string write_path_, target_;
  bool renames_, sequential_;
};

}  // namespace rtsim
