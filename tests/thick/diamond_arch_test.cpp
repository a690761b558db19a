// The diamond arch of §4.4.1, built, traced and shown mobile (seed 003 §4.4.1,
// Fig. 4-12, lost: reconstructed in data/generators/diamond_arch.hpp): a row of six-crease
// diamond vertices (sectors (4-29), a = pi/6 as in the seed's figure), its zero-thickness
// symmetric motion (4-39), and the thick arch with one plane-symmetric Bricard loop per vertex
// (4-40, 4-41) made of hinge heights, closed and traced by the core's ClosureSystem (one SE(3)
// hole per vertex, pseudo-arclength continuation) and checked with thick_mobility.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "data/generators/diamond_arch.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/panel_compatibility.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/thick/thick_check.hpp"
#include "kernel/thick/thick_mobility.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

generators::DiamondArchParams arch_params() {
  generators::DiamondArchParams p;
  p.vertices = 6;
  p.a = kPi / 6;
  return p;
}

// Dihedral phi = pi - |rho|.
double dihedral(double rho) { return kPi - std::abs(rho); }

// Independent construction of one folded diamond vertex from (4-39) alone: the creases as unit
// vectors on the sphere, c1 and c2 at +-(pi/2 - a) about x in the xy-plane (arc c1 c2 =
// pi - 2a), c0 at arc a from c1 with the sector angle (the dihedral) phi2 at c1, c3 its mirror
// image in y (the plane symmetry). Returns the turning angle of the valley line c3 -> V -> c0,
// pi - angle(c0, c3): how much the arch bends at one vertex.
double valley_turning_from_4_39(double a, double phi1) {
  const double phi2 = 2 * std::atan(std::cos(a) * std::tan(0.5 * phi1));
  const double h = 0.5 * kPi - a;
  const Eigen::Vector3d c1(std::cos(h), -std::sin(h), 0.0);
  const Eigen::Vector3d towards_c2(std::sin(h), std::cos(h), 0.0);
  // The arc from c1 to c0 leaves c1 at the angle phi2 from the arc to c2.
  const Eigen::Vector3d out = std::cos(phi2) * towards_c2 + std::sin(phi2) * c1.cross(towards_c2);
  const Eigen::Vector3d c0 = std::cos(a) * c1 + std::sin(a) * out;
  const Eigen::Vector3d c3(c0.x(), -c0.y(), c0.z());
  return kPi - std::acos(std::clamp(c0.dot(c3), -1.0, 1.0));
}

