// The thick-panel front door (kernel/thick/thick_report.hpp): a 3 x 3 Miura-ori with Bennett
// hinge heights keeps one DOF and the zero-thickness motion; the Type 3 square twist has
// uniform Bennett heights only against its letters (along them its vertices' staircases
// disagree round the central square); hinges on the valley side make a 3 x 3 Miura-ori rigid; hinges all on one face keep
// the zero-thickness kinematics; bad thickness is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/thick/thick_report.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct Flat {
  CreasePattern pattern;
  Topology topology;
  explicit Flat(CreasePattern p) : pattern(std::move(p)), topology(build_topology(pattern)) {}
};

Flat miura(int rows = 3, int cols = 3) {
  generators::MiuraParams params;
  params.rows = rows;
  params.cols = cols;
  return Flat(generators::miura_ori(params));
}

ThickReport report(const Flat& flat, ThickHinges hinges, double thickness = 0.05) {
  ThickReportRequest request;
  request.thickness = thickness;
  request.hinges = hinges;
  request.zero = zero_thickness_samples(flat.pattern, flat.topology);
  return thick_report(flat.pattern, flat.topology, request);
}

// Every reported state closes: re-checked here on a fresh ClosureSystem of the sheet.
void expect_trace_closes(const ThickReport& r) {
  const ClosureSystem system(r.sheet.pattern, r.sheet.topology, r.sheet.options);
  for (const ThickTraceStep& s : r.trace) {
    const double residual = system.residual(system.unknowns_from_edges(r.sheet.sheet_edge_angles(s.rho))).cwiseAbs().maxCoeff();
    EXPECT_LE(residual, 1e-10) << "drive " << s.drive;
    EXPECT_LE(s.residual, 1e-10);
    EXPECT_NEAR(s.rho[r.drive], s.drive, 1e-15);
  }
}

TEST(ThickReport, ZeroThicknessSamplesAreClosedAndModerate) {
  const Flat flat = miura();
  const ZeroThicknessSamples zero = zero_thickness_samples(flat.pattern, flat.topology);
  ASSERT_GE(zero.states.size(), 5u) << zero.note;
  EXPECT_GE(zero.drive, 0);
  EXPECT_LE(zero.max_residual, 1e-10);
  for (std::size_t k = 0; k < zero.states.size(); ++k) {
    EXPECT_LE(std::abs(zero.drive_angles[k]), 1.5707963267948966);
    EXPECT_EQ(zero.states[k][zero.drive], zero.drive_angles[k]);
    if (k > 0) {
      EXPECT_GT(std::abs(zero.drive_angles[k]), std::abs(zero.drive_angles[k - 1]));
    }
  }
}

TEST(ThickReport, BennettMiuraFoldsWithOneDofOnTheZeroThicknessMotion) {
  const Flat flat = miura(3, 3);  // four vertices round a cycle: their staircases agree
  const ThickReport r = report(flat, ThickHinges::kBennett);
  EXPECT_EQ(r.mobility.dof, 1);
  EXPECT_GT(r.mobility.rank.sigma_kept, 1e3 * r.mobility.rank.threshold);
  EXPECT_TRUE(r.mobility.locked_vertices.empty());
  EXPECT_TRUE(r.mobility.off_motion_vertices.empty());
  ASSERT_EQ(r.trace.size(), zero_thickness_samples(flat.pattern, flat.topology).states.size()) << r.trace_note;
  EXPECT_LE(r.max_deviation, 1e-10);
  for (const ThickTraceStep& s : r.trace) EXPECT_EQ(s.dof, 1) << "drive " << s.drive;
  expect_trace_closes(r);
  // The hinges are not all at one height: the thickness is real.
  double lo = 1e9, hi = -1e9;
  for (int e = 0; e < flat.pattern.num_edges(); ++e)
    if (flat.topology.edge_is_hinge[e]) lo = std::min(lo, r.edge_heights[e]), hi = std::max(hi, r.edge_heights[e]);
  EXPECT_GT(hi - lo, 0.01);
  std::printf("Bennett Miura 3x3, t = 0.05: DOF %d (sigma_kept %.3e, cut %.1e), %zu steps to %.3f rad, max |rho - rho_zero| %.2e rad, residual %.1e\n",
              r.mobility.dof, r.mobility.rank.sigma_kept, r.mobility.rank.threshold, r.trace.size(), r.trace.back().drive,
              r.max_deviation, r.max_trace_residual);
}

// The Type 3 square twist folded the way its letters say (trace_motion's branch): its four
// Bennett staircases disagree on a side of the central square, so the front door refuses
// Bennett heights and names the crease. (tests/thick/thick_mobility_test.cpp builds them from
// the family's other direction, crease 0 a valley, where they agree.)
TEST(ThickReport, BennettSquareTwistType3AlongItsLettersHasNoUniformHeights) {
  const Flat flat(generators::square_twist(generators::SquareTwistParams{}, generators::SquareTwistType::Type3));
  try {
    report(flat, ThickHinges::kBennett);
    ADD_FAILURE() << "Bennett heights found";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "hinges");
    EXPECT_NE(std::string(e.what()).find("crease 2 "), std::string::npos) << e.what();
  }
}

