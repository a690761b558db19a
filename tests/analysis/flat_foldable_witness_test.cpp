// Flat patterns judged within the precision of their coordinates
// (kernel/analysis/flat_foldable_witness.hpp): a Miura-ori written with 3 or 4 decimals misses
// Kawasaki by ~1e-5 rad; the witness moves no coordinate further than its rounding (checked
// here against the rounding the test applied, not the kernel's reading of it) and makes every
// vertex flat-foldable. A Miura strip (no cycle of vertices) is then "foldable within the
// input's precision" with the exact DOF; a larger Miura's witness misses loop gain 1 by the
// rounding, and a second least move with loop-gain rows closes them: foldable within the
// input's precision too. A square twist, whose gain no rounding explains, is "undecided",
// never a "no". A pattern whose defects are not rounding (a perturbed Miura) gets no witness.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/analysis/flat_foldable_witness.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = 3.141592653589793;

// A Miura rows x 5 of panel size `size` (alpha 55 deg), coordinates rounded to `decimals`.
CreasePattern rounded_miura(int rows, double size, int decimals, double perturbation = 0.0) {
  generators::MiuraParams m;
  m.rows = rows;
  m.cols = 5;
  m.alpha = 55.0 * kPi / 180.0;
  m.a = size;
  m.b = 1.31371 * size;  // not a whole number: rounding must differ from vertex to vertex
  m.perturbation = perturbation;
  CreasePattern p = generators::miura_ori(m);
  // Turned by 17 deg first, so that the rounding grid shares no symmetry with the lattice
  // (along the axes a strip's vertices stay mirror-symmetric and Kawasaki exact).
  const double scale = std::pow(10.0, decimals), c = std::cos(17.0 * kPi / 180.0), s = std::sin(17.0 * kPi / 180.0);
  for (Eigen::Vector3d& v : p.vertices) {
    const Eigen::Vector3d turned(c * v.x() - s * v.y(), s * v.x() + c * v.y(), 0.0);
    for (int k = 0; k < 2; ++k) v[k] = std::round(turned[k] * scale) / scale;
  }
  complete_and_validate(p, "rounded miura");
  return p;
}

double max_kawasaki(const Topology& t) {
  double worst = 0;
  for (int v : t.interior_vertices) {
    const auto& s = t.stars[v].fans[0].sectors;
    worst = std::max(worst, std::abs(s[0] + s[2] - kPi));
  }
  return worst;
}

TEST(FlatFoldableWitness, RoundedMiuraStripFoldsWithinItsPrecision) {
  for (const int decimals : {3, 4}) {
    const std::string where = std::to_string(decimals) + " decimals";
    const CreasePattern p = rounded_miura(2, 100.0, decimals);
    const Topology t = build_topology(p);
    ASSERT_GT(max_kawasaki(t), 1e-9) << where << ": the rounding must break Kawasaki for this test to mean anything";
    const auto w = flat_foldable_witness(p, t, 1e-9);
    ASSERT_TRUE(w.has_value()) << where;
    EXPECT_EQ(w->precision.decimal_places, decimals) << where;
    ASSERT_TRUE(w->explained) << where << ": ratio " << w->max_move_ratio;
    // Every coordinate within the rounding the test applied (half a unit in the last place,
    // plus the double rounding of the quotient).
    const double half_unit = 0.5 * std::pow(10.0, -decimals);
    for (int i = 0; i < p.num_vertices(); ++i)
      for (int k = 0; k < 3; ++k)
        EXPECT_LE(std::abs(w->witness.vertices[i][k] - p.vertices[i][k]), half_unit * (1 + 1e-9)) << where << " vertex " << i;
    EXPECT_LE(max_kawasaki(build_topology(w->witness)), 1e-12) << where;

    const FoldabilityReport r = check_foldability(p, t);
    EXPECT_EQ(r.verdict, FoldabilityClass::kFoldableWithinTolerance) << where << ": " << r.reason;
    EXPECT_EQ(r.model, FoldabilityModel::kMultiplierPropagation) << where;
    EXPECT_EQ(r.dof, 1) << where;
    ASSERT_TRUE(r.input_precision.has_value()) << where;
    EXPECT_EQ(r.input_precision->witness_kind, "coordinates");
    EXPECT_LE(r.input_precision->max_change_ratio, 1.0);
    // The witness's closure residual along its fold family.
    EXPECT_LE(r.max_residual, r.tolerances.certificate_residual) << where;

    // trace: the same model choice, the witness's fold family.
    TraceRequest rq;
    rq.steps = 4;
    const MotionTrace m = trace_motion(p, t, rq);
    ASSERT_EQ(m.branches.size(), 1u) << where;
    EXPECT_TRUE(m.branches[0].traced) << where << ": " << m.note;
    EXPECT_EQ(m.model, FoldabilityModel::kMultiplierPropagation) << where;
  }
}