TEST(DiamondArch, ZeroThicknessStripFollowsTheSymmetricMotionAndItsDofIsCounted) {
  const generators::DiamondArchParams params = arch_params();
  const int n = params.vertices;
  const CreasePattern flat = generators::diamond_arch(params);
  const Topology topology = build_topology(flat);
  ASSERT_EQ(static_cast<int>(topology.interior_vertices.size()), n);
  EXPECT_EQ(flat.num_faces(), 4 * n + 2);
  const ClosureSystem zero(flat, topology);

  // The kernel's solver, not (4-39), fills in the diagonals: valley creases and each vertex's
  // c1 held at the symmetric motion's values, c2, c4, c5 of every vertex free (3 unknowns for
  // the 3 rows of its loop), Newton from a start 0.05 rad off. (4-39) says they come back to
  // c1's value.
  double worst_413 = 0.0, worst_residual = 0.0;
  int dof = -1;
  for (int k = 1; k <= 9; ++k) {
    const double rho_v = kPi * 0.1 * k;
    const Eigen::VectorXd expected = generators::diamond_arch_symmetric_state(flat, params, rho_v);
    Eigen::VectorXd start = expected;
    NewtonOptions newton;
    newton.tolerance = 1e-14;
    for (int e = 0; e < flat.num_edges(); ++e) {
      if (zero.unknown_of_edge(e) < 0) continue;
      const bool c1 = e > n && (e - (n + 1)) % 4 == 0;
      if (e <= n || c1) newton.held_unknowns.push_back(zero.unknown_of_edge(e));
      else start[e] += 0.05;
    }
    const NewtonResult r = newton_project(zero, zero.unknowns_from_edges(start), newton);
    ASSERT_TRUE(r.converged) << "rho_valley = " << rho_v;
    const Eigen::VectorXd got = zero.edges_from_unknowns(r.x);
    worst_residual = std::max(worst_residual, zero.residual(r.x).cwiseAbs().maxCoeff());
    // (4-39) in dihedral form on every vertex: phi1 = phi4 (shared valley creases), phi2 = phi3 = phi5 = phi6,
    // tan(phi2/2) = cos a tan(phi1/2).
    for (int i = 1; i <= n; ++i) {
      const double phi1 = dihedral(got[i]), phi4 = dihedral(got[i - 1]);
      worst_413 = std::max(worst_413, std::abs(phi1 - phi4));
      for (int d = 0; d < 4; ++d) {
        const double phi_d = dihedral(got[n + 1 + 4 * (i - 1) + d]);
        worst_413 = std::max(worst_413, std::abs(std::tan(0.5 * phi_d) - std::cos(params.a) * std::tan(0.5 * phi1)));
        EXPECT_LT(got[n + 1 + 4 * (i - 1) + d], 0.0) << "diagonals are mountains";
      }
    }
    // DOF of the strip at this folded state, rank-revealed (RankOptions default: relative 1e-9).
    Eigen::VectorXd res;
    Eigen::SparseMatrix<double> J;
    zero.evaluate(r.x, res, J);
    const RankResult rank = jacobian_rank(J);
    EXPECT_GT(rank.sigma_kept, 1e3 * rank.threshold) << "rho_valley = " << rho_v;
    if (dof < 0) dof = rank.dof;
    EXPECT_EQ(rank.dof, dof) << "rho_valley = " << rho_v;
  }
  EXPECT_LE(worst_residual, 1e-13);
  EXPECT_LE(worst_413, 1e-12);
  // 5N + 1 creases, 3 independent rows per vertex loop (the vertices share only valley creases,
  // so no row of one depends on another's): the strip has 2N + 1 DOF, of which the symmetric
  // motion is one curve.
  EXPECT_EQ(dof, zero.num_unknowns() - 3 * n);
  EXPECT_EQ(dof, 2 * n + 1);
  std::printf("zero-thickness diamond strip (N = %d, a = 30 deg): (4-39) holds to %.1e on the kernel's solutions, residual "
              "%.1e; DOF %d (%d creases, %d loop rows)\n",
              n, worst_413, worst_residual, dof, zero.num_unknowns(), 3 * n);
}

TEST(DiamondArch, PanelsAgreeOnlyWithTheModelTurnedAtEveryOtherVertex) {
  const generators::DiamondArchParams params = arch_params();
  const CreasePattern flat = generators::diamond_arch(params);
  const Topology topology = build_topology(flat);
  const double t1 = 0.03, t2 = 0.02;
  const generators::DiamondArchThick thick = generators::diamond_arch_thick(flat, topology, params, t1, t2);
  // Every face is asked for a thickness, and it is t1, t2 or t1 + t2.
  int n_t1 = 0, n_t2 = 0, n_t12 = 0;
  for (double t : thick.panel_thickness) {
    n_t1 += std::abs(t - t1) < 1e-15;
    n_t2 += std::abs(t - t2) < 1e-15;
    n_t12 += std::abs(t - (t1 + t2)) < 1e-15;
  }
  EXPECT_EQ(n_t1 + n_t2 + n_t12, flat.num_faces());
  EXPECT_EQ(n_t2, 2 * params.vertices);  // the triangles T_{i-1} V_i T_i, B_{i-1} V_i B_i
  EXPECT_GT(n_t1, 0);
  EXPECT_GT(n_t12, 0);
  // One orientation everywhere (the first cyclic match at every vertex): a diamond half is asked
  // t1 by one end and t1 + t2 by the other.
  const ThickVertexModel model = diamond_vertex(params.a, t1, t2);
  std::vector<PanelThicknessClaim> same;
  for (int i = 1; i <= params.vertices; ++i) {
    const Fan& fan = topology.stars[i].fans[0];
    int start = -1;
    for (int k = 0; k < 6; ++k)
      if (fan.edges[k] == generators::diamond_arch_valley_edge(i)) start = k;
    const std::vector<PanelThicknessClaim> c = vertex_panel_claims_at(model, topology, i, start);
    same.insert(same.end(), c.begin(), c.end());
  }
  EXPECT_THROW(agreed_panel_thickness(flat.num_faces(), same), PanelThicknessConflict);
}

