// The analysis front door: check (check_foldability, the CLI's `check --json` object), trace
// (trace_motion, numpy arrays per branch) and enumerate_assignments. The GIL is released while
// the kernel works; Ctrl-C stops it at its next unit of work (interrupt_on_signal).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "report/assignments_json.hpp"
#include "report/foldability_json.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/pattern/topology.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace {

py::dict event_dict(const MotionEvent& e) {
  py::dict d;
  d["step"] = e.step;
  d["kind"] = to_string(e.kind);
  d["edge"] = e.edge;
  d["drive"] = e.drive;
  d["angle"] = e.angle;
  return d;
}

py::dict branch_dict(const MotionBranch& b, const CreasePattern& pattern) {
  const auto steps = static_cast<py::ssize_t>(b.steps.size());
  const auto edges = static_cast<py::ssize_t>(pattern.num_edges());
  const auto verts = static_cast<py::ssize_t>(pattern.num_vertices());
  py::array_t<double> drive(steps), residual(steps), mismatch(steps);
  py::array_t<double> rho({steps, edges});
  py::array_t<double> folded({steps, verts, py::ssize_t{3}});
  auto dv = drive.mutable_unchecked<1>();
  auto rv = residual.mutable_unchecked<1>();
  auto mv = mismatch.mutable_unchecked<1>();
  auto av = rho.mutable_unchecked<2>();
  auto fv = folded.mutable_unchecked<3>();
  for (py::ssize_t s = 0; s < steps; ++s) {
    const MotionStep& st = b.steps[static_cast<std::size_t>(s)];
    dv(s) = st.drive;
    rv(s) = st.residual;
    mv(s) = st.folded.relative_mismatch();
    for (py::ssize_t e = 0; e < edges; ++e) av(s, e) = e < st.rho.size() ? st.rho[e] : std::nan("");
    for (py::ssize_t v = 0; v < verts; ++v)
      for (int k = 0; k < 3; ++k)
        fv(s, v, k) = static_cast<std::size_t>(v) < st.folded.vertices.size()
                          ? std::ldexp(st.folded.vertices[static_cast<std::size_t>(v)][k], pattern.length_exponent)
                          : std::nan("");
  }
  py::list events;
  for (const MotionEvent& e : b.events) events.append(event_dict(e));
  py::dict d;
  d["id"] = b.id;
  d["drive_edge"] = b.drive;
  d["to"] = b.to;
  d["reached"] = b.reached;
  d["traced"] = b.traced;
  d["dof"] = b.dof;
  d["stop_reason"] = to_string(b.stop);
  d["stopped_by"] = b.stopped_by;
  d["message"] = b.message;
  d["drive"] = drive;
  d["fold_angles"] = rho;
  d["residual"] = residual;
  d["mismatch"] = mismatch;
  d["folded_vertices"] = folded;
  d["events"] = events;
  d["max_residual"] = b.max_residual;
  d["max_mismatch"] = b.max_mismatch;
  return d;
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def(
      "check",
      [](const CreasePattern& pattern, bool use_assignment, bool force_general, bool explore_branches,
         const std::string& source, std::optional<double> coordinate_tolerance) {
        if (coordinate_tolerance && !(*coordinate_tolerance >= 0 && std::isfinite(*coordinate_tolerance)))
          throw py::value_error("coordinate_tolerance: must be a finite number >= 0 (0: exact data), or None");
        nlohmann::ordered_json j;
        const ProgressSink interrupt = interrupt_on_signal();  // made while the GIL is held
        {
          py::gil_scoped_release release;
          const Topology topology = build_topology(pattern, source);
          FoldabilityOptions options;
          options.use_assignment = use_assignment;
          options.force_general = force_general;
          options.explore_branches = explore_branches;
          options.coordinate_tolerance = coordinate_tolerance;
          options.progress = interrupt;
          j = report::foldability_json(check_foldability(pattern, topology, options));
        }
        return json_to_python(j);
      },
      py::arg("pattern"), py::arg("use_assignment") = true, py::arg("force_general") = false,
      py::arg("explore_branches") = true, py::arg("source") = "pattern", py::arg("coordinate_tolerance") = py::none(),
      "Rigid-foldability verdict (the kernel's check_foldability) as a dict, the object `rigidfold check --json` "
      "prints (without its 'file' key): verdict_class (foldable; foldable within the input's precision; foldable "
      "only in part; not foldable (proof); not foldable (evidence); undecided), verdict, rigidly_foldable, is_proof, "
      "folds_in_part, dof, reason, "
      "model, model_choice, branches, bifurcations, obstruction, max_residual (rad), tolerances, seconds.\n"
      "use_assignment=False ignores the M-V letters; force_general skips multiplier propagation; source names "
      "the pattern in error messages; coordinate_tolerance (`check --tolerance`): how far each coordinate may lie "
      "from the true one (length unit; 0: exact data; None: read off the input), stated in coordinate_precision. Angles in the dict: keys ending in _deg are degrees, the rest radians.");

  m.def(
      "trace",
      [](const CreasePattern& pattern, std::optional<int> drive, std::optional<double> to, int steps,
         bool use_assignment, bool force_general, std::optional<int> branch, bool all_branches,
         const std::string& source, std::optional<double> coordinate_tolerance) {
        MotionTrace trace;
        const ProgressSink interrupt = interrupt_on_signal();  // made while the GIL is held
        {
          py::gil_scoped_release release;
          const Topology topology = build_topology(pattern, source);
          TraceRequest request;
          request.use_assignment = use_assignment;
          request.force_general = force_general;
          request.drive = drive;
          request.to = to;
          request.steps = steps;
          request.branch = branch;
          request.all_branches = all_branches;
          request.coordinate_tolerance = coordinate_tolerance;
          request.progress = interrupt;
          trace = trace_motion(pattern, topology, request);
        }
        py::list branches;
        for (const MotionBranch& b : trace.branches) branches.append(branch_dict(b, pattern));
        py::dict d;
        d["model"] = trace.model_name;
        d["note"] = trace.note;
        d["coordinate_precision"] = trace.coordinate_precision;
        d["branches"] = branches;
        return d;
      },
      py::arg("pattern"), py::arg("drive") = py::none(), py::arg("to") = py::none(), py::arg("steps") = 50,
      py::arg("use_assignment") = true, py::arg("force_general") = false, py::arg("branch") = py::none(),
      py::arg("all_branches") = false, py::arg("source") = "pattern", py::arg("coordinate_tolerance") = py::none(),
      "Folding motion (the kernel's trace_motion, the model `check` picks). drive: driving crease (edge index); "
      "to: its final fold angle (radians, |to| <= pi, default 170 deg its letter's way); steps: equally spaced "
      "driving angles (flat excluded); coordinate_tolerance: as check's (None: read off the input).\n"
      "Returns {'model', 'note', 'coordinate_precision', 'branches': [...]}, each branch a dict: id, drive_edge, traced, dof, "
      "stop_reason, stopped_by, message, to, reached (rad), drive (numpy (S,) rad: the driving crease per step), "
      "fold_angles (numpy (S, E) rad, FOLD sign), residual (numpy (S,) rad: max vertex closure residual), "
      "mismatch (numpy (S,), relative face-placement mismatch), folded_vertices (numpy (S, N, 3), file units), "
      "events (list of dicts: step, kind, edge, drive, angle in rad), max_residual, max_mismatch.\n"
      "Raises InputError with place 'drive', 'branch', 'to' or 'tolerance' for a request that does not fit the pattern.");

  m.def(
      "enumerate_assignments",
      [](const CreasePattern& pattern, bool symmetry, long max_assignments, long max_verdicts, int max_listed,
         const std::string& source, const std::vector<int>& branch) {
        AssignmentEnumeration r;
        const ProgressSink interrupt = interrupt_on_signal();  // made while the GIL is held
        {
          py::gil_scoped_release release;
          const Topology topology = build_topology(pattern, source);
          AssignmentEnumerationOptions options;
          options.symmetry = symmetry;
          options.max_assignments = max_assignments;
          options.max_verdicts = max_verdicts;
          options.max_listed = max_listed;
          options.progress = interrupt;
          options.branch = branch;
          r = enumerate_assignments(pattern, topology, options, source);
        }
        return json_to_python(report::assignment_enumeration_json(r, source, branch));
      },
      py::arg("pattern"), py::arg("symmetry") = true, py::arg("max_assignments") = 50'000'000L,
      py::arg("max_verdicts") = 100'000L, py::arg("max_listed") = 1000, py::arg("source") = "PATTERN",
      py::arg("branch") = std::vector<int>{},
      "Every M-V assignment of the creases (M, V, U edges) that folds each interior vertex flat, in classes "
      "under the pattern's symmetry group and the global M/V flip, each class with its rigid-foldability verdict: "
      "the dict `rigidfold assignments --json` prints (report/assignments_json.hpp): assignments, classes (their "
      "count; None when the search was stopped: classes_reached counts the representatives it reached), "
      "classes_with_verdict, foldable_classes, not_foldable_classes, undecided_classes, complete, creases (edge of "
      "each letter position), listed [{letters, orbit_size, verdict, is_proof, dof, reason}] (the first "
      "max_listed classes), no_assignment_because {vertex, reason} (a vertex off Kawasaki or of odd degree), "
      "symmetry_order, file (source), branch, seconds.\n"
      "branch: one subtree of the search (a list from assignment_branches): its classes only; the subtrees of one "
      "depth, joined in their order, give the whole search's classes (rigidfold.sweep splits the search so).");
  m.def(
      "assignment_branches",
      [](const CreasePattern& pattern, int depth, bool symmetry, const std::string& source) {
        py::gil_scoped_release release;
        const Topology topology = build_topology(pattern, source);
        AssignmentEnumerationOptions options;
        options.symmetry = symmetry;
        return assignment_search_branches(pattern, topology, depth, options, source);
      },
      py::arg("pattern"), py::arg("depth"), py::arg("symmetry") = true, py::arg("source") = "PATTERN",
      "The subtrees of enumerate_assignments' search at `depth` vertices, in search order: lists of letter-set "
      "indices, each a `branch` for enumerate_assignments. Empty when a vertex blocks every assignment.");
}

}  // namespace rigidfold::python
