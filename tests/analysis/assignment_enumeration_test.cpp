// M-V assignment enumeration (kernel/analysis/assignment_enumeration.hpp) and the symmetry
// group it reduces by (kernel/pattern/pattern_symmetry.hpp). Seed 003's counts - P: 10 classes
// (4 rigid), Q: 6 (4 rigid), square twist: 4 (2 rigid) - and independent cross-checks: the
// P/Q generator's own list of flat-foldable assignments and its loop-gain rule, and a
// brute-force orbit count on the waterbomb base's single vertex.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "data/generators/double_corrugated.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/pattern_symmetry.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/vertex_letter_rules.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

AssignmentEnumeration enumerate(const CreasePattern& p, bool symmetry = true, long max_verdicts = 100'000) {
  AssignmentEnumerationOptions o;
  o.symmetry = symmetry;
  o.max_verdicts = max_verdicts;
  return enumerate_assignments(p, build_topology(p), o);
}

// Every element maps the pattern onto itself (vertices within 1e-9), and the set is a group.
void expect_group(const CreasePattern& p, const std::vector<PatternSymmetry>& g) {
  ASSERT_FALSE(g.empty());
  std::set<std::vector<int>> maps;
  for (const auto& s : g) {
    EXPECT_LT((s.linear.transpose() * s.linear - Eigen::Matrix2d::Identity()).norm(), 1e-12);
    EXPECT_EQ(s.reflection, s.linear.determinant() < 0);
    for (int v = 0; v < p.num_vertices(); ++v) {
      const Eigen::Vector2d image = s.center + s.linear * (p.vertices[v].head<2>() - s.center);
      EXPECT_LT((image - p.vertices[s.vertex_map[v]].head<2>()).norm(), 1e-9);
    }
    maps.insert(s.vertex_map);
  }
  for (const auto& a : g)
    for (const auto& b : g) {
      std::vector<int> ab(p.num_vertices());
      for (int v = 0; v < p.num_vertices(); ++v) ab[v] = a.vertex_map[b.vertex_map[v]];
      EXPECT_TRUE(maps.count(ab)) << "not closed under composition";
    }
}

TEST(PatternSymmetry, GroupsOfTheSeedUnitsAndTheWaterbomb) {
  const auto P = generators::corrugated_unit(generators::CorrugatedUnit::P, {},
                                             generators::corrugated_rigid_assignment(generators::CorrugatedUnit::P));
  const auto gP = pattern_symmetries(P);
  expect_group(P, gP);
  EXPECT_EQ(gP.size(), 2u);  // the unit's 2-fold rotation (generator comment: mirror-free)
  EXPECT_FALSE(gP[1].reflection);
  EXPECT_NEAR(gP[1].rotation_angle, std::numbers::pi, 1e-12);

  const auto twist = generators::square_twist({}, generators::SquareTwistType::Type1);
  const auto gT = pattern_symmetries(twist);
  expect_group(twist, gT);
  EXPECT_EQ(gT.size(), 4u);  // C4: the twist is chiral
  for (const auto& s : gT) EXPECT_FALSE(s.reflection);

  generators::WaterbombParams wp;
  wp.n = 4;
  const auto wb = generators::waterbomb_base(wp);
  const auto gW = pattern_symmetries(wb);
  expect_group(wb, gW);
  EXPECT_EQ(gW.size(), 8u);  // D4 of the square sheet
}

