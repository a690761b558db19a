// Multiplier propagation (kernel/analysis/multiplier_propagation.hpp): the O(creases) exact
// rigid-foldability model of flat-foldable degree-4 patterns, checked on
//   - the Miura-ori (closed form miura_fold_angles, data/generators/miura.hpp),
//   - the square twist, all 16 flat-foldable assignments (seed 001 §2: Types 3 and 4 rigid,
//     Types 1 and 2 not, loop gain k^4 with k = cos t / (1 - sin t)),
//   - the double-corrugated units P and Q (seed 003 §3.2-3.3: 10 and 6 valid assignments up
//     to symmetry and flip, 4 rigid each; rigidity iff the loop gain K = prod k = 1),
//   - patterns outside the model (perturbed Miura, F creases).
// Every "foldable" certificate is re-checked here by face placement and by the product
// of Rx(rho) Rz(alpha) around every interior vertex.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <numbers>
#include <iomanip>
#include <set>
#include <sstream>

#include "data/generators/double_corrugated.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/geometry/face_placement.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

double rad(double deg) { return deg * kPi / 180; }
std::string sci(double x) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(3) << x;
  return out.str();
}

// Largest |R - I| entry of prod Rx(rho_i) Rz(alpha_i) over the interior vertices.
double max_vertex_closure(const Topology& t, const Eigen::VectorXd& rho) {
  double worst = 0;
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i < fan.edges.size(); ++i)
      R = R * Eigen::AngleAxisd(rho[fan.edges[i]], Eigen::Vector3d::UnitX()).toRotationMatrix() *
          Eigen::AngleAxisd(fan.sectors[i], Eigen::Vector3d::UnitZ()).toRotationMatrix();
    worst = std::max(worst, (R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
  }
  return worst;
}

double placement_mismatch(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho) {
  return place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges())).relative_mismatch();
}

// Every M / V hinge folds its assigned way.
bool signs_match(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho) {
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!t.edge_is_hinge[e]) continue;
    if (p.assignments[e] == Assignment::Valley && !(rho[e] > 0)) return false;
    if (p.assignments[e] == Assignment::Mountain && !(rho[e] < 0)) return false;
  }
  return true;
}

// ---------------------------------------------------------------- Miura-ori

generators::MiuraParams miura(int rows, int cols, double alpha_deg) {
  generators::MiuraParams m;
  m.rows = rows;
  m.cols = cols;
  m.alpha = rad(alpha_deg);
  m.a = 1.0;
  m.b = 1.4;
  return m;
}

// Seed: the Miura-ori standard mode (data/generators/miura.hpp closed form, derived from
// seed 003 eq. (3-3)). One DOF; the family equals the closed form.
TEST(VerdictMiura, RigidOneDofAndEqualsClosedForm) {
  for (auto [rows, cols] : std::vector<std::pair<int, int>>{{2, 2}, {3, 5}, {6, 4}, {8, 9}, {20, 21}}) {
    for (double alpha : {25.0, 45.0, 60.0, 80.0}) {
      const auto m = miura(rows, cols, alpha);
      const CreasePattern p = generators::miura_ori(m);
      const Topology t = build_topology(p);
      const FoldabilityVerdict v = verdict_with_assignment(p, t);
      const std::string where = std::to_string(rows) + "x" + std::to_string(cols) + " alpha " + std::to_string(alpha);
      ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << where << ": " << v.reason;
      EXPECT_EQ(v.dof, 1) << where;
      EXPECT_LE(v.certificate_mismatch, 1e-12) << where;
      EXPECT_NEAR(v.certificate_max_fold, kPi / 2, 1e-12) << where;
      EXPECT_LE(v.max_loop_defect, 1e-13) << where;
      EXPECT_EQ(v.search_steps, static_cast<long>(t.interior_vertices.size())) << where;  // no backtracking
      ASSERT_TRUE(v.family.has_value());
      // Drive by a straight interior crease and compare with the closed form.
      const auto kinds = generators::miura_crease_kinds(m);
      int driver = -1;
      for (int e = 0; e < p.num_edges() && driver < 0; ++e)
        if (kinds[e] == generators::MiuraCrease::Straight && v.family->component[e] >= 0) driver = e;
      ASSERT_GE(driver, 0);
      const double sign = p.assignments[driver] == Assignment::Valley ? 1.0 : -1.0;
      for (double rho_s : {1e-6, 0.3, 1.2, 2.9}) {
        const Eigen::VectorXd rho = v.family->angles(v.family->parameter_for(driver, sign * rho_s));
        const auto closed = generators::miura_fold_angles(p, m, rho_s);
        double worst = 0;
        for (int e = 0; e < p.num_edges(); ++e) worst = std::max(worst, std::abs(rho[e] - closed[e].value_or(0.0)));
        EXPECT_LE(worst, 1e-12) << where << " rho_s " << rho_s;
        EXPECT_TRUE(signs_match(p, t, rho)) << where;
        EXPECT_LE(placement_mismatch(p, t, rho), 1e-12) << where;
      }
    }
  }
}

