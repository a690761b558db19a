#pragma once
// OutputSet: every file one command writes, as one transaction.
//
// A command declares its inputs and outputs before it does any work; each path is resolved
// (made absolute, symlinks followed, "..", then the same file by device and inode) and
// compared with every input and every other output. A clash is bad input (InputError naming
// both flags), raised before anything is written.
// Outputs are then staged (stage()): the text of a regular-file output goes to an exclusive
// temporary in its destination directory (".NAME.tmp.XXXXXX", cut so that it never exceeds
// NAME_MAX for a legal NAME). commit() writes stream targets and renames every temporary
// onto its target; until then no existing output is touched, and destroying the set
// without commit() removes every temporary (and every directory it created, if still empty).
//
// Targets:
//   - a regular file or a missing path: replaced atomically (readers see the old file or the
//     whole new one); a symlink is followed and its target replaced, the link kept;
//   - an existing character device or FIFO (/dev/null, /dev/stdout, a named pipe): written
//     in place at commit, never replaced (a FIFO must get a reader within kFifoWaitSeconds);
//   - "-": standard output (at most one output per command);
//   - a directory, block device or socket: refused (InputError).
// Two processes writing one path each rename a complete file into place: the last rename
// wins and no reader sees a mix.
// SIGINT/SIGTERM: the CLI's handler calls remove_staged_temporaries() (async-signal-safe),
// so an interrupted command leaves the old outputs and no temporary.
#include <memory>
#include <string>
#include <vector>

namespace rigidfold {

class OutputSet {
 public:
  static constexpr int kFifoWaitSeconds = 5;

  OutputSet();
  ~OutputSet();  // without commit(): removes the temporaries and the directories it created
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // A file or directory the command reads (label: its flag or argument name, e.g. "PATTERN",
  // "--angles"). No output may resolve to it.
  void add_input(const std::string& label, const std::string& path);
  // A directory that will hold outputs (report --out, generate bundle --out-dir): must not be
  // an input directory; created now if missing, removed again on failure while still empty.
  void add_output_directory(const std::string& label, const std::string& path);
  // An output the command may write (label: its flag). Checked at once against every input
  // and every output declared so far; throws InputError(label, ...) on a clash or a target
  // that cannot be written. May be called after some work, as long as before stage().
  void add_output(const std::string& label, const std::string& path);
  // The content of a declared output (path exactly as given to add_output). Regular targets
  // are written to their temporary now. Throws InputError(label, ...) on a write error.
  void stage(const std::string& path, const std::string& text);
  // Writes stream targets, then renames every temporary into place. A set commits once.
  void commit();

  // True when one output is "-" (the CLI then prints its summary to stderr).
  bool writes_stdout() const;
  // True when the declared output `path` is a stream ("-", a device, a FIFO): stage() may
  // then be called more than once for it, each text appended (trace's several branches).
  bool writes_in_place(const std::string& path) const;

 private:
  struct Output;
  struct Input;
  Output& find(const std::string& path);
  void rollback() noexcept;

  std::vector<Input> inputs_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::vector<std::string> created_directories_;
  bool committed_ = false;
};

// Removes every temporary of every uncommitted OutputSet. Async-signal-safe.
void remove_staged_temporaries();

}  // namespace rigidfold
