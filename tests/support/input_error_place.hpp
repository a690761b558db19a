#pragma once
// The place an InputError names (its flag, parameter or JSON path) when f() throws one, for
// tests that bad input names its place; "no InputError" when f() returns normally.
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::test {

template <class F>
std::string input_error_place(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.place();
  }
  return "no InputError";
}

}  // namespace rigidfold::test
