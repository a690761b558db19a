// The independent check of seed 003 §3.3.2 (square-twist
// Poisson's ratios and maximum heights agree between the closed forms and the traced
// tessellation to <= 1e-9; nu_HL changes sign at the height maximum).
//
// The sheet: data/generators' square-twist tessellation, layout Type3Rows (every twist
// Type 3 = the seed's T1, whose corner rectangles stay parallel), 3 x 3 twists of side a,
// spacing s. It is traced by the kernel's GENERAL loop-closure solver (trace_motion with
// force_general: pseudo-arclength continuation + Newton projection), not by any closed form.
// At each traced state:
//   - the tangent of the path is the null vector of the closure Jacobian (ClosureSystem,
//     dense SVD; the test asserts a 1-D null space);
//   - the faces are placed from a corner rectangle (root, stays in the plane z = 0) with
//     their exact velocities along that tangent (design/metamaterial/folded_velocity.hpp;
//     positions checked against the kernel's place_faces below);
//   - the unit cell is measured from the placed vertices: twists (i, j) and (i, j + 2) are
//     identical (same mirroring, same letters), so the vector from vertex A of twist (i, 0)
//     to vertex A of twist (i, 2) is 2 L y (asserted: no x or z part, the same for i = 0..2),
//     likewise A(0, j) -> A(2, j) is 2 S x; H is the height range of all twist vertices
//     (every one lies on a corner rectangle, all parallel to the root);
//   - the Poisson's ratios by implicit differentiation along the path:
//     nu_SL = -(S/L) (dL/ds)/(dS/ds), nu_HL = -(L/H) (dH/ds)/(dL/ds) (s: path parameter).
// Map to the seed (3-30): theta = |rho| of vertex A's outer crease o_b (along +x: a pleat
// along S, folding at the smaller rate), phi = |rho| of A's o_a (along -y: a pleat along L).
// Both pleat creases of a pleat fold by the same magnitude with opposite letters, so the
// seed's mountain-positive theta_seed = -rho enters only as this magnitude: theta = |rho|
// (for the measured crease, rho = +theta when it is a valley). The lengths: a = side,
// b = c = (s - a (cos alpha + sin alpha)) / 2, alpha = pi - t (the flat unit is the spacing;
// the pleat panels have width a sin alpha).
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "data/generators/square_twist_tessellation.hpp"
#include "design/metamaterial/folded_velocity.hpp"
#include "design/metamaterial/square_twist_unit.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;
constexpr int kN = 3;  // twists per side

int vertex_a(int i, int j) { return 4 * (j * kN + i); }

struct Sheet {
  generators::SquareTwistTessellationParams sp;
  CreasePattern p;
  Topology topo;
  SquareTwistUnitParams unit;
  int root_rectangle = -1;
  int theta_edge = -1, phi_edge = -1;
  int drive = -1;  // side AB of the centre twist (folds like phi)
};

Sheet make_sheet(double t_deg, double side, double spacing) {
  Sheet s;
  s.sp.rows = s.sp.cols = kN;
  s.sp.twist = t_deg * kPi / 180;
  s.sp.side = side;
  s.sp.spacing = spacing;
  s.sp.layout = generators::SquareTwistTessellationLayout::Type3Rows;
  s.p = generators::square_twist_tessellation(s.sp);
  s.topo = build_topology(s.p);
  const double alpha = kPi - s.sp.twist;
  s.unit.alpha = alpha;
  s.unit.a = side;
  s.unit.b = s.unit.c = (spacing - side * (std::cos(alpha) + std::sin(alpha))) / 2;
  // Centre twist (1, 1) is unmirrored (i + j even): A's o_b runs along +x, o_a along -y.
  const int a = vertex_a(1, 1);
  for (int e = 0; e < s.p.num_edges(); ++e) {
    if (s.p.edges[e][0] != a && s.p.edges[e][1] != a) continue;
    const int other = s.p.edges[e][0] == a ? s.p.edges[e][1] : s.p.edges[e][0];
    const Eigen::Vector3d d = s.p.vertices[other] - s.p.vertices[a];
    if (std::fabs(d.y()) < 1e-12 && d.x() > 0) s.theta_edge = e;
    if (std::fabs(d.x()) < 1e-12 && d.y() < 0) s.phi_edge = e;
  }
  s.drive = 4 * (1 * kN + 1) + 0;  // side AB of twist (1, 1)
  // Root: the corner rectangle at A (right angle at A, not the central square).
  const Fan& fan = s.topo.stars[a].fans[0];
  for (std::size_t k = 0; k < fan.faces.size(); ++k) {
    const auto& f = s.p.faces[fan.faces[k]];
    const bool has_b = std::find(f.begin(), f.end(), a + 1) != f.end();
    if (std::fabs(fan.sectors[k] - kPi / 2) < 1e-12 && !has_b) s.root_rectangle = fan.faces[k];
  }
  return s;
}