// Seed: Miura-ori at the size of the large-tessellation benchmarks. Correctness only; the
// elapsed time is recorded as a test property (not asserted).
TEST(VerdictMiura, HundredByHundred) {
  const auto m = miura(100, 100, 60);
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const auto start = std::chrono::steady_clock::now();
  const FoldabilityVerdict v = verdict_with_assignment(p, t);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << v.reason;
  EXPECT_EQ(v.dof, 1);
  EXPECT_LE(v.certificate_mismatch, 1e-12);
  EXPECT_LE(v.max_loop_defect, 1e-13);
  EXPECT_EQ(v.cycles_checked, 98 * 98);  // one per face with four interior corners
  RecordProperty("verdict_seconds", sci(seconds));
  RecordProperty("certificate_mismatch", sci(v.certificate_mismatch));
  RecordProperty("max_loop_defect", sci(v.max_loop_defect));
  // Independent check of the certificate at the vertices.
  EXPECT_LE(max_vertex_closure(t, v.certificate_angles), 1e-12);
}

// Seed: Miura-ori with its letters ignored: the search prefers modes where every crease folds
// and finds the Miura mode without backtracking.
TEST(VerdictMiura, IgnoringAssignmentFindsTheMiuraMode) {
  const auto m = miura(10, 12, 50);
  CreasePattern p = generators::miura_ori(m);
  for (auto& a : p.assignments)
    if (a != Assignment::Boundary) a = Assignment::Unassigned;
  const Topology t = build_topology(p);
  const FoldabilityVerdict v = verdict_ignoring_assignment(p, t);
  ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << v.reason;
  EXPECT_EQ(v.dof, 1);
  EXPECT_EQ(v.search_steps, static_cast<long>(t.interior_vertices.size()));
  EXPECT_LE(v.certificate_mismatch, 1e-12);
  // All letters U: the assignment-respecting verdict folds too.
  EXPECT_EQ(verdict_with_assignment(p, t).verdict, Verdict::kRigidlyFoldable);
}

