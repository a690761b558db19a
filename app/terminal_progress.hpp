#pragma once
// Progress of a long command on stderr (kernel/analysis/progress.hpp), so that a slow run can
// be told from a hang. Shown when stderr is a terminal: one line, rewritten in place at most
// 5 times a second and erased when the command ends. RIGIDFOLD_PROGRESS=always shows it on
// any stderr (one plain line per update: the first at once, then at most one a second, e.g.
// for logs); RIGIDFOLD_PROGRESS=never hides it. Standard output (results, JSON) is never touched.
#include <chrono>
#include <mutex>
#include <string>

#include "kernel/analysis/progress.hpp"

namespace rigidfold::cli {

class TerminalProgress {
 public:
  explicit TerminalProgress(std::string command);  // "check", "trace", ...
  ~TerminalProgress();                             // erases the line on a terminal
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  // The sink to pass to the kernel; empty (no progress work at all) when progress is off.
  // Valid while this object lives.
  ProgressSink sink();

 private:
  void show(const std::string& message);

  std::string command_;
  bool enabled_ = false, in_place_ = false, line_shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mutex_;
};

}  // namespace rigidfold::cli
