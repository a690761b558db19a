// Seed 003 Table 2-2 (two-fold symmetric case, Fig 2-5, joints per (2-15)) by enumeration.
// The compatibility rule is derived in relation_types.hpp (the seed's (2-16)-(2-22) are
// lost). The enumeration gives the table's six 2R rows exactly. Its nine 3R chains are
// not the printed rows read as (theta_1, theta_2) types: the printed rows are the derived
// chains with the FIRST type read from joint 2 to joint 1 (Rk = (sigma, tau) printed as
// (tau, sigma)). Built as twists, only the three printed rows starting with R4 are mobile
// (R4 reversed is R12, realised by the same twists); the six starting with R2 or R3 are not.
// The independent checks: the closed-form loop A -> B -> C -> D -> A over every
// branch, and the general network solver (residual and DOF of the 12-joint assembly), for
// every derived chain, every printed row, and exhaustively over the twist classes at A, B, C.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "kernel/network/network_closure.hpp"
#include "kernel/network/relation_types.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double pi = std::numbers::pi;
using Chains = std::vector<std::vector<int>>;

// Table 2-2 as printed (seed lines ~740-756).
const Chains kTable2R{{2, 2}, {3, 3}, {4, 4}, {5, 5}, {12, 12}, {16, 16}};
const Chains kTable3R{{2, 6, 2},   {2, 7, 3},   {2, 8, 4},  {3, 13, 4}, {3, 14, 3},
                      {3, 15, 2},  {4, 9, 4},   {4, 10, 3}, {4, 11, 2}};

const S4RSectors kFig21{pi / 9, 2 * pi / 9, 4 * pi / 9, 2 * pi / 3};
const S4RSectors kFig27{2 * pi / 9, 3 * pi / 9, 13 * pi / 18, 5 * pi / 9};

std::vector<int> canonical(std::vector<int> c) {
  std::vector<int> r(c.rbegin(), c.rend());
  return std::min(c, r);
}
std::set<std::vector<int>> canonical_set(const Chains& rows) {
  std::set<std::vector<int>> s;
  for (const auto& r : rows) s.insert(canonical(r));
  return s;
}

TEST(TwoFoldTransmissions, Table22TwoRRowsByEnumeration) {
  const Chains e = two_fold_transmissions(2);
  EXPECT_EQ(e.size(), kTable2R.size());
  EXPECT_EQ(std::set<std::vector<int>>(e.begin(), e.end()), canonical_set(kTable2R));
}

TEST(TwoFoldTransmissions, Table22ThreeRRowsAreTheChainsWithTheFirstTypeReversed) {
  const Chains e = two_fold_transmissions(3);
  ASSERT_EQ(e.size(), 9u);
  const std::set<std::vector<int>> enumerated(e.begin(), e.end());
  // Read literally the printed rows are none of the closing chains ...
  for (const auto& row : kTable3R) EXPECT_EQ(enumerated.count(canonical(row)), 0u) << row[0] << "-" << row[1];
  // ... and with the first type read the other way (joint 2 -> joint 1) they are all of them.
  Chains reread;
  for (auto row : kTable3R) {
    row[0] = reversed_relation(row[0]);
    reread.push_back(row);
  }
  EXPECT_EQ(canonical_set(reread), enumerated);
  // The rule: a chain is only accepted when its placement makes the joints agree.
  EXPECT_TRUE(two_fold_compatible({1, 1, 1, 1}));
  EXPECT_TRUE(two_fold_compatible({2, 6, 5, 1}));
  EXPECT_FALSE(two_fold_compatible({2, 6, 2, 1}));
  EXPECT_THROW(two_fold_compatible({0, 1, 1, 1}), std::invalid_argument);
  EXPECT_THROW(two_fold_transmissions(4), std::invalid_argument);
  EXPECT_EQ(reversed_relation(2), 5);
  EXPECT_EQ(reversed_relation(6), 6);
}

// ---- independent checks ----

// Twists of one variant of `base` realising each type (a variant realises Rk and R(k+8)).
std::map<int, S4RSectors> variant_for_type(const S4RSectors& base) {
  std::map<int, S4RSectors> out;
  for (int code = 0; code < 256; ++code) {
    const S4RSectors v = twist_variant(base, code);
    for (int k : classify_twist_variant(base, v, 8).realised) out.emplace(k, v);
  }
  return out;
}