// Independent of the witness code: every vertex of `witness` within `rounding` of `file`, its
// sectors flat-foldable from its own topology, and its exact verdict foldable.
void expect_witness_within(const CreasePattern& file, const CreasePattern& witness, double rounding, const std::string& where) {
  ASSERT_EQ(witness.num_vertices(), file.num_vertices()) << where;
  for (int i = 0; i < file.num_vertices(); ++i)
    for (int k = 0; k < 2; ++k)
      EXPECT_LE(std::abs(witness.vertices[i][k] - file.vertices[i][k]), rounding * (1 + 1e-9)) << where << " vertex " << i;
  const Topology wt = build_topology(witness);
  EXPECT_LE(max_kawasaki(wt), 1e-12) << where;
}

TEST(FlatFoldableWitness, RoundedMiuraWithCyclesFoldsOnceTheLoopGainsAreClosedToo) {
  // A 6-row Miura written with 3 decimals: the Kawasaki-only witness misses loop gain 1 by
  // about the rounding; the second least move (gain rows, the modes the letters allow) closes
  // every cycle within the rounding, so the file is foldable within its precision.
  const CreasePattern p = rounded_miura(6, 100.0, 3);
  const Topology t = build_topology(p);
  const auto first = flat_foldable_witness(p, t, 1e-9);
  ASSERT_TRUE(first.has_value());
  ASSERT_TRUE(first->explained);
  EXPECT_EQ(first->loop_gain_rows, 0);
  VerdictOptions vo;
  const FoldabilityVerdict on_first = verdict_with_assignment(first->witness, first->witness_topology, vo);
  ASSERT_EQ(on_first.verdict, Verdict::kNotRigidlyFoldable) << "the Kawasaki-only witness should miss a loop gain: " << on_first.reason;

  const FoldabilityReport r = check_foldability(p, t);
  EXPECT_EQ(r.verdict, FoldabilityClass::kFoldableWithinTolerance) << r.reason;
  EXPECT_EQ(r.dof, 1);
  EXPECT_NE(r.reason.find("loop gain 1"), std::string::npos) << r.reason;
  ASSERT_TRUE(r.input_precision.has_value());
  EXPECT_LE(r.input_precision->max_change_ratio, 1.0);
  EXPECT_LE(r.max_residual, r.tolerances.certificate_residual);

  // With the letters ignored the witness has no one mode per vertex to close the cycles with,
  // but the lettered motion is a motion without letters too: the same answer, saying why.
  FoldabilityOptions any_signs;
  any_signs.use_assignment = false;
  const FoldabilityReport ignored = check_foldability(p, t, any_signs);
  EXPECT_EQ(ignored.verdict, FoldabilityClass::kFoldableWithinTolerance) << ignored.reason;
  EXPECT_FALSE(ignored.assignment_used);
  EXPECT_EQ(ignored.dof, 1);
  EXPECT_NE(ignored.model_choice.find("a motion that keeps the letters is a motion with them ignored"), std::string::npos)
      << ignored.model_choice;

  // The same solve called directly, checked independently.
  std::vector<FlatFoldMode> modes;
  for (int v : first->witness_topology.interior_vertices) {
    const auto m = modes_matching_letters(first->witness, first->witness_topology.stars[v].fans[0]);
    ASSERT_EQ(m.size(), 1u);
    modes.push_back(m[0]);
  }
  const auto second = flat_foldable_witness(p, t, 1e-9, &modes);
  ASSERT_TRUE(second.has_value());
  EXPECT_TRUE(second->explained);
  EXPECT_GT(second->loop_gain_rows, 0);
  EXPECT_LE(second->max_log_gain, 1e-12);
  expect_witness_within(p, second->witness, 0.5e-3, "6-row Miura, 3 decimals");
  const FoldabilityVerdict on_second = verdict_with_assignment(second->witness, build_topology(second->witness), vo);
  EXPECT_EQ(on_second.verdict, Verdict::kRigidlyFoldable) << on_second.reason;
}

