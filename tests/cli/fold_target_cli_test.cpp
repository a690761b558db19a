// `rigidfold fold --target` as a user runs it: noisy target angles of a folded square twist,
// as JSON and as a FOLD file's edges_foldAngle, folded to the nearest closed state (closure
// residual <= 1e-12, the faces meet); bad combinations of flags and a target FOLD of another
// pattern are exit 2 with nothing written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "data/generators/square_twist.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct TargetDir {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rigidfold_target_" + std::to_string(::getpid()));
  CreasePattern pattern = generators::square_twist({}, generators::SquareTwistType::Type3);
  TargetDir() {
    std::filesystem::create_directories(dir);
    write_fold(pattern, path("twist.fold"));
    const Topology t = build_topology(pattern);
    const Eigen::VectorXd state = verdict_with_assignment(pattern, t).family->angles(0.5);
    nlohmann::json angles = nlohmann::json::array();
    CreasePattern with_angles = pattern;
    for (int e = 0; e < pattern.num_edges(); ++e) {
      const double noisy = t.edge_is_hinge[e] ? state[e] + 0.01 * ((e % 3) - 1) : 0.0;  // -0.01, 0, +0.01 rad in turn
      angles.push_back(to_degrees(noisy));
      with_angles.fold_angles[e] = noisy;
    }
    std::ofstream(path("target.json")) << angles.dump();
    with_angles.fold_angles_in_file = true;
    write_fold(with_angles, path("target.fold"));
  }
  ~TargetDir() { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

TEST(FoldTargetCli, NoisyTargetsFoldToTheNearestClosedState) {
  TargetDir d;
  for (const char* target : {"target.json", "target.fold"}) {
    const auto r = test::run_command(test::cli() + " fold " + d.path("twist.fold") + " --target " + d.path(target) + " --out " +
                                     d.path("folded.fold") + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["nearest_state"]["converged"], true) << target;
    EXPECT_LE(j["nearest_state"]["residual"].get<double>(), 1e-12);
    EXPECT_GT(j["nearest_state"]["target_residual"].get<double>(), 1e-4);
    EXPECT_LE(j["nearest_state"]["max_distance_deg"].get<double>(), 2 * to_degrees(0.01));
    EXPECT_LE(j["relative_mismatch"].get<double>(), 1e-12);
    EXPECT_EQ(j["nearest_state"]["per_crease"].size(), static_cast<std::size_t>(d.pattern.num_edges()));
    EXPECT_TRUE(std::filesystem::exists(d.path("folded.fold")));
    std::filesystem::remove(d.path("folded.fold"));
  }
}

TEST(FoldTargetCli, BadFlagsAndAnotherPatternsTargetAreExit2) {
  TargetDir d;
  const std::string base = test::cli() + " fold " + d.path("twist.fold") + " --out " + d.path("folded.fold");
  EXPECT_EQ(test::run_command(base + " --target " + d.path("target.json") + " --angles " + d.path("target.json")).status, 2);
  EXPECT_EQ(test::run_command(base + " --angles " + d.path("target.json") + " --hold 1").status, 2);
  EXPECT_EQ(test::run_command(base).status, 2);
  const auto held = test::run_command(base + " --target " + d.path("target.json") + " --hold 999");
  EXPECT_EQ(held.status, 2);
  EXPECT_NE(held.err.find("999"), std::string::npos) << held.err;
  CreasePattern other = d.pattern;
  std::swap(other.edges[0], other.edges[1]);
  write_fold(other, d.path("other.fold"));
  const auto r = test::run_command(base + " --target " + d.path("other.fold"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("edges_vertices[0]"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(d.path("folded.fold")));
}

}}  // namespace
}  // namespace rigidfold