// Folded against its letters (the family's other side of flat) the four staircases agree: the
// thick Type 3 square twist keeps one DOF and the zero-thickness motion round its cycle of four
// Bennett vertices.
TEST(ThickReport, BennettSquareTwistType3AgainstItsLettersFollowsTheZeroThicknessMotion) {
  const Flat flat(generators::square_twist(generators::SquareTwistParams{}, generators::SquareTwistType::Type3));
  ThickReportRequest request;
  request.thickness = 0.05;
  request.hinges = ThickHinges::kBennett;
  request.zero = zero_thickness_samples(flat.pattern, flat.topology, 17, 1.5707963267948966, true);
  const ZeroThicknessSamples forward = zero_thickness_samples(flat.pattern, flat.topology);
  ASSERT_FALSE(request.zero.states.empty()) << request.zero.note;
  EXPECT_EQ(request.zero.drive, forward.drive);
  EXPECT_LT(request.zero.drive_angles.back() * forward.drive_angles.back(), 0.0);  // the other way
  const ThickReport r = thick_report(flat.pattern, flat.topology, request);
  EXPECT_EQ(r.mobility.dof, 1);
  EXPECT_GT(r.mobility.rank.sigma_kept, 1e3 * r.mobility.rank.threshold);
  EXPECT_TRUE(r.mobility.locked_vertices.empty());
  EXPECT_TRUE(r.mobility.off_motion_vertices.empty());
  ASSERT_EQ(r.trace.size(), request.zero.states.size()) << r.trace_note;
  EXPECT_LE(r.max_deviation, 1e-10);
  for (const ThickTraceStep& s : r.trace) EXPECT_EQ(s.dof, 1) << "drive " << s.drive;
  expect_trace_closes(r);
  std::printf("Bennett square twist Type 3 (against its letters), t = 0.05: DOF %d (sigma_kept %.3e), %zu steps to %.3f rad, max |rho - rho_zero| %.2e rad, residual %.1e\n",
              r.mobility.dof, r.mobility.rank.sigma_kept, r.trace.size(), r.trace.back().drive, r.max_deviation, r.max_trace_residual);
}

// Valley side: at each vertex the odd crease's hinge sits t off the other three, so opposite
// links differ (t, 0, 0, t) - not a Bennett. Each vertex alone still has first-order DOF 1 at
// flat (three of its axes are coplanar and concurrent: a singular point), but none follows
// the zero-thickness motion, and the pattern's flat state is regular with DOF 0: rigid.
TEST(ThickReport, ValleySideHingesMakeTheMiuraRigid) {
  const Flat flat = miura();
  const ThickReport r = report(flat, ThickHinges::kValley);
  EXPECT_EQ(r.mobility.dof, 0);
  EXPECT_GT(r.mobility.rank.sigma_kept, 1e3 * r.mobility.rank.threshold);  // a regular point: a proof of rigidity
  std::vector<int> interior = flat.topology.interior_vertices;
  std::sort(interior.begin(), interior.end());
  EXPECT_TRUE(r.mobility.locked_vertices.empty());
  EXPECT_EQ(r.mobility.off_motion_vertices, interior);
  for (const ThickVertexMobility& v : r.mobility.vertices) {
    EXPECT_GT(v.off_motion, 1e-4) << "vertex " << v.vertex;
    EXPECT_EQ(v.dof_alone, 1) << "vertex " << v.vertex;
  }
  EXPECT_TRUE(r.trace.empty());
  EXPECT_FALSE(r.trace_note.empty());
  std::printf("valley-side Miura 3x3, t = 0.05: DOF %d (sigma_kept %.3e, cut %.1e), %zu vertices off the motion\n", r.mobility.dof,
              r.mobility.rank.sigma_kept, r.mobility.rank.threshold, r.mobility.off_motion_vertices.size());
}

TEST(ThickReport, HingesOnOneFaceKeepTheZeroThicknessKinematics) {
  const Flat flat = miura();
  for (ThickHinges h : {ThickHinges::kTop, ThickHinges::kBottom, ThickHinges::kMid}) {
    const ThickReport r = report(flat, h);
    EXPECT_TRUE(r.mobility.locked_vertices.empty()) << to_string(h);
    EXPECT_TRUE(r.mobility.off_motion_vertices.empty()) << to_string(h);
    ASSERT_FALSE(r.trace.empty()) << to_string(h) << ": " << r.trace_note;
    EXPECT_LE(r.max_deviation, 1e-10) << to_string(h);
    expect_trace_closes(r);
  }
}

TEST(ThickReport, RefusesABadThicknessAFoldedFormOrAValleyPlacementWithoutLetters) {
  const Flat flat = miura();
  for (double t : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    try {
      report(flat, ThickHinges::kTop, t);
      ADD_FAILURE() << "thickness " << t << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), "thickness");
    }
  }
  Flat folded = miura();
  folded.pattern.vertices[5].z() = 0.1;
  try {
    report(folded, ThickHinges::kTop);
    ADD_FAILURE() << "a pattern off z = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "pattern");
    EXPECT_NE(std::string(e.what()).find("vertex 5 "), std::string::npos) << e.what();
  }
  Flat unlettered = miura();
  for (Assignment& a : unlettered.pattern.assignments)
    if (a == Assignment::Mountain || a == Assignment::Valley) a = Assignment::Unassigned;
  unlettered.topology = build_topology(unlettered.pattern);
  try {
    report(unlettered, ThickHinges::kValley);
    ADD_FAILURE() << "valley placement without letters accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "hinges");
  }
}

}}  // namespace
}  // namespace rigidfold
