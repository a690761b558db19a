#include "kernel/pattern/assignment.hpp"

namespace rigidfold {

char assignment_letter(Assignment a) {
  switch (a) {
    case Assignment::Boundary: return 'B';
    case Assignment::Mountain: return 'M';
    case Assignment::Valley: return 'V';
    case Assignment::Flat: return 'F';
    case Assignment::Unassigned: return 'U';
    case Assignment::Cut: return 'C';
    case Assignment::Join: return 'J';
  }
  return 'U';
}

std::optional<Assignment> assignment_from_letter(char c) {
  switch (c) {
    case 'B': case 'b': return Assignment::Boundary;
    case 'M': case 'm': return Assignment::Mountain;
    case 'V': case 'v': return Assignment::Valley;
    case 'F': case 'f': return Assignment::Flat;
    case 'U': case 'u': return Assignment::Unassigned;
    case 'C': case 'c': return Assignment::Cut;
    case 'J': case 'j': return Assignment::Join;
    default: return std::nullopt;
  }
}

}  // namespace rigidfold
