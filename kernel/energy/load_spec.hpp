#pragma once
// A vertex-height load from JSON (`rigidfold energy --load SPEC.json`), for
// vertex_height_control.hpp:
//
//   {"vertex": i, "height": h, "supports": [e, ...]}
//
//   vertex    an interior vertex (0-based index into vertices_coords)
//   height    the prescribed height of that vertex above the plane of the supports, in the
//             file's length units (finite; > 0 on the side the folded faces' normals point to);
//             VertexHeightLoad::height holds it in the kernel's normalised units
//             (length_scale.hpp), so multiply by 2^length_exponent to report it
//   supports  creases of that vertex whose far ends rest on the plane (optional; default: its
//             valley creases, the waterbomb's supports); at least 3, each once
// Force control ("force") is not supported: refused with that message. Unknown keys are refused.
// Errors: InputError(source + ": " + JSON path, ...), e.g. "load.json: supports[2]".
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

VertexHeightLoad load_from_spec(const nlohmann::ordered_json& spec, const CreasePattern& pattern, const Topology& topology,
                                const std::string& source);

// Reads `path` within json_input.hpp's limits and applies load_from_spec with source = path.
VertexHeightLoad read_load_spec(const std::string& path, const CreasePattern& pattern, const Topology& topology);

}  // namespace rigidfold
