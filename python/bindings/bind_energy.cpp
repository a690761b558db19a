// Energy bindings: the stable states of any pattern with crease springs, the object
// `rigidfold energy --json` prints (kernel/energy/crease_spring_states.hpp, report/energy_json.hpp).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <string>

#include "report/energy_json.hpp"
#include "kernel/energy/crease_spring_states.hpp"
#include "kernel/energy/rest_angles.hpp"
#include "kernel/pattern/topology.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

void bind_energy(py::module_& m) {
  m.def(
      "stable_states",
      [](const CreasePattern& pattern, py::object rest, double k_m, double k_v, double k_u, int starts, std::uint64_t seed,
         const std::string& source) {
        nlohmann::ordered_json j;
        CreaseSpringProblem problem;
        problem.stiffness.mountain = k_m;
        problem.stiffness.valley = k_v;
        problem.stiffness.unassigned = k_u;
        problem.search.random_starts = starts;
        problem.search.seed = seed;
        // rest: a path (str or os.PathLike) read as the CLI's --rest, or per-edge radians.
        const bool rest_is_path = py::isinstance<py::str>(rest) || py::hasattr(rest, "__fspath__");
        std::string rest_path;
        Eigen::VectorXd rest_angles;
        if (rest_is_path)
          rest_path = py::str(py::module_::import("os").attr("fspath")(rest));
        else
          rest_angles = rest.cast<Eigen::VectorXd>();
        {
          py::gil_scoped_release release;
          const Topology topology = build_topology(pattern, source);
          problem.rest = rest_is_path ? read_rest_state(rest_path, pattern, topology) : rest_angles;
          problem.rest_place = rest_is_path ? rest_path : "rest";
          j = report::crease_spring_states_json(pattern, topology, problem, crease_spring_states(pattern, topology, problem));
        }
        return json_to_python(j);
      },
      py::arg("pattern"), py::arg("rest"), py::arg("k_m") = 1.0, py::arg("k_v") = 1.0, py::arg("k_u") = 1.0,
      py::arg("starts") = 24, py::arg("seed") = 1, py::arg("source") = "pattern",
      "Stable states of the pattern with torsional springs at its creases (energy sum 1/2 k (rho - rest)^2), "
      "minimised on the loop-closure manifold with no symmetry imposed from the rest state and `starts` random "
      "starts that respect the letters (seeded: the same everywhere). The dict `rigidfold energy --json` prints "
      "(without its 'file' and 'rest' keys): rest_closure_residual_rad, stiffness, starts, starts_on_manifold, "
      "starts_converged, stable_states [{energy, reached_from_starts, from_rest, keeps_letters, "
      "creases_against_letters, facet_interference, interfering_face_pairs, closure_residual_rad, "
      "stationarity_residual, tangent_dimension, min_reduced_hessian_eigenvalue, fold_angles_deg}].\n"
      "rest: per-edge fold angles (radians, FOLD sign), or the path of a .json of fold angles (degrees, as for "
      "`rigidfold fold --angles`) or of a .fold of the same pattern. k_m, k_v, k_u: stiffness per letter "
      "(>= 0, energy / rad^2). A search, not a proof that no other state exists. Raises InputError (bad rest "
      "state, stiffness, more than 400 free creases), NoAnswerError (no stable state reached).");
}

}  // namespace rigidfold::python
