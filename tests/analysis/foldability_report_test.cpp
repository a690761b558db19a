// check_foldability (kernel/analysis/foldability_report.hpp), the kernel's front door, linked
// directly: its report and the CLI's `check --json` agree on every bundled and corpus file
// (same verdict, class, proof flag, DOF, model, branches and residual), and the report's own
// invariants hold (a yes has branches within the certificate bound, a no an obstruction, an
// evidence-only no is never a proof).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/sanitized.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

std::vector<std::string> pattern_files(bool corpus) {
  std::vector<std::string> files;
  const fs::path dir = corpus ? fs::path(RIGIDFOLD_CORPUS_DIR) : fs::path(RIGIDFOLD_SOURCE_DIR) / "data/bundled";
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".fold") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

void expect_report_invariants(const FoldabilityReport& r, const std::string& where) {
  if (r.foldable()) {
    EXPECT_TRUE(r.is_proof) << where;
    EXPECT_GE(r.dof, 1) << where;
    EXPECT_FALSE(r.branches.empty()) << where;
    EXPECT_FALSE(r.obstruction.has_value()) << where;
    EXPECT_LE(r.max_residual, r.tolerances.certificate_residual) << where;
  }
  if (r.not_foldable()) {
    EXPECT_TRUE(r.obstruction.has_value()) << where;
    if (!r.folds_in_part) EXPECT_EQ(r.dof, 0) << where;
    EXPECT_EQ(r.is_proof, r.verdict == FoldabilityClass::kNotFoldableProof) << where;
  }
  if (r.verdict == FoldabilityClass::kUndecided) {
    EXPECT_FALSE(r.is_proof) << where;
  }
  // A "no" of the general search rests on evidence above the floor that grows with the fold
  // (general_verdict.hpp, step 5): never on a residual near the search's own threshold.
  // Or, for a flat pattern judged on its flat-foldable witness within the rounding, on that
  // witness's exact obstruction.
  const bool on_flat_witness = r.input_precision && r.input_precision->witness_kind == "coordinates";
  if (on_flat_witness) {
    EXPECT_TRUE(r.input_precision->explained) << where;
    EXPECT_LE(r.input_precision->max_change_ratio, 1.0) << where;
    EXPECT_GT(r.input_precision->given_residual, r.tolerances.flat_kawasaki) << where;
    EXPECT_FALSE(r.not_foldable()) << where << ": a witness's no is not the file's";
  }
  if (r.verdict == FoldabilityClass::kNotFoldableEvidence && !on_flat_witness) {
    ASSERT_TRUE(r.obstruction.has_value()) << where;
    EXPECT_GE(r.obstruction->least_residual, r.tolerances.evidence_floor) << where;
    ASSERT_GE(r.search_evidence.size(), 2u) << where;
    EXPECT_GE(r.residual_growth_exponent, 0.5) << where;
    EXPECT_GT(r.search_evidence[0].least_residual, r.search_evidence[1].least_residual) << where;
  }
  // Strict and weak: the flat creases listed are lettered and flat at the certificate, and a
  // strict certificate cannot coexist with crossing lettered lines (a proof against it).
  // With letters, the headline is the strict question: "foldable" never rests on a motion
  // that leaves lettered creases flat; such a motion is "foldable only in part", or a proof of
  // "not foldable" where crossing lettered lines rule out every strict motion.
  if (r.folds_in_part) {
    ASSERT_TRUE(r.strictness.has_value()) << where;
    EXPECT_FALSE(r.strictness->strict) << where;
    EXPECT_TRUE(r.assignment_used) << where;
    EXPECT_EQ(r.verdict, r.strictness->strict_obstruction_vertices.empty() ? FoldabilityClass::kFoldableInPart
                                                                            : FoldabilityClass::kNotFoldableProof)
        << where;
  }
  if (r.verdict == FoldabilityClass::kFoldable && r.assignment_used && r.strictness) {
    EXPECT_TRUE(r.strictness->strict) << where;
  }
  if (r.strictness) {
    EXPECT_EQ(r.strictness->strict, r.strictness->flat_lettered.empty()) << where;
    if (r.strictness->strict) {
      EXPECT_TRUE(r.strictness->strict_obstruction_vertices.empty()) << where;
    }
  }
  // "Within the input's precision" only with the rounding witness that explains the gap.
  if (r.verdict == FoldabilityClass::kFoldableWithinTolerance) {
    ASSERT_TRUE(r.input_precision.has_value()) << where;
    EXPECT_TRUE(r.input_precision->explained) << where;
    EXPECT_LE(r.input_precision->max_change_ratio, 1.0) << where;
    EXPECT_GT(r.input_precision->given_residual, r.tolerances.certificate_residual) << where;
  }
}

// The sanitizer build (Debug, ASan) runs every test ~30x slower; there the five large
// box-pleat files (thousands of vertices, ~10 s each in Release) are left to the Release run.
constexpr bool kSanitized = test::kSlowSanitizedBuild;