struct Measured {
  double theta = 0, phi = 0;
  double L = 0, S = 0, H = 0, dL = 0, dS = 0, dH = 0;
  double nu_SL = 0, nu_HL = 0;
  double residual = 0;
  double sigma_null = 0, sigma_next = 0;  // smallest two singular values of J
  double period_defect = 0;               // non-axial parts and i-dependence of the period vectors
  double rectangle_tilt = 0;              // largest |R_f z - z| over the corner rectangles
  double placement_vs_kernel = 0;         // pairwise-distance difference with place_faces
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
  // Rows >= columns here (108 rows), so there are n singular values.
  m.sigma_null = sv[n - 1];
  m.sigma_next = sv[n - 2];
  const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
  Eigen::VectorXd rho_dot = sys.edges_from_unknowns(svd.matrixV().col(n - 1));
  // Orient the tangent so that |rho| of the driving crease grows.
  if (rho_dot[s.drive] * rho[s.drive] < 0) rho_dot = -rho_dot;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(s.p.num_edges());
  const FoldedVelocity fv = folded_velocity(s.p, s.topo, rho, rho_dot, zero, s.root_rectangle);

  // Period vectors.
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
    m.period_defect = std::max({m.period_defect, std::fabs(dy.x()), std::fabs(dy.z()), std::fabs(dx.y()),
                                std::fabs(dx.z()), std::fabs(dy.y() / 2 - m.L), std::fabs(dx.x() / 2 - m.S),
                                std::fabs(vy.y() / 2 - m.dL), std::fabs(vx.x() / 2 - m.dS)});
  }
  // Height range over the twist vertices.
  int top = 0, bottom = 0;
  for (int v = 0; v < 4 * kN * kN; ++v) {
    if (fv.positions[v].z() > fv.positions[top].z()) top = v;
    if (fv.positions[v].z() < fv.positions[bottom].z()) bottom = v;
  }
  m.H = fv.positions[top].z() - fv.positions[bottom].z();
  m.dH = fv.velocities[top].z() - fv.velocities[bottom].z();
  // Every face with four right angles (the corner rectangles and the central squares):
  // the rectangles stay parallel to the root. A face is a corner rectangle if it holds no
  // twist side (sides are edges 0 .. 4 N^2 - 1).
  for (int f = 0; f < s.p.num_faces(); ++f) {
    const auto& face = s.p.faces[f];
    if (face.size() != 4) continue;
    bool right = true, holds_side = false;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d a = s.p.vertices[face[(k + 3) % 4]] - s.p.vertices[face[k]];
      const Eigen::Vector3d b = s.p.vertices[face[(k + 1) % 4]] - s.p.vertices[face[k]];
      right = right && std::fabs(a.normalized().dot(b.normalized())) < 1e-12;
      for (int e = 0; e < 4 * kN * kN; ++e) {
        const auto& ed = s.p.edges[e];
        if ((ed[0] == face[k] && ed[1] == face[(k + 1) % 4]) || (ed[1] == face[k] && ed[0] == face[(k + 1) % 4]))
          holds_side = true;
      }
    }
    if (!right || holds_side) continue;
    m.rectangle_tilt = std::max(m.rectangle_tilt, (fv.face_motions[f].linear() * Eigen::Vector3d::UnitZ() -
                                                   Eigen::Vector3d::UnitZ()).norm());
  }
  // The kernel's own placement (its own spanning tree and root) gives the same shape.
  const FoldedGeometry g = place_faces(s.p, s.topo, rho, zero);
  for (int u = 0; u < 4 * kN * kN; u += 3)
    for (int v = u + 1; v < 4 * kN * kN; v += 2)
      m.placement_vs_kernel =
          std::max(m.placement_vs_kernel, std::fabs((g.vertices[u] - g.vertices[v]).norm() -
                                                    (fv.positions[u] - fv.positions[v]).norm()));
  m.theta = std::fabs(rho[s.theta_edge]);
  m.phi = std::fabs(rho[s.phi_edge]);
  m.nu_SL = -(m.S / m.L) * (m.dL / m.dS);
  m.nu_HL = -(m.L / m.H) * (m.dH / m.dL);
  return m;
}

