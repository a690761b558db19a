#include "design/repair/pattern_repair.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "kernel/analysis/flat_fold_constraints.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// The columns of J that belong to free coordinates, as a selection matrix (2n x free).
SparseMatrix free_columns(int num_vertices, const std::vector<char>& fixed, int& free_count) {
  std::vector<Eigen::Triplet<double>> t;
  free_count = 0;
  for (int v = 0; v < num_vertices; ++v)
    if (!fixed[v])
      for (int axis = 0; axis < 2; ++axis) t.emplace_back(2 * v + axis, free_count++, 1.0);
  SparseMatrix S(2 * num_vertices, free_count);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

struct Violation {
  double kawasaki = 0.0, gain = 0.0;
  bool within(const RepairOptions& o) const { return kawasaki <= o.kawasaki_tolerance && gain <= o.gain_tolerance; }
  double merit() const { return std::max(kawasaki, gain); }
};

Violation violation_of(const Eigen::VectorXd& c, int kawasaki_rows) {
  Violation out;
  if (kawasaki_rows > 0) out.kawasaki = c.head(kawasaki_rows).lpNorm<Eigen::Infinity>();
  if (c.size() > kawasaki_rows) out.gain = c.tail(c.size() - kawasaki_rows).lpNorm<Eigen::Infinity>();
  if (!c.allFinite()) out.gain = INFINITY;
  return out;
}

std::vector<Eigen::Vector3d> displaced(const std::vector<Eigen::Vector3d>& x0, const SparseMatrix& S, const Eigen::VectorXd& e) {
  const Eigen::VectorXd full = S * e;
  std::vector<Eigen::Vector3d> x = x0;
  for (std::size_t v = 0; v < x.size(); ++v) x[v] += Eigen::Vector3d(full[2 * v], full[2 * v + 1], 0.0);
  return x;
}

// The constraints' violation at the displacement e of the free coordinates.
Violation violation_at(const FlatFoldConstraints& constraints, const std::vector<Eigen::Vector3d>& x0, const SparseMatrix& S,
                       const Eigen::VectorXd& e) {
  Eigen::VectorXd c;
  constraints.evaluate(displaced(x0, S, e), c, nullptr);
  return violation_of(c, constraints.kawasaki_rows());
}

double bounding_diagonal(const std::vector<Eigen::Vector3d>& x) {
  if (x.empty()) return 0.0;
  Eigen::Vector3d lo = x[0], hi = x[0];
  for (const Eigen::Vector3d& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// The pattern with moved vertices as the user gets it: its FOLD text read back, with its
// topology; or why that is no crease pattern (creases crossing, a vertex on a crease, a face
// turned over), from the checks of reading it.
struct Reread {
  CreasePattern pattern;
  Topology topology;
  std::string invalidity;  // empty when valid
};

Reread reread(const CreasePattern& moved) {
  Reread out;
  try {
    out.pattern = parse_fold(write_fold_string(moved), "repaired pattern");
    out.topology = build_topology(out.pattern, "repaired pattern");
  } catch (const InputError& e) {
    out.invalidity = e.what();
  }
  return out;
}

// The largest fraction t of the move e (to 2^-40) at which x0 + t e is still a crease pattern
// (moved: the pattern at the full move, which is not one).
double last_valid_fraction(const CreasePattern& moved, const std::vector<Eigen::Vector3d>& x0, const SparseMatrix& S,
                           const Eigen::VectorXd& e) {
  double valid = 0.0, invalid = 1.0;
  for (int halving = 0; halving < 40; ++halving) {
    const double t = 0.5 * (valid + invalid);
    CreasePattern trial = moved;
    trial.vertices = displaced(x0, S, t * e);
    (reread(trial).invalidity.empty() ? valid : invalid) = t;
  }
  return valid;
}

// Per vertex: 1 where it stays (the boundary with keep_boundary, and the fixed vertices).
std::vector<char> fixed_vertices(const CreasePattern& pattern, const Topology& topology, const RepairOptions& options) {
  std::vector<char> fixed(pattern.num_vertices(), options.keep_boundary ? 1 : 0);
  if (options.keep_boundary)
    for (int v : topology.interior_vertices) fixed[v] = 0;
  for (int v : options.fixed_vertices) fixed[v] = 1;
  return fixed;
}

// The SQP's state: displacement e of the free coordinates from x0.
struct Solve {
  Eigen::VectorXd e;
  Eigen::VectorXd lambda;
  Violation violation;
  int iterations = 0;
  bool converged = false;  // the constraints met
  bool least = true;       // and the steps ended (first-order optimal), when converged
  std::string failure;
};

Solve least_move(const FlatFoldConstraints& constraints, const std::vector<Eigen::Vector3d>& x0, const SparseMatrix& S,
                 double size, const RepairOptions& options) {
  Solve s;
  s.e = Eigen::VectorXd::Zero(S.cols());
  Eigen::VectorXd c;
  SparseMatrix J;
  constraints.evaluate(x0, c, &J);
  s.violation = violation_of(c, constraints.kawasaki_rows());
  for (; s.iterations < options.max_iterations; ++s.iterations) {
    const SparseMatrix Jf = J * S;
    Eigen::SimplicialLDLT<SparseMatrix> ldlt(SparseMatrix(Jf * Jf.transpose()));
    if (ldlt.info() != Eigen::Success) {
      s.failure = "the constraints' Jacobian over the free coordinates is singular (a constraint on fixed vertices only, or "
                  "dependent constraints)";
      return s;
    }
    const Eigen::VectorXd lambda = ldlt.solve(Jf * s.e - c);
    const Eigen::VectorXd target = Jf.transpose() * lambda;
    if (!lambda.allFinite() || !target.allFinite()) {
      s.failure = "the least-norm step is not finite (singular constraints over the free coordinates)";
      return s;
    }
    // Full step where it lowers the violation (or the constraints already hold); otherwise
    // halve it up to six times.
    Eigen::VectorXd step = target - s.e;
    Eigen::VectorXd trial_c;
    SparseMatrix trial_J;
    Violation trial;
    for (int halving = 0;; ++halving) {
      constraints.evaluate(displaced(x0, S, s.e + step), trial_c, &trial_J);
      trial = violation_of(trial_c, constraints.kawasaki_rows());
      if (trial.merit() <= std::max(s.violation.merit(), 1e-10) || halving == 6) break;
      step *= 0.5;
    }
    s.e += step;
    s.lambda = lambda;
    c = std::move(trial_c);
    J = std::move(trial_J);
    s.violation = trial;
    if (s.violation.within(options) && step.lpNorm<Eigen::Infinity>() <= 1e-12 * size) {
      s.converged = true;
      ++s.iterations;
      break;
    }
  }
  // The steps may still move along the constraints (a linear rate where they curve much over
  // the move): the constraints met, the pattern is a repair, its least-ness stated by the
  // stationarity.
  if (!s.converged && s.violation.within(options)) {
    s.converged = true;
    s.least = false;
  }
  if (!s.converged)
    s.failure = "the constraints were not met to tolerance in " + std::to_string(options.max_iterations) + " iterations";
  return s;
}

// The distance each vertex moved (file units), the largest and the RMS.
void record_move(const CreasePattern& pattern, const std::vector<Eigen::Vector3d>& x, RepairSummary& out) {
  double sum_squares = 0;
  for (int v = 0; v < pattern.num_vertices(); ++v) {
    const double d = to_file_units(pattern, (x[v] - pattern.vertices[v]).norm());
    out.vertex_move[v] = d;
    sum_squares += d * d;
    if (d > out.max_move) {
      out.max_move = d;
      out.worst_vertex = v;
    }
  }
  out.rms_move = std::sqrt(sum_squares / std::max(1, pattern.num_vertices()));
}

// The stationarity of the move at x, and the constraints whose multipliers are largest (c0: the
// constraints at the input).
void record_multipliers(const FlatFoldConstraints& constraints, const Eigen::VectorXd& c0, const SparseMatrix& S, const Solve& s,
                        const std::vector<Eigen::Vector3d>& x, RepairSummary& out) {
  Eigen::VectorXd c;
  SparseMatrix J;
  constraints.evaluate(x, c, &J);
  const Eigen::VectorXd residual = s.e - (J * S).transpose() * s.lambda;
  out.stationarity = s.e.norm() > 0 ? residual.norm() / s.e.norm() : 0.0;
  std::vector<int> order(constraints.rows());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(s.lambda[a]) > std::abs(s.lambda[b]); });
  for (int r : order) {
    if (out.costliest.size() == 8 || s.lambda[r] == 0.0) break;
    RepairConstraint rc;
    const bool kawasaki = r < constraints.kawasaki_rows();
    rc.kind = kawasaki ? "kawasaki" : "loop gain";
    rc.vertices = kawasaki ? std::vector<int>{constraints.centres()[r]} : constraints.cycle_vertices(r - constraints.kawasaki_rows());
    rc.before = c0[r];
    rc.lambda = s.lambda[r];
    out.costliest.push_back(std::move(rc));
  }
}

}  // namespace