// Closed-form loop: theta_1^a = t -> theta_2^a -> theta_2^b = -theta_2^a -> theta_1^b ->
// theta_1^c = -theta_1^b -> theta_2^c -> theta_2^d = -theta_2^c -> theta_1^d; the smallest
// gap |-theta_1^d - t| (mod 2 pi) over every branch choice (infinity if none is feasible).
double least_loop_gap(const std::array<S4RSectors, 4>& tw, double t) {
  double best = INFINITY;
  for (const auto& a : s4r_branches(tw[0], t, 0).branches)
    for (const auto& b : s4r_branches(tw[1], -a[1], 1).branches)
      for (const auto& c : s4r_branches(tw[2], -b[0], 0).branches)
        for (const auto& d : s4r_branches(tw[3], -c[1], 1).branches)
          best = std::min(best, std::fabs(std::remainder(-d[0] - t, 2 * pi)));
  return best;
}

std::vector<double> inputs(const std::array<S4RSectors, 4>& tw) {
  const auto iv = s4r_input_range(tw[0], 0).intervals();
  std::vector<double> t;
  for (int i = 0; i < 9; ++i) t.push_back(iv[0][0] + (i + 0.5) / 9 * (iv[0][1] - iv[0][0]));
  return t;
}

// Number of inputs at which the assembly closes (gap <= 1e-9).
int closing_inputs(const std::array<S4RSectors, 4>& tw, double* worst_closed = nullptr) {
  int n = 0;
  for (double t : inputs(tw)) {
    const double g = least_loop_gap(tw, t);
    if (g <= 1e-9) {
      ++n;
      if (worst_closed) *worst_closed = std::max(*worst_closed, g);
    }
  }
  return n;
}

// The placement (first linkage) at which a chain is compatible.
int placement(const std::vector<int>& chain) {
  for (int start = 0; start < 4; ++start) {
    std::array<int, 4> types{1, 1, 1, 1};
    for (size_t i = 0; i < chain.size(); ++i) types[(start + i) % 4] = chain[i];
    if (two_fold_compatible(types)) return start;
  }
  return -1;
}

void check_base(const S4RSectors& base) {
  const auto twist_of = variant_for_type(base);
  ASSERT_EQ(twist_of.size(), 16u);
  // Every derived chain closes at every input, by the closed form and by the network solver
  // (the configuration built from the substitutions is closed, and has one DOF).
  double worst_gap = 0.0, worst_residual = 0.0;
  for (int length : {2, 3})
    for (const auto& chain : two_fold_transmissions(length)) {
      const int start = placement(chain);
      ASSERT_GE(start, 0);
      std::array<int, 4> types{1, 1, 1, 1};
      for (size_t i = 0; i < chain.size(); ++i) types[(start + i) % 4] = chain[i];
      std::array<S4RSectors, 4> tw;
      for (int k = 0; k < 4; ++k) tw[k] = twist_of.at(types[k]);
      EXPECT_EQ(closing_inputs(tw, &worst_gap), 9) << chain[0] << "-" << chain[1];

      // Base configuration of the identical assembly, then each linkage's substitution.
      const auto iv = s4r_input_range(base, 0).intervals();
      const double t = iv[0][0] + 0.37 * (iv[0][1] - iv[0][0]);
      const S4RFoldAngles b0 = s4r_branches(base, t, 0).branches.at(0);
      std::array<S4RFoldAngles, 4> conf;
      for (int k = 0; k < 4; ++k) {
        const double sgn = (k % 2 == 0) ? 1.0 : -1.0;  // B, D: central symmetry of A's
        const RelationType& rt = relation_types()[types[k] - 1];
        const double x = apply_variant(rt.input, sgn * b0[0]), y = apply_variant(rt.output, sgn * b0[1]);
        bool found = false;
        for (const auto& c : s4r_branches(tw[k], x, 0).branches)
          if (std::fabs(std::remainder(c[1] - y, 2 * pi)) < 1e-9) {
            conf[k] = c;
            found = true;
          }
        ASSERT_TRUE(found) << "type R" << types[k];
      }
      const NetworkClosure system(two_fold_assembly(tw));
      Eigen::VectorXd q(12);
      q << conf[0][0], conf[0][1], conf[1][0], conf[2][1], conf[0][2], conf[0][3], conf[1][2], conf[1][3],
          conf[2][2], conf[2][3], conf[3][2], conf[3][3];
      worst_residual = std::max(worst_residual, system.residual(q).lpNorm<Eigen::Infinity>());
      EXPECT_EQ(network_mobility(system, q).dof, 1) << chain[0] << "-" << chain[1];
      EXPECT_EQ(network_mobility(system, q, {0}).dof, 0);
    }
  EXPECT_LE(worst_gap, 1e-9);
  EXPECT_LE(worst_residual, 1e-12);

  // Built literally as twists (a variant realising each printed type, at every placement and
  // in both directions), a printed 3R row is mobile exactly when its first type and that
  // type reversed are realised by the same twists - R4 and R12 (= R4 + 8) are, R2/R5 and
  // R3/R16 are not. So R4-R9-R4, R4-R10-R3, R4-R11-R2 close at every input, and the six rows
  // starting with R2 or R3 close at no more than one of the nine (isolated configurations).
  auto cls = [](int k) { return k > 8 ? k - 8 : k; };
  int mobile = 0;
  for (const auto& row : kTable3R) {
    int most = 0;
    for (int dir = 0; dir < 2; ++dir)
      for (int start = 0; start < 4; ++start) {
        std::array<S4RSectors, 4> tw{base, base, base, base};
        for (int i = 0; i < 3; ++i) tw[(start + i) % 4] = twist_of.at(row[dir == 0 ? i : 2 - i]);
        most = std::max(most, closing_inputs(tw));
      }
    const bool same_twists = cls(reversed_relation(row[0])) == cls(row[0]);
    if (same_twists) {
      EXPECT_EQ(most, 9) << row[0] << "-" << row[1] << "-" << row[2];
      ++mobile;
    } else {
      EXPECT_LE(most, 1) << row[0] << "-" << row[1] << "-" << row[2];
    }
  }
  EXPECT_EQ(mobile, 3);
}