struct Case {
  double t_deg, side, spacing;
};

// The seed's a = b = c at its alpha = 5 pi / 6 (t = 30 deg), and other twists and spacings.
std::vector<Case> cases() {
  std::vector<Case> out;
  for (double t : {30.0, 15.0, 60.0, 75.0}) {  // 75 deg: H has two maxima and a minimum
    const double alpha = kPi - t * kPi / 180;
    out.push_back({t, 1.0, 2.0 + std::cos(alpha) + std::sin(alpha)});  // a = b = c = 1
  }
  out.push_back({40.0, 1.3, 2.6});
  return out;
}

double rel(double a, double b) { return std::fabs(a - b) / std::max(1.0, std::fabs(b)); }

TEST(MetamaterialSquareTwistTessellation, TracedUnitCellMatchesClosedFormsAndHeightMaximum) {
  for (const Case& c : cases()) {
    const std::string where = "t " + std::to_string(c.t_deg) + " side " + std::to_string(c.side) + " spacing " +
                              std::to_string(c.spacing);
    const Sheet s = make_sheet(c.t_deg, c.side, c.spacing);
    ASSERT_GE(s.root_rectangle, 0) << where;
    ASSERT_GE(s.theta_edge, 0) << where;
    ASSERT_GE(s.phi_edge, 0) << where;
    TraceRequest req;
    req.force_general = true;
    req.drive = s.drive;
    const double sign = s.p.assignments[s.drive] == Assignment::Valley ? 1.0 : -1.0;
    req.to = sign * 170.0 * kPi / 180;
    req.steps = 40;
    const MotionTrace trace = trace_motion(s.p, s.topo, req);
    ASSERT_EQ(trace.model, FoldabilityModel::kGeneralLoopClosure) << where;
    ASSERT_EQ(trace.branches.size(), 1u) << where;
    const MotionBranch& b = trace.branches[0];
    ASSERT_TRUE(b.traced) << where << ": " << b.message;
    EXPECT_EQ(b.dof, 1) << where;
    ASSERT_GE(b.steps.size(), 10u) << where;

    const ClosureSystem sys(s.p, s.topo);
    const SquareTwistHeightMaximum closed_max = square_twist_height_maximum(s.unit);
    double worst_dim = 0, worst_nu = 0, worst_phi = 0, worst_geom = 0;
    std::vector<int> brackets;  // steps k with dH/ds changing sign between k and k + 1
    std::vector<Measured> ms;
    for (std::size_t k = 0; k < b.steps.size(); ++k) {
      const Eigen::VectorXd x = sys.unknowns_from_edges(b.steps[k].rho);
      const Measured m = measure(s, sys, x);
      ms.push_back(m);
      EXPECT_LE(m.residual, 1e-12) << where << " step " << k;
      EXPECT_LE(m.sigma_null, 1e-11) << where << " step " << k;
      EXPECT_GE(m.sigma_next, 1e-4) << where << " step " << k;  // a 1-D null space: 1 DOF
      worst_geom = std::max({worst_geom, m.period_defect, m.rectangle_tilt, m.placement_vs_kernel});
      if (k > 0 && (ms[k - 1].dH > 0) != (m.dH > 0)) brackets.push_back(static_cast<int>(k) - 1);
      if (m.theta > kPi - 0.05) continue;  // the closed forms' 0/0 near the folded end
      const SquareTwistUnitState u = square_twist_unit(s.unit, m.theta);
      worst_phi = std::max(worst_phi, std::fabs(m.phi - u.phi));
      worst_dim = std::max({worst_dim, std::fabs(m.L - u.L), std::fabs(m.S - u.S), std::fabs(m.H - u.H)});
      worst_nu = std::max({worst_nu, rel(m.nu_SL, u.nu_SL), rel(m.nu_HL, u.nu_HL)});
      // Ratios of the path derivatives (independent of the path's parametrisation).
      worst_nu = std::max({worst_nu, rel(m.dS / m.dL, u.dS / u.dL), rel(m.dH / m.dL, u.dH / u.dL)});
    }
    EXPECT_LE(worst_geom, 5e-11) << where;  // measured <= 6e-12
    EXPECT_LE(worst_phi, 1e-10) << where;
    EXPECT_LE(worst_dim, 1e-10) << where;
    EXPECT_LE(worst_nu, 1e-9) << where;
    // The in-plane ratio is negative all along the traced path.
    for (const Measured& m : ms) EXPECT_LT(m.nu_SL, 0.0) << where;

    // The stationary points of H on the traced path: dH/ds changes sign between two steps;
    // each located by TOMS 748 on the driving crease's angle, every value a Newton projection
    // (drive held) and a fresh null vector. They must be the closed form's, in order.
    const auto closed_points = square_twist_height_stationary_points(s.unit);
    ASSERT_EQ(brackets.size(), closed_points.size()) << where << ": the trace did not pass every stationary point";
    const int kd = sys.unknown_of_edge(s.drive);
    double worst_max_theta = 0, worst_max_h = 0, traced_highest = 0, traced_highest_theta = 0;
    for (std::size_t i = 0; i < brackets.size(); ++i) {
      const int k = brackets[i];
      const bool maximum = ms[k].dH > 0;
      EXPECT_EQ(maximum, closed_points[i].maximum) << where;
      // nu_HL has the sign of dH/ds: it changes sign across the bracket.
      EXPECT_LT(ms[k].nu_HL * ms[k + 1].nu_HL, 0.0) << where;
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
        EXPECT_LE(nr.residual_history.back(), 1e-13) << where;
        return measure(s, sys, nr.x);
      };
      auto slope = [&](double drive) { return project(drive).dH; };
      std::uintmax_t iterations = 60;
      // TOMS 748 wants a < b; a mountain drive runs to negative angles.
      const bool up = d_lo < d_hi;
      const auto [r0, r1] = boost::math::tools::toms748_solve(
          slope, up ? d_lo : d_hi, up ? d_hi : d_lo, up ? ms[k].dH : ms[k + 1].dH, up ? ms[k + 1].dH : ms[k].dH,
          boost::math::tools::eps_tolerance<double>(48), iterations);
      const double d_star = 0.5 * (r0 + r1);
      const Measured at = project(d_star);
      worst_max_theta = std::max({worst_max_theta, std::fabs(at.theta - closed_points[i].theta),
                                  std::fabs(at.phi - closed_points[i].phi)});
      worst_max_h = std::max(worst_max_h, std::fabs(at.H - closed_points[i].height));
      if (maximum && at.H > traced_highest) {
        traced_highest = at.H;
        traced_highest_theta = at.theta;
      }
      // nu_HL changes sign at the stationary point, on the traced sheet (1e-4 rad of drive).
      const double step = 1e-4 * (d_hi > d_lo ? 1.0 : -1.0);
      const double before = project(d_star - step).nu_HL, after = project(d_star + step).nu_HL;
      EXPECT_GT(maximum ? before : after, 0.0) << where;
      EXPECT_LT(maximum ? after : before, 0.0) << where;
      EXPECT_LE(std::fabs(at.nu_HL), 1e-8) << where;
    }
    EXPECT_LE(worst_max_theta, 1e-9) << where;
    EXPECT_LE(worst_max_h, 1e-9) << where;
    // The global maximum height.
    EXPECT_LE(std::fabs(traced_highest - closed_max.height), 1e-9) << where;
    EXPECT_LE(std::fabs(traced_highest_theta - closed_max.theta), 1e-9) << where;

    char text[256];
    std::snprintf(text, sizeof text,
                  "steps %zu dims %.2e nu %.2e phi %.2e geom %.2e | %zu stationary: theta/phi %.2e H %.2e, "
                  "max height %.2e",
                  b.steps.size(), worst_dim, worst_nu, worst_phi, worst_geom, brackets.size(), worst_max_theta,
                  worst_max_h, std::fabs(traced_highest - closed_max.height));
    RecordProperty("agreement_t" + std::to_string(static_cast<int>(c.t_deg)), text);
    std::printf("[ agreement ] %s: %s\n", where.c_str(), text);
  }
}


