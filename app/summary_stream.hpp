#pragma once
// SummaryToStderrIfStdoutIsAnOutput: while alive, std::cout goes to stderr when one output of
// the command is "-" (standard output), so the file written there is not mixed with the
// command's summary. Restores std::cout when it ends (run_cli also runs in-process).
#include <iostream>

#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {

class SummaryToStderrIfStdoutIsAnOutput {
 public:
  explicit SummaryToStderrIfStdoutIsAnOutput(const OutputSet& outputs) {
    if (!outputs.writes_stdout()) return;
    std::cout.flush();
    saved_ = std::cout.rdbuf(std::cerr.rdbuf());
  }
  ~SummaryToStderrIfStdoutIsAnOutput() {
    if (saved_) std::cout.rdbuf(saved_);
  }
  SummaryToStderrIfStdoutIsAnOutput(const SummaryToStderrIfStdoutIsAnOutput&) = delete;
  SummaryToStderrIfStdoutIsAnOutput& operator=(const SummaryToStderrIfStdoutIsAnOutput&) = delete;

 private:
  std::streambuf* saved_ = nullptr;
};

}  // namespace rigidfold::cli
