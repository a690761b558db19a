// Folded geometry: placing faces by a spanning tree must be exact where the fold angles
// close every vertex loop, and must show the error where they do not.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


// One generic flat-foldable degree-4 vertex at the origin in a square sheet: creases at
// 0, 70, 180, 290 degrees (sectors 70, 110, 110, 70: opposite sectors sum to 180).
CreasePattern degree4_sheet() {
  const char* text = R"({"vertices_coords": [[0,0],[1,0],[1,1],[-1,1],[-1,-1],[1,-1],
      [0.36397023426620234,1],[-1,0],[0.36397023426620234,-1]],
    "edges_vertices": [[0,1],[0,6],[0,7],[0,8],[1,2],[2,6],[6,3],[3,7],[7,4],[4,8],[8,5],[5,1]],
    "edges_assignment": ["M","M","V","M","B","B","B","B","B","B","B","B"]})";
  return parse_fold(text, "degree4");
}

TEST(FacePlacement, FlatStateIsTheReference) {
  const CreasePattern p = degree4_sheet();
  const Topology t = build_topology(p);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.num_edges());
  const FoldedGeometry g = place_faces(p, t, zero, zero);
  for (int v = 0; v < p.num_vertices(); ++v) EXPECT_LT((g.vertices[v] - p.vertices[v]).norm(), 1e-15);
  EXPECT_EQ(g.non_tree_hinges, 1);  // 4 faces around one vertex: 4 hinges, 3 in the tree
  EXPECT_LT(g.max_mismatch, 1e-15);
}

TEST(FacePlacement, ClosedFoldAnglesGiveZeroMismatchAndRigidFaces) {
  const CreasePattern p = degree4_sheet();
  const Topology t = build_topology(p);
  ASSERT_EQ(t.interior_vertices.size(), 1u);
  const Fan& fan = t.stars[0].fans[0];
  const std::array<double, 4> sectors{fan.sectors[0], fan.sectors[1], fan.sectors[2], fan.sectors[3]};
  for (auto mode : {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02}) {
    for (double drive : {0.3, 1.5, 2.9, -2.0}) {
      const auto a = flat_fold_angles(sectors, mode, drive, fan.edges[0] == 0 ? 0 : 0);
      Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
      for (int i = 0; i < 4; ++i) rho[fan.edges[i]] = a[i];
      const FoldedGeometry g = place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges()));
      EXPECT_LT(g.relative_mismatch(), 1e-14) << to_string(mode) << " drive " << drive;
      // Rigid faces: every edge keeps its length.
      for (const auto& e : p.edges)
        EXPECT_NEAR((g.vertices[e[0]] - g.vertices[e[1]]).norm(), (p.vertices[e[0]] - p.vertices[e[1]]).norm(), 1e-14);
      // Measured back from the folded geometry, the fold angles are the ones we imposed.
      CreasePattern folded = p;
      folded.vertices = g.vertices;
      folded.coords_2d = false;
      const Topology tf = build_topology(folded);
      const Eigen::VectorXd measured = reference_fold_angles(folded, tf);
      for (int e = 0; e < p.num_edges(); ++e)
        if (t.edge_is_hinge[e]) {
          EXPECT_NEAR(measured[e], rho[e], 1e-12) << "edge " << e;
        }
    }
  }
}

TEST(FacePlacement, MismatchMeasuresTheClosureError) {
  const CreasePattern p = degree4_sheet();
  const Topology t = build_topology(p);
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  rho[0] = 0.5;  // one crease folded alone: the loop cannot close
  const FoldedGeometry g = place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges()));
  EXPECT_GT(g.max_mismatch, 0.1);
  EXPECT_GE(g.worst_edge, 0);
}

