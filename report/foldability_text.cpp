#include "report/foldability_text.hpp"

#include <sstream>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {

std::string foldability_text(const std::string& file, const FoldabilityReport& r) {
  std::ostringstream out;
  out << file << ": " << to_string(r.verdict) << " (model: " << r.model_name << ")\n";
  out << "  " << r.reason << "\n";
  out << "  precision: " << r.coordinate_precision << "\n";
  if (r.foldable() || r.folds_in_part) {
    out << "  " << (r.folds_in_part ? "the motion found: " : "") << "DOF " << r.dof << ", max closure residual along the branch " << r.max_residual << " rad";
    if (r.certificate_mismatch) out << ", certificate mismatch " << *r.certificate_mismatch;
    out << "\n";
    if (r.strictness) out << "  strict: " << strict_verdict(*r.strictness) << "\n";
  }
  if (r.obstruction) out << "  obstruction: " << r.obstruction->message << "\n";
  if (r.model == FoldabilityModel::kGivenStateHoleClosure)
    for (const TracedBranch& b : r.branches)
      out << "  branch " << b.id << " from the given state: crease " << b.driving_edge << " "
          << to_degrees(b.driving_begin) << " -> " << to_degrees(b.driving_end) << " deg, stopped by "
          << b.stop_text() << "\n";
  if (r.branches_explored) {
    int keep = 0;
    for (const TracedBranch& b : r.branches) keep += r.assignment_used && b.signs_match_assignment;
    out << "  branches: " << r.branches.size() << " traced through " << r.points.size() << " points; " << keep
        << " keep every letter from their start"
        << (r.exploration_budget_exhausted ? " (the explorer's work budget ran out: departures left untraced)" : "") << "\n";
    for (const BranchPoint& p : r.points)
      if (p.kind == PointKind::kBifurcation)
        out << "  bifurcation where crease " << p.parameter_edge << " is at " << to_degrees(p.parameter)
          << " deg (within " << p.location_error_bound << " rad), " << p.tangent_lines << " tangent lines\n";
  }
  return out.str();
}

}  // namespace rigidfold::report
