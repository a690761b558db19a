#include "kernel/analysis/multiplier_propagation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"

namespace rigidfold {

namespace {

int sign_of(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

std::string letters_at(const CreasePattern& p, const std::array<int, 4>& creases) {
  std::string s;
  for (int e : creases) s += assignment_letter(p.assignments[e]);
  return s;
}

// The model of a pattern that multiplier_model_applicable accepted (not checked again).
MultiplierModel build_applicable_model(const CreasePattern& p, const Topology& t);

// A candidate mode of one vertex and the vertex's sign: sigma * tau_v > 0 makes every
// assigned crease fold its assigned way (sigma = 0: no assigned crease, either sign).
struct Candidate {
  int mode = 0;
  int sigma = 0;
};

// The candidates of one vertex: at most its two modes, in the order they are tried.
struct Candidates {
  std::array<Candidate, 2> list{};
  int count = 0;
  void push_back(Candidate c) { list[count++] = c; }
  int size() const { return count; }
  bool empty() const { return count == 0; }
  const Candidate& operator[](int i) const { return list[i]; }
};

// Union-find over model vertices with multiplicative potentials (pot[x] = tau_x / tau_parent)
// and an orientation per root (the common sign of sigma_x * tau_x / tau_root over the
// sign-constrained members; 0 if none). Union by size, no path compression, so every union
// can be undone.
class PotentialUnionFind {
 public:
  explicit PotentialUnionFind(int n) : parent_(n), pot_(n, 1.0), size_(n, 1), orient_(n, 0) {
    for (int i = 0; i < n; ++i) parent_[i] = i;
  }
  void reset_singleton(int x, int sigma) {
    parent_[x] = x;
    pot_[x] = 1.0;
    size_[x] = 1;
    orient_[x] = sigma;
  }
  std::pair<int, double> find(int x) const {
    double p = 1.0;
    while (parent_[x] != x) {
      p *= pot_[x];
      x = parent_[x];
    }
    return {x, p};
  }
  enum class Result { kOk, kGain, kSign };
  // Requires tau_b = r * tau_a. On kGain, `gain` is the loop gain found.
  Result unite(int a, int b, double r, double tol, double& gain) {
    const auto [ra, pa] = find(a);
    const auto [rb, pb] = find(b);
    if (ra == rb) {
      gain = r * pa / pb;
      return std::abs(gain - 1.0) <= tol ? Result::kOk : Result::kGain;
    }
    int child, root;
    double k;  // tau_child_root = k * tau_root
    if (size_[ra] >= size_[rb]) {
      root = ra, child = rb, k = r * pa / pb;
    } else {
      root = rb, child = ra, k = pb / (r * pa);
    }
    const int child_orient = orient_[child] * sign_of(k);
    if (child_orient != 0 && orient_[root] != 0 && child_orient != orient_[root]) return Result::kSign;
    undo_.push_back({child, root, orient_[root], size_[root]});
    parent_[child] = root;
    pot_[child] = k;
    size_[root] += size_[child];
    if (orient_[root] == 0) orient_[root] = child_orient;
    return Result::kOk;
  }
  std::size_t mark() const { return undo_.size(); }
  void rollback(std::size_t mark) {
    while (undo_.size() > mark) {
      const Undo u = undo_.back();
      undo_.pop_back();
      parent_[u.child] = u.child;
      pot_[u.child] = 1.0;
      orient_[u.root] = u.root_orient;
      size_[u.root] = u.root_size;
    }
  }

 private:
  struct Undo {
    int child, root, root_orient, root_size;
  };
  std::vector<int> parent_;
  std::vector<double> pot_;
  std::vector<int> size_;
  std::vector<int> orient_;
  std::vector<Undo> undo_;
};

struct SearchResult {
  enum class Status { kFound, kExhausted, kBudget } status = Status::kExhausted;
  std::vector<FlatFoldMode> modes;
  long steps = 0;
  // Deepest failure seen (for the report when nothing else explains it).
  int fail_depth = -1;
  Obstruction fail;
};

// Breadth-first order of the model vertices over shared creases (each non-root vertex comes
// after a neighbour, so ties close early).
std::vector<int> bfs_order(const MultiplierModel& m) {
  const int n = static_cast<int>(m.vertices.size());
  std::vector<int> order;
  order.reserve(n);
  std::vector<char> seen(n, 0);
  for (int root = 0; root < n; ++root) {
    if (seen[root]) continue;
    seen[root] = 1;
    std::size_t head = order.size();
    order.push_back(root);
    while (head < order.size()) {
      const int k = order[head++];
      for (int e : m.creases[k])
        for (int o : m.edge_vertex[e])
          if (o >= 0 && !seen[o]) {
            seen[o] = 1;
            order.push_back(o);
          }
    }
  }
  return order;
}

SearchResult search_modes(const MultiplierModel& m, const std::vector<Candidates>& candidates,
                          double tol, long max_steps) {
  const int n = static_cast<int>(m.vertices.size());
  SearchResult out;
  const std::vector<int> order = bfs_order(m);
  PotentialUnionFind uf(n);
  std::vector<int> assigned(n, -1);
  std::vector<int> choice(n + 1, 0);
  std::vector<std::size_t> marks(n + 1, 0);
  int d = 0;
  auto record = [&](int depth, Obstruction::Kind kind, int vertex, int crease, double gain, const std::string& msg) {
    if (depth < out.fail_depth) return;
    out.fail_depth = depth;
    out.fail = Obstruction{};
    out.fail.kind = kind;
    out.fail.vertex = vertex;
    out.fail.crease = crease;
    out.fail.loop_gain = gain;
    out.fail.defect = std::abs(gain - 1.0);
    out.fail.message = msg;
  };
  while (true) {
    if (d == n) {
      out.status = SearchResult::Status::kFound;
      out.modes.resize(n);
      for (int k = 0; k < n; ++k) out.modes[k] = mode_from_index(assigned[k]);
      return out;
    }
    const int k = order[d];
    if (choice[d] >= candidates[k].size()) {
      if (d == 0) {
        out.status = SearchResult::Status::kExhausted;
        return out;
      }
      --d;
      uf.rollback(marks[d]);
      assigned[order[d]] = -1;
      ++choice[d];
      continue;
    }
    if (++out.steps > max_steps) {
      out.status = SearchResult::Status::kBudget;
      return out;
    }
    marks[d] = uf.mark();
    const Candidate c = candidates[k][choice[d]];
    uf.reset_singleton(k, c.sigma);
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) {
      const int e = m.creases[k][i];
      const int side = m.edge_vertex[e][0] == k ? 1 : 0;
      const int o = m.edge_vertex[e][side];
      if (o < 0 || assigned[o] < 0) continue;
      const double wk = m.w[k][c.mode][i];
      const double wo = m.w[o][assigned[o]][m.edge_slot[e][side]];
      if ((wk == 0.0) != (wo == 0.0)) {
        record(d, Obstruction::Kind::kPin, wk == 0.0 ? m.vertices[o] : m.vertices[k], e, 1.0,
               "crease " + std::to_string(e) + " stays flat at one end and folds at the other");
        ok = false;
        break;
      }
      if (wk == 0.0) continue;
      double gain = 1.0;
      const auto r = uf.unite(o, k, wo / wk, tol, gain);
      if (r == PotentialUnionFind::Result::kGain) {
        std::ostringstream msg;
        msg << "closing crease " << e << " at vertex " << m.vertices[k] << ": loop gain " << gain;
        record(d, Obstruction::Kind::kLoopGain, m.vertices[k], e, gain, msg.str());
        ok = false;
      } else if (r == PotentialUnionFind::Result::kSign) {
        record(d, Obstruction::Kind::kSign, m.vertices[k], e, 1.0,
               "crease " + std::to_string(e) + " forces vertex " + std::to_string(m.vertices[k]) +
                   " to fold against its M-V letters");
        ok = false;
      }
    }
    if (ok) {
      assigned[k] = c.mode;
      ++d;
      choice[d] = 0;
    } else {
      uf.rollback(marks[d]);
      ++choice[d];
    }
  }
}

// Per component: the parameter giving the largest |rho| = fold, with the sign that makes the
// first assigned crease (if `signs`) fold its assigned way.
std::vector<double> certificate_parameters(const CreasePattern& p, const FoldFamily& f, double fold, bool signs) {
  std::vector<double> biggest(f.num_components, 0.0);
  std::vector<double> sign(f.num_components, 0.0);
  for (std::size_t e = 0; e < f.component.size(); ++e) {
    const int c = f.component[e];
    if (c < 0) continue;
    biggest[c] = std::max(biggest[c], std::abs(f.multiplier[e]));
    const double s = assigned_fold_sign(p.assignments[e]);
    if (signs && sign[c] == 0.0 && s != 0.0) sign[c] = s * (f.multiplier[e] > 0 ? 1.0 : -1.0);
  }
  std::vector<double> t(f.num_components, 0.0);
  for (int c = 0; c < f.num_components; ++c)
    t[c] = (sign[c] == 0.0 ? 1.0 : sign[c]) * std::tan(0.5 * fold) / biggest[c];
  return t;
}

FoldabilityVerdict decide(const CreasePattern& pattern, const Topology& topology, const VerdictOptions& opt,
                          bool use_assignment) {
  FoldabilityVerdict out;
  out.applicability = multiplier_model_applicable(pattern, topology, opt.flat_tolerance);
  if (!out.applicability.applicable) {
    out.verdict = Verdict::kNotApplicable;
    out.reason = "multiplier model not applicable: " + out.applicability.reason;
    return out;
  }
  const MultiplierModel model = build_applicable_model(pattern, topology);
  out.vertices = model.vertices;
  const int n = static_cast<int>(model.vertices.size());

  // Candidate modes per vertex.
  std::vector<Candidates> candidates(n);
  for (int k = 0; k < n; ++k) {
    std::array<Assignment, 4> letters;
    if (use_assignment)
      for (int i = 0; i < 4; ++i) letters[i] = pattern.assignments[model.creases[k][i]];
    for (int mode = 0; mode < 2; ++mode) {
      if (!use_assignment) {
        candidates[k].push_back({mode, 0});
        continue;
      }
      if (const auto sigma = mode_sign_matching_letters(model.w[k][mode], letters))
        candidates[k].push_back({mode, *sigma});
    }
    if (!use_assignment) {
      // Modes in which every crease folds first.
      auto zeros = [&](int mode) {
        int z = 0;
        for (double x : model.w[k][mode]) z += x == 0.0;
        return z;
      };
      if (zeros(1) < zeros(0)) std::swap(candidates[k].list[0], candidates[k].list[1]);
    }
  }
  for (int k = 0; k < n; ++k) {
    if (!candidates[k].empty()) continue;
    Obstruction ob;
    ob.kind = Obstruction::Kind::kVertexAssignment;
    ob.vertex = model.vertices[k];
    std::ostringstream msg;
    msg << "vertex " << ob.vertex << ": letters " << letters_at(pattern, model.creases[k])
        << " (CCW) match neither flat-fold mode of its sectors (Maekawa 3:1 with the odd crease where"
        << " the sectors put it)";
    ob.message = msg.str();
    out.verdict = Verdict::kNotRigidlyFoldable;
    out.reason = ob.message;
    out.obstruction = ob;
    return out;
  }

  SearchResult found = search_modes(model, candidates, opt.gain_tolerance, opt.max_search_steps);
  out.search_steps = found.steps;
  if (found.status == SearchResult::Status::kBudget) {
    out.verdict = Verdict::kUndecided;
    out.reason = "mode search stopped after " + std::to_string(found.steps) + " vertex visits";
    return out;
  }
  if (found.status == SearchResult::Status::kExhausted) {
    out.verdict = Verdict::kNotRigidlyFoldable;
    out.modes.resize(n);
    bool forced = true;
    for (int k = 0; k < n; ++k) {
      out.modes[k] = mode_from_index(candidates[k][0].mode);
      forced = forced && candidates[k].size() == 1;
    }
    const ModeCheck mc = check_modes(model, out.modes, opt.gain_tolerance);
    out.max_loop_defect = mc.max_defect;
    out.cycles_checked = mc.cycles_checked;
    // Report the failure of the first candidate choice (the only one when forced).
    out.obstruction = mc.obstruction ? *mc.obstruction : found.fail;
    out.reason = std::string(use_assignment ? "no mode choice matching the M-V assignment folds"
                                            : "no mode choice folds every vertex") +
                 (forced ? " (the letters fix every vertex's mode): "
                         : " (" + std::to_string(found.steps) + " vertex visits; first choice: ") +
                 out.obstruction->message + (forced ? "" : ")");
    return out;
  }

  out.modes = std::move(found.modes);
  ModeCheck mc = check_modes(model, out.modes, opt.gain_tolerance);
  out.max_loop_defect = mc.max_defect;
  out.cycles_checked = mc.cycles_checked;
  out.dof = mc.dof;
  out.family = std::move(mc.family);
  if (mc.dof == 0) {
    out.verdict = Verdict::kNotRigidlyFoldable;
    out.reason = "no crease can fold";
    return out;
  }
  // Certificate: every component folded to certificate_fold, checked by face placement.
  const std::vector<double> t = certificate_parameters(pattern, *out.family, opt.certificate_fold, use_assignment);
  out.certificate_angles = out.family->angles(t);
  out.certificate_max_fold = out.certificate_angles.cwiseAbs().maxCoeff();
  const FoldedGeometry g =
      place_faces(pattern, topology, out.certificate_angles, reference_fold_angles(pattern, topology),
                  /*with_vertices=*/false);
  out.certificate_mismatch = g.relative_mismatch();
  int wrong_sign = -1;
  if (use_assignment)
    for (int e = 0; e < pattern.num_edges() && wrong_sign < 0; ++e)
      if (topology.edge_is_hinge[e] && has_fold_sign(pattern.assignments[e]) &&
          assigned_fold_sign(pattern.assignments[e]) * out.certificate_angles[e] <= 0.0)
        wrong_sign = e;
  if (wrong_sign >= 0 || !(out.certificate_mismatch <= opt.mismatch_tolerance)) {
    out.verdict = Verdict::kUndecided;
    std::ostringstream msg;
    msg << "certificate failed: ";
    if (wrong_sign >= 0) msg << "crease " << wrong_sign << " folds against its letter; ";
    msg << "face-placement mismatch " << out.certificate_mismatch;
    out.reason = msg.str();
    return out;
  }
  out.verdict = Verdict::kRigidlyFoldable;
  std::ostringstream msg;
  msg << "rigidly foldable, " << out.dof << " DOF; max loop-gain defect " << out.max_loop_defect
      << " over " << out.cycles_checked << " cycles; certificate mismatch " << out.certificate_mismatch;
  out.reason = msg.str();
  return out;
}

}  // namespace

const char* to_string(Obstruction::Kind kind) {
  switch (kind) {
    case Obstruction::Kind::kLoopGain: return "loop-gain";
    case Obstruction::Kind::kPin: return "pin";
    case Obstruction::Kind::kVertexAssignment: return "vertex-assignment";
    case Obstruction::Kind::kSign: return "sign";
  }
  return "?";
}

std::optional<int> mode_sign_matching_letters(const std::array<double, 4>& w, const std::array<Assignment, 4>& letters) {
  int sigma = 0;
  for (int i = 0; i < 4; ++i) {
    const int s = assigned_fold_sign(letters[i]);
    if (s == 0) continue;
    if (w[i] == 0.0) return std::nullopt;  // an assigned crease would stay flat
    const int need = sign_of(s * w[i]);
    if (sigma == 0) sigma = need;
    if (sigma != need) return std::nullopt;
  }
  return sigma;
}

std::vector<FlatFoldMode> modes_matching_letters(const CreasePattern& pattern, const Fan& fan) {
  std::vector<FlatFoldMode> modes;
  if (fan.edges.size() != 4 || fan.sectors.size() != 4) return modes;
  const std::array<double, 4> sectors{fan.sectors[0], fan.sectors[1], fan.sectors[2], fan.sectors[3]};
  std::array<Assignment, 4> letters;
  for (int i = 0; i < 4; ++i) letters[i] = pattern.assignments[fan.edges[i]];
  for (FlatFoldMode mode : {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02})
    if (mode_sign_matching_letters(flat_fold_multipliers(sectors, mode).direction, letters)) modes.push_back(mode);
  return modes;
}

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::kRigidlyFoldable: return "rigidly-foldable";
    case Verdict::kNotRigidlyFoldable: return "not-rigidly-foldable";
    case Verdict::kNotApplicable: return "not-applicable";
    case Verdict::kUndecided: return "undecided";
  }
  return "?";
}

