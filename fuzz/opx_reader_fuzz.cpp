// libFuzzer target for the ORIPA .opx reader: any byte string must either import into a
// valid pattern (whose topology then builds, which writes as FOLD and, being flat, as SVG)
// or raise InputError; nothing else may escape, crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/svg_writer.hpp"
#include "kernel/pattern/topology.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rigidfold::CreasePattern p = rigidfold::parse_opx(text, "fuzz.opx");
    const rigidfold::Topology t = rigidfold::build_topology(p, "fuzz.opx");
    (void)rigidfold::write_fold_string(p);
    (void)rigidfold::write_svg_string(p, "fuzz.opx");
    (void)t;
  } catch (const rigidfold::InputError&) {
  }
  return 0;
}
