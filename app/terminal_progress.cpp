#include "app/terminal_progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace rigidfold::cli {

TerminalProgress::TerminalProgress(std::string command) : command_(std::move(command)) {
  const char* mode = std::getenv("RIGIDFOLD_PROGRESS");
  const bool terminal = isatty(STDERR_FILENO) == 1;
  if (mode && std::strcmp(mode, "never") == 0) enabled_ = false;
  else if (mode && std::strcmp(mode, "always") == 0) enabled_ = true;
  else enabled_ = terminal;
  in_place_ = enabled_ && terminal;
  start_ = std::chrono::steady_clock::now();
  // On a terminal nothing in the first interval (a quick command shows no progress at all);
  // asked for explicitly, the first update at once.
  last_ = in_place_ ? start_ : start_ - std::chrono::seconds(1);
}

TerminalProgress::~TerminalProgress() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (in_place_ && line_shown_) std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}

ProgressSink TerminalProgress::sink() {
  if (!enabled_) return {};
  return [this](const std::string& message) { show(message); };
}

void TerminalProgress::show(const std::string& message) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  const auto interval = in_place_ ? std::chrono::milliseconds(200) : std::chrono::milliseconds(1000);
  if (now - last_ < interval) return;
  last_ = now;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  // On a terminal the line is cut to 110 columns so that it never wraps (a wrapped line
  // cannot be rewritten in place).
  std::string text = message;
  if (in_place_ && text.size() > 90) text = text.substr(0, 87) + "...";
  std::fprintf(stderr, in_place_ ? "\r\033[Krigidfold %s [%.0f s]: %s" : "rigidfold %s [%.0f s]: %s\n", command_.c_str(),
               seconds, text.c_str());
  std::fflush(stderr);
  line_shown_ = true;
}

}  // namespace rigidfold::cli
