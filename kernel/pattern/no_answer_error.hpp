#pragma once
// NoAnswerError: the command ran on valid input but found no result that passes its own
// check (a closure residual, an angle sum, a sign constraint above its tolerance, or nothing
// traced where an output was asked for). Not bad input, not a bug: the CLI prints
// "rigidfold: no answer within tolerance: <what>" with the residual, writes no output and
// exits with status 3.
#include <cmath>
#include <stdexcept>
#include <string>

namespace rigidfold {

class NoAnswerError : public std::runtime_error {
 public:
  // what: what was asked and why no answer passes (names the check); residual: the best
  // residual reached, in the units the message states (NaN when there is no residual).
  explicit NoAnswerError(const std::string& what, double residual = std::nan(""))
      : std::runtime_error(what), residual_(residual) {}
  double residual() const { return residual_; }

 private:
  double residual_;
};

}  // namespace rigidfold
