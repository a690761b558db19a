#pragma once
// Flags of `check` and `trace` that have no meaning for a thick FOLD (rigidfold thick --out):
// its answer comes from the thick model (kernel/thick/thick_check.hpp), which always runs
// the general SE(3) solver, reports which letters its motion keeps or breaks instead of
// searching with or without them, and judges the numbers as they are. A flag the user gave
// there is refused (exit 2, the flag named) rather than silently ignored.
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::cli {

struct ThickIgnoredFlags {
  bool ignore_assignment = false;  // --ignore-assignment given
  bool general = false;            // --general given
  bool tolerance = false;          // --tolerance given (any value)
};

inline void refuse_flags_a_thick_fold_ignores(const ThickIgnoredFlags& given) {
  if (given.ignore_assignment)
    throw InputError("--ignore-assignment",
                     "does not apply to a thick FOLD: the thick model traces its one motion and reports the letters it "
                     "keeps or breaks");
  if (given.general)
    throw InputError("--general", "does not apply to a thick FOLD: the thick model always uses the general SE(3) solver");
  if (given.tolerance)
    throw InputError("--tolerance",
                     "does not apply to a thick FOLD: the thick model judges its hinge heights and thicknesses as written");
}

}  // namespace rigidfold::cli