TEST(AssignmentEnumeration, UnitsPAndQReproduceSeed003AndTheGeneratorsList) {
  for (auto unit : {generators::CorrugatedUnit::P, generators::CorrugatedUnit::Q}) {
    const auto p = generators::corrugated_unit(unit, {}, generators::corrugated_rigid_assignment(unit));
    const auto r = enumerate(p);
    const bool is_p = unit == generators::CorrugatedUnit::P;
    ASSERT_TRUE(r.complete);
    EXPECT_EQ(r.creases.size(), 12u);
    EXPECT_EQ(r.assignments, is_p ? 32 : 16);
    EXPECT_EQ(r.class_count, is_p ? 10 : 6);
    EXPECT_EQ(r.verdicts, r.class_count);
    EXPECT_EQ(r.foldable_classes, 4);
    EXPECT_EQ(r.not_foldable_classes, r.class_count - 4);
    for (const auto& c : r.classes) {
      EXPECT_TRUE(c.is_proof) << c.letters;  // multiplier model: exact both ways
      if (c.verdict == FoldabilityClass::kFoldable) {
        EXPECT_EQ(c.dof, 1) << c.letters;
      }
    }

    // Without the geometric symmetry: one class per flip pair, and these are exactly the
    // generator's flat-foldable assignments (built from the odd joints), with its rigidity.
    const auto flat = enumerate(p, false);
    EXPECT_EQ(flat.class_count, is_p ? 16 : 8);
    const auto edges = generators::corrugated_interior_edges(unit);
    std::set<std::string> generated, generated_rigid, found, found_rigid;
    for (const auto& choice : generators::corrugated_flat_foldable_assignments(unit)) {
      std::string letters(flat.creases.size(), '?');
      for (std::size_t i = 0; i < flat.creases.size(); ++i) {
        const auto at = std::find(edges.begin(), edges.end(), flat.creases[i]) - edges.begin();
        letters[i] = assignment_letter(choice.assignment[at]);
      }
      if (letters[0] == 'V')  // the representative of a flip pair starts with M
        for (char& c : letters) c = c == 'M' ? 'V' : 'M';
      generated.insert(letters);
      if (choice.rigid) generated_rigid.insert(letters);
    }
    for (const auto& c : flat.classes) {
      found.insert(c.letters);
      if (c.verdict == FoldabilityClass::kFoldable) found_rigid.insert(c.letters);
    }
    EXPECT_EQ(found, generated);
    EXPECT_EQ(found_rigid, generated_rigid);
  }
}

TEST(AssignmentEnumeration, SquareTwistHasFourClassesTwoRigid) {
  const auto twist = generators::square_twist({}, generators::SquareTwistType::Type1);
  const auto r = enumerate(twist);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.class_count, 4);
  EXPECT_EQ(r.foldable_classes, 2);
  EXPECT_EQ(r.not_foldable_classes, 2);
  long orbit_sum = 0;
  for (const auto& c : r.classes) orbit_sum += c.orbit_size;
  EXPECT_EQ(orbit_sum, r.assignments);
}

TEST(AssignmentEnumeration, WaterbombVertexOrbitsMatchABruteForceCount) {
  generators::WaterbombParams wp;
  wp.n = 4;
  const auto wb = generators::waterbomb_base(wp);
  const auto r = enumerate(wb);
  ASSERT_TRUE(r.complete);
  EXPECT_EQ(r.assignments, 112);  // 2 C(8, 3): eight equal sectors
  // Independent orbit count: D4 acts on the 8 creases around the vertex as the dihedral
  // group generated by the shift by 2 (a quarter turn) and a reflection i -> -i; with the flip.
  const auto masks = flat_folding_letter_masks(std::vector<double>(8, std::numbers::pi / 4));
  std::set<std::uint32_t> canonical;
  for (std::uint32_t m : masks) {
    std::uint32_t best = m;
    for (int shift = 0; shift < 8; shift += 2)
      for (int mirror : {0, 1})
        for (std::uint32_t flip : {0u, 0xFFu}) {
          std::uint32_t image = 0;
          for (int i = 0; i < 8; ++i) {
            const int j = mirror ? (8 - i + shift) % 8 : (i + shift) % 8;
            if ((m >> i) & 1u) image |= 1u << j;
          }
          best = std::min(best, image ^ flip);
        }
    canonical.insert(best);
  }
  EXPECT_EQ(r.class_count, static_cast<long>(canonical.size()));
}

TEST(AssignmentEnumeration, KawasakiFailureBlocksEveryAssignment) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  m.perturbation = 0.05;
  const auto r = enumerate(generators::miura_ori(m));
  EXPECT_EQ(r.assignments, 0);
  EXPECT_GE(r.blocking_vertex, 0);
  EXPECT_NE(r.blocking_reason.find("Kawasaki"), std::string::npos) << r.blocking_reason;
}

TEST(AssignmentEnumeration, MiuraClassesAllCarryAVerdictAndTheOrbitsAddUp) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  const auto p = generators::miura_ori(m);
  const auto r = enumerate(p);
  ASSERT_TRUE(r.complete);
  EXPECT_GT(r.class_count, 1);
  EXPECT_EQ(r.verdicts, r.class_count);
  EXPECT_EQ(r.undecided_classes, 0);  // the multiplier model decides every class exactly
  EXPECT_GE(r.foldable_classes, 1);   // the Miura's own assignment is among them
  long orbit_sum = 0;
  for (const auto& c : r.classes) orbit_sum += c.orbit_size;
  if (static_cast<long>(r.classes.size()) == r.class_count) {
    EXPECT_EQ(orbit_sum, r.assignments);
  }
}

