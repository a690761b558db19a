// On the command line: numbers checked where they enter (NaN and +-inf refused with
// the flag named, documented ranges closed), and no closed-form result printed without its
// own check: over a grid reaching the ends of every range, `vertex miura`, `vertex s4r` and
// `string forward` either print an answer whose closure residual is within tolerance
// (exit 0) or say "no answer within tolerance" (exit 3) - never a larger residual at exit 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <span>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/math/angle_units.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// Exit 0 with a residual within tolerance, or exit 3 naming it; returns the status.
int expect_checked(const test::CommandResult& r, const std::string& what, double tolerance,
                   const std::function<double(const nlohmann::json&)>& worst_residual) {
  EXPECT_TRUE(r.status == 0 || r.status == 3) << what << " exit " << r.status << ": " << r.err;
  if (r.status == 0) {
    const double res = worst_residual(nlohmann::json::parse(r.out));
    EXPECT_LE(res, tolerance) << what;
  } else if (r.status == 3) {
    EXPECT_NE(r.err.find("no answer within tolerance"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("residual"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << what;
  }
  return r.status;
}

TEST(CheckedNumbersCli, MiuraVertexGridToTheEndsOfItsRanges) {
  const std::vector<double> alphas{1e-300, 1e-170, 1e-12, 60, 90 - 1e-12};
  int answered = 0;
  for (double a1 : alphas)
    for (double a2 : alphas) {
      const double limit = to_degrees(miura_theta_limit(to_radians(a1), to_radians(a2)));
      for (double th : {0.0, 1e-300, -1e-12, 0.5 * limit, -limit, limit}) {
        const std::string cmd = test::cli() + " vertex miura --alpha1 " + num(a1) + " --alpha2 " + num(a2) + " --theta " + num(th) + " --json";
        const auto r = test::run_command(cmd);
        const int status = expect_checked(r, cmd, kMiuraClosureTolerance, [&](const nlohmann::json& j) {
          // Recomputed from the printed numbers, not only the printed residual.
          std::vector<double> sectors, rho;
          for (double s : j["sectors_deg"]) sectors.push_back(to_radians(s));
          for (const auto& f : j["fold_angles_deg"]) rho.push_back(to_radians(f["fold_angle_deg"].get<double>()));
          return std::max(j["closure_residual_rad"].get<double>(), vertex_closure_residual(sectors, rho).norm());
        });
        answered += status == 0;
      }
    }
  // The closed form is accurate over the whole closed range: it always answers.
  EXPECT_EQ(answered, static_cast<int>(alphas.size() * alphas.size() * 6));
}

TEST(CheckedNumbersCli, S4RGridToTheEndsOfItsRanges) {
  const std::vector<std::vector<double>> twists{{50, 110, 100, 95}, {90, 90, 90, 90},  {-360, 360, 180, 0}, {1e-300, 90, 90, 90},
                                                {45, 45, 45, 45},  {180, 180, 180, 180}, {30, 60, 30, 60},  {120, 100, 80, 60}};
  for (const auto& t : twists) {
    const S4RInputRange range = s4r_input_range({to_radians(t[0]), to_radians(t[1]), to_radians(t[2]), to_radians(t[3])}, 0);
    std::vector<double> inputs{-180, 180, 0, 1e-12, 37};
    for (double lim : range.limits()) inputs.push_back(to_degrees(lim));
    for (double in : inputs) {
      const std::string cmd = test::cli() + " vertex s4r --twists " + num(t[0]) + "," + num(t[1]) + "," + num(t[2]) + "," + num(t[3]) +
                              " --input " + num(std::clamp(in, -180.0, 180.0)) + " --json";
      expect_checked(test::run_command(cmd), cmd, kS4RClosureTolerance, [](const nlohmann::json& j) {
        double worst = 0;
        for (const auto& b : j["branches"]) worst = std::max(worst, b["closure_residual_rad"].get<double>());
        return worst;
      });
    }
  }
}

// `string forward` over alphas reaching the ends of the spec's range and theta to +-the
// vertex limit: exit 0 with every vertex's printed fold angles closing its loop, 2 when the
// spec's crease pattern cannot be drawn (named as such), or 3 - never a larger residual at 0.
TEST(CheckedNumbersCli, StringForwardGridToTheEndsOfItsRanges) {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_string_grid_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::vector<double> alphas{1e-300, 1e-6, 30, 89.999999, 90 - 1e-12};
  int answered = 0;
  for (double a1 : alphas)
    for (double a2 : alphas) {
      const std::string spec = (dir / "spec.json").string();
      std::ofstream(spec) << "{\"vertices\": [{\"alpha1_deg\": " << num(a1) << ", \"alpha2_deg\": " << num(a2)
                          << "}, {\"alpha1_deg\": 40, \"alpha2_deg\": 50}], \"segment_length\": 1}";
      const double limit = to_degrees(std::min(miura_theta_limit(to_radians(a1), to_radians(a2)), miura_theta_limit(to_radians(40), to_radians(50))));
      for (double th : {0.0, 1e-12, 0.5 * limit, -0.999 * limit}) {
        const std::string cmd = test::cli() + " string forward " + spec + " --theta " + num(th) + " --json";
        const auto r = test::run_command(cmd);
        if (r.status == 2) {
          EXPECT_NE(r.err.find("cannot be drawn"), std::string::npos) << cmd << ": " << r.err;
          continue;
        }
        answered += expect_checked(r, cmd, kMiuraClosureTolerance, [](const nlohmann::json& j) {
                      double worst = 0;
                      for (const auto& v : j["vertices"]) {
                        const auto sec = miura_sectors(to_radians(v["alpha1_deg"].get<double>()), to_radians(v["alpha2_deg"].get<double>()));
                        std::vector<double> rho;
                        for (const char* c : {"spinal_out", "peripheral_1", "spinal_in", "peripheral_2"})
                          rho.push_back(to_radians(v["fold_angles_deg"][c].get<double>()));
                        worst = std::max(worst, vertex_closure_residual(std::span<const double>(sec.data(), 4), rho).norm());
                      }
                      return worst;
                    }) == 0;
      }
    }
  EXPECT_GT(answered, 40);  // the drawable part of the grid answers
  std::filesystem::remove_all(dir);
}

TEST(CheckedNumbersCli, NonFiniteAndOutOfRangeFlagsExitTwoNamingTheFlag) {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_flags_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string square = (dir / "square.fold").string();
  std::ofstream(square) << R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1]], "edges_vertices": [[0,1],[1,2],[2,3],[3,0]]})";
  struct Case {
    std::string args, flag;
  };
  const std::vector<Case> cases{
      {"info " + square + " --tolerance-deg nan", "--tolerance-deg"},
      {"info " + square + " --tolerance-deg inf", "--tolerance-deg"},
      {"info " + square + " --tolerance-deg 0", "--tolerance-deg"},
      {"info " + square + " --tolerance-deg 11", "--tolerance-deg"},
      {"vertex miura --alpha1 nan --alpha2 60 --theta 10", "--alpha1"},
      {"vertex miura --alpha1 30 --alpha2 -inf --theta 10", "--alpha2"},
      {"vertex miura --alpha1 30 --alpha2 60 --theta nan", "--theta"},
      {"vertex miura --alpha1 1e-301 --alpha2 60 --theta 10", "--alpha1"},
      {"vertex miura --alpha1 90 --alpha2 60 --theta 10", "--alpha1"},
      {"vertex s4r --twists 90,nan,90,90 --input 10", "--twists"},
      {"vertex s4r --twists 90,90,90,360.5 --input 10", "--twists"},
      {"vertex s4r --twists 90,90,90,90 --input 1e999", "--input"},
      {"generate miura --a nan --out " + (dir / "m.fold").string(), "--a"},
      {"generate miura --alpha-deg inf --out " + (dir / "m.fold").string(), "--alpha-deg"},
      {"generate square-twist --side -nan --out " + (dir / "s.fold").string(), "--side"},
      {"generate resch-triangle --side inf --out " + (dir / "r.fold").string(), "--side"},
      {"generate resch-triangle --rows 0 --out " + (dir / "r.fold").string(), "--rows"},
      {"generate resch-triangle --cols 401 --out " + (dir / "r.fold").string(), "--cols"},
      {"generate resch-triangle --n 3 --out " + (dir / "r.fold").string(), "--n"},
      {"trace " + square + " --to nan", "--to"},
  };
  for (const auto& c : cases) {
    const auto r = test::run_command(test::cli() + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.flag), std::string::npos) << c.args << ": " << r.err;
  }
  // The ends of the closed ranges are accepted.
  for (const std::string& ok : {"info " + square + " --tolerance-deg 1e-9", "info " + square + " --tolerance-deg 10",
                               std::string("vertex miura --alpha1 1e-300 --alpha2 89.999999999999 --theta 0"),
                               std::string("vertex s4r --twists -360,360,90,90 --input -180")})
    EXPECT_EQ(test::run_command(test::cli() + " " + ok).status, 0) << ok;
  std::filesystem::remove_all(dir);
}

// The regression case: exit 0 printed rho_b = 0 (80 deg off) with a residual of 1.4 rad.
TEST(CheckedNumbersCli, MiuraTinyAlphaIsAccurate) {
  const auto r = test::run_command(test::cli() + " vertex miura --alpha1 1e-170 --alpha2 60 --theta 20 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["fold_angles_deg"][1]["fold_angle_deg"].get<double>(), 80.0, 1e-11);
  EXPECT_LE(j["closure_residual_rad"].get<double>(), 1e-14);
}

}}  // namespace
}  // namespace rigidfold