// Seed: Miura-ori, every vertex in its straight-line mode (zig-zag creases flat): each
// straight line of creases is its own component, so components multiply DOF (rows - 1).
TEST(MultiplierPropagation, ComponentsMultiplyDof) {
  const auto m = miura(5, 6, 60);
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const MultiplierModel model = build_multiplier_model(p, t);
  const auto kinds = generators::miura_crease_kinds(m);
  std::vector<FlatFoldMode> modes;
  for (std::size_t k = 0; k < model.vertices.size(); ++k) {
    int chosen = -1;
    for (int mode = 0; mode < 2; ++mode) {
      bool zigzag_flat = true;
      for (int i = 0; i < 4; ++i)
        if (kinds[model.creases[k][i]] == generators::MiuraCrease::ZigZag) zigzag_flat &= model.w[k][mode][i] == 0.0;
      if (zigzag_flat) chosen = mode;
    }
    ASSERT_GE(chosen, 0);
    modes.push_back(mode_from_index(chosen));
  }
  const ModeCheck mc = check_modes(model, modes);
  EXPECT_TRUE(mc.consistent);
  EXPECT_EQ(mc.dof, m.rows - 1);
  EXPECT_EQ(mc.tie_components, m.rows - 1);
  EXPECT_EQ(mc.pinned_components, 0);
  // Fold every line by a different amount: still closes.
  std::vector<double> tau;
  for (int c = 0; c < mc.dof; ++c) tau.push_back(0.2 + 0.5 * c);
  const Eigen::VectorXd rho = mc.family.angles(tau);
  EXPECT_LE(placement_mismatch(p, t, rho), 1e-12);
  EXPECT_LE(max_vertex_closure(t, rho), 1e-12);
  for (int e = 0; e < p.num_edges(); ++e) {
    if (kinds[e] == generators::MiuraCrease::ZigZag) {
      EXPECT_EQ(rho[e], 0.0);
    }
  }
  // Mixing modes within a row pins: the flat zig-zag crease of one vertex meets a folding
  // zig-zag crease of its neighbour.
  std::vector<FlatFoldMode> mixed = modes;
  mixed[0] = mixed[0] == FlatFoldMode::kEqual13 ? FlatFoldMode::kEqual02 : FlatFoldMode::kEqual13;
  const ModeCheck pinned = check_modes(model, mixed);
  EXPECT_GT(pinned.pinned_components, 0);
  ASSERT_TRUE(pinned.obstruction.has_value());
  EXPECT_EQ(pinned.obstruction->kind, Obstruction::Kind::kPin);
  EXPECT_LT(pinned.dof, mc.dof);
}

// Seed: a one-row Miura strip has no interior vertex: each zig-zag crease is a free hinge.
TEST(VerdictMiura, StripWithoutInteriorVerticesHasOneDofPerCrease) {
  const auto m = miura(1, 5, 60);
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  ASSERT_TRUE(t.interior_vertices.empty());
  const FoldabilityVerdict v = verdict_with_assignment(p, t);
  ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << v.reason;
  EXPECT_EQ(v.dof, 4);
  EXPECT_LE(v.certificate_mismatch, 1e-12);
}

// Seed: perturbed Miura (data/generators/miura.hpp: Kawasaki fails) is outside the model.
TEST(VerdictMiura, PerturbedIsNotApplicable) {
  auto m = miura(4, 4, 60);
  m.perturbation = 0.05;
  m.seed = 7;
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const MultiplierApplicability a = multiplier_model_applicable(p, t);
  EXPECT_FALSE(a.applicable);
  EXPECT_GE(a.vertex, 0);
  EXPECT_NE(a.reason.find("not flat-foldable"), std::string::npos) << a.reason;
  const FoldabilityVerdict v = verdict_with_assignment(p, t);
  EXPECT_EQ(v.verdict, Verdict::kNotApplicable);
  EXPECT_EQ(verdict_ignoring_assignment(p, t).verdict, Verdict::kNotApplicable);
  EXPECT_THROW(build_multiplier_model(p, t), std::invalid_argument);
}

// An F crease at an interior vertex is outside the model (F/J hinges not modelled).
TEST(MultiplierPropagation, FlatJoinAtInteriorVertexIsNotApplicable) {
  const auto m = miura(3, 3, 60);
  CreasePattern p = generators::miura_ori(m);
  const Topology t0 = build_topology(p);
  const int e = t0.stars[t0.interior_vertices[0]].fans[0].edges[0];
  p.assignments[e] = Assignment::Flat;
  const Topology t = build_topology(p);
  const MultiplierApplicability a = multiplier_model_applicable(p, t);
  EXPECT_FALSE(a.applicable);
  EXPECT_EQ(a.edge, e);
  EXPECT_EQ(verdict_with_assignment(p, t).verdict, Verdict::kNotApplicable);
}