// Proper 3-colourings of the rows x cols grid graph, by a transfer matrix over rows (an
// independent count: Ginepro and Hull show that the flat-folding assignments of a Miura-ori
// of rows x cols panels are the 3-colourings of its panel grid, divided by 3).
long grid_three_colourings(int rows, int cols) {
  std::vector<std::vector<int>> states;
  std::vector<int> row(cols, 0);
  for (long code = 0; code < std::lround(std::pow(3, cols)); ++code) {
    long c = code;
    bool ok = true;
    for (int j = 0; j < cols; ++j) {
      row[j] = static_cast<int>(c % 3);
      c /= 3;
      if (j > 0 && row[j] == row[j - 1]) ok = false;
    }
    if (ok) states.push_back(row);
  }
  std::vector<long> count(states.size(), 1);
  for (int r = 1; r < rows; ++r) {
    std::vector<long> next(states.size(), 0);
    for (std::size_t a = 0; a < states.size(); ++a)
      for (std::size_t b = 0; b < states.size(); ++b) {
        bool ok = true;
        for (int j = 0; j < cols && ok; ++j) ok = states[a][j] != states[b][j];
        if (ok) next[b] += count[a];
      }
    count = next;
  }
  long total = 0;
  for (long c : count) total += c;
  return total;
}

TEST(AssignmentEnumeration, MiuraCountsAreGridThreeColouringsOverThree) {
  for (int n : {3, 4, 5}) {
    generators::MiuraParams m;
    m.rows = m.cols = n;
    const auto r = enumerate(generators::miura_ori(m), true, 0);
    ASSERT_TRUE(r.complete);
    EXPECT_EQ(r.assignments, grid_three_colourings(n, n) / 3) << n;  // 82, 2604, 193662
    EXPECT_EQ(r.verdicts, 0);
  }
}

// The subtrees of one depth split the search: joined in their order, their classes are the whole
// search's, in the same order, and their assignments add up to the whole count; a branch that
// does not exist is refused naming it.
TEST(AssignmentEnumeration, BranchesOfOneDepthJoinToTheWholeSearch) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 3;
  const auto p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  AssignmentEnumerationOptions o;
  o.max_verdicts = 0;
  o.max_listed = 1'000'000;
  const AssignmentEnumeration whole = enumerate_assignments(p, t, o);
  ASSERT_TRUE(whole.complete);
  ASSERT_EQ(static_cast<long>(whole.classes.size()), whole.class_count);
  for (int depth : {0, 1, 2, 3}) {
    const auto branches = assignment_search_branches(p, t, depth, o);
    ASSERT_FALSE(branches.empty());
    if (depth == 0) {
      EXPECT_EQ(branches.size(), 1u);
    }
    long assignments = 0, orbit_sum = 0;
    std::vector<std::string> joined;
    for (const auto& b : branches) {
      EXPECT_EQ(static_cast<int>(b.size()), depth);
      AssignmentEnumerationOptions part = o;
      part.branch = b;
      const AssignmentEnumeration r = enumerate_assignments(p, t, part);
      ASSERT_TRUE(r.complete);
      assignments += r.assignments;
      for (const auto& c : r.classes) {
        joined.push_back(c.letters);
        orbit_sum += c.orbit_size;
      }
    }
    EXPECT_EQ(assignments, whole.assignments) << depth;
    EXPECT_EQ(orbit_sum, whole.assignments) << depth;
    ASSERT_EQ(joined.size(), whole.classes.size()) << depth;
    for (std::size_t i = 0; i < joined.size(); ++i) EXPECT_EQ(joined[i], whole.classes[i].letters) << depth << " " << i;
  }
  AssignmentEnumerationOptions bad = o;
  bad.branch = {99};
  try {
    enumerate_assignments(p, t, bad, "miura.fold");
    FAIL() << "branch {99} accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("miura.fold: branch[0]"), std::string::npos) << e.what();
  }
}

}}  // namespace
}  // namespace rigidfold
