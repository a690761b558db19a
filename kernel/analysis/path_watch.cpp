#include "kernel/analysis/path_watch.hpp"

#include <cmath>
#include <numbers>

namespace rigidfold {

int first_crease_against_letter(const std::vector<int>& letter_signs, const Eigen::VectorXd& rho,
                                double sign_threshold) {
  for (int e = 0; e < static_cast<int>(letter_signs.size()); ++e)
    if (letter_signs[e] * rho[e] < -sign_threshold) return e;
  return -1;
}

void PathWatch::mark_letters(const Segment& segment, TracedBranch& branch) {
  if (segment.first_against_letter < 0 || !branch.signs_match_assignment) return;
  branch.signs_match_assignment = false;
  branch.first_wrong_crease = segment.first_against_letter;
}

PathWatch::PathWatch(const CreasePattern& pattern, int driving_edge, const PathWatchOptions& options,
                     std::vector<bool> movable)
    : letter_(pattern.num_edges(), 0), movable_(std::move(movable)), driving_edge_(driving_edge), options_(options),
      last_sign_(pattern.num_edges(), 0), at_180_(pattern.num_edges(), false) {
  if (movable_.empty()) movable_.assign(pattern.num_edges(), true);
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (movable_[e]) letter_[e] = assigned_fold_sign(pattern.assignments[e]);
  if (options_.letters_from_start) last_sign_ = letter_;
}

PathWatch::Segment PathWatch::observe(const Eigen::VectorXd& rho) {
  const Tolerances& tol = options_.tolerances;
  const double limit = tol.fold_limit();
  Segment seg;
  const bool first = points_ == 0;
  // The first point has no segment: it only seeds the signs, unless the letters did.
  const bool record_switches =
      (!first || options_.letters_from_start) && !(options_.skip_first_segment && points_ == 1);
  seg.first_against_letter = first_crease_against_letter(letter_, rho, tol.sign_threshold);
  double first_fraction = 2.0;
  for (int e = 0; e < static_cast<int>(letter_.size()); ++e) {
    if (!movable_[e]) continue;
    const double r = rho[e];
    if (!at_180_[e] && std::fabs(r) >= std::numbers::pi - tol.at_fold_limit) {
      at_180_[e] = true;
      seg.reached_180.push_back(e);
    }
    if (std::fabs(r) >= limit) {
      const double before = first ? std::fabs(r) : std::fabs(previous_[e]);
      const double s = before >= limit ? 0.0 : (limit - before) / (std::fabs(r) - before);
      if (s < first_fraction) {
        first_fraction = s;
        seg.fold_limit_crease = e;
      }
    }
    if (std::fabs(r) <= tol.sign_threshold) continue;
    const int sign = r > 0 ? 1 : -1;
    if (record_switches && last_sign_[e] != 0 && sign != last_sign_[e]) {
      SignSwitch s;
      s.crease = e;
      if (driving_edge_ >= 0) {
        s.driving_value = rho[driving_edge_];
        if (!first && previous_[e] * r < 0) {  // where the crease crosses 0 on the segment
          const double f = previous_[e] / (previous_[e] - r);
          s.driving_value = previous_[driving_edge_] + f * (rho[driving_edge_] - previous_[driving_edge_]);
        }
      }
      s.against_assignment = letter_[e] != 0 && letter_[e] * sign < 0;
      seg.switches.push_back(s);
    }
    last_sign_[e] = sign;
  }
  if (seg.fold_limit_crease >= 0) seg.fold_limit_fraction = first_fraction;
  previous_ = rho;
  ++points_;
  return seg;
}

}  // namespace rigidfold
