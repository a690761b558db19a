// SORCE bindings (seed 002): rolling-contact joint profiles of a flat-foldable degree-4 vertex
// with thick panels (design/sorce/), each fold's profile pair sampled and its diagnostics.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

#include "design/sorce/sorce_fold_report.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/pattern/input_error.hpp"
#include "python/bindings/bindings.hpp"

namespace rigidfold::python {

// A named namespace, so that its using-directive reaches no other bindings file compiled in
// the same unity unit.
namespace sorce_bindings {

using namespace rigidfold::sorce;

VertexParameterization parameterization(const std::string& name) {
  if (name == "symmetric") return VertexParameterization::kSymmetric;
  if (name == "major_linear") return VertexParameterization::kMajorLinear;
  throw InputError("parameterization", "must be \"symmetric\" (eq 35) or \"major_linear\" (eqs 24-25), not \"" + name + "\"");
}

py::list spans(const std::vector<Span>& s) {
  py::list out;
  for (const Span& x : s) out.append(py::make_tuple(x.begin, x.end));
  return out;
}

// One fold: its report `r` and its profiles sampled at `samples` evenly spaced t in [0, 1] (the
// end points from their analytic limits, eqs 29-31; an interior t where gamma' = 0 is skipped).
py::dict fold_dict(const FoldMotion& motion, const FoldReport& r, int samples) {
  const SampledProfiles sampled = sample_profiles(motion, samples);
  const std::vector<double>& ts = sampled.t;
  Eigen::MatrixXd sl(static_cast<Eigen::Index>(ts.size()), 2), sr(static_cast<Eigen::Index>(ts.size()), 2);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    sl.row(static_cast<Eigen::Index>(i)) = sampled.left[i].transpose();
    sr.row(static_cast<Eigen::Index>(i)) = sampled.right[i].transpose();
  }
  py::dict d;
  d["t"] = Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(ts.data(), static_cast<Eigen::Index>(ts.size())));
  d["s_left"] = sl;
  d["s_right"] = sr;
  d["s0"] = r.s0;
  d["arc_length_left"] = r.arc_length_left;
  d["arc_length_right"] = r.arc_length_right;
  d["min_convexity_left"] = r.min_convexity_left;
  d["max_convexity_left"] = r.max_convexity_left;
  d["min_convexity_right"] = r.min_convexity_right;
  d["max_convexity_right"] = r.max_convexity_right;
  d["concave_left"] = spans(r.concave_left);
  d["concave_right"] = spans(r.concave_right);
  d["cusps"] = r.cusps;
  d["ill_behaved"] = r.ill_behaved;
  d["stationary"] = r.stationary;
  d["pivot_at_start"] = r.pivot_at_start;
  d["pivot_at_end"] = r.pivot_at_end;
  d["protrusion_left"] = r.protrusion_left;
  d["protrusion_right"] = r.protrusion_right;
  d["max_rolling_residual"] = r.max_rolling_residual;
  d["max_contact_residual"] = r.max_contact_residual;
  d["end_separation"] = r.end_separation;
  d["stacks"] = r.stacks;
  return d;
}

py::dict vertex_dict(const SorceVertex& v, int samples) {
  if (samples < 3) throw InputError("samples", "must be at least 3");
  py::list folds;
  std::vector<FoldReport> reports;
  ReportOptions options;
  options.samples = samples;
  for (const FoldMotion& f : v.folds) {
    reports.push_back(fold_report(f, options));
    folds.append(fold_dict(f, reports.back(), samples));
  }
  py::dict d;
  d["sectors"] = std::vector<double>(v.sectors.begin(), v.sectors.end());
  d["folds"] = folds;
  d["figure_of_merit"] = figure_of_merit(reports, 0.0);
  return d;
}

}  // namespace sorce_bindings

void bind_sorce(py::module_& m) {
  using namespace sorce_bindings;
  m.def(
      "sorce_vertex",
      [](const std::array<double, 4>& sectors, const std::array<double, 4>& end_offsets, const std::array<double, 4>& thickness,
         const std::string& param, int offset_power, double sign, int samples) {
        if (offset_power < 1) throw InputError("offset_power", "must be >= 1");
        const auto gamma = vertex_fold_angles(sectors, parameterization(param), sign);
        std::array<ScalarFunction, 4> offsets;
        for (int i = 0; i < 4; ++i) offsets[i] = power_function(end_offsets[i], offset_power);
        return vertex_dict(sorce_vertex(sectors, gamma, offsets, thickness), samples);
      },
      py::arg("sectors"), py::arg("end_offsets"), py::arg("thickness"), py::arg("parameterization") = "symmetric",
      py::arg("offset_power") = 1, py::arg("sign") = 1.0, py::arg("samples") = 401,
      "SORCE joints of a flat-foldable degree-4 vertex (seed 002): sectors alpha_1..alpha_4 (radians), panel offsets "
      "z_i(t) = end_offsets[i] * t^offset_power (z_i(1): the flat-folded layer heights, lengths), slab thicknesses, "
      "folding path 'symmetric' (eq 35) or 'major_linear' (eqs 24-25), sign +1 (folds 2, 4 valleys) or -1. Returns "
      "sectors, figure_of_merit (eq 38) and per fold j = 1..4 (list index j - 1): t, s_left, s_right (numpy (K, 2), "
      "each profile in its own panel's frame), s0, arc lengths, convexity extremes and concave spans, cusps, "
      "ill-behaved and stationary t, pivots, protrusion, the largest rolling and contact residuals, stacking.");
  m.def(
      "sorce_circular_vertex",
      [](const std::array<double, 4>& sectors, double r, const std::string& param, int samples) {
        return vertex_dict(circular_split_vertex(sectors, parameterization(param), r), samples);
      },
      py::arg("sectors"), py::arg("r"), py::arg("parameterization") = "symmetric", py::arg("samples") = 401,
      "Circular joints by construction (seed 002 section 11) on a vertex split along its collinear folds 1 and 3 "
      "(alpha_1 + alpha_2 = pi): every panel offset -r tan(gamma_2 / 4), slabs of thickness 2 r. Same dict as "
      "sorce_vertex.");
}

}  // namespace rigidfold::python
