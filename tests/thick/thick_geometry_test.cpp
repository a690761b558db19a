// Thick panels as solids along their path (kernel/thick/slab_interference.hpp,
// stacking_order.hpp, through thick_report): slabs hinged on their top face interpenetrate
// across every mountain crease (and no valley), hinged on the bottom across every valley;
// Bennett heights as slabs collide exactly where a hinge sits on the face away from its fold
// (and, past 90 deg, at a step between its panels); at the fully folded end top hinges put
// every panel on top (through its mountains), and each Bennett crease stacks by where its
// hinge sits: as its letter says on the fold side, the other way round away from it, level at a step.
// Oracles: a two-panel sheet whose overlap is known in closed form, and the pattern's own
// letters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/slab_interference.hpp"
#include "kernel/thick/stacking_order.hpp"
#include "kernel/thick/thick_report.hpp"
#include "kernel/thick/thick_slabs.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct Flat {
  CreasePattern pattern;
  Topology topology;
  explicit Flat(CreasePattern p) : pattern(std::move(p)), topology(build_topology(pattern)) {}
};

const Flat& bundled_miura() {
  static const Flat flat(read_pattern(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold"));
  return flat;
}

ThickReport report(const Flat& flat, ThickHinges hinges, double thickness = 0.05) {
  ThickReportRequest request;
  request.thickness = thickness;
  request.hinges = hinges;
  request.zero = zero_thickness_samples(flat.pattern, flat.topology);
  return thick_report(flat.pattern, flat.topology, request);
}

// Fold angles of interference state k: flat, then the trace, then the extension.
Eigen::VectorXd state_rho(const ThickReport& r, int k) {
  if (k == 0) return Eigen::VectorXd::Zero(static_cast<Eigen::Index>(r.edge_heights.size()));
  const int nt = static_cast<int>(r.trace.size());
  return k - 1 < nt ? r.trace[k - 1].rho : r.extension[k - 1 - nt].rho;
}

// Face pairs across the hinges whose fold at rho has the given sign (and is not tiny).
std::set<std::pair<int, int>> pairs_folded(const Flat& flat, const Eigen::VectorXd& rho, int sign) {
  std::set<std::pair<int, int>> out;
  for (int e = 0; e < flat.pattern.num_edges(); ++e) {
    if (!flat.topology.edge_is_hinge[e] || !(sign * rho[e] > 1e-3)) continue;
    const int a = flat.topology.edge_faces[e][0], b = flat.topology.edge_faces[e][1];
    out.insert({std::min(a, b), std::max(a, b)});
  }
  return out;
}

std::set<std::pair<int, int>> colliding(const SlabInterferenceState& s) {
  std::set<std::pair<int, int>> out;
  for (const SlabCollision& c : s.collisions) out.insert({c.face_a, c.face_b});
  return out;
}

int lettered_hinges(const Flat& flat, Assignment letter) {
  int n = 0;
  for (int e = 0; e < flat.pattern.num_edges(); ++e) n += flat.topology.edge_is_hinge[e] && flat.pattern.assignments[e] == letter;
  return n;
}

// Two unit squares sharing the crease x = 0 (edge 0), a mountain: the closed-form oracle.
// Slabs [0, t] hinged on the top face (z = t). In the cross-section, with the hinge at the
// origin and the left slab x <= 0, -t <= z <= 0, the right slab folded by rho is
// {x (cos rho, -sin rho) + z (sin rho, cos rho) : 0 <= x <= 1, -t <= z <= 0}. For a valley
// (rho > 0) both coordinates' signs keep it out of the left slab at every rho in (0, pi]. For
// a mountain (rho < 0) it overlaps the left slab for every |rho| in (0, pi): up to 90 deg its
// bottom corner lies t sin|rho| deep, past 90 deg its top face dips sin(pi - |rho|) below the
// left top face at x = 1. At +-pi it lies on top, touching. The samples keep every overlap
// far deeper than the margin.
Flat two_squares() {
  CreasePattern p;
  p.vertices = {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {-1, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  p.edges = {{0, 1}, {2, 0}, {1, 3}, {3, 2}, {0, 4}, {4, 5}, {5, 1}};
  p.assignments = {Assignment::Mountain, Assignment::Boundary, Assignment::Boundary, Assignment::Boundary,
                   Assignment::Boundary, Assignment::Boundary, Assignment::Boundary};
  p.faces = {{0, 1, 3, 2}, {0, 4, 5, 1}};
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  return Flat(std::move(p));
}

TEST(ThickSlabInterference, TwoSlabsHingedOnTopOverlapOnlyWhenTheyFoldAsAMountain) {
  const Flat flat = two_squares();
  const double t = 0.1;
  const std::vector<double> heights(flat.pattern.num_edges(), t);
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat.pattern, flat.topology, heights);
  const std::vector<PanelSlab> slabs(2, PanelSlab{0.0, t});
  const double margin = 1e-4 * t;
  std::vector<double> drives;
  std::vector<Eigen::VectorXd> states;
  for (double deg : {0.0, -1.0, -30.0, -90.0, -150.0, -179.0, 1.0, 30.0, 90.0, 150.0, 179.0, 180.0}) {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(flat.pattern.num_edges());
    rho[0] = deg * kPi / 180;
    drives.push_back(rho[0]);
    states.push_back(rho);
  }
  const SlabInterference in = slab_interference(flat.pattern, flat.topology, sheet, slabs, drives, states, margin);
  ASSERT_EQ(in.states.size(), states.size());
  for (std::size_t k = 0; k < states.size(); ++k) {
    const double rho = drives[k];
    const double depth = rho < 0 ? std::min(t, 1.0) * std::sin(-rho) : 0.0;  // a lower bound of the overlap's depth
    const bool expected = rho < 0 && rho > -kPi;
    if (expected) {
      ASSERT_GT(depth, 10 * margin);
    }
    EXPECT_EQ(!in.states[k].collisions.empty(), expected) << "rho " << rho * 180 / kPi << " deg";
    if (!in.states[k].collisions.empty()) {
      EXPECT_EQ(in.states[k].collisions[0].face_a, 0);
      EXPECT_EQ(in.states[k].collisions[0].face_b, 1);
      EXPECT_EQ(in.states[k].collisions[0].shared_edge, 0);
    }
  }
  EXPECT_EQ(in.first_state, 1);
  EXPECT_EQ(in.collision_count, 5);
}

TEST(ThickSlabInterference, ASlabInsideAnotherIsFound) {
  // The same two squares, the right one folded by pi onto the left and given a slab thinner
  // than the left's and inside it: no surfaces cross, the point-in-slab test finds it.
  const Flat flat = two_squares();
  const std::vector<double> heights(flat.pattern.num_edges(), 0.05);  // hinge mid-height of [0, 0.1]
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat.pattern, flat.topology, heights);
  // Folded by pi about the hinge at z = 0.05, the right slab [0.04, 0.06] maps onto
  // [0.04, 0.06] over the left panel, inside the left slab [0, 0.1]: its top and bottom cross
  // nothing, its sides lie in the left slab's side planes (a coplanar touch either way), and
  // its centre is strictly inside.
  const std::vector<PanelSlab> slabs{{0.0, 0.1}, {0.04, 0.06}};
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(flat.pattern.num_edges());
  rho[0] = -kPi;
  const SlabInterference in = slab_interference(flat.pattern, flat.topology, sheet, slabs, {rho[0]}, {rho}, 1e-4);
  ASSERT_EQ(in.states.size(), 1u);
  EXPECT_EQ(in.collision_count, 1);
}

// Faces a, b share a vertex of the flat pattern (panels meeting at a corner).
bool share_vertex(const Flat& flat, int a, int b) {
  for (int u : flat.pattern.faces[a])
    for (int v : flat.pattern.faces[b])
      if (u == v) return true;
  return false;
}

// Slabs hinged on one face: at every state short of flat-folded, the panels across every crease
// folded towards the other face collide (next to the hinge), across no other crease, and
// otherwise only panels that meet at a corner of such a crease's vertex.
void expect_one_sided_collisions(const Flat& flat, const ThickReport& r, Assignment colliding_letter, int fold_sign) {
  const SlabInterference& in = r.interference;
  ASSERT_EQ(in.states.size(), 1 + r.trace.size() + r.extension.size());
  EXPECT_FALSE(in.passed());
  EXPECT_TRUE(in.states[0].collisions.empty()) << "slabs only touch at the flat state";
  EXPECT_EQ(in.first_state, 1);  // the first folded state
  int checked = 0;
  for (int k = 1; k < static_cast<int>(in.states.size()); ++k) {
    const Eigen::VectorXd rho = state_rho(r, k);
    if (rho.cwiseAbs().maxCoeff() > kPi - 1e-6) continue;  // flat-folded: see the stacking tests
    const std::set<std::pair<int, int>> hits = colliding(in.states[k]);
    for (const auto& pair : pairs_folded(flat, rho, fold_sign)) EXPECT_TRUE(hits.count(pair)) << "state " << k;
    for (const SlabCollision& c : in.states[k].collisions) {
      if (c.shared_edge >= 0) {
        EXPECT_EQ(flat.pattern.assignments[c.shared_edge], colliding_letter) << "state " << k << " edge " << c.shared_edge;
      } else {
        EXPECT_TRUE(share_vertex(flat, c.face_a, c.face_b)) << "state " << k << " faces " << c.face_a << ", " << c.face_b;
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 8);
  EXPECT_EQ(static_cast<int>(pairs_folded(flat, state_rho(r, 1), fold_sign).size()), lettered_hinges(flat, colliding_letter));
}

TEST(ThickSlabInterference, TopHingedMiuraCollidesAcrossEveryMountain) {
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kTop);
  ASSERT_FALSE(r.trace.empty()) << r.trace_note;
  expect_one_sided_collisions(flat, r, Assignment::Mountain, -1);
  // The first reported pair is one of them.
  const SlabCollision& first = r.interference.states[1].collisions.front();
  if (first.shared_edge >= 0) {
    EXPECT_EQ(flat.pattern.assignments[first.shared_edge], Assignment::Mountain);
  }
}

TEST(ThickSlabInterference, BottomHingedMiuraCollidesAcrossEveryValley) {
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kBottom);
  ASSERT_FALSE(r.trace.empty()) << r.trace_note;
  expect_one_sided_collisions(flat, r, Assignment::Valley, +1);
}

// Where a hinge sits on its two panels' slabs, from the heights alone (the independent oracle
// of the Bennett tests): on the face the crease folds towards for both (top for a valley,
// bottom for a mountain: the slabs open away from the hinge), on the face away from the fold
// for both (they close into each other next to it, as hinges on the top face do across a
// mountain), or at a step (top of one, bottom of the other: clear until 90 deg, past it
// the panels swing into each other's level; a turn by pi about the step maps each slab onto
// the other's heights).
enum class HingeSide { kFoldSide, kAwayFromFold, kStep, kOther };
HingeSide hinge_side(const Flat& flat, const ThickReport& r, int e) {
  const int a = flat.topology.edge_faces[e][0], b = flat.topology.edge_faces[e][1];
  const double h = r.edge_heights[e], eps = 1e-9 * r.thickness;
  auto at = [&](double z) { return std::abs(h - z) <= eps; };
  const bool top = at(r.slabs[a].top) && at(r.slabs[b].top), bottom = at(r.slabs[a].bottom) && at(r.slabs[b].bottom);
  const bool step = (at(r.slabs[a].top) && at(r.slabs[b].bottom)) || (at(r.slabs[a].bottom) && at(r.slabs[b].top));
  const bool valley = flat.pattern.assignments[e] == Assignment::Valley;
  if (top) return valley ? HingeSide::kFoldSide : HingeSide::kAwayFromFold;
  if (bottom) return valley ? HingeSide::kAwayFromFold : HingeSide::kFoldSide;
  return step ? HingeSide::kStep : HingeSide::kOther;
}

// Bennett heights keep the zero-thickness motion to 180 deg, but as slabs spanning their
// hinges' heights (thick_slabs.hpp) they are not free of interference: on the bundled Miura
// four straight creases carry their hinge on the face away from their fold, and the zig-zag
// lines' hinges are steps.
TEST(ThickSlabInterference, BennettMiuraSlabsCollideWhereTheHingeIsAwayFromTheFold) {
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kBennett);
  ASSERT_EQ(r.mobility.dof, 1);
  ASSERT_FALSE(r.trace.empty()) << r.trace_note;
  // The zero-thickness Miura folds flat: past the trace, every state to +-180 deg closes on the
  // thick sheet as it is.
  ASSERT_FALSE(r.extension.empty());
  EXPECT_NEAR(std::abs(r.extension.back().drive), kPi, 1e-12);
  for (const ThickTraceStep& s : r.extension) EXPECT_LE(s.residual, 1e-10);
  const SlabInterference& in = r.interference;
  ASSERT_EQ(in.states.size(), 1 + r.trace.size() + r.extension.size());
  EXPECT_TRUE(in.states[0].collisions.empty());
  std::set<int> away, step;
  for (int e = 0; e < flat.pattern.num_edges(); ++e) {
    if (!flat.topology.edge_is_hinge[e]) continue;
    const HingeSide side = hinge_side(flat, r, e);
    EXPECT_NE(side, HingeSide::kOther) << "edge " << e;
    if (side == HingeSide::kAwayFromFold) away.insert(e);
    if (side == HingeSide::kStep) step.insert(e);
  }
  EXPECT_FALSE(away.empty());
  EXPECT_FALSE(step.empty());
  for (int k = 1; k < static_cast<int>(in.states.size()); ++k) {
    const Eigen::VectorXd rho = state_rho(r, k);
    if (rho.cwiseAbs().maxCoeff() > kPi - 1e-6) continue;  // flat-folded: see the stacking test
    const bool past_90 = std::abs(in.states[k].drive) > kPi / 2 + 1e-9;
    std::set<int> hinges;
    for (const SlabCollision& c : in.states[k].collisions) {
      if (c.shared_edge >= 0) {
        hinges.insert(c.shared_edge);
      } else {
        EXPECT_TRUE(share_vertex(flat, c.face_a, c.face_b)) << "state " << k;
      }
    }
    std::set<int> expected = away;
    if (past_90) expected.insert(step.begin(), step.end());
    EXPECT_EQ(hinges, expected) << "state " << k << " drive " << in.states[k].drive;
  }
  EXPECT_EQ(in.first_state, 1);
}

TEST(ThickStacking, BennettMiuraStacksEachCreaseByWhereItsHingeSits) {
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kBennett);
  ASSERT_TRUE(r.end_is_extension);
  const StackingOrder& st = r.stacking;
  EXPECT_TRUE(st.flat_folded) << "tilt " << st.max_tilt;
  int disagree = 0, agree = 0;
  for (const CreaseStacking& c : st.creases) {
    ASSERT_TRUE(c.has_letter) << "edge " << c.edge;
    EXPECT_EQ(c.b_side_of_a, c.a_side_of_b) << "edge " << c.edge;
    const int letter = flat.pattern.assignments[c.edge] == Assignment::Valley ? 1 : -1;
    switch (hinge_side(flat, r, c.edge)) {
      case HingeSide::kFoldSide: EXPECT_EQ(c.b_side_of_a, letter) << "edge " << c.edge; ++agree; break;
      case HingeSide::kAwayFromFold: EXPECT_EQ(c.b_side_of_a, -letter) << "edge " << c.edge; ++disagree; break;
      case HingeSide::kStep: EXPECT_EQ(c.b_side_of_a, 0) << "edge " << c.edge; ++disagree; break;
      case HingeSide::kOther: ADD_FAILURE() << "edge " << c.edge; break;
    }
  }
  EXPECT_EQ(st.letter_disagreements, disagree);
  EXPECT_GT(agree, 0);
  // Every panel in the stack, sorted by height; panels turned onto one level overlap with a
  // negative gap, which the FCL test at that state reports as collisions too.
  ASSERT_EQ(st.panels.size(), static_cast<std::size_t>(flat.pattern.num_faces()));
  for (std::size_t i = 1; i < st.panels.size(); ++i)
    EXPECT_LE(st.panels[i - 1].low + st.panels[i - 1].high, st.panels[i].low + st.panels[i].high);
  EXPECT_FALSE(st.overlaps.empty());
  EXPECT_LT(st.min_gap, 0.0);
  EXPECT_FALSE(r.interference.states.back().collisions.empty());
  // Panels across a crease overlap when folded flat onto each other: listed as a pair.
  for (const CreaseStacking& c : st.creases) {
    const bool listed = std::any_of(st.overlaps.begin(), st.overlaps.end(), [&](const StackedPair& p) {
      return (p.lower == c.face_a && p.upper == c.face_b) || (p.lower == c.face_b && p.upper == c.face_a);
    });
    EXPECT_TRUE(listed) << "edge " << c.edge;
  }
}

