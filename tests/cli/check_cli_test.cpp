// `rigidfold check --json` on generated patterns: the documented keys, verdicts that match
// seed 001 (square twist Types 3/4 fold, 1/2 do not), exit 2 on bad input.
#include <cmath>
#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <nlohmann/json.hpp>

#include "data/generators/miura.hpp"
#include "data/generators/miura_tube.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/closure/closure_system.hpp"
#include "data/generators/waterbomb.hpp"
#include "tests/closure/closure_test_utils.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

nlohmann::json check(const CreasePattern& p, const std::string& name, const std::string& flags = "") {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_check_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = (dir / (name + ".fold")).string();
  write_fold(p, path);
  const auto r = test::run_command(test::cli() + " check " + path + " --json " + flags);
  EXPECT_EQ(r.status, 0) << r.err;
  std::filesystem::remove_all(dir);
  return nlohmann::json::parse(r.out);
}

TEST(CheckCli, MiuraIsFoldableWithOneDofAndSmallResidual) {
  generators::MiuraParams m;
  m.rows = 5;
  m.cols = 7;
  const auto j = check(generators::miura_ori(m), "miura");
  for (const char* key : {"rigidly_foldable", "dof", "branches", "bifurcations", "obstruction", "model", "max_residual", "seconds"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["rigidly_foldable"], true);
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["model"], "multiplier-propagation");
  ASSERT_EQ(j["branches"].size(), 1u);
  EXPECT_EQ(j["branches"][0]["signs_match_assignment"], true);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-12);
  EXPECT_GT(std::fabs(j["branches"][0]["range_deg"][1].get<double>()), 170.0);  // the driving crease may be a mountain
  EXPECT_TRUE(j["obstruction"].is_null());
}

TEST(CheckCli, SquareTwistTypesFollowSeed001) {
  for (double twist_deg : {20.0, 45.0, 70.0}) {
    generators::SquareTwistParams params;
    params.twist = twist_deg * 3.141592653589793 / 180;
    using T = generators::SquareTwistType;
    for (auto [type, foldable] : {std::pair{T::Type1, false}, {T::Type2, false}, {T::Type3, true}, {T::Type4, true}}) {
      const auto j = check(generators::square_twist(params, type), "twist");
      EXPECT_EQ(j["rigidly_foldable"], foldable) << twist_deg << " type " << generators::to_string(type);
      if (!foldable) {
        ASSERT_FALSE(j["obstruction"].is_null());
        EXPECT_EQ(j["obstruction"]["loop_vertices"].size(), 4u);  // the four vertices around the central square
        EXPECT_EQ(j["dof"], 0);
        // Ignoring the assignment, the same geometry folds (in another M-V assignment).
        EXPECT_EQ(check(generators::square_twist(params, type), "twist", "--ignore-assignment")["rigidly_foldable"], true);
      }
    }
  }
}

TEST(CheckCli, OutsideTheMultiplierModelTheGeneralSolverAnswersAndSaysHowSure) {
  // A perturbed Miura is not flat-foldable. Its faces' cycles of degree-4 vertices have
  // first-order loop gains away from 1: a proof (interval_loop_gain.hpp). Forced onto the
  // general solver (--general), the numerical search finds no folded point near flat,
  // reports the least residual, and flags its "no" as numerical evidence.
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  m.perturbation = 0.05;
  const auto proof = check(generators::miura_ori(m), "perturbed");
  EXPECT_EQ(proof["model"], "first-order loop gain (interval arithmetic)");
  EXPECT_EQ(proof["rigidly_foldable"], false);
  EXPECT_EQ(proof["is_proof"], true);
  const auto j = check(generators::miura_ori(m), "perturbed", "--general");
  EXPECT_EQ(j["model"], "general-loop-closure");
  EXPECT_EQ(j["rigidly_foldable"], false);
  EXPECT_EQ(j["is_proof"], false);
  ASSERT_FALSE(j["obstruction"].is_null());
  EXPECT_GT(j["obstruction"]["least_residual"].get<double>(), 1e-8);
  EXPECT_FALSE(j["obstruction"]["worst_vertices"].empty());
}

