#pragma once
// The offsets a user gives `rigidfold sorce --offsets SPEC.json`: a JSON object with
//   "end_offsets":  [z_f(1) per face]          (optional; file length units; default: derived
//                                               by the stacking rule of sorce_pattern.hpp)
//   "coefficients": [[b_1, b_2, b_3] per face] (optional; each list 0..3 numbers, the seed's
//                                               bases eq 37; [] or absent: linear offsets)
// and no other key. Faces in the pattern's order. Every number finite, |b| <= 100.
// Errors name the file and the JSON pointer (InputError("SPEC.json: /end_offsets/3", ...)).
#include <string>
#include <vector>

namespace rigidfold::sorce {

struct OffsetSpec {
  std::vector<double> end_offsets;                // empty or one per face (file units)
  std::vector<std::vector<double>> coefficients;  // empty or one list per face
};

// text: the file's content; source: its name for messages; faces: the pattern's face count.
OffsetSpec parse_offset_spec(const std::string& text, const std::string& source, int faces);

}  // namespace rigidfold::sorce
