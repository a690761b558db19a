// Waterbomb design sweeps (design/waterbomb/waterbomb_sweep.hpp): every row equals the checked
// single analysis, invalid combinations are rows with a reason, and the seed's trends hold
// across the table (lower n nearer flat; a stiffer mountain moves state 2 away from flat; split
// folds lower the energy).
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_sweep.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombSweep, RowsEqualTheSingleAnalyses) {
  waterbomb::SweepSpec spec;
  spec.n = {3, 4, 5, 6, 8};
  spec.split_deg = {0.0, 5.0, 70.0};
  spec.k_ratio = {0.5, 1.0, 2.0};
  spec.theta0_deg = 60.0;
  const auto rows = waterbomb::waterbomb_sweep(spec);
  ASSERT_EQ(rows.size(), 45u);
  for (const auto& r : rows) {
    if (r.split_deg == 70.0) {  // >= 180/n for every n here
      EXPECT_EQ(r.status, "split width >= 180/n") << r.n;
      continue;
    }
    ASSERT_EQ(r.status, "ok") << r.n << " " << r.split_deg << " " << r.k_ratio;
    EXPECT_EQ(r.stable_states, 2);
    if (r.n == 4 && r.k_ratio == 2.0) {
      const double th0 = to_radians(60.0);
      double want = NAN;
      if (r.split_deg == 0.0) {
        for (const auto& s : waterbomb::waterbomb_bistability(4, th0, 2.0, 1.0).stable_states())
          if (s.path.theta > kPi / 2) want = s.path.theta;
      } else {
        for (const auto& s : waterbomb::split_fold_bistability(4, to_radians(5.0), th0, 2.0, 1.0).stable_states())
          if (s.path.theta > kPi / 2) want = s.path.theta;
      }
      EXPECT_EQ(r.state2_theta_deg, to_degrees(want));
    }
  }
  // Trends across the table.
  auto at = [&](int n, double b, double k) {
    for (const auto& r : rows)
      if (r.n == n && r.split_deg == b && r.k_ratio == k) return r;
    ADD_FAILURE() << "no row";
    return waterbomb::SweepRow{};
  };
  for (double b : {0.0, 5.0})
    for (double k : {0.5, 1.0, 2.0}) {
      for (int i = 0; i + 1 < 5; ++i) {
        const int n0 = spec.n[i], n1 = spec.n[i + 1];
        EXPECT_LT(at(n0, b, k).state2_theta_deg, at(n1, b, k).state2_theta_deg) << n0 << " " << b << " " << k;  // lower n nearer 90
      }
    }
  for (int n : spec.n)
    for (double b : {0.0, 5.0}) {
      EXPECT_LT(at(n, b, 0.5).state2_theta_deg, at(n, b, 1.0).state2_theta_deg) << n;
      EXPECT_LT(at(n, b, 1.0).state2_theta_deg, at(n, b, 2.0).state2_theta_deg) << n;
    }
  for (int n : spec.n)
    for (double k : spec.k_ratio) {
      EXPECT_LT(at(n, 5.0, k).barrier_from_rest, at(n, 0.0, k).barrier_from_rest) << n << " " << k;
      EXPECT_GT(at(n, 0.0, k).switching_force, 0.0);
      EXPECT_TRUE(std::isnan(at(n, 5.0, k).switching_force));
    }
}

TEST(WaterbombSweep, CsvHasOneLinePerRow) {
  waterbomb::SweepSpec spec;
  spec.n = {4, 40 / 10};
  spec.split_deg = {0.0, 50.0};
  spec.k_ratio = {1.0};
  const auto rows = waterbomb::waterbomb_sweep(spec);
  const std::string csv = waterbomb::sweep_csv(rows);
  std::size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, rows.size() + 1);
  EXPECT_NE(csv.find("4,50,1,60,split width >= 180/n,,,,,,,,\n"), std::string::npos) << csv;
}

TEST(WaterbombSweep, BadSpecNamesTheList) {
  auto place = [](waterbomb::SweepSpec s) {
    try {
      waterbomb::waterbomb_sweep(s);
    } catch (const InputError& e) {
      return e.place();
    }
    return std::string("no error");
  };
  const waterbomb::SweepSpec good{{4}, {0.0}, {1.0}, 60.0};
  auto s = good;
  s.n = {2};
  EXPECT_EQ(place(s), "n");
  s = good;
  s.n = {};
  EXPECT_EQ(place(s), "n");
  s = good;
  s.split_deg = {-1.0};
  EXPECT_EQ(place(s), "split_deg");
  s = good;
  s.k_ratio = {NAN};
  EXPECT_EQ(place(s), "k_ratio");
  s = good;
  s.theta0_deg = 95.0;
  EXPECT_EQ(place(s), "theta0");
  s = good;
  s.n = std::vector<int>(401, 4);
  EXPECT_EQ(place(s), "rows");
  s = good;
  s.n = {30, 31, 32, 33, 34, 35, 36};
  s.split_deg = {1.0};
  EXPECT_EQ(place(s), "rows");  // the work budget
}

}}  // namespace
}  // namespace rigidfold