TEST(DiamondArch, ThickArchIsTracedWithOneDofOnTheZeroThicknessMotionAndCurves) {
  const generators::DiamondArchParams params = arch_params();
  const int n = params.vertices;
  const CreasePattern flat = generators::diamond_arch(params);
  const Topology topology = build_topology(flat);
  const generators::DiamondArchThick model = generators::diamond_arch_thick(flat, topology, params, 0.03, 0.02);
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, topology, model.edge_heights);
  const ClosureSystem thick(sheet.pattern, sheet.topology, sheet.options);
  ASSERT_EQ(thick.num_holes(), n);

  // Pseudo-arclength trace of the thick sheet from a folded start on the symmetric motion, with
  // landings on the first valley crease at 0.05 pi .. 0.95 pi.
  const int drive = generators::diamond_arch_valley_edge(0);
  const int drive_unknown = thick.unknown_of_edge(drive);
  const double ref = sheet.reference_edge_angles[drive];  // the unknowns are fold angles of the sheet's own (truncated, 3D) faces
  ContinuationOptions options;
  options.tolerance = 1e-13;
  options.max_step = 0.2;
  options.landing_unknown = drive_unknown;
  for (int k = 1; k <= 19; ++k) options.landing_values.push_back(ref + 0.05 * kPi * k);
  const Eigen::VectorXd start = generators::diamond_arch_symmetric_state(flat, params, 0.04 * kPi);
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(thick.num_unknowns());
  direction[drive_unknown] = 1.0;
  const Eigen::VectorXd x0 = thick.unknowns_from_edges(sheet.sheet_edge_angles(start));
  const ContinuationResult trace = continue_one_dof(
      thick, x0, direction, [&](const Eigen::VectorXd& x) { return x[drive_unknown] - ref >= 0.95 * kPi - 1e-12; }, options);
  ASSERT_TRUE(trace.stopped) << trace.reason;

  double off = 0.0, worst_residual = 0.0, worst_sigma_ratio = 1e300, previous_turn = 0.0, worst_turn = 0.0, worst_end = 0.0;
  int landed = 0;
  for (const ContinuationPoint& point : trace.points) {
    if (point.landing < 0) continue;
    ++landed;
    const Eigen::VectorXd rho = sheet.fold_angles(thick.edges_from_unknowns(point.x));
    const double rho_v = rho[drive];
    const Eigen::VectorXd zero = generators::diamond_arch_symmetric_state(flat, params, rho_v);
    off = std::max(off, (rho - zero).cwiseAbs().maxCoeff());
    worst_residual = std::max(worst_residual, thick.residual(point.x).cwiseAbs().maxCoeff());
    // DOF by jacobian_rank's default cut (1e-9 x sigma_max), with the kept singular value
    // required to sit >= 1e3 x above the cut (worst_sigma_ratio below).
    const ThickMobilityReport m = thick_mobility(sheet, rho, {}, 1e-12);
    EXPECT_EQ(m.dof, 1) << "rho_valley = " << rho_v;
    worst_sigma_ratio = std::min(worst_sigma_ratio, m.rank.sigma_kept / m.rank.threshold);

    // The arch bends: the valley hinges of the placed thick sheet turn in one plane, by the
    // same angle at every vertex, which is (4-39)'s.
    const FoldedGeometry placed = place_faces(sheet.pattern, sheet.topology, thick.edges_from_unknowns(point.x), sheet.reference_edge_angles);
    EXPECT_LE(placed.relative_mismatch(), 1e-10);
    std::vector<Eigen::Vector3d> d;
    for (int j = 0; j <= n; ++j) {
      const auto& e = sheet.pattern.edges[generators::diamond_arch_valley_edge(j)];
      d.push_back((placed.vertices[e[1]] - placed.vertices[e[0]]).normalized());
    }
    const Eigen::Vector3d normal = d[0].cross(d[1]).normalized();
    const double turn_4_39 = valley_turning_from_4_39(params.a, dihedral(rho_v));
    double total = 0.0;
    for (int j = 0; j < n; ++j) {
      EXPECT_LE(std::abs(d[j + 1].dot(normal)), 1e-10) << "valley hinge " << j + 1 << " leaves the plane";
      const double turn = std::atan2(d[j].cross(d[j + 1]).dot(normal), d[j].dot(d[j + 1]));
      worst_turn = std::max(worst_turn, std::abs(turn - turn_4_39));
      total += turn;
    }
    // End to end: the angle between the end valley hinges against n turns of (4-39)'s.
    const double end_angle = std::acos(std::clamp(d[0].dot(d[n]), -1.0, 1.0));
    worst_end = std::max(worst_end, std::abs(end_angle - std::acos(std::cos(n * turn_4_39))));
    EXPECT_GT(total, previous_turn) << "rho_valley = " << rho_v << ": the arch must bend further";
    previous_turn = total;
  }
  EXPECT_EQ(landed, 19);
  EXPECT_LE(off, 1e-10);
  EXPECT_LE(worst_residual, 1e-12);
  EXPECT_GT(worst_sigma_ratio, 1e3);
  EXPECT_LE(worst_turn, 1e-9);
  EXPECT_LE(worst_end, 1e-9);
  std::printf("thick diamond arch (N = %d, a = 30 deg, t1 = 0.03, t2 = 0.02): %zu continuation points, %d landings to "
              "valley 171 deg; %.1e off the zero-thickness motion, residual %.1e, DOF 1 with sigma_kept/cut >= %.1e; "
              "bends %.2f deg end to end (turns %.1e off (4-39))\n",
              n, trace.points.size(), landed, off, worst_residual, worst_sigma_ratio, previous_turn * 180 / kPi, worst_turn);
}