void require_repair_scope(const CreasePattern& pattern, const Topology& topology) {
  for (int v = 0; v < pattern.num_vertices(); ++v)
    if (pattern.vertices[v].z() != 0.0)
      throw InputError("vertices_coords[" + std::to_string(v) + "]",
                       "repair works on flat crease patterns; this vertex has z != 0 (a folded form?)");
  if (count_holes(topology) > 0)
    throw InputError("faces", "the sheet has a hole: repair's model (the multiplier model) needs every piece to be a disk");
  for (int v : topology.interior_vertices) {
    const std::vector<int>& edges = topology.stars[v].fans[0].edges;
    if (edges.size() != 4)
      throw InputError("vertex " + std::to_string(v), "has " + std::to_string(edges.size()) +
                                                          " creases; repair handles patterns whose interior vertices all have four "
                                                          "(the general-closure repair is not built)");
    for (int e : edges)
      if (!is_foldable_crease(pattern.assignments[e]))
        throw InputError("edges_assignment[" + std::to_string(e) + "]",
                         std::string("crease at interior vertex ") + std::to_string(v) + " is '" + assignment_letter(pattern.assignments[e]) +
                             "'; repair needs the four creases of each interior vertex to fold (M, V or U)");
  }
}

// The mode of each interior vertex: the letters' (at x0), else the less degenerate one.
std::vector<FlatFoldMode> repair_modes(const CreasePattern& pattern, const Topology& topology, int& chosen_without_letters,
                                       std::string& refusal, bool use_letters) {
  std::vector<FlatFoldMode> modes;
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans[0];
    std::array<Assignment, 4> letters{};
    for (int i = 0; i < 4; ++i) letters[i] = pattern.assignments[fan.edges[i]];
    std::vector<FlatFoldMode> matching;
    double smallest[2] = {0, 0};
    for (FlatFoldMode mode : {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02}) {
      const std::array<double, 4> w = mode_multipliers(fan.sectors[0], fan.sectors[1], mode);
      smallest[mode_index(mode)] = std::min({std::abs(w[0]), std::abs(w[1]), std::abs(w[2]), std::abs(w[3])});
      if (!use_letters || mode_sign_matching_letters(w, letters)) matching.push_back(mode);
    }
    if (matching.empty()) {
      std::string text;
      for (Assignment a : letters) text += assignment_letter(a);
      refusal = "vertex " + std::to_string(v) + ": letters " + text +
                " (counter-clockwise) match neither flat-fold mode of its sectors, and a small move keeps the odd crease where "
                "the sectors put it";
      return {};
    }
    if (matching.size() == 2) {
      ++chosen_without_letters;
      modes.push_back(smallest[1] > smallest[0] ? FlatFoldMode::kEqual02 : FlatFoldMode::kEqual13);
    } else {
      modes.push_back(matching[0]);
    }
  }
  return modes;
}