TEST(CheckCli, BothModelsAgreeOnMiuraAndSquareTwists) {
  generators::MiuraParams m;
  m.rows = 3;
  m.cols = 4;
  const auto exact = check(generators::miura_ori(m), "miura");
  const auto general = check(generators::miura_ori(m), "miura", "--general");
  EXPECT_EQ(general["model"], "general-loop-closure");
  EXPECT_EQ(exact["rigidly_foldable"], general["rigidly_foldable"]);
  EXPECT_EQ(exact["dof"], general["dof"]);
  EXPECT_LE(general["max_residual"].get<double>(), 1e-12);
  // The general model's branches say which linear solver traced them and how many
  // factorisations it took; the certifying path is published, sampled, and its
  // states close (replayable by other tools).
  ASSERT_FALSE(general["branches"].empty());
  int traced = 0;
  for (const auto& b : general["branches"]) {
    if (b["points"].get<int>() < 10) continue;
    ++traced;
    EXPECT_EQ(b["linear_solver"], "direct (CHOLMOD)");
    EXPECT_GT(b["factorizations"].get<int>(), 0);
  }
  EXPECT_GE(traced, 2);
  const CreasePattern miura = generators::miura_ori(m);
  ASSERT_TRUE(general.contains("certificate_states_deg"));
  const auto& states = general["certificate_states_deg"];
  ASSERT_GE(states.size(), 2u);
  const Topology topo = build_topology(miura);
  const ClosureSystem sys(miura, topo);
  double largest = 0;
  for (const auto& state : states) {
    ASSERT_EQ(state.size(), static_cast<std::size_t>(miura.num_edges()));
    Eigen::VectorXd rho(miura.num_edges());
    for (int e = 0; e < miura.num_edges(); ++e) rho[e] = state[e].get<double>() * std::numbers::pi / 180;
    EXPECT_LE(sys.residual(sys.unknowns_from_edges(rho)).lpNorm<Eigen::Infinity>(), 1e-11);
    largest = std::max(largest, rho.cwiseAbs().maxCoeff());
  }
  EXPECT_GE(largest, std::numbers::pi / 6);  // the certificate fold
  EXPECT_FALSE(exact.contains("certificate_states_deg"));  // multiplier model: its closed-form family
  generators::SquareTwistParams params;
  params.twist = 40 * 3.141592653589793 / 180;
  using T = generators::SquareTwistType;
  for (auto type : {T::Type1, T::Type2, T::Type3, T::Type4}) {
    const auto a = check(generators::square_twist(params, type), "twist");
    const auto b = check(generators::square_twist(params, type), "twist", "--general");
    EXPECT_EQ(a["rigidly_foldable"], b["rigidly_foldable"]) << generators::to_string(type);
  }
}

// The strict question answered on its own: certified where the certificate folds
// every M/V crease (the waterbomb base), disproved where straight lettered lines cross (a
// degree-4 vertex of two straight lines, one valley and one mountain: each folds alone).
TEST(CheckCli, SaysWhetherFoldingIsStrict) {
  const auto waterbomb = check(generators::waterbomb_base({}), "waterbomb");
  EXPECT_EQ(waterbomb["verdict_class"], "foldable");
  EXPECT_EQ(waterbomb["strictness"]["strict"], true);
  EXPECT_EQ(waterbomb["strictness"]["strict_verdict"], "strictly foldable (certified: the certificate folds every M/V crease)");
  const double q = std::numbers::pi / 2;
  CreasePattern cross = testing::single_vertex_pattern({0.0, q, 2 * q, 3 * q});
  for (int e : {0, 2}) cross.assignments[e] = Assignment::Valley;
  for (int e : {1, 3}) cross.assignments[e] = Assignment::Mountain;
  const auto crossing = check(cross, "crossing");
  // The headline answers the strict question: no motion folds every lettered crease (proof);
  // a line folds alone, which is said beside it.
  EXPECT_EQ(crossing["verdict_class"], "not foldable (proof)");
  EXPECT_EQ(crossing["is_proof"], true);
  EXPECT_EQ(crossing["folds_in_part"], true);
  EXPECT_EQ(crossing["obstruction"]["kind"], "crossing lettered lines");
  EXPECT_EQ(waterbomb["folds_in_part"], false);
  EXPECT_EQ(crossing["strictness"]["strict"], false);
  EXPECT_EQ(crossing["strictness"]["flat_lettered_creases"].size(), 2u);
  EXPECT_EQ(crossing["strictness"]["strict_obstruction_vertices"], nlohmann::json::array({0}));
  EXPECT_EQ(crossing["strictness"]["strict_verdict"], "not strictly foldable (proof: straight lettered lines cross)");
}

