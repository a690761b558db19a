// Crease patterns: the CreasePattern class (numpy views of its arrays), FOLD load/save and the
// pattern generators of data/generators.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "data/generators/bundled_examples.hpp"
#include "data/generators/double_corrugated.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/validate_pattern.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

namespace gen = rigidfold::generators;

namespace {

py::array_t<double> vertices_array(const CreasePattern& p) {
  py::array_t<double> out({static_cast<py::ssize_t>(p.num_vertices()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (int i = 0; i < p.num_vertices(); ++i)
    for (int k = 0; k < 3; ++k) a(i, k) = std::ldexp(p.vertices[i][k], p.length_exponent);
  return out;
}

py::array_t<std::int64_t> edges_array(const CreasePattern& p) {
  py::array_t<std::int64_t> out({static_cast<py::ssize_t>(p.num_edges()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (int e = 0; e < p.num_edges(); ++e) {
    a(e, 0) = p.edges[e][0];
    a(e, 1) = p.edges[e][1];
  }
  return out;
}

py::list assignment_list(const CreasePattern& p) {
  py::list out;
  for (Assignment a : p.assignments) out.append(py::str(std::string(1, assignment_letter(a))));
  return out;
}

py::array_t<double> fold_angle_array(const std::vector<std::optional<double>>& angles) {
  py::array_t<double> out(static_cast<py::ssize_t>(angles.size()));
  auto a = out.mutable_unchecked<1>();
  for (std::size_t e = 0; e < angles.size(); ++e)
    a(static_cast<py::ssize_t>(e)) = angles[e] ? *angles[e] : std::numeric_limits<double>::quiet_NaN();
  return out;
}

gen::SquareTwistParams twist_params(double twist, double side, double pleat) {
  gen::SquareTwistParams p;
  p.twist = twist;
  p.side = side;
  p.pleat = pleat;
  return p;
}

// A pattern from arrays, completed and validated as a FOLD file's key frame is.
CreasePattern pattern_from_arrays(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                                  const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& edges,
                                  const std::optional<std::vector<std::string>>& assignments,
                                  const std::optional<std::vector<std::vector<int>>>& faces,
                                  const std::optional<py::array_t<double, py::array::c_style | py::array::forcecast>>& fold_angles,
                                  const std::string& source) {
  if (vertices.ndim() != 2 || (vertices.shape(1) != 2 && vertices.shape(1) != 3))
    throw InputError(source + ": vertices", "must be an array of shape (N, 2) or (N, 3)");
  if (edges.ndim() != 2 || edges.shape(1) != 2) throw InputError(source + ": edges", "must be an array of shape (E, 2)");
  CreasePattern p;
  const auto v = vertices.unchecked<2>();
  p.coords_2d = vertices.shape(1) == 2;
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    p.vertices.emplace_back(v(i, 0), v(i, 1), p.coords_2d ? 0.0 : v(i, 2));
  const auto e = edges.unchecked<2>();
  for (py::ssize_t i = 0; i < e.shape(0); ++i) {
    for (int k = 0; k < 2; ++k)
      if (e(i, k) < std::numeric_limits<int>::min() || e(i, k) > std::numeric_limits<int>::max())
        throw InputError(source + ": edges[" + std::to_string(i) + "][" + std::to_string(k) + "]", "out of range");
    p.edges.push_back({static_cast<int>(e(i, 0)), static_cast<int>(e(i, 1))});
  }
  if (assignments) {
    if (assignments->size() != p.edges.size())
      throw InputError(source + ": assignments", "has " + std::to_string(assignments->size()) + " letters for " +
                                                     std::to_string(p.edges.size()) + " edges");
    for (std::size_t i = 0; i < assignments->size(); ++i) {
      const std::string& a = (*assignments)[i];
      const std::optional<Assignment> letter = a.size() == 1 ? assignment_from_letter(a[0]) : std::nullopt;
      if (!letter) throw InputError(source + ": assignments[" + std::to_string(i) + "]", "'" + a + "' is not a FOLD letter");
      p.assignments.push_back(*letter);
    }
  }
  if (faces) p.faces = *faces;
  if (fold_angles) {
    if (fold_angles->ndim() != 1 || fold_angles->shape(0) != static_cast<py::ssize_t>(p.edges.size()))
      throw InputError(source + ": fold_angles", "must be an array of shape (E,)");
    const auto f = fold_angles->unchecked<1>();
    for (py::ssize_t i = 0; i < f.shape(0); ++i)
      p.fold_angles.push_back(std::isnan(f(i)) ? std::nullopt : std::optional<double>(f(i)));
    p.fold_angles_in_file = true;
  }
  complete_and_validate(p, source);
  return p;
}

}  // namespace

void bind_pattern(py::module_& m) {
  py::class_<CreasePattern>(m, "CreasePattern",
                            "A validated crease pattern (FOLD key frame). Arrays are copies; lengths in the "
                            "file's units, fold angles in radians (FOLD sign: valley > 0, mountain < 0).")
      .def(py::init(&pattern_from_arrays), py::arg("vertices"), py::arg("edges"), py::arg("assignments") = py::none(),
           py::arg("faces") = py::none(), py::arg("fold_angles") = py::none(), py::arg("source") = "arrays",
           "A pattern from arrays: vertices (N, 2) or (N, 3), edges (E, 2) vertex indices, assignments (E letters "
           "M V F U B C J; default as a FOLD file without edges_assignment), faces (CCW vertex lists; default "
           "derived), fold_angles (E,) radians (NaN: none). Completed and validated as a FOLD file; raises "
           "InputError naming `source` and the place.")
      .def_property_readonly("vertices", &vertices_array,
                             "numpy (N, 3) float64: reference coordinates in the file's units (z = 0 for 2D input)")
      .def_property_readonly("edges", &edges_array, "numpy (E, 2) int64: vertex indices of each edge")
      .def_property_readonly("assignments", &assignment_list,
                             "list of E one-letter strings: FOLD edges_assignment (M, V, F, U, B, C, J)")
      .def_property_readonly(
          "fold_angles", [](const CreasePattern& p) { return fold_angle_array(p.fold_angles); },
          "numpy (E,) float64: the file's edges_foldAngle in radians (NaN where the file gave none)")
      .def_property_readonly(
          "faces", [](const CreasePattern& p) { return p.faces; },
          "list of faces, each a list of vertex indices counter-clockwise")
      .def_property_readonly("faces_derived", [](const CreasePattern& p) { return p.faces_derived; },
                             "True when the faces were derived from the planar embedding (none in the file)")
      .def_property_readonly("coords_2d", [](const CreasePattern& p) { return p.coords_2d; },
                             "True when the file gave 2D coordinates")
      .def_property_readonly("length_exponent", [](const CreasePattern& p) { return p.length_exponent; },
                             "the kernel works on the coordinates times 2**-length_exponent (0 unless the "
                             "pattern's extent is outside [2**-20, 2**20])")
      .def_property_readonly("warnings", [](const CreasePattern& p) { return p.warnings; },
                             "non-fatal remarks from reading and validation, each naming its place")
      .def_property_readonly("num_vertices", &CreasePattern::num_vertices)
      .def_property_readonly("num_edges", &CreasePattern::num_edges)
      .def_property_readonly("num_faces", &CreasePattern::num_faces)
      .def("to_fold_string", &write_fold_string,
           "The pattern as FOLD JSON text (fold angles in degrees), as `save` writes it.")
      .def("__copy__", [](const CreasePattern& p) { return CreasePattern(p); })
      .def("__deepcopy__", [](const CreasePattern& p, py::dict) { return CreasePattern(p); }, py::arg("memo"))
      .def("__repr__", [](const CreasePattern& p) {
        return "<rigidfold.CreasePattern: " + std::to_string(p.num_vertices()) + " vertices, " +
               std::to_string(p.num_edges()) + " edges, " + std::to_string(p.num_faces()) + " faces>";
      });

  m.def(
      "load", [](const std::string& path) { return read_pattern(path); }, py::arg("path"),
      "Reads a crease pattern: FOLD, an SVG in Origami Simulator's colours, ORIPA .opx or .cp, the format\n"
      "recognised by the file's content. Raises InputError naming the file and the place in it.");
  m.def("parse_fold", &parse_fold, py::arg("text"), py::arg("source") = "<string>",
        "Parses FOLD JSON text; `source` names it in error messages. Raises InputError.");
  m.def("save", &write_fold, py::arg("pattern"), py::arg("path"),
        "Writes the pattern as a FOLD file (atomically: a temporary renamed into place). Fold angles in degrees.");
  m.def(
      "bundled_examples",
      [] {
        py::dict out;
        for (auto& [name, pattern] : gen::bundled_examples()) out[py::str(name)] = std::move(pattern);
        return out;
      },
      "The patterns of data/bundled/ as {name: CreasePattern} (what `rigidfold generate bundle` writes).");

  m.def(
      "miura_ori",
      [](int rows, int cols, double alpha, double a, double b, double perturbation, std::uint64_t seed) {
        gen::MiuraParams p;
        p.rows = rows;
        p.cols = cols;
        p.alpha = alpha;
        p.a = a;
        p.b = b;
        p.perturbation = perturbation;
        p.seed = seed;
        return gen::miura_ori(p);
      },
      py::arg("rows") = 4, py::arg("cols") = 4, py::arg("alpha") = std::numbers::pi / 3, py::arg("a") = 1.0,
      py::arg("b") = 1.0, py::arg("perturbation") = 0.0, py::arg("seed") = 1,
      "Miura-ori of rows x cols panels. alpha: acute panel angle (radians, in (0, pi/2)); a, b: zig-zag and "
      "straight segment lengths; perturbation: uniform random move of interior vertices (length units).\n"
      "Raises InputError naming the parameter.");
  m.def(
      "miura_fold_angles",
      [](const CreasePattern& pattern, int rows, int cols, double alpha, double a, double b, double rho_straight) {
        gen::MiuraParams p;
        p.rows = rows;
        p.cols = cols;
        p.alpha = alpha;
        p.a = a;
        p.b = b;
        return fold_angle_array(gen::miura_fold_angles(pattern, p, rho_straight));
      },
      py::arg("pattern"), py::arg("rows") = 4, py::arg("cols") = 4, py::arg("alpha") = std::numbers::pi / 3,
      py::arg("a") = 1.0, py::arg("b") = 1.0, py::arg("rho_straight") = 0.5,
      "Closed-form fold angles (radians, numpy (E,), NaN on boundary edges) of a Miura-ori made by miura_ori "
      "with the same parameters, at straight-crease fold angle rho_straight (radians).");
  m.def(
      "square_twist",
      [](const std::string& type, double twist, double side, double pleat) {
        const gen::SquareTwistParams p = twist_params(twist, side, pleat);
        if (type == "type1") return gen::square_twist(p, gen::SquareTwistType::Type1);
        if (type == "type2") return gen::square_twist(p, gen::SquareTwistType::Type2);
        if (type == "type3") return gen::square_twist(p, gen::SquareTwistType::Type3);
        if (type == "type4") return gen::square_twist(p, gen::SquareTwistType::Type4);
        if (type == "type1m") return gen::square_twist_modified(p, gen::SquareTwistModifiedType::Type1M);
        if (type == "type2m") return gen::square_twist_modified(p, gen::SquareTwistModifiedType::Type2M);
        throw InputError("type", "'" + type + "' is not one of type1, type2, type3, type4, type1m, type2m");
      },
      py::arg("type") = "type1", py::arg("twist") = std::numbers::pi / 6, py::arg("side") = 1.0,
      py::arg("pleat") = 1.0,
      "Square twist (seed 001): type in type1..type4, or the modified type1m, type2m. twist: radians in "
      "(0, pi/2); side: central square side; pleat: outer crease length. Raises InputError naming the parameter.");
  m.def(
      "waterbomb_base",
      [](int n, double radius, bool corners_mountain) {
        gen::WaterbombParams p;
        p.n = n;
        p.radius = radius;
        p.corners_mountain = corners_mountain;
        return gen::waterbomb_base(p);
      },
      py::arg("n") = 4, py::arg("radius") = 1.0, py::arg("corners_mountain") = true,
      "Waterbomb base with n mountain and n valley creases (n >= 3), circumradius `radius`; corners_mountain: "
      "corner creases M and mid-lines V (False swaps). Raises InputError naming the parameter.");
  m.def(
      "corrugated_unit",
      [](const std::string& unit, double alpha, double beta, double a, double b) {
        gen::CorrugatedUnit u;
        if (unit == "P" || unit == "p") {
          u = gen::CorrugatedUnit::P;
        } else if (unit == "Q" || unit == "q") {
          u = gen::CorrugatedUnit::Q;
        } else {
          throw InputError("unit", "'" + unit + "' is not P or Q");
        }
        gen::CorrugatedParams p;
        p.alpha = alpha;
        p.beta = beta;
        p.a = a;
        p.b = b;
        return gen::corrugated_unit(u, p, gen::corrugated_rigid_assignment(u));
      },
      py::arg("unit") = "P", py::arg("alpha") = 3 * std::numbers::pi / 4, py::arg("beta") = std::numbers::pi / 3,
      py::arg("a") = 1.0, py::arg("b") = 1.0,
      "Double-corrugated unit P or Q (seed 003) with its rigid M-V assignment. alpha: radians in (pi/2, pi); "
      "beta: radians in (pi - alpha, alpha); a, b: i- and j-edge lengths. Raises InputError naming the parameter.");
}

}  // namespace rigidfold::python
