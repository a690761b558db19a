#include "design/waterbomb/waterbomb_sweep.hpp"

#include <cmath>
#include <string>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::waterbomb {

namespace {

template <class States, class Barriers>
void fill(SweepRow& row, const States& stable, const Barriers& barriers, double theta0) {
  row.stable_states = static_cast<int>(stable.size());
  row.state2_theta_deg = row.state2_gamma_m_deg = row.state2_gamma_v_deg = row.state2_energy = NAN;
  row.barrier_from_rest = row.barrier_from_state2 = NAN;
  for (const auto& s : stable)
    if (s.path.theta > kPi / 2) {
      row.state2_theta_deg = to_degrees(s.path.theta);
      row.state2_gamma_m_deg = to_degrees(s.path.angles.gamma_m);
      row.state2_gamma_v_deg = to_degrees(s.path.angles.gamma_v);
      row.state2_energy = s.path.energy;
    }
  for (const auto& b : barriers) {
    if (std::fabs(b.from_theta - theta0) <= 1e-9) row.barrier_from_rest = b.height;
    else if (b.from_theta > kPi / 2) row.barrier_from_state2 = b.height;
  }
}

std::string field(double x) { return std::isfinite(x) ? round_trip_text(x) : std::string(); }

}  // namespace

std::vector<SweepRow> waterbomb_sweep(const SweepSpec& spec) {
  if (spec.n.empty()) throw InputError("n", "the sweep needs at least one degree n");
  if (spec.split_deg.empty()) throw InputError("split_deg", "the sweep needs at least one split width (0 for the plain base)");
  if (spec.k_ratio.empty()) throw InputError("k_ratio", "the sweep needs at least one stiffness ratio");
  for (int n : spec.n)
    if (n < 3 || n > kMaxSweepDegree)
      throw InputError("n", "each degree must lie in [3, " + std::to_string(kMaxSweepDegree) + "], got " + std::to_string(n));
  for (double b : spec.split_deg)
    if (!std::isfinite(b) || b < 0.0) throw InputError("split_deg", "each split width must be finite and >= 0 deg");
  for (double k : spec.k_ratio)
    if (!std::isfinite(k) || k < 0.0) throw InputError("k_ratio", "each stiffness ratio must be finite and >= 0");
  if (!std::isfinite(spec.theta0_deg) || !(spec.theta0_deg > 0.0) || !(spec.theta0_deg < 90.0))
    throw InputError("theta0", "the sweep's rest angle must lie in (0, 90) deg");
  const std::size_t rows = spec.n.size() * spec.split_deg.size() * spec.k_ratio.size();
  if (rows > static_cast<std::size_t>(kMaxSweepRows))
    throw InputError("rows", std::to_string(rows) + " combinations; a sweep takes at most " + std::to_string(kMaxSweepRows));
  double work = 0.0;
  for (int n : spec.n)
    for (double b : spec.split_deg) work += spec.k_ratio.size() * std::pow((b == 0.0 ? 2.0 : 4.0) * n, 3);
  if (work > kMaxSweepWork)
    throw InputError("rows", "the sweep would check " + std::to_string(rows) + " rows with an estimated work of " +
                                 round_trip_text(work) + " (sum of creases^3) > " + round_trip_text(kMaxSweepWork) +
                                 ": split it into smaller sweeps (fewer or smaller n, fewer split widths or ratios)");
  const double theta0 = to_radians(spec.theta0_deg);
  std::vector<SweepRow> out;
  for (int n : spec.n)
    for (double b : spec.split_deg)
      for (double k : spec.k_ratio) {
        SweepRow row;
        row.n = n;
        row.split_deg = b;
        row.k_ratio = k;
        row.theta0_deg = spec.theta0_deg;
        try {
          if (b == 0.0) {
            const WaterbombBistability r = waterbomb_bistability(n, theta0, k, 1.0);
            fill(row, r.stable_states(), r.symmetric_path_barriers(), theta0);
            row.switching_force = switching_force_checked(n, theta0, k, 1.0).force;
          } else if (!(b < 180.0 / n) || !(to_radians(b) < kPi / n)) {
            row.status = "split width >= 180/n";
          } else {
            const SplitFoldRange range = split_fold_range(n, to_radians(b));
            if (theta0 < range.theta_min || theta0 > range.theta_max) {
              row.status = "theta0 outside the split fold's valid range";
            } else {
              const SplitFoldBistability r = split_fold_bistability(n, to_radians(b), theta0, k, 1.0);
              fill(row, r.stable_states(), r.symmetric_path_barriers(), theta0);
              row.switching_force = NAN;
            }
          }
        } catch (const NoAnswerError& e) {
          row = SweepRow{n, b, k, spec.theta0_deg, std::string("no answer: ") + e.what()};
        }
        out.push_back(row);
      }
  return out;
}

std::string sweep_csv(const std::vector<SweepRow>& rows) {
  std::string csv =
      "n,split_deg,k_ratio,theta0_deg,status,stable_states,state2_theta_deg,state2_gamma_m_deg,state2_gamma_v_deg,"
      "state2_energy,barrier_from_rest,barrier_from_state2,switching_force\n";
  for (const SweepRow& r : rows) {
    std::string status = r.status;
    for (char& c : status)
      if (c == ',' || c == '\n' || c == '"') c = ';';
    csv += std::to_string(r.n) + "," + round_trip_text(r.split_deg) + "," + round_trip_text(r.k_ratio) + "," +
           round_trip_text(r.theta0_deg) + "," + status + ",";
    if (r.status == "ok")
      csv += std::to_string(r.stable_states) + "," + field(r.state2_theta_deg) + "," + field(r.state2_gamma_m_deg) + "," +
             field(r.state2_gamma_v_deg) + "," + field(r.state2_energy) + "," + field(r.barrier_from_rest) + "," +
             field(r.barrier_from_state2) + "," + field(r.switching_force) + "\n";
    else
      csv += ",,,,,,,\n";
  }
  return csv;
}

}  // namespace rigidfold::waterbomb
