#pragma once
// run_metamaterial: the one front door of `rigidfold metamaterial` and rigidfold.metamaterial().
// A request holds what the user gave (an empty optional was not given and takes the documented
// default, docs/cli/metamaterial.md); the whole request is checked before any work, so that
// both doors refuse the same input with the same message:
//   - a unit (square-twist, element1..3): metamaterial_table along the motion, with the
//     square twist's cross-check on request (square_twist_cross_check.hpp) and the plots
//     (metamaterial.csv, dimensions.svg, poisson.svg) written into a directory on request;
//   - a stacked metamaterial 1..4 (stacked_metamaterial_check.hpp), instead of a unit.
// Throws InputError naming the field (as a flag or as a keyword: FieldNaming) for a value out
// of range, a field that does not apply, or a plot directory that cannot be written;
// NoAnswerError when a sample, the cross-check or the stack fails its checks. The plot files
// are written only after every check passed (one OutputSet), never in part.
#include <optional>
#include <string>
#include <vector>

#include "design/metamaterial/metamaterial_table.hpp"
#include "design/metamaterial/square_twist_cross_check.hpp"
#include "design/metamaterial/stacked_metamaterial_check.hpp"

namespace rigidfold::metamaterial {

// How error messages name the request's fields: as the CLI's flags ("--alpha-deg",
// "--unit square-twist") or as Python's keyword arguments ("alpha_deg", "unit=square-twist").
enum class FieldNaming { kCommandLineFlags, kKeywordArguments };

struct MetamaterialRequest {
  std::string unit;                      // square-twist, element1, element2, element3; "": not given
  std::optional<int> stacked;            // 1..4: a stacked metamaterial instead of a unit
  std::optional<double> alpha_deg;       // square twist (90, 180), default 150; else (0, 180), default 60
  std::optional<double> beta_deg;        // elements and stacks: (0, 180), default 70
  std::optional<double> a, b, c;         // square twist: a > 0; b, c so that S, L > 0; default 1 each
  std::optional<double> l;               // elements and stacks: > 0, default 1
  std::optional<int> samples;            // units: 3..100000, default 181
  std::optional<std::string> plot;       // units: directory for the plots ("": none written)
  std::optional<bool> cross_check;       // square twist; given as false it still counts as given
  std::optional<int> cross_check_steps;  // with cross_check: 10..2000, default 40
  std::optional<int> layers;             // stacks: 2..16, default 4
  std::optional<int> stacked_steps;      // stacks: 8..200, default 24
  FieldNaming naming = FieldNaming::kCommandLineFlags;
};

struct MetamaterialUnitRun {
  MetamaterialParams params;  // as checked (angles in radians)
  MetamaterialTable table;
  std::optional<SquareTwistCrossCheck> cross_check;
  std::vector<std::string> plot_files;  // written: metamaterial.csv, dimensions.svg, poisson.svg; or none
};

struct StackedMetamaterialRun {
  double alpha_deg = 0, beta_deg = 0;  // as given or defaulted (check.params holds radians)
  StackedMetamaterialCheck check;      // with the parameters and options it ran on
};

// Exactly one of the two is set: `unit` for a request with a unit, `stacked` for a stack.
struct MetamaterialRun {
  std::optional<MetamaterialUnitRun> unit;
  std::optional<StackedMetamaterialRun> stacked;
};

MetamaterialRun run_metamaterial(const MetamaterialRequest& request);

}  // namespace rigidfold::metamaterial
