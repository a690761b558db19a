// libFuzzer target for the FOLD reader: any byte string must either parse into a valid
// pattern (whose topology then builds, and whose thick extension, if any, checks) or raise
// InputError; nothing else may escape.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rigidfold::CreasePattern p = rigidfold::parse_fold(text, "fuzz.fold");
    const rigidfold::Topology t = rigidfold::build_topology(p, "fuzz.fold");
    (void)rigidfold::write_fold_string(p);
    (void)t;
    // A thick FOLD's extension (rigidfold:thickness, rigidfold:hinge_heights), as check and
    // trace read it first.
    if (rigidfold::is_thick_fold(p)) (void)rigidfold::thick_extension_hinges(p);
  } catch (const rigidfold::InputError&) {
  }
  return 0;
}
