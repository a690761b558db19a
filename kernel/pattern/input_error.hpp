#pragma once
// InputError: the one exception type for bad user input (files, JSON, flags).
// Its message always names the place: "FILE: JSON_PATH: what is wrong".
// The CLI turns it into one line on stderr and exit status 2.
#include <stdexcept>
#include <string>

namespace rigidfold {

class InputError : public std::runtime_error {
 public:
  // place: where the problem is (e.g. "edges_vertices[12][1]"); what: the problem.
  InputError(std::string place, const std::string& what)
      : std::runtime_error(place.empty() ? what : place + ": " + what), place_(std::move(place)), message_(what) {}
  const std::string& place() const { return place_; }
  // The problem alone, without the place: for re-raising under another place (a kernel's
  // "thickness" becomes the CLI's "--thickness").
  const std::string& message() const { return message_; }

 private:
  std::string place_;
  std::string message_;
};

}  // namespace rigidfold
