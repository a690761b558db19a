// Metamaterial bindings: the square-twist unit cell of seed 003 section 3.3.2
// (design/metamaterial/square_twist_unit.hpp): dimensions and Poisson's ratios along the motion.
#include <pybind11/stl.h>

#include "design/metamaterial/square_twist_unit.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

void bind_metamaterial(py::module_& m) {
  using namespace rigidfold::metamaterial;
  m.def(
      "square_twist_unit",
      [](double theta, double alpha, double a, double b, double c) {
        const SquareTwistUnitParams params{alpha, a, b, c};
        const SquareTwistUnitState s = square_twist_unit(params, theta);
        py::dict d;
        d["theta"] = s.theta;
        d["phi"] = s.phi;
        d["dphi_dtheta"] = s.dphi_dtheta;
        d["L"] = s.L;
        d["S"] = s.S;
        d["H"] = s.H;
        d["dL"] = s.dL;
        d["dS"] = s.dS;
        d["dH"] = s.dH;
        d["nu_SL"] = s.nu_SL;
        d["nu_HL"] = s.nu_HL;
        return d;
      },
      py::arg("theta"), py::arg("alpha") = 5.0 * 3.14159265358979323846 / 6.0, py::arg("a") = 1.0, py::arg("b") = 1.0,
      py::arg("c") = 1.0,
      "The square-twist metamaterial unit (seed 003 eqs 3-29..3-32, rigid T1 tessellation) at pleat fold angle "
      "theta in [0, pi] (radians, magnitude): phi (the other pleats, from 3-31), dphi_dtheta, the unit-cell "
      "dimensions L, S, H (length units of a, b, c) and their derivatives per radian of theta, and the Poisson's "
      "ratios nu_SL = -(S/L) dL/dS and nu_HL = -(L/H) dH/dL (3-32b with the seed's printed definition corrected; "
      "NaN at theta = 0 and pi). alpha in (pi/2, pi) is the vertices' sector (twist angle pi - alpha), a the "
      "central square's side. Raises ValueError for bad parameters.");
  m.def(
      "square_twist_height_stationary_points",
      [](double alpha, double a, double b, double c) {
        const SquareTwistUnitParams params{alpha, a, b, c};
        py::list out;
        for (const SquareTwistStationaryPoint& p : square_twist_height_stationary_points(params)) {
          py::dict d;
          d["theta"] = p.theta;
          d["phi"] = p.phi;
          d["height"] = p.height;
          d["maximum"] = p.maximum;
          out.append(d);
        }
        return out;
      },
      py::arg("alpha") = 5.0 * 3.14159265358979323846 / 6.0, py::arg("a") = 1.0, py::arg("b") = 1.0, py::arg("c") = 1.0,
      "Every stationary point of the unit's height H on (0, pi) (radians; TOMS 748 on the analytic dH/dtheta "
      "after a scan of 4096 steps): theta, phi, height, maximum (else a minimum). nu_HL changes sign at each.");
}

}  // namespace rigidfold::python
