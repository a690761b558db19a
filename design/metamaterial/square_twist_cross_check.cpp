#include "design/metamaterial/square_twist_cross_check.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "data/generators/square_twist_tessellation.hpp"
#include "design/metamaterial/folded_velocity.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/math/number_text.hpp"

namespace rigidfold::metamaterial {
namespace {

constexpr int kN = 3;                 // twists per side: a centre twist and two periods
constexpr double kFoldedEnd = 0.05;   // states with theta > pi - this are not compared (0/0)
constexpr double kSignProbe = 1e-4;   // drive offset (rad) for nu_HL either side of a stationary point

int vertex_a(int i, int j) { return 4 * (j * kN + i); }

struct Sheet {
  CreasePattern pattern;
  Topology topology;
  int root_rectangle = -1;
  int theta_edge = -1, phi_edge = -1;
  int drive = -1;  // side AB of the centre twist
  std::vector<int> rectangles;  // corner rectangles (four right angles, no twist side)
};

Sheet make_sheet(const SquareTwistUnitParams& unit) {
  generators::SquareTwistTessellationParams sp;
  sp.rows = sp.cols = kN;
  sp.twist = kPi - unit.alpha;
  sp.side = 1.0;
  const double flat = std::cos(unit.alpha) + std::sin(unit.alpha);
  sp.spacing = 2 * unit.b + flat;
  sp.spacing_y = 2 * unit.c + flat;
  sp.layout = generators::SquareTwistTessellationLayout::Type3Rows;
  Sheet s;
  s.pattern = generators::square_twist_tessellation(sp);
  s.topology = build_topology(s.pattern);
  const CreasePattern& p = s.pattern;
  // Centre twist (1, 1) is unmirrored (i + j even): A's o_b runs along +x, o_a along -y.
  const int a = vertex_a(1, 1);
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.edges[e][0] != a && p.edges[e][1] != a) continue;
    const int other = p.edges[e][0] == a ? p.edges[e][1] : p.edges[e][0];
    const Eigen::Vector3d d = p.vertices[other] - p.vertices[a];
    if (std::fabs(d.y()) < 1e-12 && d.x() > 0) s.theta_edge = e;
    if (std::fabs(d.x()) < 1e-12 && d.y() < 0) s.phi_edge = e;
  }
  s.drive = 4 * (1 * kN + 1);  // side AB of twist (1, 1)
  const Fan& fan = s.topology.stars[a].fans[0];
  for (std::size_t k = 0; k < fan.faces.size(); ++k) {
    const auto& f = p.faces[fan.faces[k]];
    const bool has_b = std::find(f.begin(), f.end(), a + 1) != f.end();
    if (std::fabs(fan.sectors[k] - kPi / 2) < 1e-12 && !has_b) s.root_rectangle = fan.faces[k];
  }
  // Corner rectangles: faces with four right angles holding no twist side (edges 0 .. 4 N^2 - 1).
  for (int f = 0; f < p.num_faces(); ++f) {
    const auto& face = p.faces[f];
    if (face.size() != 4) continue;
    bool right = true, holds_side = false;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d u = p.vertices[face[(k + 3) % 4]] - p.vertices[face[k]];
      const Eigen::Vector3d w = p.vertices[face[(k + 1) % 4]] - p.vertices[face[k]];
      right = right && std::fabs(u.normalized().dot(w.normalized())) < 1e-12;
      const int v0 = face[k], v1 = face[(k + 1) % 4];
      if (v0 < 4 * kN * kN && v1 < 4 * kN * kN && v0 / 4 == v1 / 4) holds_side = true;
    }
    if (right && !holds_side) s.rectangles.push_back(f);
  }
  if (s.root_rectangle < 0 || s.theta_edge < 0 || s.phi_edge < 0 || s.rectangles.empty())
    throw std::logic_error("square_twist_cross_check: the generator's sheet does not have the expected layout");
  return s;
}

struct Measured {
  double theta = 0, phi = 0;
  double L = 0, S = 0, H = 0;
  double dL = 0, dS = 0, dH = 0;  // per unit path parameter
  double dtheta = 0;              // dtheta/ds
  double nu_SL = 0, nu_HL = 0;
  double residual = 0;
  double sigma_null = 0, sigma_next = 0;
  double geometry_defect = 0;
};

