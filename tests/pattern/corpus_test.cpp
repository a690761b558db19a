// Files made by other tools (tests/data/corpus, with their licences): FOLD reference examples, the rigid-origami
// Python solver's patterns, Origami Simulator exports. Each must load (none is rejected
// today; a rejection would have to be asserted here with its reason), round-trip, and
// where it holds a folded 3D state, give the right sector angles.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/flat_foldability.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/expect_same_pattern.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


std::string corpus(const std::string& rel) { return std::string(RIGIDFOLD_CORPUS_DIR) + "/" + rel; }

struct CorpusFile {
  const char* path;
  int vertices, edges, faces, interior;
};

const CorpusFile kFiles[] = {
    {"fold-spec/box.fold", 39, 80, 42, 17},
    {"fold-spec/diagonal-cp.fold", 4, 5, 2, 0},
    {"fold-spec/diagonal-folded.fold", 4, 5, 2, 0},
    {"fold-spec/simple.fold", 6, 9, 4, 0},
    {"fold-spec/squaretwist.fold", 16, 24, 9, 4},
    {"origami-simulator/BoxPleatInOutWave.fold", 2601, 5100, 2500, 2401},
    {"origami-simulator/BoxPleatPyramid.fold", 2704, 5304, 2601, 2500},
    {"origami-simulator/BoxPleatSkipOneWave.fold", 2704, 5304, 2601, 2500},
    {"origami-simulator/BoxPleatSpiralPyramid.fold", 3249, 6384, 3136, 3025},
    {"origami-simulator/BoxPleatTessellation.fold", 5776, 11400, 5625, 5476},
    {"rigid-origami/birdBase.fold", 13, 28, 16, 5},
    {"rigid-origami/flappingBird.fold", 24, 59, 36, 14},
    {"rigid-origami/huffmanExdentedBoxes.fold", 684, 1949, 1266, 584},
    {"rigid-origami/huffmanRectangularWeave.fold", 512, 1441, 930, 420},
    {"rigid-origami/huffmanWaterbomb.fold", 440, 1237, 798, 360},
    {"rigid-origami/squareBase.fold", 9, 16, 8, 1},
    {"rigid-origami/waterbombBase.fold", 9, 16, 8, 1},
};

void PrintTo(const CorpusFile& c, std::ostream* os) { *os << c.path; }

class Corpus : public ::testing::TestWithParam<CorpusFile> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(std::filesystem::exists(corpus(GetParam().path))) << "missing from tests/data/corpus";
  }
};

TEST_P(Corpus, LoadsWithExpectedCountsAsOneDisk) {
  const auto& c = GetParam();
  const CreasePattern p = read_fold(corpus(c.path));
  EXPECT_EQ(p.num_vertices(), c.vertices);
  EXPECT_EQ(p.num_edges(), c.edges);
  EXPECT_EQ(p.num_faces(), c.faces);
  const Topology t = build_topology(p, c.path);
  EXPECT_EQ(static_cast<int>(t.interior_vertices.size()), c.interior);
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].euler_characteristic, 1);  // every corpus sheet is a disk
  EXPECT_EQ(t.components[0].holes, 0);
}

TEST_P(Corpus, RoundTripPreservesEveryField) {
  const auto& c = GetParam();
  const CreasePattern a = read_fold(corpus(c.path));
  const CreasePattern b = parse_fold(write_fold_string(a), "roundtrip");
  test::expect_same_pattern(a, b, 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Files, Corpus, ::testing::ValuesIn(kFiles), [](const auto& info) {
  std::string n = info.param.path;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
});

TEST(CorpusSquareTwist, FoldedReferenceGivesTheDesignSectorAngles) {
  const std::string path = corpus("fold-spec/squaretwist.fold");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing from tests/data/corpus";
  const CreasePattern p = read_fold(path);
  const Topology t = build_topology(p, path);
  ASSERT_EQ(t.interior_vertices.size(), 4u);
  // A 45-degree square twist: around each vertex 45, 90, 135, 90 (cyclically). The file
  // has 6 significant digits, so agreement is to about 3e-4 degrees.
  for (int v : t.interior_vertices) {
    const auto& s = t.stars[v].fans[0].sectors;
    ASSERT_EQ(s.size(), 4u);
    const int k = static_cast<int>(std::min_element(s.begin(), s.end()) - s.begin());
    const double expected[4] = {45, 90, 135, 90};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(to_degrees(s[(k + i) % 4]), expected[i], 3e-4) << "vertex " << v;
  }
  // Its measured fold angles close every vertex loop to the file's precision, and the
  // signs follow the file's M/V assignment.
  const Eigen::VectorXd rho = reference_fold_angles(p, t);
  for (int v : t.interior_vertices) {
    const auto& fan = t.stars[v].fans[0];
    std::vector<double> angles;
    for (int e : fan.edges) {
      angles.push_back(rho[e]);
      if (p.assignments[e] == Assignment::Mountain) {
        EXPECT_LT(rho[e], 0);
      }
      if (p.assignments[e] == Assignment::Valley) {
        EXPECT_GT(rho[e], 0);
      }
    }
    EXPECT_LT(vertex_closure_residual(fan.sectors, angles).norm(), 2e-5) << "vertex " << v;
    EXPECT_GT(std::fabs(angles[0]), 0.1);  // genuinely folded, not a flat reference
  }
}

TEST(CorpusDiagonalFolded, FlatFoldedFormGivesPlusPiForTheValley) {
  const std::string path = corpus("fold-spec/diagonal-folded.fold");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing from tests/data/corpus";
  const CreasePattern p = read_fold(path);
  const Topology t = build_topology(p, path);
  const Eigen::VectorXd rho = reference_fold_angles(p, t);
  EXPECT_DOUBLE_EQ(rho[4], std::numbers::pi);
}

TEST(CorpusSquareBase, OrigamiSimulatorExportIsLocallyFlatFoldable) {
  const std::string path = corpus("rigid-origami/squareBase.fold");
  ASSERT_TRUE(std::filesystem::exists(path)) << "missing from tests/data/corpus";
  const CreasePattern p = read_fold(path);
  const Topology t = build_topology(p, path);
  const auto ff = flat_foldability(p, t, 1e-6);
  ASSERT_EQ(ff.size(), 1u);
  EXPECT_EQ(ff[0].degree, 6);  // 8 edges meet, 2 of them are F (triangulation): merged away
  EXPECT_TRUE(ff[0].kawasaki);
  EXPECT_EQ(ff[0].maekawa, std::optional<bool>(true));
}

}}  // namespace
}  // namespace rigidfold
