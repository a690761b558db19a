#pragma once
// Design sweeps of the waterbomb base (sweeps over n, b and k ratio
// producing tables and plots): one checked bistability analysis per combination of degree n,
// split width b (0: the plain base) and stiffness ratio k_m / k_v (k_v = 1) at one rest angle.
// Each row comes from waterbomb_bistability (plain) or split_fold_bistability (b > 0), so its
// numbers passed those checks (general-model confirmation); a combination that is not valid
// (b >= 180/n, theta0 outside the split fold's range) or whose check fails gets a row with its
// reason and no numbers.
// Units: angles in degrees in the rows (the user's edge), energies in the unit of k_v rad^2,
// forces on the radius-1 base (plain only).
#include <string>
#include <vector>

namespace rigidfold::waterbomb {

struct SweepSpec {
  std::vector<int> n;               // each in [3, kMaxSweepDegree]
  std::vector<double> split_deg;    // each >= 0 (0 = plain base)
  std::vector<double> k_ratio;      // each finite, >= 0
  double theta0_deg = 60.0;         // rest angle, (0, 90) deg
};
inline constexpr int kMaxSweepDegree = 36;
inline constexpr int kMaxSweepRows = 400;
// Work budget: each row checks its states on a dense model of c creases (c = 2n plain, 4n
// split) at a cost ~ c^3; a sweep whose sum of c^3 exceeds this is refused (measured on a
// shared 2-core machine, Release: a split row at n = 36 takes ~3.6 s; n = 3..12 x 3 widths x
// 3 ratios, work 2.5e6, ~6 s; so the budget is ~10 s; n = 3..36 with a split width is refused).
inline constexpr double kMaxSweepWork = 4e6;

struct SweepRow {
  int n = 0;
  double split_deg = 0.0, k_ratio = 0.0, theta0_deg = 0.0;
  std::string status = "ok";        // "ok" or why the row has no numbers
  int stable_states = 0;
  // The stable state past flat (NaN when there is none): theta, fold angles (deg), energy.
  double state2_theta_deg = 0.0, state2_gamma_m_deg = 0.0, state2_gamma_v_deg = 0.0, state2_energy = 0.0;
  // Symmetric-path barriers over the flat cusp from the rest state and from state 2 (NaN if none).
  double barrier_from_rest = 0.0, barrier_from_state2 = 0.0;
  double switching_force = 0.0;     // plain base, radius 1 (NaN for split folds: not available)
};

// Throws InputError naming "n", "split_deg", "k_ratio", "theta0" (bad values, empty lists)
// or "rows" (more than kMaxSweepRows combinations, or more work than kMaxSweepWork).
std::vector<SweepRow> waterbomb_sweep(const SweepSpec& spec);

// CSV: n,split_deg,k_ratio,theta0_deg,status,stable_states,state2_theta_deg,state2_gamma_m_deg,
// state2_gamma_v_deg,state2_energy,barrier_from_rest,barrier_from_state2,switching_force
// (numbers round-trip; empty fields where a row has no number).
std::string sweep_csv(const std::vector<SweepRow>& rows);

}  // namespace rigidfold::waterbomb
