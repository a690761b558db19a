// Example: load a crease pattern and ask whether it folds rigidly.
//   check_pattern PATTERN.fold
// Prints the verdict class, the model that decided it, the DOF and, for a yes, each branch's
// range and closure residual; for a no, the obstruction. Exit 0, or 2 on bad input.
#include <iostream>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

int main(int argc, char** argv) {
  using namespace rigidfold;
  if (argc != 2) {
    std::cerr << "usage: check_pattern PATTERN.fold\n";
    return 2;
  }
  try {
    const CreasePattern pattern = read_fold(argv[1]);
    const Topology topology = build_topology(pattern, argv[1]);
    const FoldabilityReport report = check_foldability(pattern, topology);  // letters as given
    std::cout << argv[1] << ": " << to_string(report.verdict) << " (" << report.model_name << ")\n"
              << "  " << report.reason << "\n";
    if (report.foldable()) {
      std::cout << "  DOF " << report.dof << "\n";
      for (const TracedBranch& b : report.branches)
        std::cout << "  branch " << b.id << ": crease " << b.driving_edge << " from " << to_degrees(b.driving_begin)
                  << " to " << to_degrees(b.driving_end) << " deg, max residual " << b.max_residual << " rad, "
                  << b.stop_text() << "\n";
    }
    if (report.obstruction) std::cout << "  obstruction: " << report.obstruction->message << "\n";
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  return 0;
}