// ---------------------------------------------------------------- square twist

generators::SquareTwistParams twist_params(double twist_deg) {
  generators::SquareTwistParams s;
  s.twist = rad(twist_deg);
  s.side = 1.3;
  s.pleat = 0.8;
  return s;
}

// Seed 001 §2: of the four flat-foldable types, 3 and 4 are rigidly foldable, 1 and 2 are
// not; the loop gain of 1 and 2 is k^(+-4), k = cos t / (1 - sin t) (seed 001 eqs. (7), (8)).
// All 16 side patterns (every flat-foldable assignment), twist 15..75 deg.
TEST(VerdictSquareTwist, AllAssignmentsTypes3And4RigidTypes1And2Not) {
  double worst_rigid_defect = 0, worst_mismatch = 0, smallest_bad_defect = 1e300;
  for (int twist = 15; twist <= 75; twist += 5) {
    const double tw = rad(twist);
    const double k = std::cos(tw) / (1 - std::sin(tw));
    for (int mask = 0; mask < 16; ++mask) {
      std::array<Assignment, 4> sides{};
      int changes = 0;
      for (int i = 0; i < 4; ++i) sides[i] = (mask >> i) & 1 ? Assignment::Valley : Assignment::Mountain;
      for (int i = 0; i < 4; ++i) changes += sides[i] != sides[(i + 1) % 4];
      // changes 0: Type 1 class; 4: Type 2 class; 2: Types 3 and 4 (rigid).
      const bool rigid = changes == 2;
      const CreasePattern p =
          generators::square_twist(twist_params(twist), generators::square_twist_assignment(sides));
      const Topology t = build_topology(p);
      const FoldabilityVerdict v = verdict_with_assignment(p, t);
      const std::string where = "twist " + std::to_string(twist) + " mask " + std::to_string(mask);
      if (rigid) {
        ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << where << ": " << v.reason;
        EXPECT_EQ(v.dof, 1) << where;
        EXPECT_EQ(v.cycles_checked, 1) << where;
        EXPECT_LE(v.max_loop_defect, 1e-13) << where;
        EXPECT_LE(v.certificate_mismatch, 1e-12) << where;
        // Cross-check the certificate and the family at other folds.
        EXPECT_LE(placement_mismatch(p, t, v.certificate_angles), 1e-12) << where;
        EXPECT_LE(max_vertex_closure(t, v.certificate_angles), 1e-12) << where;
        EXPECT_TRUE(signs_match(p, t, v.certificate_angles)) << where;
        for (double scale : {1e-4, 0.3, 3.0}) {
          std::vector<double> tau{0};
          const int e0 = 0;
          tau[0] = v.family->parameter_for(e0, 0.5 * v.certificate_angles[e0]) * scale;
          const Eigen::VectorXd rho = v.family->angles(tau);
          EXPECT_LE(placement_mismatch(p, t, rho), 1e-12) << where;
          EXPECT_TRUE(signs_match(p, t, rho)) << where;
        }
        worst_rigid_defect = std::max(worst_rigid_defect, v.max_loop_defect);
        worst_mismatch = std::max(worst_mismatch, v.certificate_mismatch);
      } else {
        ASSERT_EQ(v.verdict, Verdict::kNotRigidlyFoldable) << where << ": " << v.reason;
        ASSERT_TRUE(v.obstruction.has_value()) << where;
        const Obstruction& ob = *v.obstruction;
        EXPECT_EQ(ob.kind, Obstruction::Kind::kLoopGain) << where;
        EXPECT_EQ(std::set<int>(ob.cycle_vertices.begin(), ob.cycle_vertices.end()), (std::set<int>{0, 1, 2, 3}))
            << where;
        EXPECT_EQ(std::set<int>(ob.cycle_creases.begin(), ob.cycle_creases.end()), (std::set<int>{0, 1, 2, 3}))
            << where;  // the four sides of the central square
        EXPECT_GT(ob.loop_gain, 0) << where;
        EXPECT_NEAR(std::abs(std::log(ob.loop_gain)), 4 * std::log(k), 1e-12) << where;
        EXPECT_NEAR(ob.defect, std::abs(ob.loop_gain - 1), 0) << where;
        EXPECT_GT(ob.defect, 0.5) << where;
        smallest_bad_defect = std::min(smallest_bad_defect, ob.defect);
      }
    }
  }
  RecordProperty("worst_rigid_loop_defect", sci(worst_rigid_defect));
  RecordProperty("worst_certificate_mismatch", sci(worst_mismatch));
  RecordProperty("smallest_nonrigid_defect", sci(smallest_bad_defect));
}