// Without vertices the motions and the mismatch are the same as with them.
TEST(FacePlacement, WithoutVerticesKeepsTheMotionsAndTheMismatch) {
  const CreasePattern p = degree4_sheet();
  const Topology t = build_topology(p);
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  rho[0] = 0.5;
  rho[1] = -0.3;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(p.num_edges());
  const FoldedGeometry full = place_faces(p, t, rho, zero);
  const FoldedGeometry lean = place_faces(p, t, rho, zero, /*with_vertices=*/false);
  EXPECT_TRUE(lean.vertices.empty());
  EXPECT_EQ(full.vertices.size(), p.vertices.size());
  EXPECT_EQ(lean.max_mismatch, full.max_mismatch);
  EXPECT_EQ(lean.worst_edge, full.worst_edge);
  ASSERT_EQ(lean.face_motions.size(), full.face_motions.size());
  for (std::size_t f = 0; f < full.face_motions.size(); ++f)
    EXPECT_TRUE(lean.face_motions[f].matrix() == full.face_motions[f].matrix()) << "face " << f;
}

// A NaN fold angle must not pass for a closed fold: the mismatch is NaN, so no "<= tolerance"
// check can accept it.
TEST(FacePlacement, ANanFoldAngleGivesANanMismatch) {
  const CreasePattern p = degree4_sheet();
  const Topology t = build_topology(p);
  for (int e = 0; e < 4; ++e) {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
    rho[e] = std::nan("");
    const FoldedGeometry g = place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges()));
    EXPECT_TRUE(std::isnan(g.max_mismatch)) << "edge " << e;
    EXPECT_FALSE(g.relative_mismatch() <= 1e-9);
    EXPECT_GE(g.worst_edge, 0);
  }
}

TEST(FoldCli, WritesFoldedFrameAndObjAndReportsMismatch) {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_foldcli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const CreasePattern p = degree4_sheet();
  write_fold(p, (dir / "p.fold").string());
  const Topology t = build_topology(p);
  const Fan& fan = t.stars[0].fans[0];
  const auto a = flat_fold_angles({fan.sectors[0], fan.sectors[1], fan.sectors[2], fan.sectors[3]}, FlatFoldMode::kEqual02, 1.0);
  nlohmann::json angles = nlohmann::json::object();
  for (int i = 0; i < 4; ++i) angles[std::to_string(fan.edges[i])] = to_degrees(a[i]);
  std::ofstream(dir / "angles.json") << angles.dump();
  const auto r = test::run_command(test::cli() + " fold " + (dir / "p.fold").string() + " --angles " + (dir / "angles.json").string() +
                                   " --out " + (dir / "f.fold").string() + " --obj " + (dir / "f.obj").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto report = nlohmann::json::parse(r.out);
  EXPECT_LT(report["relative_mismatch"].get<double>(), 1e-14);
  const CreasePattern f = read_fold((dir / "f.fold").string());
  ASSERT_TRUE(f.extra["file_frames"].is_array());
  const auto& frame = f.extra["file_frames"].back();
  EXPECT_EQ(frame["frame_classes"][0], "foldedForm");
  EXPECT_EQ(frame["vertices_coords"].size(), 9u);
  EXPECT_NEAR(frame["edges_foldAngle"][fan.edges[0]].get<double>(), to_degrees(a[0]), 1e-12);
  EXPECT_TRUE(std::filesystem::exists(dir / "f.obj"));

  // Bad angles: exit 2, message names the key, and no output file appears.
  std::ofstream(dir / "bad.json") << R"({"4": 30})";  // edge 4 is a boundary edge
  const auto bad = test::run_command(test::cli() + " fold " + (dir / "p.fold").string() + " --angles " + (dir / "bad.json").string() +
                                     " --out " + (dir / "g.fold").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.json: 4"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "g.fold"));
  std::ofstream(dir / "bad2.json") << R"({"0": 200})";
  EXPECT_EQ(test::run_command(test::cli() + " fold " + (dir / "p.fold").string() + " --angles " + (dir / "bad2.json").string() +
                              " --out " + (dir / "g.fold").string()).status, 2);
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