TEST(ThickStacking, TopHingesPutEveryFoldedPanelOnTopThroughItsMountains) {
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kTop);
  ASSERT_TRUE(r.end_is_extension);
  const StackingOrder& st = r.stacking;
  EXPECT_TRUE(st.flat_folded);
  // A rotation by +pi and by -pi about a top hinge is the same: each panel ends on its
  // neighbour's top side, so exactly the mountains disagree with their letter.
  EXPECT_EQ(st.letter_disagreements, lettered_hinges(flat, Assignment::Mountain));
  for (const CreaseStacking& c : st.creases) {
    EXPECT_EQ(c.b_side_of_a, 1) << "edge " << c.edge;
    EXPECT_EQ(c.a_side_of_b, 1) << "edge " << c.edge;
  }
}

TEST(ThickStacking, ValleySideHingesStopAtTheFlatState) {
  // DOF 0: no trace, so the path's end is the flat state - not folded flat, every panel level.
  const Flat& flat = bundled_miura();
  const ThickReport r = report(flat, ThickHinges::kValley);
  ASSERT_EQ(r.mobility.dof, 0);
  EXPECT_TRUE(r.trace.empty());
  EXPECT_FALSE(r.end_is_extension);
  EXPECT_EQ(r.end.drive, 0.0);
  EXPECT_EQ(r.interference.states.size(), 1u);
  EXPECT_TRUE(r.interference.passed());
  EXPECT_FALSE(r.stacking.flat_folded);  // all parallel, none turned over
  EXPECT_LE(r.stacking.max_tilt, 1e-12);
  for (const CreaseStacking& c : r.stacking.creases) {
    EXPECT_EQ(c.b_side_of_a, 0) << "edge " << c.edge;  // level: neither side
    EXPECT_FALSE(c.agrees_with_letter);
  }
  EXPECT_EQ(r.stacking.letter_disagreements, static_cast<int>(r.stacking.creases.size()));
}

}}  // namespace
}  // namespace rigidfold
