#pragma once
// FOLD 1.1/1.2 reading and writing (https://github.com/edemaine/fold, spec 1.2).
//
// read_fold: parses the key frame of a FOLD file into a CreasePattern, validates it
// (see validate_pattern.hpp) and derives faces when faces_vertices is missing.
//   Inputs:  path of a .fold file (JSON).
//   Output:  CreasePattern; edges_foldAngle converted from degrees to radians.
//   Throws:  InputError naming the file and the JSON path of the first problem.
// write_fold: the inverse. Unknown keys (extra) are written back unchanged; fold angles in
// degrees; numbers print with the shortest text that reads back to the same double.
// Files are written to a temporary name and renamed, so a failure leaves no partial file.
// The CLI writes through an OutputSet instead, to commit all outputs of a command together.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// Parse a FOLD document held in memory. `source` names it in error messages.
CreasePattern parse_fold(const std::string& text, const std::string& source);
CreasePattern read_fold(const std::string& path);

nlohmann::ordered_json fold_to_json(const CreasePattern& pattern);
std::string write_fold_string(const CreasePattern& pattern);
// Serialises any FOLD document in the same layout as write_fold (one element per line).
std::string dump_fold_json(const nlohmann::ordered_json& doc);
void write_fold(const CreasePattern& pattern, const std::string& path);

// Reads a whole regular file within the input limits (json_input.hpp: read_input_file);
// throws InputError(path, ...) if it cannot be read, is not a regular file or is too large.
std::string read_text_file(const std::string& path);
// Writes one file through an OutputSet (output_set.hpp): a temporary in the destination
// directory renamed into place, so readers see the old file or the whole new one; a device
// or FIFO is written in place; throws InputError(path, ...) on failure.
void write_text_file_atomically(const std::string& path, const std::string& text);

}  // namespace rigidfold
