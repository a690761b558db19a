#pragma once
// The verdict vocabulary: one class per answer, used by every report that says whether
// something folds or moves (check, trace, network, ...). foldability_report.hpp says what each
// class means for a crease pattern; with M/V letters given, "foldable" is the strict answer
// (every lettered crease folds with its letter).
namespace rigidfold {

enum class FoldabilityClass {
  kFoldable,                 // a certified motion
  kFoldableWithinTolerance,  // a certified motion of an input within the input's precision
  kFoldableInPart,           // a certified motion that leaves lettered creases flat, no strict one found
  kNotFoldableProof,         // no motion, proven
  kNotFoldableEvidence,      // no motion found, with numerical evidence that none exists
  kUndecided                 // the models available did not decide
};
const char* to_string(FoldabilityClass c);

}  // namespace rigidfold
