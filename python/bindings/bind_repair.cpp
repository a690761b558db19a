// Design for any pattern: repair (the least vertex move to rigid foldability), add_creases (the
// fewest face diagonals) and nearest_closed_state (the closed state nearest to target angles).
// Each returns the dict the CLI prints with --json (report/), plus the resulting pattern. The
// GIL is released while the kernel works.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "design/repair/crease_addition.hpp"
#include "design/repair/pattern_repair.hpp"
#include "design/target/nearest_state.hpp"
#include "kernel/pattern/topology.hpp"
#include "python/bindings/bindings.hpp"
#include "report/nearest_state_json.hpp"
#include "report/repair_json.hpp"

namespace rigidfold::python {

void bind_repair(py::module_& m) {
  m.def(
      "repair",
      [](const CreasePattern& pattern, bool keep_boundary, const std::vector<int>& fixed_vertices, std::optional<double> max_move,
         bool use_letters) {
        RepairOptions options;
        options.use_letters = use_letters;
        options.keep_boundary = keep_boundary;
        options.fixed_vertices = fixed_vertices;
        options.max_move = max_move;
        if (std::string why; !options.IsValid(pattern.num_vertices(), &why)) throw py::value_error(why);
        options.check.progress = interrupt_on_signal();
        RepairSummary s;
        {
          py::gil_scoped_release release;
          s = repair_pattern(pattern, build_topology(pattern), options);
        }
        py::dict d = json_to_python(report::repair_json(s));
        d["repaired"] = succeeded(s.termination) ? py::cast(s.repaired) : py::none();
        return d;
      },
      py::arg("pattern"), py::arg("keep_boundary") = false, py::arg("fixed_vertices") = std::vector<int>{},
      py::arg("max_move") = py::none(), py::arg("use_letters") = true,
      "The least vertex move that makes a flat pattern of degree-4 vertices rigidly foldable with its letters "
      "(`rigidfold repair --json`'s object) with 'repaired': the moved pattern, or None when it does not fold "
      "(see 'termination'). docs/cli/repair.md.");
  m.def(
      "add_creases",
      [](const CreasePattern& pattern, int max_added) {
        CreaseAdditionOptions options;
        options.max_added = max_added;
        if (std::string why; !options.IsValid(&why)) throw py::value_error(why);
        options.check.progress = interrupt_on_signal();
        CreaseAdditionSummary s;
        {
          py::gil_scoped_release release;
          s = add_creases(pattern, build_topology(pattern), options);
        }
        py::dict d = json_to_python(report::crease_addition_json(s));
        py::list patterns;
        for (const CreaseAddition& a : s.found) patterns.append(py::cast(a.pattern));
        d["patterns"] = patterns;
        return d;
      },
      py::arg("pattern"), py::arg("max_added") = 2,
      "The fewest face diagonals (each M or V) whose addition makes the pattern fold with its letters "
      "(`rigidfold repair --add-creases --json`'s object), with 'patterns': one per entry of 'found'.");
  m.def(
      "nearest_closed_state",
      [](const CreasePattern& pattern, const Eigen::VectorXd& target, const std::vector<int>& held_edges) {
        if (target.size() != pattern.num_edges())
          throw py::value_error("target: " + std::to_string(target.size()) + " angles for " + std::to_string(pattern.num_edges()) + " edges");
        if (!target.allFinite()) throw py::value_error("target: every angle must be finite (radians)");
        NearestStateOptions options;
        options.held_edges = held_edges;
        NearestState s;
        {
          py::gil_scoped_release release;
          s = nearest_closed_state(pattern, build_topology(pattern), target, options);
        }
        py::dict d = json_to_python(report::nearest_state_json(s));
        d["angles"] = s.angles;
        return d;
      },
      py::arg("pattern"), py::arg("target"), py::arg("held_edges") = std::vector<int>{},
      "The closed rigid state nearest to target fold angles (per edge, radians), held creases kept at theirs: "
      "`rigidfold fold --target --json`'s 'nearest_state' object, with 'angles' (per edge, radians).");
}

}  // namespace rigidfold::python
