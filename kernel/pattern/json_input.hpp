#pragma once
// Reading user input files and parsing them as JSON, within the limits of input_limits.hpp.
//
// read_input_file: the whole content of a regular file of at most kMaxInputFileBytes.
//   A FIFO, socket, device (/dev/zero, /dev/urandom, a terminal) or directory is refused
//   without blocking on it (the file is opened non-blocking and checked with fstat before
//   any read), so a hostile path can neither hang the program nor exhaust its memory.
//   Throws InputError(path, ...).
// parse_json_input: JSON text -> document. Throws InputError(source, ...) for malformed
//   JSON (with the byte offset), a number that does not fit a double (1e999), and arrays or
//   objects nested deeper than kMaxJsonDepth (refused while parsing, at the byte where the
//   limit is passed), and a key given twice in one object (InputError(source + ": " + path),
//   e.g. "a.fold: file_frames[0].frame_title"). Never lets a nlohmann::json exception escape.
#include <nlohmann/json.hpp>
#include <string>

namespace rigidfold {

std::string read_input_file(const std::string& path);

nlohmann::json parse_json_input(const std::string& text, const std::string& source);
nlohmann::ordered_json parse_ordered_json_input(const std::string& text, const std::string& source);

}  // namespace rigidfold
