#include "report/repair_text.hpp"

#include <sstream>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {

std::string repair_text(const std::string& file, const RepairSummary& s) {
  std::ostringstream out;
  out << file << ": " << to_string(s.termination) << "\n  " << s.message << "\n";
  out << "  before: " << to_string(s.before.verdict) << " (model: " << s.before.model_name << "): " << s.before.reason << "\n";
  if (s.termination == RepairTermination::kAlreadyFoldable || s.kawasaki_rows == 0) return out.str();
  out << "  constraints: " << s.kawasaki_rows << " Kawasaki, " << s.gain_rows << " loop gain, over " << s.free_coordinates
      << " free coordinates (" << s.fixed_vertex_count << " vertices fixed); modes from the letters at "
      << s.kawasaki_rows - s.modes_chosen_without_letters << " vertices, chosen at " << s.modes_chosen_without_letters << "\n";
  out << "  violation: Kawasaki " << s.kawasaki_before << " -> " << s.kawasaki_after << " rad, |log loop gain| "
      << s.gain_before << " -> " << s.gain_after << "; " << s.iterations << " iterations, stationarity " << s.stationarity << "\n";
  out << "  move: largest " << s.max_move << " (vertex " << s.worst_vertex << "), RMS " << s.rms_move << ", pattern size "
      << s.pattern_size << "\n";
  for (const RepairConstraint& c : s.costliest) {
    out << "  costs the move: " << c.kind << (c.kind == "kawasaki" ? " at vertex " : " around vertices ");
    for (std::size_t i = 0; i < c.vertices.size(); ++i) out << (i ? "-" : "") << c.vertices[i];
    out << " (was " << c.before << ", lambda " << c.lambda << ")\n";
  }
  if (s.after) {
    out << "  after: " << to_string(s.after->verdict) << " (model: " << s.after->model_name << "), DOF " << s.after->dof;
    if (s.after->certificate_mismatch) out << ", certificate mismatch " << *s.after->certificate_mismatch;
    out << "\n";
  }
  return out.str();
}

std::string crease_addition_text(const std::string& file, const CreaseAdditionSummary& s) {
  std::ostringstream out;
  out << file << ": " << s.message << "\n";
  out << "  before: " << to_string(s.before.verdict) << " (model: " << s.before.model_name << "): " << s.before.reason << "\n";
  if (s.already_foldable) return out.str();
  out << "  candidates: " << s.candidates << " face diagonals, each M and V; " << s.checks << " patterns checked\n";
  for (std::size_t k = 0; k < s.found.size(); ++k) {
    const CreaseAddition& a = s.found[k];
    out << "  " << k + 1 << ".";
    for (const AddedCrease& c : a.creases)
      out << " " << assignment_letter(c.letter) << " crease " << c.v0 << "-" << c.v1 << " across face " << c.face << ";";
    out << " " << to_string(a.check.verdict) << ", DOF " << a.check.dof;
    if (a.check.certificate_mismatch) out << ", certificate mismatch " << *a.check.certificate_mismatch;
    out << (k == 0 ? " (written)" : "") << "\n";
  }
  return out.str();
}

std::string tolerance_study_text(const std::string& file, const ToleranceStudy& s) {
  std::ostringstream out;
  out << file << ": " << s.message << "\n";
  for (const auto& [verdict, count] : s.verdicts) out << "  " << count << " x " << verdict << "\n";
  if (!s.degree4_model) return out.str();
  for (const LoopSensitivity& l : s.loops) {
    out << "  loop";
    for (std::size_t i = 0; i < l.vertices.size(); ++i) out << (i ? "-" : " ") << l.vertices[i];
    out << ": mean |log loop gain| " << l.mean_log_gain << "\n";
  }
  if (s.repairs > 0)
    out << "  least repair move (RMS over the vertices) / sigma: median " << s.repair_move_median << ", max " << s.repair_move_max
              << " over " << s.repairs << " repaired samples\n";
  return out.str();
}

std::string nearest_state_text(const std::string& target, const NearestState& n) {
  std::ostringstream out;
  out << "  nearest closed state to " << target << ": " << n.message << "; RMS " << to_degrees(n.rms_distance) << " deg over "
      << n.free_creases << " free creases, the target's own closure residual " << n.target_residual << " rad, " << n.iterations
      << " iterations, stationarity " << n.stationarity
      << (n.against_letters.empty() ? "" : "; " + std::to_string(n.against_letters.size()) + " creases against their letters") << "\n";
  return out.str();
}

}  // namespace rigidfold::report