// data/thick/diamond_arch_6_a30_thick.fold is this test's thick sheet (t1 = 0.03, t2 = 0.02) written
// as a thick FOLD (rigidfold:thickness per face, rigidfold:hinge_heights per edge), for
// `rigidfold check/trace`. It must stay what the generator builds, and thick_check must read it
// as the same sheet: its flat state is singular (first-order DOF above 1: the Bricard loops
// branch there), so thick_check traces by projected driving; every state it reports must close
// and have DOF 1. (Which branch it follows from flat is not asserted: from this singular point
// it leaves the symmetric motion, which the trace above follows from a folded start.)
TEST(DiamondArch, BundledThickFoldIsTheGeneratorsSheet) {
  const generators::DiamondArchParams params = arch_params();
  const CreasePattern flat = generators::diamond_arch(params);
  const Topology topology = build_topology(flat);
  const generators::DiamondArchThick model = generators::diamond_arch_thick(flat, topology, params, 0.03, 0.02);
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, topology, model.edge_heights);
  const CreasePattern file = read_pattern(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/thick/diamond_arch_6_a30_thick.fold");
  ASSERT_TRUE(is_thick_fold(file));
  ASSERT_EQ(file.num_vertices(), sheet.pattern.num_vertices());
  ASSERT_EQ(file.num_edges(), sheet.pattern.num_edges());
  double worst = 0.0;
  for (int v = 0; v < file.num_vertices(); ++v)
    worst = std::max(worst, (std::ldexp(1.0, file.length_exponent) * file.vertices[v] - std::ldexp(1.0, sheet.pattern.length_exponent) * sheet.pattern.vertices[v]).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1e-14);
  const ThickCheckReport r = thick_check(file, build_topology(file));
  EXPECT_EQ(r.hinges, flat.num_edges());
  EXPECT_EQ(r.holes, params.vertices);
  const ThickMobilityReport m = thick_mobility(sheet, Eigen::VectorXd::Zero(flat.num_edges()), {}, 1e-12);
  EXPECT_EQ(r.mobility.dof, m.dof);
  EXPECT_GT(m.dof, 1);
  EXPECT_EQ(r.verdict, "mobile");
  ASSERT_EQ(static_cast<int>(r.steps.size()), ThickCheckRequest{}.steps);
  for (const ThickCheckStep& s : r.steps) {
    EXPECT_LE(s.residual, 1e-10);
    EXPECT_EQ(s.dof, 1) << "drive " << s.drive;
  }
  EXPECT_NEAR(r.min_thickness * std::ldexp(1.0, file.length_exponent), 0.02, 1e-15);
  EXPECT_NEAR(r.max_thickness * std::ldexp(1.0, file.length_exponent), 0.05, 1e-15);
  std::printf("bundled thick arch: flat-state first-order DOF %d (file) / %d (built), smallest kept singular value %.2e; "
              "thick_check: %s, %zu steps to %.1f deg, %d hinge(s) against their letter at the end\n",
              r.mobility.dof, m.dof, m.rank.sigma_kept, r.verdict.c_str(), r.steps.size(), r.steps.back().drive * 180 / kPi,
              r.letter_disagreements);
}

}}  // namespace
}  // namespace rigidfold
