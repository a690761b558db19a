// libFuzzer target for the SVG crease-pattern reader: any byte string must either import
// into a valid pattern (whose topology then builds and which writes as FOLD) or raise
// InputError; nothing else may escape, crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/svg_reader.hpp"
#include "kernel/pattern/topology.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rigidfold::CreasePattern p = rigidfold::parse_svg(text, "fuzz.svg");
    const rigidfold::Topology t = rigidfold::build_topology(p, "fuzz.svg");
    (void)rigidfold::write_fold_string(p);
    (void)t;
  } catch (const rigidfold::InputError&) {
  }
  return 0;
}