// Exhaustive at one placement: of the 7^3 assemblies with variants (one per twist class
// {Rk, R(k+8)}, k = 2..8) at A, B, C and the base at D, exactly those whose classes are a
// derived chain's close at all nine inputs; of the 7^2 with variants at A, B, exactly the
// derived 2R ones. (Identical adjacent linkages also close wherever both are feasible - the
// mirror pair of the two-fold assembly - which here covers only part of the input range of
// classes 5..8, 2 of 9 inputs; they are not counted.)
void check_exhaustive(const S4RSectors& base) {
  const auto twist_of = variant_for_type(base);
  auto cls = [](int k) { return k > 8 ? k - 8 : k; };
  std::set<std::vector<int>> derived3, derived2, closed3, closed2;
  for (int a = 2; a <= 16; ++a)
    for (int b = 2; b <= 16; ++b) {
      if (two_fold_compatible({a, b, 1, 1})) derived2.insert({cls(a), cls(b)});
      for (int c = 2; c <= 16; ++c)
        if (two_fold_compatible({a, b, c, 1}) && cls(b) != 1) derived3.insert({cls(a), cls(b), cls(c)});
    }
  for (int a = 2; a <= 8; ++a)
    for (int b = 2; b <= 8; ++b) {
      if (closing_inputs({twist_of.at(a), twist_of.at(b), base, base}) == 9) closed2.insert({a, b});
      for (int c = 2; c <= 8; ++c)
        if (closing_inputs({twist_of.at(a), twist_of.at(b), twist_of.at(c), base}) == 9) closed3.insert({a, b, c});
    }
  EXPECT_EQ(closed2, derived2);
  EXPECT_EQ(closed3, derived3);
  EXPECT_EQ(closed3.size(), 8u);  // R4-R9-R12 has the base's twists in the middle: a 2R assembly
}

TEST(TwoFoldTransmissions, ExhaustiveTwistAssembliesAtABCFig21) { check_exhaustive(kFig21); }

TEST(TwoFoldTransmissions, ClosedFormAndNetworkSolverAgreeFig21) { check_base(kFig21); }
TEST(TwoFoldTransmissions, ClosedFormAndNetworkSolverAgreeFig27) { check_base(kFig27); }

}}  // namespace
}  // namespace rigidfold