// Seed 001 §2 by its type names (data/generators/square_twist.hpp naming).
TEST(VerdictSquareTwist, NamedTypes) {
  using generators::SquareTwistType;
  for (int twist : {15, 30, 45, 60, 75}) {
    for (auto type : {SquareTwistType::Type1, SquareTwistType::Type2, SquareTwistType::Type3, SquareTwistType::Type4}) {
      const CreasePattern p = generators::square_twist(twist_params(twist), type);
      const Topology t = build_topology(p);
      const FoldabilityVerdict v = verdict_with_assignment(p, t);
      const bool rigid = type == SquareTwistType::Type3 || type == SquareTwistType::Type4;
      EXPECT_EQ(v.verdict, rigid ? Verdict::kRigidlyFoldable : Verdict::kNotRigidlyFoldable)
          << generators::to_string(type) << " twist " << twist << ": " << v.reason;
      // The geometry folds rigidly once the letters are ignored (a Type 3 / 4 mode exists).
      const FoldabilityVerdict free = verdict_ignoring_assignment(p, t);
      EXPECT_EQ(free.verdict, Verdict::kRigidlyFoldable) << free.reason;
      EXPECT_LE(free.certificate_mismatch, 1e-12);
      EXPECT_LE(free.search_steps, 64);
    }
  }
}

// Seed 001 §2: the modes the Type 1 letters force give the loop gain k^(+-4) in check_modes
// directly, and every other mode choice with gain 1 folds.
TEST(MultiplierPropagation, SquareTwistModeChoicesAndLoopGain) {
  const CreasePattern p = generators::square_twist(twist_params(30), generators::SquareTwistType::Type1);
  const Topology t = build_topology(p);
  const MultiplierModel model = build_multiplier_model(p, t);
  ASSERT_EQ(model.vertices.size(), 4u);
  int consistent = 0;
  for (int mask = 0; mask < 16; ++mask) {
    std::vector<FlatFoldMode> modes;
    for (int k = 0; k < 4; ++k) modes.push_back(mode_from_index((mask >> k) & 1));
    const ModeCheck mc = check_modes(model, modes);
    EXPECT_EQ(mc.cycles_checked, 1);
    EXPECT_EQ(mc.tie_components, 1);
    if (mc.consistent) {
      ++consistent;
      EXPECT_EQ(mc.dof, 1);
      for (double tau : {0.05, 0.7, 4.0}) {
        const Eigen::VectorXd rho = mc.family.angles(tau);
        EXPECT_LE(placement_mismatch(p, t, rho), 1e-12);
        EXPECT_LE(max_vertex_closure(t, rho), 1e-12);
      }
    } else {
      EXPECT_EQ(mc.dof, 0);
      ASSERT_TRUE(mc.obstruction.has_value());
      EXPECT_EQ(mc.obstruction->cycle_vertices.size(), 4u);
    }
  }
  // Two of the four vertices with the odd crease on a side: C(4, 2) = 6 mode choices.
  EXPECT_EQ(consistent, 6);
}

