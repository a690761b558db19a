// Design-layer bindings: the bistable waterbomb base (seed 004).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace {

py::dict equilibrium_dict(const waterbomb::CheckedEquilibrium& e) {
  py::dict d;
  d["kind"] = waterbomb::to_string(e.path.kind);
  d["theta"] = e.path.theta;
  d["gamma_m"] = e.path.angles.gamma_m;
  d["gamma_v"] = e.path.angles.gamma_v;
  d["energy"] = e.path.energy;
  d["slope_residual"] = e.path.slope_residual;
  d["slope_below"] = e.path.slope_below;
  d["slope_above"] = e.path.slope_above;
  d["at_validity_limit"] = e.path.at_validity_limit;
  d["closure_residual"] = e.closure_residual;
  d["stationarity_residual"] = e.stationarity_residual;
  d["min_reduced_eigenvalue"] = e.min_reduced_eigenvalue;
  d["stable"] = e.stable_unrestricted;
  return d;
}

design::MiuraString make_string(const std::vector<double>& alpha1, const std::vector<double>& alpha2,
                                const std::vector<double>& lengths, double width) {
  design::MiuraString s;
  s.alpha1 = alpha1;
  s.alpha2 = alpha2;
  s.lengths = lengths;
  s.width = width;
  return s;
}

Eigen::MatrixXd points_matrix(const std::vector<Eigen::Vector3d>& points) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  return out;
}

}  // namespace

void bind_design(py::module_& m) {
  m.def(
      "string_pattern",
      [](const std::vector<double>& alpha1, const std::vector<double>& alpha2, const std::vector<double>& lengths,
         double width) { return design::build_string_pattern(make_string(alpha1, alpha2, lengths, width)); },
      py::arg("alpha1"), py::arg("alpha2"), py::arg("lengths"), py::arg("width") = 1.0,
      "The flat crease pattern of an origami string (a strip of N Miura vertices): alpha1, alpha2 per vertex "
      "(radians, (0, pi/2)), lengths the N + 1 spine segments, width the strip width (length units).");
  m.def(
      "string_forward",
      [](const std::vector<double>& alpha1, const std::vector<double>& alpha2, const std::vector<double>& lengths,
         double theta0, double width) {
        const design::MiuraString s = make_string(alpha1, alpha2, lengths, width);
        const design::StringState st = design::string_forward(s, theta0);
        py::dict d;
        d["theta"] = st.theta;
        d["spine"] = points_matrix(st.spine);
        d["edge_fold_angles"] = st.edge_fold_angles;
        d["shared_crease_mismatch"] = st.shared_crease_mismatch;
        d["min_theta_margin"] = st.min_theta_margin;
        d["limiting_vertex"] = st.limiting_vertex;
        return d;
      },
      py::arg("alpha1"), py::arg("alpha2"), py::arg("lengths"), py::arg("theta0"), py::arg("width") = 1.0,
      "Forward kinematics of an origami string actuated by theta0 (radians; transmitted along the string) in "
      "the pattern's own pose. Returns theta per vertex (rad), spine (numpy (N + 2, 3): S, V_0..V_{N-1}, E), "
      "edge_fold_angles (rad, per edge of string_pattern), shared_crease_mismatch and min_theta_margin (rad), "
      "limiting_vertex. Raises ValueError for an invalid string or |theta_i| >= its limit.");
  m.def(
      "design_string_from_curve",
      [](const Eigen::MatrixXd& points, std::optional<double> theta0, std::optional<double> roll) {
        if (points.cols() != 3) throw std::invalid_argument("points must have shape (M, 3)");
        std::vector<Eigen::Vector3d> pts;
        for (Eigen::Index i = 0; i < points.rows(); ++i) pts.emplace_back(points.row(i).transpose());
        design::CurveDesignOptions options;
        options.theta0 = theta0;
        options.roll = roll;
        design::CurveDesign r;
        {
          py::gil_scoped_release release;
          r = design::design_from_curve(pts, options);
        }
        py::list vertices;
        for (const design::VertexDesign& v : r.vertices) {
          py::dict vd;
          vd["feasible"] = v.feasible;
          vd["reason"] = v.reason;
          vd["alpha1"] = v.alpha1;
          vd["alpha2"] = v.alpha2;
          vd["theta"] = v.theta;
          vd["phi_error"] = v.phi_error;
          vd["psi_error"] = v.psi_error;
          vertices.append(vd);
        }
        py::dict d;
        d["feasible"] = r.feasible;
        d["alpha1"] = r.string.alpha1;
        d["alpha2"] = r.string.alpha2;
        d["lengths"] = r.string.lengths;
        d["theta0"] = r.theta0;
        d["roll"] = r.roll;
        d["start"] = Eigen::Vector3d(r.pose.start);
        d["frame"] = Eigen::Matrix3d(r.pose.frame);
        d["vertices"] = vertices;
        d["first_infeasible"] = r.first_infeasible;
        d["alpha_margin"] = r.alpha_margin;
        return d;
      },
      py::arg("points"), py::arg("theta0") = py::none(), py::arg("roll") = py::none(),
      "Inverse design of an origami string by closed form (design/strings/string_inverse.hpp): the spine "
      "through points (numpy (M, 3), S, the vertices, E). theta0, roll (radians): the actuation and the roll "
      "of the first frame, grid-searched when None. Returns feasible, alpha1, alpha2 (rad), lengths, theta0, "
      "roll, start, frame (the pose), vertices [{feasible, reason, alpha1, alpha2, theta, phi_error, psi_error}], "
      "first_infeasible, alpha_margin (rad).");

  m.def(
      "waterbomb_bistability",
      [](int n, double theta0, double k_m, double k_v) {
        waterbomb::WaterbombBistability b;
        {
          py::gil_scoped_release release;
          b = waterbomb::waterbomb_bistability(n, theta0, k_m, k_v);
        }
        py::list eq, stable;
        for (const auto& e : b.equilibria) eq.append(equilibrium_dict(e));
        for (const auto& e : b.stable_states()) stable.append(equilibrium_dict(e));
        py::dict d;
        d["n"] = b.springs.n;
        d["k_m"] = b.springs.k_m;
        d["k_v"] = b.springs.k_v;
        d["theta0"] = b.theta0;
        d["rest_gamma_m"] = b.springs.rest.gamma_m;
        d["rest_gamma_v"] = b.springs.rest.gamma_v;
        d["theta_limit"] = waterbomb::theta_limit(n);
        d["equilibria"] = eq;
        d["stable_states"] = stable;
        return d;
      },
      py::arg("n"), py::arg("theta0"), py::arg("k_m") = 1.0, py::arg("k_v") = 1.0,
      "Every equilibrium of the crease-spring energy of the n-fold waterbomb base along its symmetric path "
      "(as `rigidfold waterbomb`), springs at rest at path angle theta0 (radians, in [0, theta_limit(n)]); "
      "k_m, k_v: stiffness of each mountain / valley crease (energy per rad^2, >= 0). Returns a dict with "
      "equilibria (increasing theta) and stable_states, each {kind, theta, gamma_m, gamma_v (rad), energy, "
      "closure_residual (rad), stationarity_residual, min_reduced_eigenvalue, stable, at_validity_limit}. "
      "Raises InputError naming n, theta0, k_m or k_v.");
}

}  // namespace rigidfold::python
