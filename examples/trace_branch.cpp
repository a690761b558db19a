// Example: trace the folding motion of a pattern and print the fold angles per step.
//   trace_branch PATTERN.fold [STEPS]
// Uses the model check_foldability would pick; prints, per step, the driving crease's angle,
// the largest closure residual and the events (a crease at 180 deg, M/V switches).
#include <iostream>
#include <string>

#include "kernel/analysis/trace_motion.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

int main(int argc, char** argv) {
  using namespace rigidfold;
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: trace_branch PATTERN.fold [STEPS]\n";
    return 2;
  }
  try {
    const CreasePattern pattern = read_fold(argv[1]);
    const Topology topology = build_topology(pattern, argv[1]);
    TraceRequest request;
    request.steps = argc == 3 ? std::stoi(argv[2]) : 10;
    const MotionTrace motion = trace_motion(pattern, topology, request);
    std::cout << argv[1] << ": " << motion.model_name << "\n";
    if (!motion.note.empty()) std::cout << "  " << motion.note << "\n";
    for (const MotionBranch& b : motion.branches) {
      std::cout << "  branch " << b.id << ", driving crease " << b.drive << ": " << b.stopped_by << "\n";
      if (!b.traced) std::cout << "    not traced: " << b.message << "\n";
      for (std::size_t k = 0; k < b.steps.size(); ++k) {
        const MotionStep& s = b.steps[k];
        std::cout << "    step " << k + 1 << ": drive " << to_degrees(s.drive) << " deg, residual " << s.residual
                  << " rad";
        for (const MotionEvent& e : s.events) std::cout << ", " << to_string(e.kind) << " at crease " << e.edge;
        std::cout << "\n";
      }
    }
  } catch (const InputError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // std::stoi on a bad STEPS
    std::cerr << "STEPS: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
