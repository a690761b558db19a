// Metamaterial bindings: the square-twist unit cell of seed 003 section 3.3.2
// (design/metamaterial/square_twist_unit.hpp): dimensions and Poisson's ratios along the motion;
// and `rigidfold metamaterial` whole (design/metamaterial/metamaterial_request.hpp), returned as
// the object its --json prints (report/metamaterial_json.hpp), the GIL released while it runs.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "design/metamaterial/metamaterial_request.hpp"
#include "design/metamaterial/square_twist_unit.hpp"
#include "python/bindings/bindings.hpp"
#include "report/metamaterial_json.hpp"

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
  m.def(
      "metamaterial",
      [](const std::optional<std::string>& unit, std::optional<int> stacked, std::optional<double> alpha_deg,
         std::optional<double> beta_deg, std::optional<double> a, std::optional<double> b, std::optional<double> c,
         std::optional<double> l, std::optional<int> samples, const py::object& plot, bool cross_check,
         std::optional<int> cross_check_steps, std::optional<int> layers, std::optional<int> stacked_steps) {
        // None is a flag not given (its default applies; a field that does not apply is refused
        // only when given); cross_check=False is the flag left off.
        MetamaterialRequest request;
        request.unit = unit.value_or("");
        request.stacked = stacked;
        request.alpha_deg = alpha_deg;
        request.beta_deg = beta_deg;
        request.a = a;
        request.b = b;
        request.c = c;
        request.l = l;
        request.samples = samples;
        if (!plot.is_none()) request.plot = py::module_::import("os").attr("fspath")(plot).cast<std::string>();
        if (cross_check) request.cross_check = true;
        request.cross_check_steps = cross_check_steps;
        request.layers = layers;
        request.stacked_steps = stacked_steps;
        request.naming = FieldNaming::kKeywordArguments;
        nlohmann::ordered_json j;
        {
          py::gil_scoped_release release;
          j = report::metamaterial_json(run_metamaterial(request));
        }
        return json_to_python(j);
      },
      py::arg("unit") = py::none(), py::kw_only(), py::arg("stacked") = py::none(), py::arg("alpha_deg") = py::none(),
      py::arg("beta_deg") = py::none(), py::arg("a") = py::none(), py::arg("b") = py::none(), py::arg("c") = py::none(),
      py::arg("l") = py::none(), py::arg("samples") = py::none(), py::arg("plot") = py::none(),
      py::arg("cross_check") = false, py::arg("cross_check_steps") = py::none(), py::arg("layers") = py::none(),
      py::arg("stacked_steps") = py::none(),
      "`rigidfold metamaterial` (docs/cli/metamaterial.md): the dict its --json prints (without 'provenance'), "
      "each keyword its flag. unit: 'square-twist', 'element1', 'element2' or 'element3', followed from flat "
      "to the fold limit: unit, parameters, fold_angle, samples, dimensions, ratios, height_maximum, "
      "height_stationary_points, sign_changes, ratios_defined, checks, rows, and with cross_check=True "
      "(square twist: the traced 3x3 tessellation against the closed forms) cross_check. stacked: 1..4, a "
      "stacked metamaterial instead of a unit (stacked_metamaterial, parameters, ..., states, seconds).\n"
      "alpha_deg, beta_deg (degrees), a, b, c (square twist), l (elements, stacks), samples (3..100000), "
      "cross_check_steps (10..2000), layers (2..16), stacked_steps (8..200): None takes the CLI's default. "
      "plot: a directory to write metamaterial.csv, dimensions.svg and poisson.svg into (written only after "
      "every check passed). Raises InputError (e.place: the keyword, e.g. 'alpha_deg') for a value out of "
      "range or a keyword that does not apply, NoAnswerError when a sample, the cross-check or the stack "
      "fails its checks.");
}

}  // namespace rigidfold::python