MultiplierApplicability multiplier_model_applicable(const CreasePattern& p, const Topology& t, double tol) {
  MultiplierApplicability out;
  for (std::size_t c = 0; c < t.components.size(); ++c) {
    if (t.components[c].holes > 0 || t.components[c].genus > 0) {
      out.reason = "component " + std::to_string(c) + " is not a disk (" + std::to_string(t.components[c].holes) +
                   " holes, genus " + std::to_string(t.components[c].genus) +
                   "): a hole needs a closure the vertex multipliers do not express";
      return out;
    }
  }
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans.at(0);
    for (int e : fan.edges) {
      if (!is_foldable_crease(p.assignments[e])) {
        out.vertex = v;
        out.edge = e;
        out.reason = "vertex " + std::to_string(v) + " has edge " + std::to_string(e) + " assigned " +
                     assignment_letter(p.assignments[e]) + " (only M, V, U creases are modelled)";
        return out;
      }
    }
    if (fan.edges.size() != 4) {
      out.vertex = v;
      out.reason = "vertex " + std::to_string(v) + " has degree " + std::to_string(fan.edges.size()) + ", not 4";
      return out;
    }
    try {
      validate_flat_foldable({fan.sectors[0], fan.sectors[1], fan.sectors[2], fan.sectors[3]}, tol);
    } catch (const std::invalid_argument& err) {
      out.vertex = v;
      out.reason = "vertex " + std::to_string(v) + " is not flat-foldable: " + err.what();
      return out;
    }
  }
  out.applicable = true;
  return out;
}

