// libFuzzer target for the .cp reader: any byte string must either import into a valid
// pattern (whose topology then builds, which writes as FOLD and, being flat, as SVG) or raise
// InputError; nothing else may escape, crash or hang. Lines drawn twice: the default reading
// (the later line wins, svg_reader.hpp "Lines drawn twice") and strict_lines must agree, so a
// file read with no piece drawn in two letters is read by strict_lines too, and one with such
// a piece is refused by it. Seeds: fuzz/seeds/cp.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "kernel/pattern/cp_reader.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/svg_writer.hpp"
#include "kernel/pattern/topology.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rigidfold::CpImportSummary summary;
  try {
    const rigidfold::CreasePattern p = rigidfold::parse_cp(text, "fuzz.cp", {}, &summary);
    const rigidfold::Topology t = rigidfold::build_topology(p, "fuzz.cp");
    (void)rigidfold::write_fold_string(p);
    (void)rigidfold::write_svg_string(p, "fuzz.cp");
    (void)t;
  } catch (const rigidfold::InputError&) {
    return 0;
  }
  rigidfold::SvgReadOptions strict;
  strict.strict_lines = true;
  bool strict_read = true;
  try {
    (void)rigidfold::parse_cp(text, "fuzz.cp", strict);
  } catch (const rigidfold::InputError&) {
    strict_read = false;
  }
  if (strict_read != (summary.arrangement.overwritten_edges == 0)) std::abort();
  return 0;
}
