#pragma once
// Progress of long work - a check on the general model, a trace, a string design - for a
// caller that shows it: the CLI prints it on stderr when stderr is a terminal
// (app/terminal_progress.hpp), so that a slow run can be told from a hang. The kernel calls
// the sink at each unit of work (a Newton start, a continuation point, a grid cell) with one
// line of text saying what runs and how far it is; the sink decides how often to print.
// Nothing is built or called when no sink is set. The sink is called from the thread that
// runs the work, never from inside a parallel region.
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

namespace rigidfold {

using ProgressSink = std::function<void(const std::string& message)>;

// Thrown by a sink to stop the work at its next unit (the Python module's sink throws it when
// Ctrl-C arrives). Not a std::exception, so that no handler of failed computations takes it for
// one of theirs: it unwinds to the sink's owner.
struct WorkInterrupted {};

// sink(make_message()) when a sink is set; make_message is not called otherwise.
template <class MakeMessage>
void report_progress(const ProgressSink& sink, MakeMessage&& make_message) {
  if (sink) sink(make_message());
}

// An angle in degrees with one decimal ("47.3"), for progress lines only - never for results.
inline std::string progress_degrees(double radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", radians * 180.0 / std::numbers::pi);
  return text;
}

}  // namespace rigidfold