Measured measure(const Sheet& s, const ClosureSystem& sys, const Eigen::VectorXd& x) {
  Measured m;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Js;
  sys.evaluate(x, r, Js);
  m.residual = r.lpNorm<Eigen::Infinity>();
  const Eigen::MatrixXd J(Js);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const int n = static_cast<int>(J.cols());
  const Eigen::VectorXd sv = svd.singularValues();
  if (J.rows() < n || n < 2) throw std::logic_error("square_twist_cross_check: unexpected closure system size");
  m.sigma_null = sv[n - 1];
  m.sigma_next = sv[n - 2];
  const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
  Eigen::VectorXd rho_dot = sys.edges_from_unknowns(svd.matrixV().col(n - 1));
  // Orient the tangent so that |rho| of the driving crease grows.
  if (rho_dot[s.drive] * rho[s.drive] < 0) rho_dot = -rho_dot;
  const CreasePattern& p = s.pattern;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.num_edges());
  const FoldedVelocity fv = folded_velocity(p, s.topology, rho, rho_dot, zero, s.root_rectangle);

  for (int i = 0; i < kN; ++i) {
    const Eigen::Vector3d dy = fv.positions[vertex_a(i, 2)] - fv.positions[vertex_a(i, 0)];
    const Eigen::Vector3d vy = fv.velocities[vertex_a(i, 2)] - fv.velocities[vertex_a(i, 0)];
    const Eigen::Vector3d dx = fv.positions[vertex_a(2, i)] - fv.positions[vertex_a(0, i)];
    const Eigen::Vector3d vx = fv.velocities[vertex_a(2, i)] - fv.velocities[vertex_a(0, i)];
    if (i == 0) {
      m.L = dy.y() / 2;
      m.dL = vy.y() / 2;
      m.S = dx.x() / 2;
      m.dS = vx.x() / 2;
    }
    m.geometry_defect = std::max({m.geometry_defect, std::fabs(dy.x()), std::fabs(dy.z()), std::fabs(dx.y()),
                                  std::fabs(dx.z()), std::fabs(dy.y() / 2 - m.L), std::fabs(dx.x() / 2 - m.S),
                                  std::fabs(vy.y() / 2 - m.dL), std::fabs(vx.x() / 2 - m.dS)});
  }
  int top = 0, bottom = 0;
  for (int v = 0; v < 4 * kN * kN; ++v) {
    if (fv.positions[v].z() > fv.positions[top].z()) top = v;
    if (fv.positions[v].z() < fv.positions[bottom].z()) bottom = v;
  }
  m.H = fv.positions[top].z() - fv.positions[bottom].z();
  m.dH = fv.velocities[top].z() - fv.velocities[bottom].z();
  for (int f : s.rectangles)
    m.geometry_defect = std::max(m.geometry_defect, (fv.face_motions[f].linear() * Eigen::Vector3d::UnitZ() -
                                                     Eigen::Vector3d::UnitZ()).norm());
  const double rt = rho[s.theta_edge];
  m.theta = std::fabs(rt);
  m.phi = std::fabs(rho[s.phi_edge]);
  m.dtheta = (rt >= 0 ? 1.0 : -1.0) * rho_dot[s.theta_edge];
  m.nu_SL = -(m.S / m.L) * (m.dL / m.dS);
  m.nu_HL = -(m.L / m.H) * (m.dH / m.dL);
  return m;
}

double rel(double traced, double closed) { return std::fabs(traced - closed) / std::max(1.0, std::fabs(closed)); }

}  // namespace

double square_twist_cross_check_min_offset(double alpha, double a) {
  if (!(alpha > kPi / 2 && alpha < kPi)) throw std::invalid_argument("alpha must lie in (pi/2, pi)");
  return -a * std::cos(alpha);
}