// `check --tolerance` (FoldabilityOptions::coordinate_tolerance): one Miura written at 17
// digits and rounded to 6, 4 and 3 decimals. Read off the digits, the rounded files fold
// within their precision; stated as exact, no rounded file gets that verdict (the numbers are
// judged as they are); a stated bound 100x the rounding still explains the defects, one
// 1/100 of it does not. The 17-digit file folds, exactly, under every setting.
TEST(FlatFoldableWitness, StatedToleranceOverridesWhatTheDigitsSay) {
  for (const int decimals : {17, 6, 4, 3}) {
    const std::string where = std::to_string(decimals) + " decimals";
    const CreasePattern p = rounded_miura(4, 100.0, decimals);
    const Topology t = build_topology(p);
    const double half_unit = 0.5 * std::pow(10.0, -decimals);
    auto check = [&](std::optional<double> tolerance) {
      FoldabilityOptions o;
      o.coordinate_tolerance = tolerance;
      return check_foldability(p, t, o);
    };
    const FoldabilityReport read = check(std::nullopt), exact = check(0.0);
    EXPECT_EQ(exact.coordinate_precision, "coordinates taken as exact (--tolerance exact)") << where;
    EXPECT_FALSE(exact.input_precision.has_value()) << where;
    if (decimals == 17) {
      EXPECT_EQ(read.verdict, FoldabilityClass::kFoldable) << where << ": " << read.reason;
      EXPECT_EQ(exact.verdict, FoldabilityClass::kFoldable) << where << ": " << exact.reason;
      EXPECT_EQ(read.coordinate_precision, "full-precision coordinates, taken as exact") << where;
      continue;
    }
    ASSERT_GT(max_kawasaki(t), 1e-9) << where;
    EXPECT_EQ(read.verdict, FoldabilityClass::kFoldableWithinTolerance) << where << ": " << read.reason;
    EXPECT_NE(read.coordinate_precision.find("written with " + std::to_string(decimals) + " decimals"), std::string::npos)
        << where << ": " << read.coordinate_precision;
    EXPECT_NE(exact.verdict, FoldabilityClass::kFoldableWithinTolerance) << where << ": " << exact.reason;
    EXPECT_NE(exact.verdict, FoldabilityClass::kFoldable) << where << ": " << exact.reason;
    const FoldabilityReport loose = check(100 * half_unit), tight = check(0.01 * half_unit);
    EXPECT_EQ(loose.verdict, FoldabilityClass::kFoldableWithinTolerance) << where << ": " << loose.reason;
    EXPECT_NE(loose.coordinate_precision.find("stated with --tolerance"), std::string::npos) << where;
    EXPECT_NE(tight.verdict, FoldabilityClass::kFoldableWithinTolerance) << where << ": " << tight.reason;
    EXPECT_NE(tight.verdict, FoldabilityClass::kFoldable) << where << ": " << tight.reason;
  }
}

TEST(FlatFoldableWitness, RoundedSquareTwistIsProvenRigidOverItsRounding) {
  // The classic square twist (Type 1, not foldable: loop gain far from 1) written with 3
  // decimals: no pattern within the rounding closes its gain, so no second witness; the first
  // witness does not fold, and the same cycle's gain, enclosed by interval arithmetic over
  // every pattern within the rounding (interval_loop_gain.hpp), excludes 1: a proof for the
  // file. (Before the enclosure this was "undecided": a proof for the witness only.)
  generators::SquareTwistParams sp;
  sp.side = 100.0;
  sp.pleat = 100.0;
  CreasePattern p = generators::square_twist(sp, generators::SquareTwistType::Type1);
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (Eigen::Vector3d& v : p.vertices) {
    const Eigen::Vector3d turned(c * v.x() - s * v.y(), s * v.x() + c * v.y(), 0.0);
    for (int k = 0; k < 2; ++k) v[k] = std::round(turned[k] * 1e3) / 1e3;
  }
  complete_and_validate(p, "rounded square twist");
  const Topology t = build_topology(p);
  ASSERT_GT(max_kawasaki(t), 1e-9);
  const FoldabilityReport r = check_foldability(p, t);
  EXPECT_EQ(r.verdict, FoldabilityClass::kNotFoldableProof) << r.reason;
  EXPECT_TRUE(r.is_proof);
  EXPECT_NE(r.reason.find("loop gain"), std::string::npos) << r.reason;
  ASSERT_TRUE(r.input_precision && r.input_precision->loop_gain_enclosure);
  const auto [lo, hi] = *r.input_precision->loop_gain_enclosure;
  EXPECT_TRUE(hi < 1.0 || lo > 1.0) << lo << " " << hi;
}

TEST(FlatFoldableWitness, DefectsBeyondTheRoundingGetNoWitness) {
  // A perturbed Miura (vertices moved by 2% of the panel) written with 6 decimals: its
  // Kawasaki defects are the perturbation's, far above what 6 decimals explain.
  const CreasePattern p = rounded_miura(6, 1.0, 6, 0.02);
  const Topology t = build_topology(p);
  const auto w = flat_foldable_witness(p, t, 1e-9);
  ASSERT_TRUE(w.has_value());
  EXPECT_FALSE(w->explained);
  EXPECT_GT(w->max_move_ratio, 1.0);
  const ModelChoice c = choose_model(p, t, {});
  EXPECT_EQ(c.model, FoldabilityModel::kGeneralLoopClosure);
  EXPECT_NE(c.why.find("not explained by the rounding"), std::string::npos) << c.why;

  // Exact (17-digit) coordinates of a flat-foldable Miura: the exact model, no witness.
  const CreasePattern exact = generators::miura_ori({});
  EXPECT_FALSE(flat_foldable_witness(exact, build_topology(exact), 1e-9).has_value());
}

}}  // namespace
}  // namespace rigidfold
