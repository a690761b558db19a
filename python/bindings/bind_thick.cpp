// Thick-panel bindings: the vertices of seed 003 ch. 4 as spatial linkages
// (kernel/thick/thick_vertex_models.hpp) with their loop closure (thick_closure_system.hpp).
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <functional>
#include <string>
#include <vector>

#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace {

// A model with the zero-thickness relations of the vertex it thickens.
struct ThickVertex {
  ThickVertexModel model;
  std::function<std::vector<double>(double)> zero_thickness;  // rho0 -> fold angles (radians)
};

py::list joints_list(const ThickVertexModel& model) {
  py::list out;
  for (const ThickJoint& j : model.thick.loops.at(0).joints) {
    py::dict d;
    d["crease"] = j.crease;
    d["angle_sign"] = j.angle_sign;
    d["angle_offset"] = j.angle_offset;
    d["link_length"] = j.link.length;
    d["link_offset"] = j.link.offset;
    d["link_twist"] = j.link.twist;
    out.append(d);
  }
  return out;
}

// The 4 x 4 homogeneous matrix prod_i T_i of the loop at per-crease fold angles (radians).
Eigen::Matrix4d loop_product(const ThickVertexModel& model, const Eigen::VectorXd& fold_angles) {
  const ThickLoop& loop = model.thick.loops.at(0);
  if (fold_angles.size() != model.thick.num_creases)
    throw std::invalid_argument("fold_angles must have " + std::to_string(model.thick.num_creases) + " entries (one per crease)");
  Eigen::VectorXd theta(static_cast<Eigen::Index>(loop.joints.size()));
  for (std::size_t i = 0; i < loop.joints.size(); ++i)
    theta[static_cast<Eigen::Index>(i)] = joint_angle(loop.joints[i], fold_angles[loop.joints[i].crease]);
  return thick_loop_product(loop, theta).matrix();
}

}  // namespace

void bind_thick(py::module_& m) {
  py::class_<ThickVertex>(m, "ThickVertex",
                          "A thick-panel vertex of seed 003 ch. 4: one closed loop of revolute joints (Denavit-Hartenberg "
                          "links), one joint per crease, whose panel thicknesses keep the zero-thickness motion.")
      .def_property_readonly("name", [](const ThickVertex& v) { return v.model.name; })
      .def_property_readonly("sectors", [](const ThickVertex& v) { return v.model.sectors; },
                             "zero-thickness sector angles (radians), sector i between crease i and i+1")
      .def_property_readonly("mountain_valley", [](const ThickVertex& v) { return v.model.mountain_valley; },
                             "per crease on the modelled branch: +1 valley, -1 mountain")
      .def_property_readonly("joints", [](const ThickVertex& v) { return joints_list(v.model); },
                             "per joint in loop order: crease, angle_sign, angle_offset (rad), link_length, link_offset "
                             "(pattern units), link_twist (rad); DH joint angle = angle_offset + angle_sign * rho")
      .def("zero_thickness_fold_angles",
           [](const ThickVertex& v, double rho0) { return v.zero_thickness(rho0); }, py::arg("rho0"),
           "Fold angles (radians, FOLD sign) of the zero-thickness vertex on the modelled branch, from crease 0's "
           "fold angle rho0 (with the sign of mountain_valley[0], |rho0| <= pi): the digest's closed forms.")
      .def("loop_product", [](const ThickVertex& v, const Eigen::VectorXd& rho) { return loop_product(v.model, rho); },
           py::arg("fold_angles"),
           "The loop's product of DH transforms (numpy 4 x 4, lengths in pattern units) at per-crease fold angles "
           "(radians): the identity where the thick vertex closes.");

  m.def(
      "thick_bennett_vertex",
      [](double alpha12, double alpha23, double thickness) {
        return ThickVertex{bennett_vertex(alpha12, alpha23, thickness),
                           [=](double rho0) { return bennett_zero_thickness(alpha12, alpha23, rho0); }};
      },
      py::arg("alpha12"), py::arg("alpha23"), py::arg("thickness"),
      "Bennett model of the flat-foldable degree-4 vertex with sectors (alpha12, alpha23, pi - alpha12, pi - alpha23) "
      "(radians, 0 < alpha12 < alpha23 < pi); link lengths thickness * sin of the sectors.");
  m.def(
      "thick_myard_vertex",
      [](double a, double thickness) {
        return ThickVertex{myard_vertex(a, thickness), [=](double rho0) { return myard_zero_thickness(a, rho0); }};
      },
      py::arg("a"), py::arg("thickness"),
      "Myard model of the symmetric degree-5 vertex with sectors (a, pi/2, pi - 2a, pi/2, a), 0 < a < pi/2.");
  m.def(
      "thick_diamond_vertex",
      [](double a, double t1, double t2) {
        return ThickVertex{diamond_vertex(a, t1, t2), [=](double rho0) { return diamond_zero_thickness(a, rho0); }};
      },
      py::arg("a"), py::arg("t1"), py::arg("t2"),
      "Plane-symmetric Bricard model of the diamond vertex (a, pi - 2a, a, a, pi - 2a, a), 0 < a <= pi/4, "
      "thicknesses t1, t2 > 0.");
  m.def(
      "thick_waterbomb_vertex",
      [](double mu, double thickness) {
        return ThickVertex{waterbomb_vertex(mu, thickness), [](double rho0) { return waterbomb_zero_thickness(rho0); }};
      },
      py::arg("mu"), py::arg("thickness"),
      "Plane-symmetric Bricard model of the waterbomb vertex (pi/2, pi/4, pi/4, pi/4, pi/4, pi/2), link lengths "
      "thickness * (1+mu, 1, mu, mu, 1, 1+mu); only mu = 1 keeps the zero-thickness motion (seed eq 4-60).");
}

}  // namespace rigidfold::python