// folded_velocity's velocities are the derivative of its positions: at an arbitrary (not
// closed) fold-angle vector, against the 5-point central difference of the positions along a
// random direction (h = 1e-3: truncation h^4/30 |x^(5)| with |x^(5)| ~ (sum |rho_dot|)^5 ~ 1e4
// on this 3 x 3 sheet, below 1e-9; round-off ~1e-16 / h). (On the closure manifold the
// positions are compared with the kernel's place_faces in measure() above.)
TEST(MetamaterialFoldedVelocity, VelocitiesAreTheDerivativeOfPositions) {
  const Sheet s = make_sheet(30, 1.0, 2.6);
  const int ne = s.p.num_edges();
  Eigen::VectorXd rho(ne), dir(ne);
  for (int e = 0; e < ne; ++e) {
    rho[e] = 0.3 * std::sin(1.7 * e + 0.4);
    dir[e] = std::cos(2.3 * e + 1.1);
  }
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(ne);
  const FoldedVelocity fv = folded_velocity(s.p, s.topo, rho, dir, zero, s.root_rectangle);
  const double h = 1e-3;
  auto at = [&](double t) { return folded_velocity(s.p, s.topo, rho + t * dir, zero, zero, s.root_rectangle); };
  const FoldedVelocity p1 = at(h), m1 = at(-h), p2 = at(2 * h), m2 = at(-2 * h);
  double worst = 0;
  for (int v = 0; v < s.p.num_vertices(); ++v) {
    const Eigen::Vector3d fd =
        (8 * (p1.positions[v] - m1.positions[v]) - (p2.positions[v] - m2.positions[v])) / (12 * h);
    worst = std::max(worst, (fd - fv.velocities[v]).norm());
  }
  EXPECT_LE(worst, 1e-8);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  RecordProperty("worst_velocity_vs_fd", text);
  // The root face does not move; a zero direction gives zero velocities.
  for (int v : s.p.faces[s.root_rectangle]) {
    EXPECT_LE((fv.positions[v] - s.p.vertices[v]).norm(), 1e-15);
    EXPECT_LE(fv.velocities[v].norm(), 1e-15);
  }
  const FoldedVelocity still = folded_velocity(s.p, s.topo, rho, zero, zero, s.root_rectangle);
  for (const auto& w : still.velocities) EXPECT_EQ(w.norm(), 0.0);
  EXPECT_THROW(folded_velocity(s.p, s.topo, rho, dir, zero, s.p.num_faces()), std::invalid_argument);
  EXPECT_THROW(folded_velocity(s.p, s.topo, rho.head(3), dir, zero, 0), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
