// Split creases through the whole-pattern path (sorce_pattern.hpp, PatternSorceRequest::splits;
// the CLI's --split) against the single-vertex collinear split (sorce_vertex.hpp,
// collinear_split, eqs 58, 59): the seed's bird's-foot vertex B (data/sorce/vertex_b.fold),
// folds 1 and 3 (edges 0 and 2) split with one d(t). Both code paths on the same fold angles
// and offsets give the same profiles to round-off; the pattern's vertex closure, which now
// carries the split translations, closes, and does not with one split's sign flipped.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "design/sorce/sorce_design.hpp"
#include "design/sorce/sorce_pattern.hpp"
#include "tests/sorce/sorce_pattern_requests.hpp"
#include "design/sorce/sorce_split_spec.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::kVertexB;
const VertexSectors kSectorsB = {to_radians(135.0), to_radians(45.0), to_radians(45.0), to_radians(135.0)};
PatternSorceRequest vertex_b_request(double h) { return testing::single_vertex_request(h); }

TEST(SorceSplitPattern, BirdsFootSplitMatchesTheVertexCollinearSplit) {
  const CreasePattern p = read_fold(kVertexB);
  const double h = 0.1;
  PatternSorceRequest rq = vertex_b_request(h);
  const ScalarFunction d = power_function(0.04, 2);  // eq 61's shape, d = 0.4 h t^2
  rq.splits = {{0, d}, {2, d}};
  // Traced as the CLI does (sorce_design: the exact multiplier family of a flat-foldable
  // degree-4 vertex). The general solver's path ends ~1e-7 rad off gamma_3 = -gamma_1 at the
  // flat-folded end, where the zero-thickness closure is blind to it (second order) but the
  // split translations are not (first order: d times the angle error).
  SorceDesignRequest design;
  design.sorce = rq;
  const SorceDesign sd = sorce_design(p, design);
  const PatternSorce& s = sd.sorce;
  std::printf("path model: %s\n", sd.model.c_str());
  ASSERT_EQ(s.creases.size(), 4u);
  // The vertex built from the pattern's own fold angles and offsets, split by collinear_split.
  std::array<ScalarFunction, 4> gamma, offset;
  for (int j = 0; j < 4; ++j) {
    ASSERT_EQ(s.creases[j].edge, j);
    gamma[j] = s.creases[j].motion.gamma;
    offset[j] = s.faces[j].z;
  }
  const SorceVertex v = sorce_vertex(kSectorsB, gamma, offset, {h, h, h, h}, collinear_split(kSectorsB, gamma, d));
  double err = 0.0, split_size = 0.0;
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(static_cast<bool>(s.creases[j].motion.d), j == 0 || j == 2) << j;
    for (int i = 1; i < 200; ++i) {
      const double t = i / 200.0;
      const ProfilePoint a = profile_point(s.creases[j].motion, t), b = profile_point(v.folds[j], t);
      err = std::max({err, (a.s_left - b.s_left).norm(), (a.s_right - b.s_right).norm()});
      if (j == 0) split_size = std::max(split_size, std::hypot(s.creases[0].motion.d(t)[0][0], s.creases[0].motion.d(t)[1][0]));
    }
    const FoldEndPoints ea = end_points(s.creases[j].motion), eb = end_points(v.folds[j]);
    err = std::max({err, (ea.left0 - eb.left0).norm(), (ea.left1 - eb.left1).norm(), (ea.right0 - eb.right0).norm(),
                    (ea.right1 - eb.right1).norm()});
  }
  std::printf("vertex B split (d = 0.04 t^2): pattern vs vertex profiles %.2e; closure knots %.2e, consistency %.2e, "
              "contact %.2e, rolling %.2e\n",
              err, s.checks.closure_knots, s.checks.consistency, s.checks.contact, s.checks.rolling);
  EXPECT_LE(err, 1e-10);
  EXPECT_NEAR(split_size, 0.04 * (199.0 / 200) * (199.0 / 200), 1e-15);  // the split is really there
  // Eqs 58, 59 close the vertex with the split translations in it; the poses follow the joints.
  EXPECT_LE(s.checks.closure_knots, 1e-9);
  EXPECT_LE(s.checks.consistency, 1e-9);
  EXPECT_LE(s.checks.contact, 1e-9);
  EXPECT_LE(s.checks.rolling, 1e-9);

  // One sign flipped (d_3 = -d u(gamma_3/2)): the closure check sees the split.
  PatternSorceRequest flipped = vertex_b_request(h);
  flipped.splits = {{0, d}, {2, power_function(-0.04, 2)}};
  design.sorce = flipped;
  const PatternSorce f = sorce_design(p, design).sorce;
  std::printf("  with d_3's sign flipped: closure knots %.2e\n", f.checks.closure_knots);
  EXPECT_GT(f.checks.closure_knots, 1e-3);
}

TEST(SorceSplitPattern, SpecsAndBadSplitsNameThePlace) {
  const PatternSorceRequest::Split a = parse_split_spec("2:linear:0.05");
  EXPECT_EQ(a.edge, 2);
  EXPECT_DOUBLE_EQ(a.d(0.5)[0], 0.025);
  EXPECT_DOUBLE_EQ(a.d(0.5)[1], 0.05);
  const PatternSorceRequest::Split b = parse_split_spec("0:quadratic:-4e-2");
  EXPECT_DOUBLE_EQ(b.d(0.5)[0], -0.01);
  for (const char* bad : {"", "2", "x:linear:1", "-1:linear:1", "2:cubic:1", "2:linear", "2:linear:", "2:linear:nan",
                          "2:linear:1e7", "2:linear:1x", "2:linear: 1"}) {
    try {
      parse_split_spec(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), bad);
    }
  }
  const CreasePattern p = read_fold(kVertexB);
  auto place = [&](std::vector<PatternSorceRequest::Split> splits) -> std::string {
    PatternSorceRequest rq = vertex_b_request(0.1);
    rq.splits = std::move(splits);
    try {
      pattern_sorce(p, rq);
    } catch (const InputError& e) {
      return e.place();
    }
    return "no error";
  };
  EXPECT_EQ(place({{5, power_function(0.1, 1)}}), "splits[0]");                              // a boundary edge
  EXPECT_EQ(place({{0, power_function(0.1, 1)}, {0, power_function(0.1, 1)}}), "splits[1]");  // twice
  EXPECT_EQ(place({{0, constant_function(0.1)}}), "splits[0]");                              // d(0) != 0
}

}}  // namespace
}  // namespace rigidfold::sorce
