#pragma once
// The crease letters of FOLD (edges_assignment) and the fold-angle sign each asks for.
// Sign convention (FOLD edges_foldAngle): rho > 0 valley, rho < 0 mountain, 0 flat.
// The one place that maps a letter to a sign: a mountain asks for -1, a valley for +1, every
// other letter (U, F, B, C, J) for 0 (no sign asked).
#include <optional>

namespace rigidfold {

// FOLD edges_assignment letters.
enum class Assignment { Boundary, Mountain, Valley, Flat, Unassigned, Cut, Join };

char assignment_letter(Assignment a);
// Returns nullopt for a letter FOLD does not define.
std::optional<Assignment> assignment_from_letter(char c);
// A crease that may fold (M, V, U). F and J are rigid joins, B and C are not joins.
inline bool is_foldable_crease(Assignment a) {
  return a == Assignment::Mountain || a == Assignment::Valley || a == Assignment::Unassigned;
}
// A crease whose letter asks for a sign (M or V).
inline bool has_fold_sign(Assignment a) { return a == Assignment::Mountain || a == Assignment::Valley; }
// Sign a crease's letter asks of its fold angle: -1 M, +1 V, 0 for any other letter.
inline int assigned_fold_sign(Assignment a) {
  return a == Assignment::Mountain ? -1 : (a == Assignment::Valley ? 1 : 0);
}

}  // namespace rigidfold