MultiplierModel build_multiplier_model(const CreasePattern& p, const Topology& t, double tol) {
  const MultiplierApplicability a = multiplier_model_applicable(p, t, tol);
  if (!a.applicable) throw std::invalid_argument("multiplier model: " + a.reason);
  return build_applicable_model(p, t);
}

namespace {

MultiplierModel build_applicable_model(const CreasePattern& p, const Topology& t) {
  MultiplierModel m;
  m.num_edges = p.num_edges();
  m.vertices = t.interior_vertices;
  const int n = static_cast<int>(m.vertices.size());
  m.creases.resize(n);
  m.w.resize(n);
  m.edge_vertex.assign(m.num_edges, {-1, -1});
  m.edge_slot.assign(m.num_edges, {-1, -1});
  for (int k = 0; k < n; ++k) {
    const Fan& fan = t.stars[m.vertices[k]].fans[0];
    const std::array<double, 4> sectors{fan.sectors[0], fan.sectors[1], fan.sectors[2], fan.sectors[3]};
    m.w[k] = flat_fold_directions(sectors);  // indexed by mode_index
    for (int i = 0; i < 4; ++i) {
      const int e = fan.edges[i];
      m.creases[k][i] = e;
      const int side = m.edge_vertex[e][0] < 0 ? 0 : 1;
      m.edge_vertex[e][side] = k;
      m.edge_slot[e][side] = i;
    }
  }
  m.free_hinge.assign(m.num_edges, false);
  for (int e = 0; e < m.num_edges; ++e)
    m.free_hinge[e] = t.edge_is_hinge[e] && is_foldable_crease(p.assignments[e]) && m.edge_vertex[e][0] < 0;
  return m;
}

}  // namespace

