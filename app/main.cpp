// rigidfold: command-line front end (app/run_cli.cpp). Exit status 0 on success (every
// requested output written), 2 on bad input (including input past the documented limits, or
// too large for the memory available), 3 when no answer passes the command's own check
// (nothing written), 1 only for an internal error (a bug).
#include <csignal>

#include "app/commands.hpp"
#include "kernel/pattern/output_set.hpp"

namespace {

// SIGINT/SIGTERM/SIGHUP: remove the temporaries of the outputs being staged (the old
// outputs, if any, stay in place), then die of the signal as the default action would.
extern "C" void on_terminating_signal(int sig) {
  rigidfold::remove_staged_temporaries();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

int main(int argc, char** argv) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction sa {};
    sa.sa_handler = on_terminating_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(sig, &sa, nullptr);
  }
  return rigidfold::cli::run_cli(argc, argv);
}
