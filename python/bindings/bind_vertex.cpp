// Vertex closed forms (flat-foldable degree-4 multipliers) and the loop-closure system of a
// whole pattern (residual and exact sparse Jacobian, as scipy.sparse).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace {

FlatFoldMode parse_mode(const std::string& mode) {
  if (mode == "equal02") return FlatFoldMode::kEqual02;
  if (mode == "equal13") return FlatFoldMode::kEqual13;
  throw InputError("mode", "'" + mode + "' is not equal02 or equal13");
}

// A ClosureSystem with the topology it was built from (the system keeps no reference to either).
struct PatternClosure {
  PatternClosure(const CreasePattern& pattern, const std::vector<std::pair<int, double>>& fixed, bool close_holes)
      : system(pattern, build_topology(pattern), [&] {
          ClosureOptions o;
          o.fixed = fixed;
          o.close_holes = close_holes;
          return o;
        }()) {}
  ClosureSystem system;
};

void check_size(const Eigen::VectorXd& v, int expected, const char* what) {
  if (v.size() != expected)
    throw InputError(what, "has " + std::to_string(v.size()) + " entries, expected " + std::to_string(expected));
}

}  // namespace

void bind_vertex(py::module_& m) {
  m.def(
      "flat_fold_angles",
      [](const std::array<double, 4>& sectors, const std::string& mode, double rho, int driver, double tol) {
        const std::array<double, 4> r = flat_fold_angles(sectors, parse_mode(mode), rho, driver, tol);
        return Eigen::Vector4d(r[0], r[1], r[2], r[3]);
      },
      py::arg("sectors"), py::arg("mode"), py::arg("rho"), py::arg("driver") = 0, py::arg("tol") = 1e-9,
      "Fold angles rho_0..rho_3 (radians, numpy (4,), FOLD sign) of a flat-foldable degree-4 vertex in one mode, "
      "with crease `driver` at rho (radians, in [-pi, pi]). sectors: alpha_0..alpha_3 (radians, counter-clockwise, "
      "sector i between crease i and i+1; alpha_0 + alpha_2 = alpha_1 + alpha_3 = pi within tol). mode: 'equal02' "
      "(rho_2 = rho_0, rho_3 = -rho_1; the Miura mode) or 'equal13' (rho_3 = rho_1, rho_2 = -rho_0). Exact: "
      "tan(rho_i/2) = w_i * tau. Raises ValueError if the vertex is not flat-foldable or the driver stays flat.");
  m.def(
      "flat_fold_multipliers",
      [](const std::array<double, 4>& sectors, const std::string& mode, double tol) {
        const FlatFoldMultipliers w = flat_fold_multipliers(sectors, parse_mode(mode), tol);
        py::dict d;
        d["direction"] = w.direction;
        d["step"] = w.step;
        d["from_first"] = w.from_first;
        d["odd_crease"] = w.odd_crease;
        return d;
      },
      py::arg("sectors"), py::arg("mode"), py::arg("tol") = 1e-9,
      "Tan-half-angle multipliers of a flat-foldable degree-4 vertex (sectors in radians): direction w with "
      "tan(rho_i/2) = w_i * tau, step k_i = w_{i+1}/w_i, from_first m_i = w_i/w_0, odd_crease (-1 if none).");

  m.def(
      "miura_vertex",
      [](double alpha1, double alpha2, double theta) {
        const MiuraVertexState v = miura_vertex_checked(alpha1, alpha2, theta);
        py::list names;
        for (std::string_view n : kMiuraCreaseNames) names.append(py::str(std::string(n)));
        py::dict d;
        d["phi"] = v.phi;
        d["psi"] = v.psi;
        d["theta"] = v.theta;
        d["theta_limit"] = v.theta_limit;
        d["crease_names"] = names;
        d["fold_angles"] = Eigen::Vector4d(v.fold_angles[0], v.fold_angles[1], v.fold_angles[2], v.fold_angles[3]);
        d["sectors"] = Eigen::Vector4d(v.sectors[0], v.sectors[1], v.sectors[2], v.sectors[3]);
        d["flat_directions"] =
            Eigen::Vector4d(v.flat_directions[0], v.flat_directions[1], v.flat_directions[2], v.flat_directions[3]);
        d["closure_residual"] = check_miura_vertex(v).closure_residual;
        return d;
      },
      py::arg("alpha1"), py::arg("alpha2"), py::arg("theta"),
      "Asymmetric Miura vertex (seed 000; `rigidfold vertex miura`): alpha1, alpha2 in (0, pi/2) radians, theta "
      "the input (radians, |theta| <= theta_limit; half the fold angle of the incoming spinal crease). Returns a "
      "dict: phi, psi, theta_limit (rad), crease_names, fold_angles (numpy (4,), rad, valley > 0), sectors (rad), "
      "flat_directions (rad), closure_residual (rad). Checked before it returns: raises NoAnswerError (with the "
      "residual) if the closed form misses its check, InputError/ValueError for parameters out of range.");

  py::class_<PatternClosure>(m, "ClosureSystem",
                             "The loop-closure system of a whole pattern: unknowns are the fold angles (radians, "
                             "FOLD sign) of the free creases (M, V, U hinges not fixed), 3 residual rows per "
                             "interior vertex (log of the vertex's rotation product, radians), then 6 per hole "
                             "when close_holes.")
      .def(py::init<const CreasePattern&, const std::vector<std::pair<int, double>>&, bool>(), py::arg("pattern"),
           py::arg("fixed") = std::vector<std::pair<int, double>>{}, py::arg("close_holes") = false,
           "fixed: [(edge, fold angle in radians)] creases held at a value. Raises ValueError for a bad fixed edge, "
           "RuntimeError for a sheet with holes without close_holes.")
      .def_property_readonly("num_unknowns", [](const PatternClosure& c) { return c.system.num_unknowns(); })
      .def_property_readonly("num_rows", [](const PatternClosure& c) { return c.system.num_rows(); })
      .def_property_readonly("num_vertices", [](const PatternClosure& c) { return c.system.num_vertices(); },
                             "interior vertices with rows (rows 3k..3k+2 for the k-th)")
      .def_property_readonly("num_holes", [](const PatternClosure& c) { return c.system.num_holes(); })
      .def_property_readonly("num_edges", [](const PatternClosure& c) { return c.system.num_edges(); })
      .def_property_readonly("free_edges", [](const PatternClosure& c) { return c.system.free_edges(); },
                             "edge index of each unknown, increasing")
      .def(
          "vertex_of_block",
          [](const PatternClosure& c, long long k) {
            if (k < 0 || k >= c.system.num_vertices())
              throw py::index_error("vertex_of_block: block " + std::to_string(k) + " out of range [0, " +
                                    std::to_string(c.system.num_vertices()) + ")");
            return c.system.vertex_of_block(static_cast<int>(k));
          },
          py::arg("k"), "vertex index of row block k (rows 3k..3k+2); IndexError outside [0, num_vertices)")
      .def(
          "unknowns_from_edges",
          [](const PatternClosure& c, const Eigen::VectorXd& rho) {
            check_size(rho, c.system.num_edges(), "fold_angles");
            return Eigen::VectorXd(c.system.unknowns_from_edges(rho));
          },
          py::arg("fold_angles"), "per-edge fold angles (radians, (E,)) -> unknowns (free creases)")
      .def(
          "edges_from_unknowns",
          [](const PatternClosure& c, const Eigen::VectorXd& x) {
            check_size(x, c.system.num_unknowns(), "x");
            return Eigen::VectorXd(c.system.edges_from_unknowns(x));
          },
          py::arg("x"), "unknowns -> per-edge fold angles (fixed creases their value, the rest 0)")
      .def(
          "residual",
          [](const PatternClosure& c, const Eigen::VectorXd& x) {
            check_size(x, c.system.num_unknowns(), "x");
            return Eigen::VectorXd(c.system.residual(x));
          },
          py::arg("x"), "residual r(x), numpy (num_rows,), radians (hole translation rows relative to the size)")
      .def(
          "evaluate",
          [](const PatternClosure& c, const Eigen::VectorXd& x) {
            check_size(x, c.system.num_unknowns(), "x");
            Eigen::VectorXd r;
            Eigen::SparseMatrix<double> jac;
            c.system.evaluate(x, r, jac);
            return std::make_pair(r, jac);
          },
          py::arg("x"),
          "(residual numpy (num_rows,), exact Jacobian dr/dx as scipy.sparse.csc_matrix (num_rows, num_unknowns)); "
          "radians per radian. Needs scipy.");
}

}  // namespace rigidfold::python