Eigen::VectorXd FoldFamily::angles(const std::vector<double>& t) const {
  if (static_cast<int>(t.size()) != num_components)
    throw std::invalid_argument("FoldFamily::angles: " + std::to_string(t.size()) + " parameters for " +
                                std::to_string(num_components) + " components");
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(component.size()));
  for (std::size_t e = 0; e < component.size(); ++e) {
    if (component[e] < 0 || multiplier[e] == 0.0) continue;  // a zero multiplier stays flat, even at t = inf
    const double tc = t[component[e]];
    rho[e] = std::isinf(tc) ? std::copysign(std::numbers::pi, multiplier[e] * tc) : 2.0 * std::atan(multiplier[e] * tc);
  }
  return rho;
}

Eigen::VectorXd FoldFamily::angles(double t) const { return angles(std::vector<double>(num_components, t)); }

Eigen::VectorXd FoldFamily::component_angles(int c, double t) const {
  std::vector<double> params(num_components, 0.0);
  params.at(c) = t;
  return angles(params);
}

int FoldFamily::fastest_crease(int c) const {
  int fastest = -1;
  for (std::size_t e = 0; e < component.size(); ++e)
    if (component[e] == c && multiplier[e] != 0.0 &&
        (fastest < 0 || std::fabs(multiplier[e]) > std::fabs(multiplier[fastest])))
      fastest = static_cast<int>(e);
  return fastest;
}

