#include "kernel/thick/thick_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"

namespace rigidfold {

namespace {

constexpr const char* kThicknessKey = "rigidfold:thickness";
constexpr const char* kHeightsKey = "rigidfold:hinge_heights";

// Numbers in messages: 6 significant digits (std::to_string prints 170.000000).
std::string num(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

std::string at(const char* key, int i) { return std::string(key) + "[" + std::to_string(i) + "]"; }

double diagonal(const CreasePattern& p) {
  Eigen::Vector3d lo = p.vertices.front(), hi = p.vertices.front();
  for (const Eigen::Vector3d& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return std::max((hi - lo).norm(), std::numeric_limits<double>::min());
}

// The extension, checked: per-face thickness and the number of hinge edges H (heights 0..H-1).
struct Extension {
  std::vector<double> thickness;  // pattern units
  int hinges = 0;
};

Extension read_extension(const CreasePattern& p) {
  const bool has_t = p.extra.contains(kThicknessKey), has_h = p.extra.contains(kHeightsKey);
  if (!has_t) throw InputError(kThicknessKey, std::string("missing (a thick FOLD needs it with ") + kHeightsKey + ")");
  if (!has_h) throw InputError(kHeightsKey, std::string("missing (a thick FOLD needs it with ") + kThicknessKey + ")");
  const nlohmann::ordered_json& t = p.extra[kThicknessKey];
  const nlohmann::ordered_json& h = p.extra[kHeightsKey];
  if (!t.is_array()) throw InputError(kThicknessKey, "must be an array (one thickness per face)");
  if (p.num_faces() == 0 || p.num_edges() == 0) throw InputError(kThicknessKey, "the sheet has no faces or no edges");
  if (static_cast<int>(t.size()) != p.num_faces())
    throw InputError(kThicknessKey, "has " + std::to_string(t.size()) + " entries for " + std::to_string(p.num_faces()) + " faces");
  if (!h.is_array()) throw InputError(kHeightsKey, "must be an array (one entry per edge)");
  if (static_cast<int>(h.size()) != p.num_edges())
    throw InputError(kHeightsKey, "has " + std::to_string(h.size()) + " entries for " + std::to_string(p.num_edges()) + " edges");
  Extension ext;
  for (int f = 0; f < p.num_faces(); ++f) {
    if (!t[f].is_number()) throw InputError(at(kThicknessKey, f), "must be a number");
    const double v = t[f].get<double>();
    if (!std::isfinite(v) || !(v > 0)) throw InputError(at(kThicknessKey, f), "must be finite and > 0");
    ext.thickness.push_back(std::ldexp(v, -p.length_exponent));
  }
  while (ext.hinges < p.num_edges() && !h[ext.hinges].is_null()) ++ext.hinges;
  if (ext.hinges == 0) throw InputError(at(kHeightsKey, 0), "the hinge edges come first and carry a height; found null");
  const double tol = 1e-9 * diagonal(p);
  for (int e = 0; e < p.num_edges(); ++e) {
    if (e >= ext.hinges) {
      if (!h[e].is_null())
        throw InputError(at(kHeightsKey, e), "heights must be a prefix of the edges (edge " + std::to_string(ext.hinges) + " is null)");
      continue;
    }
    if (!h[e].is_number()) throw InputError(at(kHeightsKey, e), "must be a number or null");
    const double z = std::ldexp(h[e].get<double>(), -p.length_exponent);
    if (!std::isfinite(z)) throw InputError(at(kHeightsKey, e), "must be finite");
    for (int end = 0; end < 2; ++end) {
      const double zv = p.vertices[p.edges[e][end]].z();
      if (std::abs(zv - z) > tol)
        throw InputError(at(kHeightsKey, e), "is " + num(to_file_units(p, z)) + " but the edge's vertex " +
                                                 std::to_string(p.edges[e][end]) + " lies at z = " + num(to_file_units(p, zv)) +
                                                 ": the sheet is not at its flat state");
    }
  }
  return ext;
}

int dof_at(const ClosureSystem& system, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  RankOptions options;
  options.compute_null_space = false;
  return jacobian_rank(J, options).dof;
}

}  // namespace

bool is_thick_fold(const CreasePattern& pattern) {
  return pattern.extra.is_object() && (pattern.extra.contains(kThicknessKey) || pattern.extra.contains(kHeightsKey));
}

int thick_extension_hinges(const CreasePattern& pattern) { return read_extension(pattern).hinges; }

ThickCheckReport thick_check(const CreasePattern& pattern, const Topology& topology, const ThickCheckRequest& request) {
  const Extension ext = read_extension(pattern);
  if (request.to && !(std::isfinite(*request.to) && *request.to != 0 && std::abs(*request.to) <= kPi))
    throw InputError(request.to_place, "must be in [-180, 180] deg and not 0");
  if (request.steps < 1 || request.steps > 1000) throw InputError(request.steps_place, "must be in 1 .. 1000");

  ThickHeightSheet sheet;
  sheet.pattern = pattern;
  sheet.topology = topology;
  sheet.options.close_holes = true;
  sheet.reference_edge_angles = reference_fold_angles(pattern, topology);
  sheet.num_cut_edges = pattern.num_edges() - ext.hinges;
  for (int f = 0; f < pattern.num_faces(); ++f) sheet.flat_face_of_face.push_back(f);
  const ClosureSystem system(pattern, topology, sheet.options);
  sheet.vertex_of_hole.assign(system.num_holes(), -1);

  ThickCheckReport report;
  report.hinges = ext.hinges;
  report.cut_edges = sheet.num_cut_edges;
  report.holes = system.num_holes();
  report.min_thickness = *std::min_element(ext.thickness.begin(), ext.thickness.end());
  report.max_thickness = *std::max_element(ext.thickness.begin(), ext.thickness.end());
  if (report.holes == 0) throw InputError(kHeightsKey, "the sheet has no hole: no thick vertex to close");
  if (request.drive) {
    const int d = *request.drive;
    if (d < 0 || d >= ext.hinges || system.unknown_of_edge(d) < 0)
      throw InputError(request.drive_place, "edge " + std::to_string(d) + " is not a hinge crease (hinges are edges 0.." + std::to_string(ext.hinges - 1) +
                                    " that are not boundary)");
  }

  report.mobility = thick_mobility(sheet, Eigen::VectorXd::Zero(ext.hinges), {}, request.closure_tolerance);
  const int dof = report.mobility.dof;
  if (dof == 0) {
    report.verdict = "rigid";
    report.verdict_class = FoldabilityClass::kNotFoldableProof;
    report.reason = "DOF 0 at the flat state: the thick closure is injective to first order there (smallest kept singular value " +
                    num(report.mobility.rank.sigma_kept) + ", cut " + num(report.mobility.rank.threshold) +
                    "), so the flat state is isolated";
    return report;
  }
  // The tangent (DOF 1) or the null space (DOF > 1: a singular flat state, first order is
  // inconclusive) picks the default drive: the hinge that moves most.
  const bool singular = dof > 1;
  const Eigen::VectorXd x0 = system.unknowns_from_edges(sheet.reference_edge_angles);
  const Eigen::MatrixXd& null_space = report.mobility.rank.null_space;
  int drive = request.drive.value_or(-1);
  if (drive < 0) {
    double best = -1.0;
    for (int e = 0; e < ext.hinges; ++e) {
      const int u = system.unknown_of_edge(e);
      if (u >= 0 && null_space.row(u).norm() > best + 1e-12) {
        best = null_space.row(u).norm();
        drive = e;
      }
    }
  }
  report.drive = drive;
  const int du = system.unknown_of_edge(drive);
  const Assignment letter = pattern.assignments[drive];
  report.target = request.to.value_or(letter == Assignment::Mountain ? -to_radians(170.0) : to_radians(170.0));
  if (null_space.row(du).norm() <= 1e-9) {
    report.verdict = "undecided";
    report.reason = "DOF " + std::to_string(dof) + " at the flat state, but hinge " + std::to_string(drive) +
                    " does not move along it to first order: not traced";
    return report;
  }
  const double sign = report.target > 0 ? 1.0 : -1.0;
  const double ref = x0[du];
  std::string stop_why;
  auto beyond_pi = [&](const Eigen::VectorXd& x) {
    for (int e = 0; e < ext.hinges; ++e) {
      const int u = system.unknown_of_edge(e);
      if (u >= 0 && std::abs(x[u] - sheet.reference_edge_angles[e]) >= kPi) {
        stop_why = "hinge " + std::to_string(e) + " reached +-180 deg (local interference)";
        return true;
      }
    }
    return false;
  };
  auto add_step = [&](const Eigen::VectorXd& x, double goal) {
    ThickCheckStep step;
    step.residual = system.residual(x).cwiseAbs().maxCoeff();
    if (!(step.residual <= request.closure_tolerance)) {
      stop_why = "the step at " + num(to_degrees(goal - ref)) + " deg closes only to " + num(step.residual);
      return false;
    }
    step.rho = sheet.fold_angles(system.edges_from_unknowns(x));
    step.drive = step.rho[drive];
    step.dof = dof_at(system, x);
    report.max_residual = std::max(report.max_residual, step.residual);
    report.steps.push_back(std::move(step));
    return true;
  };

  if (!singular) {
    // A regular flat state: 1-DOF pseudo-arclength continuation, landing on the steps.
    ContinuationOptions options;
    options.tolerance = std::min(1e-12, request.closure_tolerance);
    options.max_points = request.max_points;
    options.landing_unknown = du;
    for (int k = 1; k <= request.steps; ++k) options.landing_values.push_back(ref + report.target * k / request.steps);
    Eigen::VectorXd direction = Eigen::VectorXd::Zero(system.num_unknowns());
    direction[du] = sign;
    auto stop = [&](const Eigen::VectorXd& x) {
      const double moved = sign * (x[du] - ref);
      if (moved >= std::abs(report.target) - 1e-12) return true;
      if (moved < -1e-9) {
        stop_why = "the drive turned back past the flat state (a fold limit)";
        return true;
      }
      return beyond_pi(x);
    };
    const ContinuationResult trace = continue_one_dof(system, x0, direction, stop, options);
    report.continuation_points = static_cast<int>(trace.points.size());
    int landed_last = -1;
    for (const ContinuationPoint& point : trace.points) {
      if (point.landing < 0 || point.landing <= landed_last) continue;
      if (!add_step(point.x, options.landing_values[point.landing])) break;
      landed_last = point.landing;
    }
    if (stop_why.empty() && landed_last != request.steps - 1) stop_why = trace.reason;
  } else {
    // A singular flat state: projected driving - the drive held at each sub-step (8 per step)
    // and every other hinge Newton-projected from the secant predictor. Each point closes to
    // the tolerance, so the points reached are states of the thick sheet; a sub-step that moves
    // any hinge by more than 0.25 rad is taken as a jump between branches and ends the trace.
    NewtonOptions newton;
    newton.tolerance = std::min(1e-12, request.closure_tolerance);
    newton.held_unknowns = {du};
    // Where the flat state branches, the letters pick the branch: projected Gauss-Newton keeps
    // each M hinge <= 0 and V hinge >= 0 (hinges whose sheet reference angle is 0 only; the
    // bound acts on the sheet's own fold angle).
    newton.sign_bounds.assign(system.num_unknowns(), 0);
    for (int e = 0; e < ext.hinges; ++e) {
      const int u = system.unknown_of_edge(e);
      if (u < 0 || u == du || std::abs(sheet.reference_edge_angles[e]) > 1e-12) continue;
      if (pattern.assignments[e] == Assignment::Valley) newton.sign_bounds[u] = 1;
      if (pattern.assignments[e] == Assignment::Mountain) newton.sign_bounds[u] = -1;
    }
    const int sub = 8;
    Eigen::VectorXd x = x0, previous = x0;
    for (int k = 1; k <= request.steps && stop_why.empty(); ++k) {
      for (int s = 1; s <= sub && stop_why.empty(); ++s) {
        const double goal = ref + report.target * ((k - 1) * sub + s) / (static_cast<double>(request.steps) * sub);
        Eigen::VectorXd guess = (k == 1 && s == 1) ? x : Eigen::VectorXd(2 * x - previous);
        guess[du] = goal;
        const NewtonResult r = newton_project(system, guess, newton);
        ++report.continuation_points;
        if (!r.converged) {
          stop_why = "Newton did not close the sheet at " + num(to_degrees(goal - ref)) + " deg of the drive";
        } else if ((r.x - x).cwiseAbs().maxCoeff() > 0.25) {
          stop_why = "a sub-step at " + num(to_degrees(goal - ref)) + " deg jumped (a hinge moved by more than 0.25 rad)";
        } else if (!beyond_pi(r.x)) {
          previous = x;
          x = r.x;
          if (s == sub) add_step(x, goal);
        }
      }
    }
  }

  if (!report.steps.empty())
    for (int e = 0; e < ext.hinges; ++e) {
      const double rho = report.steps.back().rho[e];
      const Assignment letter_e = pattern.assignments[e];
      report.letter_disagreements += (letter_e == Assignment::Valley && rho < -1e-9) || (letter_e == Assignment::Mountain && rho > 1e-9);
    }
  const bool reached = static_cast<int>(report.steps.size()) == request.steps;
  const std::string how = singular ? "projected driving from the singular flat state (DOF " + std::to_string(dof) + " to first order)"
                                   : "continuation from the flat state (DOF 1)";
  if (reached) {
    report.verdict = "mobile";
    report.verdict_class = report.letter_disagreements == 0 ? FoldabilityClass::kFoldable : FoldabilityClass::kUndecided;
    report.reason = "traced by " + how + " to " + num(to_degrees(report.target)) + " deg of hinge " + std::to_string(drive) + " in " +
                    std::to_string(report.steps.size()) + " steps, every step closed to " + num(request.closure_tolerance);
    // Mobile as a mechanism; the letters are a separate question on this motion.
    if (report.letter_disagreements > 0)
      report.reason += "; on this motion " + std::to_string(report.letter_disagreements) +
                       " hinge(s) end folded against their letter, so whether a motion that keeps every letter exists "
                       "is not decided here";
  } else {
    report.verdict = "undecided";
    report.trace_note = "trace ended after " + std::to_string(report.steps.size()) + " of " + std::to_string(request.steps) +
                        " steps: " + stop_why;
    report.reason = "the thick motion was not traced to the target by " + how + " (" + report.trace_note + ")";
  }
  return report;
}

nlohmann::ordered_json thick_check_json(const CreasePattern& p, const ThickCheckReport& r, bool with_steps) {
  nlohmann::ordered_json j;
  j["model"] = "thick";
  j["solver"] = "SE(3) loop closure of the thick sheet (one hole per thick vertex), pseudo-arclength continuation";
  j["verdict"] = r.verdict;
  j["verdict_class"] = to_string(r.verdict_class);
  j["reason"] = r.reason;
  j["hinges"] = r.hinges;
  j["cut_edges"] = r.cut_edges;
  j["thick_vertices"] = r.holes;
  j["thickness_min"] = to_file_units(p, r.min_thickness);
  j["thickness_max"] = to_file_units(p, r.max_thickness);
  const ThickMobilityReport& m = r.mobility;
  nlohmann::ordered_json flat;
  flat["dof"] = m.dof;
  flat["rank_cut"] = m.rank.threshold;
  flat["smallest_kept_singular_value"] = m.rank.sigma_kept;
  flat["largest_dropped_singular_value"] = m.rank.sigma_dropped;
  flat["locked_loops"] = m.locked_vertices.size();
  nlohmann::ordered_json loops = nlohmann::ordered_json::array();
  for (const ThickVertexMobility& v : m.vertices) loops.push_back({{"hole", v.hole}, {"creases", v.creases}, {"dof_alone", v.dof_alone}});
  flat["loops"] = loops;
  j["flat_state"] = flat;
  nlohmann::ordered_json trace;
  trace["driving_crease"] = r.drive >= 0 ? nlohmann::ordered_json(r.drive) : nlohmann::ordered_json();
  trace["to_deg"] = to_degrees(r.target);
  trace["reached_deg"] = r.steps.empty() ? 0.0 : to_degrees(r.steps.back().drive);
  trace["steps_reached"] = r.steps.size();
  trace["continuation_points"] = r.continuation_points;
  trace["max_residual"] = r.max_residual;
  int min_dof = -1, max_dof = -1;
  for (const ThickCheckStep& s : r.steps) {
    min_dof = min_dof < 0 ? s.dof : std::min(min_dof, s.dof);
    max_dof = std::max(max_dof, s.dof);
  }
  trace["dof_min"] = min_dof >= 0 ? nlohmann::ordered_json(min_dof) : nlohmann::ordered_json();
  trace["dof_max"] = max_dof >= 0 ? nlohmann::ordered_json(max_dof) : nlohmann::ordered_json();
  trace["letter_disagreements_at_end"] = r.letter_disagreements;
  if (!r.trace_note.empty()) trace["note"] = r.trace_note;
  if (with_steps) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (const ThickCheckStep& s : r.steps) {
      nlohmann::ordered_json angles = nlohmann::ordered_json::array();
      for (Eigen::Index e = 0; e < s.rho.size(); ++e) angles.push_back(to_degrees(s.rho[e]));
      steps.push_back({{"drive_deg", to_degrees(s.drive)}, {"residual", s.residual}, {"dof", s.dof}, {"fold_angles_deg", angles}});
    }
    trace["steps"] = steps;
  }
  j["trace"] = trace;
  return j;
}

std::string thick_check_text(const CreasePattern& p, const ThickCheckReport& r, bool with_steps) {
  std::string out;
  char line[400];
  std::snprintf(line, sizeof line, "  model: thick (rigidfold:thickness %.6g .. %.6g, %d hinges, %d thick vertices closed in SE(3))\n",
                to_file_units(p, r.min_thickness), to_file_units(p, r.max_thickness), r.hinges, r.holes);
  out += line;
  out += "  " + r.verdict + ": " + r.reason + "\n";
  std::snprintf(line, sizeof line, "  flat state: DOF %d (smallest kept singular value %.3g, cut %.3g), %zu loop(s) locked alone\n",
                r.mobility.dof, r.mobility.rank.sigma_kept, r.mobility.rank.threshold, r.mobility.locked_vertices.size());
  out += line;
  if (!r.steps.empty()) {
    int max_dof = 0;
    for (const ThickCheckStep& s : r.steps) max_dof = std::max(max_dof, s.dof);
    std::snprintf(line, sizeof line,
                  "  trace: hinge %d to %.6g deg in %zu steps (%d points), closure <= %.3g rad, DOF <= %d, %d hinge(s) against their letter at the end\n",
                  r.drive, to_degrees(r.steps.back().drive), r.steps.size(), r.continuation_points, r.max_residual, max_dof,
                  r.letter_disagreements);
    out += line;
  }
  if (with_steps)
    for (std::size_t k = 0; k < r.steps.size(); ++k) {
      std::snprintf(line, sizeof line, "    step %zu: drive %.6g deg, residual %.3g, DOF %d\n", k + 1, to_degrees(r.steps[k].drive),
                    r.steps[k].residual, r.steps[k].dof);
      out += line;
    }
  return out;
}

}  // namespace rigidfold