TEST(CheckCli, BadInputExitsTwo) {
  EXPECT_EQ(test::run_command(test::cli() + " check /nonexistent.fold --json").status, 2);
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";
  for (const std::string bad : {"-1", "nan", "inf", "1e-3x", "", "exactly"}) {
    const test::CommandResult r = test::run_command(test::cli() + " check " + miura + " --tolerance '" + bad + "'");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--tolerance"), std::string::npos) << bad << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << bad;
  }
}

// --tolerance: the precision the verdict assumed is stated, whatever its source.
TEST(CheckCli, StatesThePrecisionItAssumed) {
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";
  const auto precision = [&](const std::string& flags) {
    const test::CommandResult r = test::run_command(test::cli() + " check --json " + miura + flags);
    EXPECT_EQ(r.status, 0) << flags << r.err;
    return nlohmann::json::parse(r.out)["coordinate_precision"].get<std::string>();
  };
  EXPECT_EQ(precision(" --tolerance exact"), "coordinates taken as exact (--tolerance exact)");
  EXPECT_EQ(precision(" --tolerance 0.001"), "coordinates within 0.001 of the true ones (stated with --tolerance)");
  EXPECT_FALSE(precision("").empty());
}

// Seed 001 Type 2M through the CLI: every branch from flat and through the interior
// bifurcation, the bifurcation located within a bound <= 1e-10 rad, with its two tangent lines.
TEST(CheckCli, Type2MBranchesAndLocatedBifurcation) {
  const auto j = check(generators::square_twist_modified({}, generators::SquareTwistModifiedType::Type2M), "type2m");
  EXPECT_EQ(j["rigidly_foldable"], true);
  ASSERT_TRUE(j["branch_exploration"].is_object());
  int located = 0;
  for (const auto& b : j["bifurcations"]) {
    if (b["kind"] != "bifurcation") continue;
    ++located;
    EXPECT_LE(b["location_error_bound_rad"].get<double>(), 1e-10);
    EXPECT_EQ(b["tangent_lines"], 2);
    EXPECT_EQ(b["kernel_dimension"], 2);
  }
  EXPECT_GE(located, 1);
  int keep = 0;
  for (const auto& b : j["branches"]) {
    EXPECT_LE(b["max_residual"].get<double>(), 1e-12);
    if (b["signs_match_assignment"] == true && b["from_point"] == 0) {
      ++keep;
      EXPECT_EQ(b["stopped_by"], "bifurcation");
      EXPECT_TRUE(b["global_interference"].is_null());
    }
  }
  EXPECT_EQ(keep, 2);
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// A sheet with a hole (the bundled Miura tube's generator): checked from its given 3D state
// with the SE(3) hole closure instead of being refused.
TEST(CheckCli, MiuraTubeIsCheckedFromItsGivenState) {
  generators::MiuraTubeParams tp;
  tp.rows = 4;
  const auto j = check(generators::miura_tube(tp), "miura_tube");
  EXPECT_EQ(j["rigidly_foldable"], true);
  EXPECT_EQ(j["dof"], 1);
  EXPECT_EQ(j["holes_closed"], 1);
  EXPECT_NE(j["model"].get<std::string>().find("hole"), std::string::npos);
  ASSERT_EQ(j["branches"].size(), 2u);
  for (const auto& b : j["branches"]) {
    EXPECT_EQ(b["stopped_by"], "fold limit");
    EXPECT_EQ(b["signs_match_assignment"], true);
    EXPECT_LE(b["max_residual"].get<double>(), 1e-11);
  }
  EXPECT_TRUE(j["obstruction"].is_null());
}

}}  // namespace
}  // namespace rigidfold
