// Design-layer bindings: the bistable waterbomb base (seed 004).
#include <pybind11/stl.h>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace {

const char* kind_name(waterbomb::EquilibriumKind k) {
  switch (k) {
    case waterbomb::EquilibriumKind::kMinimum: return "minimum";
    case waterbomb::EquilibriumKind::kMaximum: return "maximum";
    case waterbomb::EquilibriumKind::kCuspMaximum: return "cusp maximum (flat state)";
    case waterbomb::EquilibriumKind::kCuspMinimum: return "cusp minimum (flat state)";
  }
  return "?";
}

py::dict equilibrium_dict(const waterbomb::CheckedEquilibrium& e) {
  py::dict d;
  d["kind"] = kind_name(e.path.kind);
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

}  // namespace

void bind_design(py::module_& m) {
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