const char* to_string(RepairTermination t) {
  switch (t) {
    case RepairTermination::kAlreadyFoldable: return "already foldable";
    case RepairTermination::kRepaired: return "repaired";
    case RepairTermination::kCheckDisagrees: return "constraints met, check disagrees";
    case RepairTermination::kBeyondMaxMove: return "no repair within max move";
    case RepairTermination::kNoConvergence: return "no convergence";
    case RepairTermination::kInvalidPattern: return "no valid pattern";
    case RepairTermination::kNotRepairable: return "not repairable";
  }
  return "?";
}

bool succeeded(RepairTermination t) { return t == RepairTermination::kAlreadyFoldable || t == RepairTermination::kRepaired; }

bool RepairOptions::IsValid(int num_vertices, std::string* error) const {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  for (int v : fixed_vertices)
    if (v < 0 || v >= num_vertices)
      return fail("fixed vertex " + std::to_string(v) + " is not a vertex of the pattern (it has " + std::to_string(num_vertices) + ")");
  if (max_move && !(std::isfinite(*max_move) && *max_move > 0)) return fail("max move must be finite and > 0");
  if (!(std::isfinite(kawasaki_tolerance) && kawasaki_tolerance > 0)) return fail("kawasaki tolerance must be finite and > 0");
  if (!(std::isfinite(gain_tolerance) && gain_tolerance > 0)) return fail("gain tolerance must be finite and > 0");
  if (max_iterations < 1) return fail("max iterations must be >= 1");
  return true;
}