SquareTwistCrossCheck square_twist_cross_check(const SquareTwistUnitParams& params,
                                               const SquareTwistCrossCheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!(params.alpha > kPi / 2 && params.alpha < kPi))
    throw InputError("alpha", "must lie strictly between 90 and 180 degrees");
  if (!(std::isfinite(params.a) && params.a > 0)) throw InputError("a", "must be a finite number > 0");
  const double least = square_twist_cross_check_min_offset(params.alpha, params.a);
  if (!(std::isfinite(params.b) && params.b > least * (1 + 1e-9)))
    throw InputError("b", "the traced tessellation needs b > -a cos(alpha) = " + short_text(least) +
                              " (pleat creases between twists of positive length)");
  if (!(std::isfinite(params.c) && params.c > least * (1 + 1e-9)))
    throw InputError("c", "the traced tessellation needs c > -a cos(alpha) = " + short_text(least) +
                              " (pleat creases between twists of positive length)");
  if (options.steps < 10 || options.steps > 2000)
    throw InputError("steps", "must be between 10 and 2000, got " + std::to_string(options.steps));
  if (!(std::isfinite(options.to_deg) && options.to_deg > 90 && options.to_deg < 180))
    throw InputError("to_deg", "must lie strictly between 90 and 180 degrees");

  SquareTwistCrossCheck out;
  out.params = params;
  out.options = options;
  out.twists_per_side = kN;
  // Built and traced at a = 1; lengths scale back by a.
  SquareTwistUnitParams unit = params;
  unit.a = 1.0;
  unit.b = params.b / params.a;
  unit.c = params.c / params.a;
  const Sheet s = make_sheet(unit);

  TraceRequest req;
  req.force_general = true;
  req.drive = s.drive;
  const double sign = s.pattern.assignments[s.drive] == Assignment::Valley ? 1.0 : -1.0;
  req.to = sign * options.to_deg * kPi / 180;
  req.steps = options.steps;
  const MotionTrace trace = trace_motion(s.pattern, s.topology, req);
  if (trace.model != FoldabilityModel::kGeneralLoopClosure || trace.branches.size() != 1 ||
      !trace.branches[0].traced)
    throw NoAnswerError("square-twist cross-check: the general solver did not trace the tessellation" +
                        (trace.branches.empty() ? std::string() : ": " + trace.branches[0].message));
  const MotionBranch& b = trace.branches[0];
  if (b.steps.size() < 10)
    throw NoAnswerError("square-twist cross-check: the trace stopped after " + std::to_string(b.steps.size()) +
                        " steps (" + b.stopped_by + ")");

  const ClosureSystem sys(s.pattern, s.topology);
  out.creases = sys.num_unknowns();
  out.traced_steps = static_cast<int>(b.steps.size());
  out.min_next_singular = INFINITY;
  std::vector<Measured> ms;
  std::vector<int> brackets;  // steps k with dH/ds changing sign between k and k + 1
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const Measured m = measure(s, sys, sys.unknowns_from_edges(b.steps[k].rho));
    ms.push_back(m);
    out.max_residual = std::max(out.max_residual, m.residual);
    out.max_null_singular = std::max(out.max_null_singular, m.sigma_null);
    out.min_next_singular = std::min(out.min_next_singular, m.sigma_next);
    out.max_geometry_defect = std::max(out.max_geometry_defect, m.geometry_defect);
    if (!(m.nu_SL < 0)) out.nu_SL_negative = false;
    if (k > 0 && (ms[k - 1].dH > 0) != (m.dH > 0)) brackets.push_back(static_cast<int>(k) - 1);
    if (m.theta > kPi - kFoldedEnd) continue;
    ++out.compared_steps;
    const SquareTwistUnitState u = square_twist_unit(unit, m.theta);
    out.max_phi_difference = std::max(out.max_phi_difference, std::fabs(m.phi - u.phi));
    out.max_dimension_difference =
        std::max({out.max_dimension_difference, std::fabs(m.L - u.L), std::fabs(m.S - u.S), std::fabs(m.H - u.H)});
    out.max_derivative_difference =
        std::max({out.max_derivative_difference, rel(m.dL / m.dtheta, u.dL), rel(m.dS / m.dtheta, u.dS),
                  rel(m.dH / m.dtheta, u.dH)});
    out.max_ratio_difference = std::max({out.max_ratio_difference, rel(m.nu_SL, u.nu_SL), rel(m.nu_HL, u.nu_HL)});
  }
  out.theta_range_deg[0] = ms.front().theta * 180 / kPi;
  out.theta_range_deg[1] = ms.back().theta * 180 / kPi;

  auto fail = [](const std::string& what, double value, double limit) {
    throw NoAnswerError("square-twist cross-check: " + what + " " + short_text(value) + " exceeds " + short_text(limit), value);
  };
  if (out.max_residual > kCrossCheckResidual) fail("closure residual (rad)", out.max_residual, kCrossCheckResidual);
  if (out.max_null_singular > kCrossCheckNullSingular)
    fail("smallest singular value of the closure Jacobian", out.max_null_singular, kCrossCheckNullSingular);
  if (out.min_next_singular < kCrossCheckNextSingular)
    throw NoAnswerError("square-twist cross-check: second smallest singular value " + short_text(out.min_next_singular) +
                        " below " + short_text(kCrossCheckNextSingular) + ": the traced sheet is not clearly 1 DOF");
  if (out.max_geometry_defect > kCrossCheckGeometry)
    fail("unit-cell geometry defect (periods, parallel rectangles)", out.max_geometry_defect, kCrossCheckGeometry);
  if (out.compared_steps == 0) throw NoAnswerError("square-twist cross-check: no traced state to compare");
  if (out.max_phi_difference > kCrossCheckTolerance) fail("phi difference (rad)", out.max_phi_difference, kCrossCheckTolerance);
  if (out.max_dimension_difference > kCrossCheckTolerance)
    fail("L, S, H difference (relative to a)", out.max_dimension_difference, kCrossCheckTolerance);
  if (out.max_derivative_difference > kCrossCheckTolerance)
    fail("dL, dS, dH / dtheta difference (relative)", out.max_derivative_difference, kCrossCheckTolerance);
  if (out.max_ratio_difference > kCrossCheckTolerance)
    fail("Poisson's ratio difference (relative)", out.max_ratio_difference, kCrossCheckTolerance);
  if (!out.nu_SL_negative) throw NoAnswerError("square-twist cross-check: traced nu_SL is not negative at every step");

  // Stationary points of H on the traced path.
  const auto closed_points = square_twist_height_stationary_points(unit);
  if (brackets.size() != closed_points.size())
    throw NoAnswerError("square-twist cross-check: the traced path has " + std::to_string(brackets.size()) +
                        " sign changes of dH/ds, the closed form " + std::to_string(closed_points.size()) +
                        " stationary points of H (trace more steps or further)");
  const int kd = sys.unknown_of_edge(s.drive);
  double worst_projection = 0;
  std::vector<double> traced_heights;  // at a = 1
  for (std::size_t i = 0; i < brackets.size(); ++i) {
    const int k = brackets[i];
    const bool maximum = ms[k].dH > 0;
    const Eigen::VectorXd x_lo = sys.unknowns_from_edges(b.steps[k].rho);
    const Eigen::VectorXd x_hi = sys.unknowns_from_edges(b.steps[k + 1].rho);
    const double d_lo = x_lo[kd], d_hi = x_hi[kd];
    auto project = [&](double drive) {
      Eigen::VectorXd x0 = x_lo + (drive - d_lo) / (d_hi - d_lo) * (x_hi - x_lo);
      x0[kd] = drive;
      NewtonOptions opt;
      opt.held_unknowns = {kd};
      opt.tolerance = 1e-14;
      opt.max_iterations = 50;
      const NewtonResult nr = newton_project(sys, x0, opt);
      worst_projection = std::max(worst_projection, nr.residual_history.back());
      return measure(s, sys, nr.x);
    };
    auto slope = [&](double drive) { return project(drive).dH; };
    std::uintmax_t iterations = 60;
    const bool up = d_lo < d_hi;  // a mountain drive runs to negative angles
    const auto [r0, r1] = boost::math::tools::toms748_solve(
        slope, up ? d_lo : d_hi, up ? d_hi : d_lo, up ? ms[k].dH : ms[k + 1].dH, up ? ms[k + 1].dH : ms[k].dH,
        boost::math::tools::eps_tolerance<double>(48), iterations);
    const double d_star = 0.5 * (r0 + r1);
    const Measured at = project(d_star);
    const double probe = kSignProbe * (up ? 1.0 : -1.0);
    SquareTwistCrossCheckStationary st;
    st.maximum = maximum;
    st.theta_traced = at.theta;
    st.theta_closed = closed_points[i].theta;
    st.height_traced = at.H * params.a;
    st.height_closed = closed_points[i].height * params.a;
    st.nu_HL_at = at.nu_HL;
    st.nu_HL_before = project(d_star - probe).nu_HL;
    st.nu_HL_after = project(d_star + probe).nu_HL;
    if (maximum != closed_points[i].maximum)
      throw NoAnswerError("square-twist cross-check: traced stationary point " + std::to_string(i + 1) + " is a " +
                          (maximum ? "maximum" : "minimum") + ", the closed form's is not");
    const bool flips = maximum ? (st.nu_HL_before > 0 && st.nu_HL_after < 0) : (st.nu_HL_before < 0 && st.nu_HL_after > 0);
    if (!flips)
      throw NoAnswerError("square-twist cross-check: traced nu_HL does not change sign at stationary point " +
                          std::to_string(i + 1) + " (" + short_text(st.nu_HL_before) + " before, " + short_text(st.nu_HL_after) +
                          " after)");
    out.max_stationary_theta_difference =
        std::max({out.max_stationary_theta_difference, std::fabs(at.theta - closed_points[i].theta),
                  std::fabs(at.phi - closed_points[i].phi)});
    out.max_stationary_height_difference =
        std::max(out.max_stationary_height_difference, std::fabs(at.H - closed_points[i].height));
    traced_heights.push_back(at.H);
    out.stationary.push_back(st);
  }
  if (worst_projection > 1e-13)
    fail("Newton projection residual at a stationary point (rad)", worst_projection, 1e-13);
  if (out.max_stationary_theta_difference > kCrossCheckTolerance)
    fail("stationary theta/phi difference (rad)", out.max_stationary_theta_difference, kCrossCheckTolerance);
  if (out.max_stationary_height_difference > kCrossCheckTolerance)
    fail("stationary height difference (relative to a)", out.max_stationary_height_difference, kCrossCheckTolerance);
  // The global maximum: the traced stationary point at the closed form's index (two maxima of
  // equal height, alpha = 95 or 105 deg, are told apart by theta, not by round-off in H),
  // and no traced maximum higher than it.
  const SquareTwistHeightMaximum closed_max = square_twist_height_maximum(unit);
  std::size_t top = closed_points.size();
  for (std::size_t i = 0; i < closed_points.size(); ++i)
    if (closed_points[i].maximum && closed_points[i].theta == closed_max.theta) top = i;
  if (top == closed_points.size())
    throw std::logic_error("square_twist_cross_check: the closed-form maximum is not a stationary point");
  for (std::size_t i = 0; i < closed_points.size(); ++i)
    if (out.stationary[i].maximum && traced_heights[i] > traced_heights[top] + kCrossCheckTolerance)
      throw NoAnswerError("square-twist cross-check: traced stationary point " + std::to_string(i + 1) +
                          " is higher than the one the closed form finds highest");
  out.height_maximum_traced = traced_heights[top];
  out.height_maximum_theta_traced = out.stationary[top].theta_traced;
  const double dh = std::fabs(out.height_maximum_traced - closed_max.height);
  const double dt = std::fabs(out.height_maximum_theta_traced - closed_max.theta);
  if (dh > kCrossCheckTolerance) fail("height maximum difference (relative to a)", dh, kCrossCheckTolerance);
  if (dt > kCrossCheckTolerance) fail("height maximum theta difference (rad)", dt, kCrossCheckTolerance);
  out.height_maximum_traced *= params.a;
  out.height_maximum_closed = closed_max.height * params.a;
  out.height_maximum_theta_closed = closed_max.theta;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rigidfold::metamaterial
