// Split-fold waterbomb closed forms (seed 004 eqs 3.13-3.30, as printed) against the loop
// closure of the 4n-crease vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "design/waterbomb/split_fold_kinematics.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {
namespace {

double split_closure(int n, double b, waterbomb::FoldPair g) {
  const double a = kPi / n - b;
  std::vector<double> sectors, rho;
  for (int k = 0; k < n; ++k) {
    sectors.insert(sectors.end(), {b, a, b, a});
    rho.insert(rho.end(), {g.gamma_v, g.gamma_v, g.gamma_m, g.gamma_m});
  }
  return vertex_closure_residual(sectors, rho).norm();
}

TEST(WaterbombSplitFold, PrintedFormsCloseTheLoop) {
  for (int n : {3, 4, 10})
    for (double bdeg : {1.0, 5.0, 10.0}) {
      if (bdeg >= 180.0 / n) continue;
      for (double deg : {20.0, 45.0, 70.0, 85.0, 95.0, 110.0}) {
        waterbomb::FoldPair g;
        try {
          g = waterbomb::split_fold_angles_printed(n, to_radians(bdeg), to_radians(deg));
        } catch (const InputError&) {
          continue;  // beyond the model's range for this n (theta_max)
        }
        // DESIGN.md's closed-form bar, 1e-10: the printed acos forms lose digits (measured up
        // to 3.4e-12 at n = 10); a stable rewrite is not done yet.
        EXPECT_LE(split_closure(n, to_radians(bdeg), g), 1e-10) << "n " << n << " b " << bdeg << " theta " << deg
                                                                 << " gm " << to_degrees(g.gamma_m) << " gv " << to_degrees(g.gamma_v);
      }
    }
}

}  // namespace
}  // namespace rigidfold
