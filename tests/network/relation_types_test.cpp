// Seed 003 §2.2: the 256 twist variants of a spherical 4R and the relation types R1..R16
// (Table 2-1) they realise for the joint pair (theta_1, theta_2). The counts come from the
// enumeration; the general network solver cross-checks every realised variant.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_closure.hpp"
#include "kernel/network/relation_types.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double pi = std::numbers::pi;

// Fig 2-1 solid line (pi/9, 2pi/9, 4pi/9, 2pi/3) and the Fig 2-7 linkage.
const S4RSectors kFig21{pi / 9, 2 * pi / 9, 4 * pi / 9, 2 * pi / 3};
const S4RSectors kFig27{2 * pi / 9, 3 * pi / 9, 13 * pi / 18, 5 * pi / 9};

double angle_gap(double a, double b) { return std::fabs(std::remainder(a - b, 2 * pi)); }

int code_of(std::array<AngleVariant, 4> v) {
  int code = 0;
  for (int k = 0; k < 4; ++k) code += static_cast<int>(v[k]) << (2 * k);
  return code;
}

TEST(NetworkRelationTypes, TableHasCentralSymmetryPairs) {
  // R(i+8) is Ri composed with (theta, theta') -> (-theta, -theta') (the seed's (2-10)).
  const auto& t = relation_types();
  for (int i = 0; i < 8; ++i)
    for (double x : {-2.5, -0.4, 0.3, 1.9}) {
      EXPECT_LT(angle_gap(apply_variant(t[i + 8].input, x), -apply_variant(t[i].input, x)), 1e-15) << i;
      EXPECT_LT(angle_gap(apply_variant(t[i + 8].output, x), -apply_variant(t[i].output, x)), 1e-15) << i;
    }
  // All 16 pairs are distinct.
  for (int i = 0; i < 16; ++i)
    for (int k = i + 1; k < 16; ++k) EXPECT_FALSE(t[i].input == t[k].input && t[i].output == t[k].output);
}

TEST(NetworkRelationTypes, Example26RealisesR3) {
  // (2-6): alpha' = (alpha12, pi - alpha23, pi - alpha34, alpha41) gives theta2' = -pi + theta2.
  using V = AngleVariant;
  const int code = code_of({V::kSame, V::kPiMinus, V::kPiMinus, V::kSame});
  const VariantRelation r = classify_twist_variant(kFig21, twist_variant(kFig21, code));
  ASSERT_FALSE(r.realised.empty());
  EXPECT_EQ(r.realised.front(), 3);
  EXPECT_EQ(r.realised, (std::vector<int>{3, 11}));
  EXPECT_LT(r.realised_residual, 1e-12);
  EXPECT_GT(r.rejected_margin, 1e-3);
  // The base realises R1 (and its mirror R9).
  EXPECT_EQ(classify_twist_variant(kFig21, kFig21).realised, (std::vector<int>{1, 9}));
}

// Table 2-4 (rotation case) by enumeration: three 2R and nine 3R transmissions.
TEST(NetworkRelationTypes, RotationTransmissionsAreTable24) {
  using C = std::vector<std::vector<int>>;
  EXPECT_EQ(closing_transmissions(2), (C{{2, 5}, {3, 16}, {4, 12}}));
  EXPECT_EQ(closing_transmissions(3), (C{{2, 6, 5}, {2, 7, 16}, {2, 8, 12}, {3, 13, 12}, {3, 14, 16}, {3, 15, 5},
                                         {4, 9, 12}, {4, 10, 16}, {4, 11, 5}}));
}

// The digest's statement, by enumeration: 128 of the 256 variants realise one of R1..R8,
// 16 each (each also R(i+8), nothing else); the other 128 realise no type, clearly.
void expect_counts(const S4RSectors& base) {
  std::map<int, int> count;
  int none = 0;
  double worst_realised = 0.0, least_margin = INFINITY;
  for (int code = 0; code < 256; ++code) {
    const VariantRelation r = classify_twist_variant(base, twist_variant(base, code));
    least_margin = std::min(least_margin, r.rejected_margin);
    if (r.realised.empty()) {
      ++none;
      continue;
    }
    worst_realised = std::max(worst_realised, r.realised_residual);
    ASSERT_EQ(r.realised.size(), 2u) << code;
    ASSERT_LE(r.realised[0], 8) << code;
    EXPECT_EQ(r.realised[1], r.realised[0] + 8) << code;
    ++count[r.realised[0]];
  }
  EXPECT_EQ(none, 128);
  ASSERT_EQ(count.size(), 8u);
  for (const auto& [type, n] : count) EXPECT_EQ(n, 16) << "R" << type;
  EXPECT_LT(worst_realised, 1e-12);
  EXPECT_GT(least_margin, 1e-3);
}

TEST(NetworkRelationTypes, EnumerationCountsFig21) { expect_counts(kFig21); }
TEST(NetworkRelationTypes, EnumerationCountsFig27) { expect_counts(kFig27); }

// Cross-check with the general network solver: with theta_1', theta_2' held at a type's
// substitution (sigma(theta_1), tau(theta_2)) of a base configuration, the variant's loop
// closes (Newton on theta_3', theta_4' from a few starts reaches 1e-12) exactly for the types
// the closed form says the variant realises.
TEST(NetworkRelationTypes, GeneralSolverAgreesOnEveryVariant) {
  const S4RSectors base = kFig21;
  const S4RInputRange range = s4r_input_range(base, 0);
  ASSERT_TRUE(range.feasible);
  const auto iv = range.intervals();
  std::vector<double> inputs;  // inside the first feasible interval, away from its limits
  for (double f : {0.3, 0.7}) inputs.push_back(iv[0][0] + f * (iv[0][1] - iv[0][0]));
  const std::vector<std::array<double, 2>> starts{{0.3, 0.4}, {2.5, -2.0}, {-2.2, 2.4}, {-1.0, -1.2}};
  int realised = 0, closed = 0;
  double worst = 0.0;
  for (int code = 0; code < 256; ++code) {
    const S4RSectors var = twist_variant(base, code);
    const VariantRelation cls = classify_twist_variant(base, var);
    LinkageNetwork net;
    net.joint_names = {"t1", "t2", "t3", "t4"};
    net.linkages.push_back({"V", {var[0], var[1], var[2], var[3]}, {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}}});
    const NetworkClosure system(net);
    NetworkNewtonOptions opt;
    opt.held = {0, 1};
    opt.max_iterations = 25;
    std::vector<int> general;
    for (const RelationType& type : relation_types()) {
      bool all = true;
      for (double x : inputs) {
        for (const S4RFoldAngles& b : s4r_branches(base, x).branches) {
          bool ok = false;
          for (const auto& s : starts) {
            Eigen::VectorXd q0(4);
            q0 << apply_variant(type.input, b[0]), apply_variant(type.output, b[1]), s[0], s[1];
            const NetworkNewtonResult res = network_project(system, q0, opt);
            if (res.converged) {
              worst = std::max(worst, system.residual(res.q).lpNorm<Eigen::Infinity>());
              ok = true;
              break;
            }
          }
          all = all && ok;
          if (!all) break;
        }
        if (!all) break;
      }
      if (all) general.push_back(type.number);
    }
    if (!cls.realised.empty()) ++realised;
    if (!general.empty()) ++closed;
    EXPECT_EQ(general, cls.realised) << "code " << code;
  }
  EXPECT_EQ(realised, 128);
  EXPECT_EQ(closed, 128);
  EXPECT_LE(worst, 1e-12);
}

}}  // namespace
}  // namespace rigidfold
