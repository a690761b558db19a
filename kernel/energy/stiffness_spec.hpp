#pragma once
// Per-crease stiffness from a JSON specification (`rigidfold energy --stiffness SPEC.json`):
//
//   {
//     "default": k,                          every spring crease not given otherwise (default 1)
//     "material": {"youngs_modulus": E, "thickness": h, "flexure_length": l, "length_scale": s},
//                                            k_e = E (s L_e) h^3 / (12 l)  (crease_stiffness.hpp's
//                                            flexure; L_e the crease's length in the pattern's
//                                            units, s metres per unit, default 1) for every
//                                            spring crease not given by letter or edge
//     "mountain" | "valley" | "unassigned": k    by letter (M, V, U), over default and material
//     "edges": {"12": k, ...}                by edge index (0-based, decimal), over everything
//   }
// Every k finite and >= 0 (energy / rad^2, N m / rad for SI input). Only crease edges
// (M, V, U) carry springs: B, C, F and J edges get 0 and may not be named in "edges".
// Unknown keys are refused (a misspelt "valey" would otherwise pass silently).
// Errors: InputError(source + ": " + JSON path, ...), e.g. "k.json: edges.\"12\"",
// "k.json: material.thickness", "k.json: valey".
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// One stiffness per edge of `pattern` (size num_edges()).
Eigen::VectorXd stiffness_from_spec(const nlohmann::ordered_json& spec, const CreasePattern& pattern,
                                    const std::string& source);

// Reads `path` (json_input.hpp's limits: size, depth, duplicate keys) and applies
// stiffness_from_spec with source = path.
Eigen::VectorXd read_stiffness_spec(const std::string& path, const CreasePattern& pattern);

}  // namespace rigidfold