double FoldFamily::parameter_for(int edge, double rho) const {
  if (edge < 0 || edge >= static_cast<int>(component.size()) || component[edge] < 0 || multiplier[edge] == 0.0)
    throw std::invalid_argument("FoldFamily::parameter_for: edge " + std::to_string(edge) + " stays flat");
  return std::tan(0.5 * rho) / multiplier[edge];
}

ModeCheck check_modes(const MultiplierModel& m, const std::vector<FlatFoldMode>& modes, double tol) {
  const int n = static_cast<int>(m.vertices.size());
  if (static_cast<int>(modes.size()) != n)
    throw std::invalid_argument("check_modes: " + std::to_string(modes.size()) + " modes for " + std::to_string(n) +
                                " vertices");
  auto W = [&](int k, int i) { return m.w[k][mode_index(modes[k])][i]; };
  ModeCheck out;
  out.vertex_component.assign(n, -1);
  std::vector<double> scale(n, 1.0);
  std::vector<int> parent(n, -1), parent_crease(n, -1), depth(n, 0);
  // Spanning forest of the tie graph, breadth first (`queue` holds every vertex reached; those
  // from `head` on wait).
  std::vector<int> queue;
  queue.reserve(n);
  for (int root = 0; root < n; ++root) {
    if (out.vertex_component[root] >= 0) continue;
    const int c = out.tie_components++;
    out.vertex_component[root] = c;
    std::size_t head = queue.size();
    queue.push_back(root);
    while (head < queue.size()) {
      const int k = queue[head++];
      for (int i = 0; i < 4; ++i) {
        const int e = m.creases[k][i];
        const int side = m.edge_vertex[e][0] == k ? 1 : 0;
        const int o = m.edge_vertex[e][side];
        if (o < 0 || out.vertex_component[o] >= 0) continue;
        const double wk = W(k, i), wo = W(o, m.edge_slot[e][side]);
        if (wk == 0.0 || wo == 0.0) continue;
        out.vertex_component[o] = c;
        scale[o] = scale[k] * wk / wo;  // tau_o = (w_k / w_o) tau_k
        parent[o] = k;
        parent_crease[o] = e;
        depth[o] = depth[k] + 1;
        queue.push_back(o);
      }
    }
  }
  // Non-tree ties close cycles; one-sided zeros pin.
  std::vector<char> bad(out.tie_components, 0), pinned(out.tie_components, 0);
  int worst_u = -1, worst_v = -1, worst_e = -1;
  double worst_gain = 1.0;
  std::optional<Obstruction> first_pin;
  for (int e = 0; e < m.num_edges; ++e) {
    const int u = m.edge_vertex[e][0], v = m.edge_vertex[e][1];
    if (u < 0 || v < 0) continue;
    const double wu = W(u, m.edge_slot[e][0]), wv = W(v, m.edge_slot[e][1]);
    if (wu == 0.0 && wv == 0.0) continue;
    if (wu == 0.0 || wv == 0.0) {
      const int k = wu == 0.0 ? v : u;
      pinned[out.vertex_component[k]] = 1;
      if (!first_pin) {
        Obstruction ob;
        ob.kind = Obstruction::Kind::kPin;
        ob.vertex = m.vertices[k];
        ob.crease = e;
        ob.message = "crease " + std::to_string(e) + " stays flat at vertex " +
                     std::to_string(m.vertices[wu == 0.0 ? u : v]) + " and so pins vertex " +
                     std::to_string(m.vertices[k]) + " flat";
        first_pin = ob;
      }
      continue;
    }
    if (parent_crease[u] == e || parent_crease[v] == e) continue;
    // Cycle u -> (tree) -> v -> (crease e) -> u: gain = (s_v / s_u) * (w_v / w_u).
    const double gain = (scale[v] / scale[u]) * (wv / wu);
    const double defect = std::abs(gain - 1.0);
    ++out.cycles_checked;
    out.max_defect = std::max(out.max_defect, defect);
    if (defect > tol) {
      bad[out.vertex_component[u]] = 1;
      if (worst_e < 0 || defect > std::abs(worst_gain - 1.0)) worst_u = u, worst_v = v, worst_e = e, worst_gain = gain;
    }
  }
  for (int c = 0; c < out.tie_components; ++c) {
    out.inconsistent_components += bad[c];
    out.pinned_components += pinned[c];
  }
  out.consistent = out.inconsistent_components == 0;
  if (worst_e >= 0) {
    Obstruction ob;
    ob.kind = Obstruction::Kind::kLoopGain;
    std::vector<int> pu{worst_u}, pv{worst_v}, cu, cv;
    int a = worst_u, b = worst_v;
    while (depth[a] > depth[b]) cu.push_back(parent_crease[a]), a = parent[a], pu.push_back(a);
    while (depth[b] > depth[a]) cv.push_back(parent_crease[b]), b = parent[b], pv.push_back(b);
    while (a != b) {
      cu.push_back(parent_crease[a]), a = parent[a], pu.push_back(a);
      cv.push_back(parent_crease[b]), b = parent[b], pv.push_back(b);
    }
    for (int k : pu) ob.cycle_vertices.push_back(m.vertices[k]);
    for (int i = static_cast<int>(pv.size()) - 2; i >= 0; --i) ob.cycle_vertices.push_back(m.vertices[pv[i]]);
    ob.cycle_creases = cu;
    for (int i = static_cast<int>(cv.size()) - 1; i >= 0; --i) ob.cycle_creases.push_back(cv[i]);
    ob.cycle_creases.push_back(worst_e);
    ob.crease = worst_e;
    ob.loop_gain = worst_gain;
    ob.defect = std::abs(worst_gain - 1.0);
    std::ostringstream msg;
    msg << "loop gain " << worst_gain << " (defect " << ob.defect << ") around vertices";
    for (int v : ob.cycle_vertices) msg << ' ' << v;
    msg << " closing at crease " << worst_e;
    ob.message = msg.str();
    out.obstruction = ob;
  } else if (first_pin) {
    out.obstruction = first_pin;
  }
  // The family of the mobile components.
  std::vector<int> family_id(out.tie_components, -1);
  FoldFamily& f = out.family;
  f.component.assign(m.num_edges, -1);
  f.multiplier.assign(m.num_edges, 0.0);
  for (int c = 0; c < out.tie_components; ++c)
    if (!bad[c] && !pinned[c]) family_id[c] = f.num_components++;
  for (int e = 0; e < m.num_edges; ++e) {
    for (int side = 0; side < 2; ++side) {
      const int k = m.edge_vertex[e][side];
      if (k < 0) continue;
      const double w = W(k, m.edge_slot[e][side]);
      const int c = family_id[out.vertex_component[k]];
      if (w == 0.0 || c < 0) continue;
      f.component[e] = c;
      f.multiplier[e] = w * scale[k];
      break;
    }
  }
  for (int e = 0; e < m.num_edges; ++e)
    if (m.free_hinge[e]) {
      f.component[e] = f.num_components++;
      f.multiplier[e] = 1.0;
    }
  // A component whose creases all stay flat does not move (cannot happen for a mobile
  // component: every vertex has a non-zero multiplier).
  out.dof = f.num_components;
  return out;
}

FoldabilityVerdict verdict_with_assignment(const CreasePattern& pattern, const Topology& topology,
                                           const VerdictOptions& options) {
  return decide(pattern, topology, options, true);
}

FoldabilityVerdict verdict_ignoring_assignment(const CreasePattern& pattern, const Topology& topology,
                                               const VerdictOptions& options) {
  return decide(pattern, topology, options, false);
}

}  // namespace rigidfold
