// Scale-free geometry: random Miura-ori and square-twist patterns scaled by 10^k,
// k in [-300, 300], read back from FOLD text, get the verdict and DOF they get at scale 1;
// the file's coordinates survive the round trip bit for bit; `check` on the CLI agrees.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using generators::miura_ori;
using generators::MiuraParams;
using generators::square_twist;
using generators::SquareTwistParams;
using generators::SquareTwistType;

// The pattern's FOLD text with every coordinate multiplied by 10^k.
std::string scaled_fold_text(const CreasePattern& p, int k) {
  CreasePattern q = p;
  const double f = std::pow(10.0, k);
  for (auto& v : q.vertices) v *= f;
  return write_fold_string(q);
}

struct Verdict {
  FoldabilityClass verdict;
  int dof;
};

Verdict verdict_of(const std::string& fold_text, const std::string& name) {
  const CreasePattern p = parse_fold(fold_text, name);
  const FoldabilityReport r = check_foldability(p, build_topology(p, name));
  return {r.verdict, r.dof};
}

std::vector<CreasePattern> random_patterns(SplitMix64& rng) {
  std::vector<CreasePattern> out;
  for (int i = 0; i < 3; ++i) {
    MiuraParams m;
    m.rows = 2 + static_cast<int>(rng.next() % 3);
    m.cols = 2 + static_cast<int>(rng.next() % 3);
    m.alpha = to_radians(35 + 45 * rng.uniform());
    m.a = 0.5 + 1.5 * rng.uniform();
    m.b = 0.5 + 1.5 * rng.uniform();
    if (i == 2) {
      m.perturbation = 0.05;  // no longer flat-foldable: the general solver decides
      m.seed = rng.next() % 1000;
    }
    out.push_back(miura_ori(m));
  }
  for (SquareTwistType type : {SquareTwistType::Type1, SquareTwistType::Type4}) {
    SquareTwistParams s;
    s.twist = to_radians(15 + 60 * rng.uniform());
    s.side = 0.5 + rng.uniform();
    s.pleat = 0.5 + rng.uniform();
    out.push_back(square_twist(s, type));
  }
  return out;
}

TEST(ScaleInvariance, RandomMiuraAndSquareTwistsKeepVerdictAndDofAtEveryScale) {
  SplitMix64 rng{2020};
  const std::vector<CreasePattern> patterns = random_patterns(rng);
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    const std::string name = "pattern " + std::to_string(i);
    const Verdict at_one = verdict_of(scaled_fold_text(patterns[i], 0), name);
    std::vector<int> ks{-300, 300, -19, 19};  // both ends, and just inside the unscaled band
    for (int j = 0; j < 3; ++j) ks.push_back(-300 + static_cast<int>(rng.next() % 601));
    for (int k : ks) {
      Verdict v;
      ASSERT_NO_THROW(v = verdict_of(scaled_fold_text(patterns[i], k), name)) << name << " at 1e" << k;
      EXPECT_EQ(v.verdict, at_one.verdict) << name << " at 1e" << k;
      EXPECT_EQ(v.dof, at_one.dof) << name << " at 1e" << k;
    }
  }
}

std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// The regression case: a unit square's edge norm underflowed (1e-300) or overflowed (1e300) and
// the square was refused as "zero-length edge". A vertex really on another is still refused.
TEST(ScaleInvariance, TinyAndHugeSquaresAreReadAndWrittenBackExactly) {
  for (double side : {1e-300, 3e-308, 1e300, 1.7e308}) {
    const std::string text = "{\"vertices_coords\": [[0, 0], [" + num(side) + ", 0], [" + num(side) + ", " + num(side) + "], [0, " +
                             num(side) + "]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0]]," +
                             " \"edges_assignment\": [\"B\",\"B\",\"B\",\"B\"]}";
    CreasePattern p;
    ASSERT_NO_THROW(p = parse_fold(text, "square")) << side;
    EXPECT_NE(p.length_exponent, 0) << side;
    EXPECT_EQ(p.num_faces(), 1);
    EXPECT_GE((p.vertices[2] - p.vertices[0]).norm(), 1.0);  // kernel units: size ~1
    const CreasePattern back = parse_fold(write_fold_string(p), "square written");
    const CreasePattern direct = parse_fold(text, "square");
    for (int v = 0; v < 4; ++v) EXPECT_EQ(to_file_units(back, back.vertices[v]), to_file_units(direct, direct.vertices[v]));
    // The written coordinates are the file's: scaling back is exact.
    EXPECT_EQ(to_file_units(back, back.vertices[2]), Eigen::Vector3d(side, side, 0));
  }
  // Within the band nothing moves.
  const CreasePattern unit = parse_fold(
      "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0]]}", "unit");
  EXPECT_EQ(unit.length_exponent, 0);
  EXPECT_EQ(unit.vertices[2], Eigen::Vector3d(1, 1, 0));
  // Coincident vertices are still a zero-length edge at any scale.
  EXPECT_THROW(parse_fold("{\"vertices_coords\": [[0,0],[1e-300,0],[1e-300,0],[0,1e-300]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0]]}",
                          "degenerate"),
               InputError);
}

// `check` on the command line: a Miura-ori written at 1e-300 and 1e300 reports the verdict
// and DOF of the same pattern at scale 1.
TEST(ScaleInvariance, CheckCommandGivesTheSameVerdictAtTheEndsOfTheScale) {
  MiuraParams m;
  m.rows = 3;
  m.cols = 3;
  const CreasePattern p = miura_ori(m);
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_scale_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string verdicts[3];
  const int ks[3] = {0, -300, 300};
  for (int i = 0; i < 3; ++i) {
    const auto in = dir / ("m" + std::to_string(i) + ".fold");
    std::ofstream(in) << scaled_fold_text(p, ks[i]);
    const auto out = dir / ("m" + std::to_string(i) + ".json");
    const std::string cmd = std::string(RIGIDFOLD_CLI) + " check " + in.string() + " --json > " + out.string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream f(out);
    const nlohmann::json j = nlohmann::json::parse(f);
    verdicts[i] = j["verdict_class"].dump() + " dof " + j["dof"].dump();
  }
  EXPECT_EQ(verdicts[1], verdicts[0]);
  EXPECT_EQ(verdicts[2], verdicts[0]);
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