RepairSummary repair_pattern(const CreasePattern& pattern, const Topology& topology, const RepairOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (std::string why; !options.IsValid(pattern.num_vertices(), &why)) throw InputError("repair options", why);
  require_repair_scope(pattern, topology);
  RepairSummary out;
  out.repaired = pattern;
  out.interior_vertices = topology.interior_vertices;
  out.letters_used = options.use_letters;
  out.pattern_size = to_file_units(pattern, bounding_diagonal(pattern.vertices));
  out.vertex_move.assign(pattern.num_vertices(), 0.0);
  FoldabilityOptions check = options.check;
  check.use_assignment = options.use_letters;
  out.before = check_foldability(pattern, topology, check);
  auto finish = [&](RepairTermination t, std::string message) {
    out.termination = t;
    out.message = std::move(message);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  if (out.before.verdict == FoldabilityClass::kFoldable)
    return finish(RepairTermination::kAlreadyFoldable,
                  std::string("the pattern already folds") + (options.use_letters ? " with its letters" : "") + "; nothing moved");
  if (topology.interior_vertices.empty())
    return finish(RepairTermination::kNotRepairable, "no interior vertex: moving vertices cannot change whether it folds");
  std::string refusal;
  out.modes = repair_modes(pattern, topology, out.modes_chosen_without_letters, refusal, options.use_letters);
  if (!refusal.empty()) return finish(RepairTermination::kNotRepairable, refusal);
  const FlatFoldConstraints constraints(pattern, topology, out.modes);
  if (!constraints.gains_usable()) return finish(RepairTermination::kNotRepairable, constraints.why_no_gains());
  out.kawasaki_rows = constraints.kawasaki_rows();
  out.gain_rows = constraints.gain_rows();

  const std::vector<char> fixed = fixed_vertices(pattern, topology, options);
  out.fixed_vertex_count = static_cast<int>(std::count(fixed.begin(), fixed.end(), 1));
  const SparseMatrix S = free_columns(pattern.num_vertices(), fixed, out.free_coordinates);

  Eigen::VectorXd c0;
  constraints.evaluate(pattern.vertices, c0, nullptr);
  const Violation before = violation_of(c0, out.kawasaki_rows);
  out.kawasaki_before = before.kawasaki;
  out.gain_before = before.gain;
  const double size = bounding_diagonal(pattern.vertices);
  const Solve s = least_move(constraints, pattern.vertices, S, size, options);
  out.iterations = s.iterations;
  out.least_move_converged = s.converged && s.least;
  out.kawasaki_after = s.violation.kawasaki;
  out.gain_after = s.violation.gain;
  const std::vector<Eigen::Vector3d> x = displaced(pattern.vertices, S, s.e);
  record_move(pattern, x, out);
  if (s.lambda.size() == constraints.rows()) record_multipliers(constraints, c0, S, s, x, out);
  if (!s.converged) return finish(RepairTermination::kNoConvergence, s.failure);
  if (options.max_move && out.max_move > *options.max_move) {
    // The violation left at the largest step along the least move that keeps within the bound.
    const Violation at_bound = violation_at(constraints, pattern.vertices, S, (*options.max_move / out.max_move) * s.e);
    out.kawasaki_after = at_bound.kawasaki;
    out.gain_after = at_bound.gain;
    std::ostringstream msg;
    msg << "the least move takes vertex " << out.worst_vertex << " " << out.max_move << " from where it was, beyond the "
        << *options.max_move << " allowed; scaled back to that bound it leaves Kawasaki off by " << at_bound.kawasaki
        << " rad and a loop gain off by " << at_bound.gain << " (evidence that no repair lies within the bound, not a proof)";
    return finish(RepairTermination::kBeyondMaxMove, msg.str());
  }
  out.repaired.vertices = x;
  out.repaired.position_bounds = {};
  const Reread written = reread(out.repaired);
  if (const std::string& why = written.invalidity; !why.empty()) {
    const double valid = last_valid_fraction(out.repaired, pattern.vertices, S, s.e);
    const Violation last = violation_at(constraints, pattern.vertices, S, valid * s.e);
    out.kawasaki_after = last.kawasaki;
    out.gain_after = last.gain;
    out.repaired = pattern;
    std::ostringstream msg;
    msg << "the least move in these modes is no crease pattern (" << why << "); the last valid pattern along it, at "
        << valid << " of the move, leaves Kawasaki off by " << last.kawasaki << " rad and a loop gain off by " << last.gain
        << " (evidence that no repair in these modes keeps the pattern's layout, not a proof)";
    return finish(RepairTermination::kInvalidPattern, msg.str());
  }
  // Judged from scratch: the FOLD text the user gets, read back, its numbers taken as exact.
  FoldabilityOptions exact = check;
  exact.coordinate_tolerance = 0.0;
  out.after = check_foldability(written.pattern, written.topology, exact);
  if (out.after->verdict != FoldabilityClass::kFoldable)
    return finish(RepairTermination::kCheckDisagrees,
                  "the constraints hold, but the repaired pattern's check says " + std::string(to_string(out.after->verdict)) + ": " +
                      out.after->reason);
  std::ostringstream msg;
  msg << "moved " << std::count_if(out.vertex_move.begin(), out.vertex_move.end(), [](double d) { return d > 0; })
      << " vertices (largest " << out.max_move << ", RMS " << out.rms_move << "); the repaired pattern folds"
      << (options.use_letters ? " with its letters" : " (letters ignored)")
      << (out.least_move_converged ? "" : "; the steps toward the least move had not ended (stationarity " + std::to_string(out.stationarity) +
                                              "): a repair, perhaps not the least");
  return finish(RepairTermination::kRepaired, msg.str());
}

}  // namespace rigidfold
