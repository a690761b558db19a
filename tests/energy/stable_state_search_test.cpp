// The general multistart search for stable states (kernel/energy/stable_state_search.hpp),
// with no waterbomb-specific code on its path, against the closed forms of seed 004: on the
// n = 4 base with rest at theta0 = 60 deg and equal springs it finds exactly the two stable
// states of `rigidfold waterbomb` (1e-9 rad, 1e-9 relative energy); the same for n = 6.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/stable_state_search.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(StableStateSearch, FindsTheWaterbombsTwoStatesWithoutKnowingItIsAWaterbomb) {
  for (auto [n, theta0_deg, k_m] : {std::tuple{4, 60.0, 1.0}, std::tuple{6, 45.0, 2.0}}) {
    generators::WaterbombParams wp;
    wp.n = n;
    const CreasePattern p = generators::waterbomb_base(wp);
    const Topology t = build_topology(p);
    const ClosureSystem sys(p, t);
    const auto closed = waterbomb::waterbomb_bistability(n, to_radians(theta0_deg), k_m, 1.0);
    const auto expected = closed.stable_states();
    ASSERT_EQ(expected.size(), 2u);
    const Eigen::VectorXd rest = waterbomb::waterbomb_edge_angles(p, waterbomb::waterbomb_fold_angles(n, to_radians(theta0_deg)));
    const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {k_m, 1.0, 1.0}), rest);
    const StableStateSearch s = search_stable_states(p, t, sys, springs, rest);
    // The springs alone also have unsymmetric minima with creases flipped against their
    // letters (n = 4: three more, energies 5.74 and 2 x 6.09). With the letters kept, n = 4
    // has exactly the closed form's two states; n = 6 (k_m = 2) has three more, unsymmetric
    // (energy 6.197, images of each other under the 6-fold rotation): stable states the
    // symmetric-path analysis cannot see, all above the two symmetric ones.
    std::vector<const FoundState*> physical;
    for (const auto& f : s.states) {
      if (f.physical()) physical.push_back(&f);
      else EXPECT_FALSE(f.creases_against_letters.empty() && f.interfering_faces.empty());
    }
    ASSERT_GE(physical.size(), 2u) << "n = " << n;
    if (n == 4) {
      EXPECT_EQ(physical.size(), 2u);
    }
    for (std::size_t i = 2; i < physical.size(); ++i) {
      EXPECT_GT(physical[i]->state.energy, expected[1].path.energy + 1e-6);
      double lo = 10, hi = -10;  // mountain angles of an unsymmetric state differ
      for (int e = 0; e < p.num_edges(); ++e)
        if (p.assignments[e] == Assignment::Mountain) {
          lo = std::min(lo, physical[i]->state.edge_angles[e]);
          hi = std::max(hi, physical[i]->state.edge_angles[e]);
        }
      EXPECT_GT(hi - lo, 1e-3) << "n = " << n << " state " << i;
    }
    EXPECT_TRUE(physical[0]->from_rest);  // the rest state is the zero-energy minimum
    for (std::size_t i = 0; i < 2; ++i) {
      const auto& found = physical[i]->state;
      const auto& want = expected[i].path;  // both lists in increasing energy
      EXPECT_LT((found.edge_angles - waterbomb::waterbomb_edge_angles(p, want.angles)).lpNorm<Eigen::Infinity>(), 1e-9) << "n = " << n << " state " << i;
      EXPECT_NEAR(found.energy, want.energy, 1e-9 * std::max(1.0, want.energy)) << "n = " << n;
      EXPECT_LE(found.closure_residual, 1e-12);
      EXPECT_GT(found.min_eigenvalue, 0.0);
      EXPECT_EQ(found.tangent_dimension, 2 * n - 3);
    }
  }
}

}}  // namespace
}  // namespace rigidfold
