#include "design/metamaterial/stacked_metamaterial_check.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>

#include "design/metamaterial/corrugated_elements.hpp"
#include "design/metamaterial/folded_velocity.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/math/number_text.hpp"

namespace rigidfold::metamaterial {
namespace {

using V3 = Eigen::Vector3d;
using generators::StackedLayerSheet;

struct Layer {
  StackedLayerSheet sheet;
  Topology topology;
  std::vector<Eigen::VectorXd> rho;  // per step, per edge (radians)
};

// The layer traced by the kernel's general solver: its continuation (continue_one_dof:
// pseudo-arclength predictor, Newton corrector on the loop closure of all 21 vertices, no
// closed form), landing on the drive's step values sign * to * k / steps, k = 1..steps.
// The start is the analytic motion at a small fold (0.1 deg of its parameter), projected
// onto the manifold: trace_motion's own start (small equal folds the letters' way) lands on
// another branch of these sheets (11 of metamaterial 1's 52 letters disagree there).
Layer trace_layer(const generators::StackedMetamaterialParams& params, bool reversed,
                  const StackedMetamaterialOptions& options) {
  Layer out;
  out.sheet = generators::stacked_layer_sheet(params, reversed);
  out.topology = build_topology(out.sheet.pattern);
  const ClosureSystem sys(out.sheet.pattern, out.topology);
  const int kd = sys.unknown_of_edge(out.sheet.phi_edge);
  const double sign = out.sheet.pattern.assignments[out.sheet.phi_edge] == Assignment::Valley ? 1.0 : -1.0;
  const double to = options.to_deg * kPi / 180;
  // Start below half the first step of the drive (the drive moves up to 1/|k| times faster
  // than the parameter for metamaterial 4).
  Eigen::VectorXd x0;
  for (double delta = 0.1 * kPi / 180;; delta /= 10) {
    const std::vector<double> start = generators::stacked_layer_fold_angles(params, reversed, kPi - delta);
    x0 = sys.unknowns_from_edges(Eigen::Map<const Eigen::VectorXd>(start.data(), start.size()));
    if (std::fabs(x0[kd]) < 0.5 * to / options.steps) break;
    if (delta < 1e-9) throw NoAnswerError("stacked metamaterial: no analytic start before the first step");
  }
  ContinuationOptions co;
  co.max_angle_step = 0.2;
  co.landing_unknown = kd;
  for (int k = 1; k <= options.steps; ++k) co.landing_values.push_back(sign * to * k / options.steps);
  auto stop = [&](const Eigen::VectorXd& x) { return sign * x[kd] >= to - 1e-12; };
  const ContinuationResult cr = continue_one_dof(sys, x0, x0, stop, co);
  // Each step value: a continuation point that landed on it, else a Newton projection with
  // the drive held from the chord between the two points that bracket it.
  for (int k = 1; k <= options.steps; ++k) {
    const double value = co.landing_values[k - 1];
    for (std::size_t i = 0; i + 1 < cr.points.size(); ++i) {
      const Eigen::VectorXd &xa = cr.points[i].x, &xb = cr.points[i + 1].x;
      if (!(sign * xa[kd] <= sign * value && sign * value <= sign * xb[kd])) continue;
      if (cr.points[i + 1].landing == k - 1) {
        out.rho.push_back(sys.edges_from_unknowns(xb));
        break;
      }
      Eigen::VectorXd guess = xa + (value - xa[kd]) / (xb[kd] - xa[kd]) * (xb - xa);
      guess[kd] = value;
      NewtonOptions no;
      no.held_unknowns = {kd};
      const NewtonResult nr = newton_project(sys, guess, no);
      if (nr.converged) out.rho.push_back(sys.edges_from_unknowns(nr.x));
      break;
    }
  }
  if (static_cast<int>(out.rho.size()) != options.steps)
    throw NoAnswerError("stacked metamaterial: the general solver traced " + std::to_string(out.rho.size()) + " of " +
                        std::to_string(options.steps) + " steps of the " + (reversed ? "reversed " : "") + "layer (" +
                        cr.reason + ")");
  return out;
}

// Positions and velocities along the traced tangent of one layer state.
struct Placed {
  std::vector<V3> x, v;
  double residual = 0;
};

Placed place(const Layer& layer, const ClosureSystem& sys, const Eigen::VectorXd& rho) {
  const Eigen::VectorXd q = sys.unknowns_from_edges(rho);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Js;
  sys.evaluate(q, r, Js);
  Placed p;
  p.residual = r.lpNorm<Eigen::Infinity>();
  const Eigen::MatrixXd J(Js);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const int n = static_cast<int>(J.cols());
  Eigen::VectorXd rho_dot = sys.edges_from_unknowns(svd.matrixV().col(n - 1));
  const int d = layer.sheet.phi_edge;
  if (rho_dot[d] * rho[d] < 0) rho_dot = -rho_dot;  // |rho| of the drive grows along s
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(layer.sheet.pattern.num_edges());
  const FoldedVelocity fv = folded_velocity(layer.sheet.pattern, layer.topology, rho, rho_dot, zero, 0);
  p.x = fv.positions;
  p.v = fv.velocities;
  return p;
}

// The proper rigid motion mapping points `from` onto `to` in the least-squares sense.
Eigen::Isometry3d fit(const std::vector<V3>& from, const std::vector<V3>& to) {
  Eigen::Matrix3Xd a(3, from.size()), b(3, to.size());
  for (std::size_t k = 0; k < from.size(); ++k) {
    a.col(k) = from[k];
    b.col(k) = to[k];
  }
  Eigen::Isometry3d t;
  t.matrix() = Eigen::umeyama(a, b, false);
  return t;
}

double rel(double traced, double closed) { return std::fabs(traced - closed) / std::max(1.0, std::fabs(closed)); }

}  // namespace

StackedMetamaterialCheck stacked_metamaterial_check(const generators::StackedMetamaterialParams& params,
                                                    const StackedMetamaterialOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (options.layers < 2 || options.layers > 16)
    throw InputError("layers", "must be between 2 and 16, got " + std::to_string(options.layers));
  if (options.steps < 8 || options.steps > 200)
    throw InputError("steps", "must be between 8 and 200, got " + std::to_string(options.steps));
  if (!(std::isfinite(options.to_deg) && options.to_deg > 10 && options.to_deg < 175))
    throw InputError("to_deg", "must lie strictly between 10 and 175 degrees");
  const Layer base = trace_layer(params, false, options);   // validates params (generator)
  const Layer twin = trace_layer(params, true, options);
  const StackedLayerSheet& s = base.sheet;
  const ClosureSystem sys(s.pattern, base.topology), sys_twin(twin.sheet.pattern, twin.topology);

  StackedMetamaterialCheck out;
  out.params = params;
  out.options = options;
  out.creases = sys.num_unknowns();
  out.bonding_vertices = static_cast<int>(s.bonding_vertices.size());
  std::vector<int> bottom;  // level-0 nodes
  for (int j = 0; j <= s.nj; ++j)
    for (int i = 0; i <= s.ni; ++i)
      if (s.levels[s.levels_along_j ? j : i] == 0) bottom.push_back(s.node(i, j));
  const int top_node = s.bonding_vertices.front(), o = s.node(0, 0);
  const CorrugatedElementParams ep{params.alpha, params.beta, params.l};
  const double k_abs = std::fabs(std::cos((params.beta + params.alpha) / 2) / std::cos((params.beta - params.alpha) / 2));
  const int N = options.layers;
  std::vector<double> dH_layer;

  for (int step = 0; step < options.steps; ++step) {
    const Eigen::VectorXd& rho = base.rho[step];
    const Placed a = place(base, sys, rho);
    const Placed b = place(twin, sys_twin, twin.rho[step]);
    out.max_residual = std::max({out.max_residual, a.residual, b.residual});
    StackedMetamaterialState st;

    // Layer dimensions and their derivatives.
    const V3 w = a.x[s.node(s.ni, 0)] - a.x[o], dw = a.v[s.node(s.ni, 0)] - a.v[o];
    const V3 l = a.x[s.node(0, s.nj)] - a.x[o], dl = a.v[s.node(0, s.nj)] - a.v[o];
    const V3 c = w.cross(l), dc = dw.cross(l) + w.cross(dl);
    const V3 n = c.normalized(), dn = (dc - n * n.dot(dc)) / c.norm();
    const V3 h = a.x[top_node] - a.x[o], dh = a.v[top_node] - a.v[o];
    const double W = w.norm(), L = l.norm(), H = std::fabs(n.dot(h));
    const double dW = w.dot(dw) / W, dL = l.dot(dl) / L, dH = (n.dot(h) >= 0 ? 1 : -1) * (n.dot(dh) + dn.dot(h));
    dH_layer.push_back(dH);
    st.nu_in = -(dL / L) / (dW / W);
    st.nu_out = -(dH / H) / (dW / W);

    // The stack: alternate layers, each placed on the previous one by its bonding vertices.
    std::vector<std::vector<V3>> layers{a.x};
    double lo = INFINITY, hi = -INFINITY, gap = 0;
    for (int k = 1; k < N; ++k) {
      const std::vector<V3>& src = (k % 2 == 1) ? b.x : a.x;
      const std::vector<int>& bond = (k % 2 == 1) ? s.bonding_vertices : bottom;
      std::vector<V3> from, to;
      for (int v : bond) {
        from.push_back(src[v]);
        to.push_back(layers[k - 1][v]);
      }
      const Eigen::Isometry3d t = fit(from, to);
      std::vector<V3> placed;
      for (const V3& x : src) placed.push_back(t * x);
      for (int v : bond) gap = std::max(gap, (placed[v] - layers[k - 1][v]).norm());
      // The new layer lies beyond the bond: heights along n from the bond's level.
      const double bond_level = n.dot(layers[k - 1][bond.front()]);
      const double side = n.dot(layers[k - 1][bond.front()] - layers[k - 1][k % 2 == 1 ? o : top_node]) >= 0 ? 1 : -1;
      std::vector<bool> on_bond(placed.size(), false);
      for (int v : bond) on_bond[v] = true;  // their distance is the gap above
      for (std::size_t v = 0; v < placed.size(); ++v)
        if (!on_bond[v] && side * (n.dot(placed[v]) - bond_level) < -kStackBond)
          throw NoAnswerError("stacked metamaterial: layer " + std::to_string(k) + " crosses into layer " +
                              std::to_string(k - 1) + " at step " + std::to_string(step + 1));
      layers.push_back(placed);
    }
    for (const auto& layer : layers)
      for (const V3& x : layer) {
        lo = std::min(lo, n.dot(x));
        hi = std::max(hi, n.dot(x));
      }
    st.bond_gap = gap;
    out.max_bond_gap = std::max(out.max_bond_gap, gap);
    st.W = W;
    st.L = L;
    st.H = hi - lo;

    // Closed forms.
    st.phi = kPi - std::fabs(rho[s.phi_edge]);
    CorrugatedElementState e;
    if (s.element == 3) {
      st.theta = kPi - std::fabs(rho[s.theta_edge]);
      e = corrugated_element3_at_theta(ep, st.theta);
      const double inverse = 2 * std::atan(k_abs * std::tan(st.theta / 2));
      out.max_relation_difference = std::max(out.max_relation_difference, std::fabs(inverse - st.phi));
      out.printed_relation_difference =
          std::max(out.printed_relation_difference, std::fabs(element3_theta(ep, st.phi) - st.theta));
    } else {
      st.theta = st.phi;
      e = corrugated_element(s.element == 1 ? CorrugatedElement::kElement1 : CorrugatedElement::kElement2, ep, st.phi);
    }
    st.W_closed = s.cells_W * e.W;
    st.L_closed = s.cells_L * e.L;
    st.H_closed = N * e.H;
    st.nu_in_closed = e.nu_in;
    st.nu_out_closed = e.nu_out;
    out.max_dimension_difference =
        std::max({out.max_dimension_difference, std::fabs(st.W - st.W_closed), std::fabs(st.L - st.L_closed),
                  std::fabs(st.H - st.H_closed)});
    out.max_ratio_difference =
        std::max({out.max_ratio_difference, rel(st.nu_in, st.nu_in_closed), rel(st.nu_out, st.nu_out_closed)});
    out.states.push_back(st);
  }

  auto fail = [](const std::string& what, double value, double limit) {
    throw NoAnswerError("stacked metamaterial: " + what + " " + short_text(value) + " exceeds " + short_text(limit), value);
  };
  if (out.max_residual > kStackResidual) fail("closure residual (rad)", out.max_residual, kStackResidual);
  if (out.max_bond_gap > kStackBond) fail("bond gap between layers", out.max_bond_gap, kStackBond);
  if (out.max_dimension_difference > kStackTolerance)
    fail("W, L, H difference to the closed forms", out.max_dimension_difference, kStackTolerance);
  if (out.max_ratio_difference > kStackTolerance)
    fail("Poisson's ratio difference to (3-28) (relative)", out.max_ratio_difference, kStackTolerance);
  if (out.max_relation_difference > kStackTolerance)
    fail("phi-theta relation difference (rad)", out.max_relation_difference, kStackTolerance);

  // Height maximum: the traced bracket, the closed form's root inside it.
  for (int k = 0; k + 1 < options.steps; ++k) {
    if (!(dH_layer[k] > 0 && dH_layer[k + 1] < 0)) continue;
    const double lo_t = out.states[k + 1].theta, hi_t = out.states[k].theta;  // the angle falls along s
    auto slope = [&](double t) {
      return s.element == 3 ? corrugated_element3_at_theta(ep, t).dH
                            : corrugated_element(s.element == 1 ? CorrugatedElement::kElement1
                                                                : CorrugatedElement::kElement2, ep, t).dH;
    };
    const double flo = slope(lo_t), fhi = slope(hi_t);
    if (!(flo > 0 && fhi < 0))
      throw NoAnswerError("stacked metamaterial: the closed form has no height maximum in the traced bracket");
    std::uintmax_t iterations = 200;
    const auto [r0, r1] = boost::math::tools::toms748_solve(slope, lo_t, hi_t, flo, fhi,
                                                            boost::math::tools::eps_tolerance<double>(52), iterations);
    out.has_maximum = true;
    out.theta_II = 0.5 * (r0 + r1);
    out.phi_II = s.element == 3 ? 2 * std::atan(k_abs * std::tan(out.theta_II / 2)) : out.theta_II;
    const double he = s.element == 3 ? corrugated_element3_at_theta(ep, out.theta_II).H
                                     : corrugated_element(s.element == 1 ? CorrugatedElement::kElement1
                                                                         : CorrugatedElement::kElement2, ep, out.theta_II).H;
    out.height_max = N * he;
    break;
  }
  for (const auto& st : out.states) {
    if (!out.has_maximum) break;
    if (st.phi < out.phi_II && !(st.nu_in < 0 && st.nu_out < 0)) out.negative_3d_before = false;
    if (st.phi > out.phi_II && !(st.nu_in < 0 && st.nu_out > 0)) out.in_negative_out_positive_after = false;
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rigidfold::metamaterial