void expect_cli_agrees(const std::string& file, bool use_assignment) {
  const std::string where = file + (use_assignment ? "" : " (letters ignored)");
  const CreasePattern p = read_fold(file);
  const Topology t = build_topology(p, file);
  if (kSanitized && p.num_vertices() > 1000) GTEST_SKIP() << where << ": large; checked by the Release run";
  FoldabilityOptions o;
  o.use_assignment = use_assignment;
  const FoldabilityReport r = check_foldability(p, t, o);
  expect_report_invariants(r, where);

  const test::CommandResult c =
      test::run_command(test::cli() + " check '" + file + "' --json" + (use_assignment ? "" : " --ignore-assignment"));
  ASSERT_EQ(c.status, 0) << where << ": " << c.err;
  const auto j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["verdict_class"], to_string(r.verdict)) << where;
  const nlohmann::json expected_foldable =
      r.foldable() ? nlohmann::json(true) : r.not_foldable() ? nlohmann::json(false) : nlohmann::json(nullptr);
  EXPECT_EQ(j["rigidly_foldable"], expected_foldable) << where;
  EXPECT_EQ(j["is_proof"], r.is_proof) << where;
  EXPECT_EQ(j["dof"], r.dof) << where;
  EXPECT_EQ(j["model"], r.model_name) << where;
  EXPECT_EQ(j["model_choice"], r.model_choice) << where;
  EXPECT_EQ(j["obstruction"].is_null(), !r.obstruction.has_value()) << where;
  ASSERT_EQ(j["branches"].size(), r.branches.size()) << where;
  for (std::size_t i = 0; i < r.branches.size(); ++i) {
    EXPECT_EQ(j["branches"][i]["stopped_by"], r.branches[i].stop_text()) << where << " branch " << i;
    EXPECT_EQ(j["branches"][i]["driving_crease"], r.branches[i].driving_edge) << where << " branch " << i;
  }
  // The solvers are deterministic (seeded starts); only BLAS summation order may differ.
  EXPECT_NEAR(j["max_residual"].get<double>(), r.max_residual, 1e-13) << where;
  EXPECT_EQ(j["tolerances"]["residual_rad"].get<double>(), r.tolerances.residual) << where;
}

class BundledFile : public ::testing::TestWithParam<std::string> {};
class CorpusFile : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledFile, KernelReportAndCliAgreeWithAndWithoutLetters) {
  expect_cli_agrees(GetParam(), true);
  expect_cli_agrees(GetParam(), false);
}

// Letters as given only: ignoring them doubles the time of the large box-pleat files.
TEST_P(CorpusFile, KernelReportAndCliAgree) { expect_cli_agrees(GetParam(), true); }

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = fs::path(info.param).stem().string();
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Foldability, BundledFile, ::testing::ValuesIn(pattern_files(false)), test_name);
INSTANTIATE_TEST_SUITE_P(Foldability, CorpusFile, ::testing::ValuesIn(pattern_files(true)), test_name);

// A sheet with no interior vertex (a unit square folded along one diagonal) has no closure
// rows: the general model and the branch explorer used to crash on it (Eigen's SVD of an
// empty matrix). It folds with 1 DOF, one crease from flat to the fold limit.
TEST(Foldability, NoInteriorVertexFoldsAlongItsOneCrease) {
  CreasePattern p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
  p.assignments = {Assignment::Boundary, Assignment::Boundary, Assignment::Boundary, Assignment::Boundary,
                   Assignment::Valley};
  p.fold_angles.assign(5, std::nullopt);
  p.faces = {{0, 1, 2}, {0, 2, 3}};
  const Topology t = build_topology(p);
  for (bool general : {false, true}) {
    FoldabilityOptions o;
    o.force_general = general;
    const FoldabilityReport r = check_foldability(p, t, o);
    expect_report_invariants(r, general ? "diagonal, general" : "diagonal");
    EXPECT_EQ(r.verdict, FoldabilityClass::kFoldable);
    EXPECT_EQ(r.dof, 1);
  }
  FoldabilityOptions o;
  o.force_general = true;
  const FoldabilityReport r = check_foldability(p, t, o);
  ASSERT_TRUE(r.branches_explored);
  bool reaches_limit = false;
  for (const TracedBranch& b : r.branches)
    reaches_limit |= b.stopped_by == StopReason::kFoldLimit && b.stop_crease == 4 && b.signs_match_assignment;
  EXPECT_TRUE(reaches_limit);
}

TEST(Foldability, EveryBundledAndCorpusFileIsListed) {
  EXPECT_GE(pattern_files(false).size(), 10u);
  ASSERT_TRUE(fs::is_directory(RIGIDFOLD_CORPUS_DIR));
  EXPECT_GE(pattern_files(true).size(), 15u);
}

}}  // namespace
}  // namespace rigidfold
