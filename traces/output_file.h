// Where an output file is written so that it appears whole or not at all. A regular file, or a
// path that does not exist yet, is written to PATH.tmp-PID beside it and renamed over it when
// done. A symbolic link is followed: the file it names is replaced, and the link stays. A
// character or block device, a FIFO or a socket is written in place: renaming over it would
// replace the device itself (as root, `-o /dev/null` would replace /dev/null).
// A temporary never outlives its process: an OutputFile destroyed uncommitted removes it, so do
// SIGINT, SIGTERM and SIGHUP once remove_temporaries_on_signals() is installed, and a new
// OutputFile for PATH removes the PATH.tmp-PID files of processes that no longer exist (killed
// with SIGKILL, or a crashed machine).
#pragma once

#include <string>
#include <vector>

namespace rtsim {

// Creates the output folder `dir` (and its parents) and checks that files can be written in
// it; InputError naming the folder otherwise. Commands call it before any work, so a bad -o
// is one line and exit 2 at once, not an error after hours of simulation.
void create_output_folder(const std::string& dir);

// Takes `dir`'s lock (the file DIR/.rtsim.lock, which holds the owner's pid) for the rest of
// this process, so two commands never write one folder at once: if another process holds it,
// InputError naming the folder, that process and `command`. Taking a lock this process already
// holds does nothing. Forked children share it; programs they exec do not.
void lock_output_folder(const std::string& dir, const std::string& command);

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove this process's temporaries,
// then end it by the same signal (so its parent sees how it ended). Called once, by main().
void remove_temporaries_on_signals();

// The file writing `path` replaces: path with its symbolic links followed (also to a file that
// does not exist yet), as open() would; at most 40, as Linux.
std::string output_target(const std::string& path);

// Whether writing `path` makes a regular file (one exists there, or nothing does yet), rather
// than writing into a device, FIFO or socket in place.
bool writes_regular_file(const std::string& path);

// Throws InputError naming path and option unless a file can be written there: a folder, or a
// path whose folder is missing or not writable, is refused (a device, FIFO or socket is written
// in place and passes). Commands call it before any work, so a bad path is not found hours later.
void check_output_path(const std::string& path, const std::string& option);

// A file a command reads or writes, and the option (or argument) that names it, for messages.
struct NamedPath {
  std::string option, path;
};

// Throws InputError naming an output and its option when writing it would replace one of the
// inputs or an earlier output. Files are compared by what they are, device and inode, so links,
// relative paths and other spellings of one file are caught; an output that does not exist yet
// by its absolute path with links resolved. An output that is a device, FIFO or socket is written
// in place and replaces nothing, so it is not compared. Empty paths are skipped. Commands call it
// before any work.
void refuse_overwriting(const std::vector<NamedPath>& inputs,
                        const std::vector<NamedPath>& outputs);

class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // The path to open for writing now.
  const std::string& write_path() const { return write_path_; }
  // Whether it is a temporary file renamed by commit() (false: the target itself).
  bool renames() const { return renames_; }
  // Whether the target is a FIFO or socket: written in order only, no seeking back.
  bool sequential() const { return sequential_; }
  // Makes the written file the output (renames it over the target). False if that failed (or
  // it was discarded).
  bool commit();
  // Removes what was written, if it went to a temporary file and was not committed.
  void discard();

 private:
  std::string write_path_, target_;
  bool renames_, sequential_;
  bool done_ = false;  // committed or discarded
  int pending_ = -1;   // this temporary's entry in the table the signal handlers clean up
};

}  // namespace rtsim