// ---------------------------------------------------------------- double corrugated

generators::CorrugatedParams corrugated_angles(double alpha_deg, double beta_deg) {
  generators::CorrugatedParams c;
  c.alpha = rad(alpha_deg);
  c.beta = rad(beta_deg);
  c.a = 1.1;
  c.b = 0.9;
  return c;
}

// Seed 003 §3.2: units P and Q have 10 and 6 flat-foldable M-V assignments up to the unit's
// 2-fold symmetry and the global flip; 4 of each are rigidly foldable (loop gain K = 1).
// Same expectation as tests/data/double_corrugated_test.cpp, decided here by the kernel.
TEST(VerdictCorrugated, FourRigidAssignmentsEachInPAndQ) {
  using generators::CorrugatedUnit;
  double worst_rigid_defect = 0, worst_mismatch = 0, smallest_bad_defect = 1e300;
  for (auto unit : {CorrugatedUnit::P, CorrugatedUnit::Q}) {
    for (auto [al, be] : std::vector<std::pair<double, double>>{{135, 60}, {135, 120}, {100, 85}, {150, 40}, {120, 90}}) {
      std::set<std::array<int, 4>> classes, rigid_classes;
      for (const auto& c : generators::corrugated_flat_foldable_assignments(unit)) {
        const CreasePattern p = generators::corrugated_unit(unit, corrugated_angles(al, be), c.assignment);
        const Topology t = build_topology(p);
        const FoldabilityVerdict v = verdict_with_assignment(p, t);
        const std::string where = std::string(generators::to_string(unit)) + " " + std::to_string(al) + "/" +
                                  std::to_string(be);
        const bool rigid = v.verdict == Verdict::kRigidlyFoldable;
        EXPECT_EQ(rigid, c.rigid) << where << ": " << v.reason;
        ASSERT_TRUE(rigid || v.verdict == Verdict::kNotRigidlyFoldable) << where << ": " << v.reason;
        const std::array<int, 4> rotated{c.odd_joint[2], c.odd_joint[3], c.odd_joint[0], c.odd_joint[1]};
        const auto key = std::min(c.odd_joint, rotated);
        classes.insert(key);
        if (rigid) {
          rigid_classes.insert(key);
          EXPECT_EQ(v.dof, 1);
          EXPECT_LE(v.max_loop_defect, 1e-13) << where;
          EXPECT_LE(v.certificate_mismatch, 1e-12) << where;
          EXPECT_LE(placement_mismatch(p, t, v.certificate_angles), 1e-12) << where;
          EXPECT_LE(max_vertex_closure(t, v.certificate_angles), 1e-12) << where;
          EXPECT_TRUE(signs_match(p, t, v.certificate_angles)) << where;
          worst_rigid_defect = std::max(worst_rigid_defect, v.max_loop_defect);
          worst_mismatch = std::max(worst_mismatch, v.certificate_mismatch);
        } else {
          ASSERT_TRUE(v.obstruction.has_value());
          smallest_bad_defect = std::min(smallest_bad_defect, v.obstruction->defect);
          EXPECT_EQ(v.obstruction->kind, Obstruction::Kind::kLoopGain) << where;
          EXPECT_EQ(v.obstruction->cycle_vertices.size(), 4u) << where;
          EXPECT_GT(v.obstruction->defect, 1e-3) << where;
        }
      }
      EXPECT_EQ(classes.size(), unit == CorrugatedUnit::P ? 10u : 6u);
      EXPECT_EQ(rigid_classes.size(), 4u) << generators::to_string(unit) << " " << al << "/" << be;
    }
  }
  RecordProperty("worst_rigid_loop_defect", sci(worst_rigid_defect));
  RecordProperty("worst_certificate_mismatch", sci(worst_mismatch));
  RecordProperty("smallest_nonrigid_defect", sci(smallest_bad_defect));
}

}}  // namespace
}  // namespace rigidfold
