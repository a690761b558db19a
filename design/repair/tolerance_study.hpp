#pragma once
// tolerance_study: does a pattern stay rigidly foldable when it is made with an error in its
// vertex positions (`rigidfold check --tolerance-study SIGMA`; docs/cli/check.md)? The reverse
// of the rounding witness: there the kernel asks whether some pattern within the input's
// precision folds; here, what a builder gets when every vertex lands within sigma of the design.
//
// A folded form is studied on its flat development (flat_development.hpp): the crease pattern
// it folds from, which is what a builder cuts. Each sample moves every vertex (boundary
// included) by an independent
// error per coordinate (x and y), Gaussian with standard deviation
// sigma or uniform in [-sigma, sigma], from a SplitMix64 stream seeded by `seed` (the same
// seed gives the same samples on every platform), and checks the moved pattern with its
// letters, the numbers taken as exact. Reported:
//   - the fraction of samples whose check says "foldable", with its 95% Wilson interval (a
//     statement about the samples drawn, not a proof about all patterns within sigma);
//   - the count of each verdict class;
//   - on patterns of degree-4 vertices (the repair's model): per loop of the multiplier model
//     (a panel whose corners are interior vertices), the mean |log loop gain| the errors cause,
//     the ten largest first: the loops the fabrication error opens most; and the least repair
//     move of each sample (repair_pattern), RMS over the vertices, relative to sigma.
// A pattern with closed loops of degree-4 vertices is rigidly foldable only on a set of
// patterns of measure zero (Kawasaki and loop gain 1 are equations), so its fraction is 0 for
// any sigma > 0: the repair move then says how far from foldable the samples are.
// Units: sigma in the pattern's length unit.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

enum class ErrorDistribution { kGaussian, kUniform };
const char* to_string(ErrorDistribution d);

struct ToleranceStudyOptions {
  double sigma = 0.0;          // length unit, > 0
  int samples = 100;           // 1 .. 100000
  std::uint64_t seed = 1;
  ErrorDistribution distribution = ErrorDistribution::kGaussian;
  bool with_repair = true;     // the least repair move per sample, where the repair applies
  FoldabilityOptions check;    // letters used; coordinates taken as exact

  // False, with the reason, for sigma not finite and > 0, or samples outside 1 .. 100000.
  bool IsValid(std::string* error) const;
};

struct LoopSensitivity {
  std::vector<int> vertices;   // the loop's interior vertices, in order
  double mean_log_gain = 0.0;  // mean over the samples of |log loop gain|
};

struct ToleranceStudy {
  int samples = 0;
  bool on_flat_development = false;                // the input was a folded form
  int foldable = 0;
  double fraction = 0.0;
  double interval_low = 0.0, interval_high = 0.0;  // 95% Wilson interval of the fraction
  std::map<std::string, int> verdicts;             // verdict class -> samples
  bool degree4_model = false;                      // loops and repairs below were computed
  std::vector<LoopSensitivity> loops;              // the ten largest mean |log gain| first
  int repairs = 0;                                 // samples the repair brought back to foldable
  double repair_move_median = 0.0, repair_move_max = 0.0;  // RMS move / sigma over the repaired samples
  std::string message;
  double seconds = 0.0;
};

// Throws InputError for invalid options, or a folded form with no flat development.
ToleranceStudy tolerance_study(const CreasePattern& pattern, const Topology& topology, const ToleranceStudyOptions& options);

}  // namespace rigidfold
