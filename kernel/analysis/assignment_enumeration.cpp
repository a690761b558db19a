#include "kernel/analysis/assignment_enumeration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <queue>
#include <stdexcept>

#include "kernel/math/number_text.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/pattern_symmetry.hpp"
#include "kernel/pattern/vertex_letter_rules.hpp"

namespace rigidfold {

namespace {

struct VertexRule {
  int vertex = -1;
  std::vector<int> positions;         // crease positions around the vertex, CCW
  std::vector<std::uint32_t> masks;   // flat-folding letter sets (bit i: positions[i] is V)
};

// The search's order and group, from the pattern alone.
struct SearchPlan {
  std::vector<VertexRule> rules;      // interior vertices in search order
  std::vector<int> free_positions;    // creases on no interior vertex
  std::vector<std::vector<int>> perms;  // the group on crease positions: perm[j] = the position whose image is j
};

// Letters: 0 mountain, 1 valley, -1 not set yet.
class Search {
 public:
  Search(const CreasePattern& pattern, const Topology& topology, const AssignmentEnumerationOptions& options,
         AssignmentEnumeration& out, SearchPlan plan)
      : topology_(topology), options_(options), out_(out), rules_(std::move(plan.rules)),
        free_(std::move(plan.free_positions)), perms_(std::move(plan.perms)), letters_(out.creases.size(), -1),
        work_(pattern) {}

  void run() {
    vertex_step(0);
    // Only the whole search meets every member of the classes it finds.
    if (options_.branch.empty() && out_.complete && orbit_total_ != out_.assignments)
      throw std::logic_error("enumerate_assignments: the orbit sizes sum to " + std::to_string(orbit_total_) +
                             ", not to the " + std::to_string(out_.assignments) + " assignments found");
  }

  // The subtrees at `depth` vertices instead of the assignments.
  std::vector<std::vector<int>> branches(std::size_t depth) {
    list_depth_ = std::min(depth, rules_.size());
    listing_ = true;
    vertex_step(0);
    return std::move(listed_);
  }

 private:
  bool stopped() const { return !out_.complete; }

  void vertex_step(std::size_t k) {
    if (stopped()) return;
    if (++out_.search_steps > options_.max_search_steps) {
      out_.complete = false;
      return;
    }
    if (listing_ && k == list_depth_) {
      listed_.push_back(path_);
      return;
    }
    if (k == rules_.size()) {
      free_step(0);
      return;
    }
    const VertexRule& r = rules_[k];
    std::vector<int> newly;
    for (std::size_t choice = 0; choice < r.masks.size(); ++choice) {
      if (k < options_.branch.size() && static_cast<std::size_t>(options_.branch[k]) != choice) continue;
      const std::uint32_t mask = r.masks[choice];
      bool fits = true;
      for (std::size_t i = 0; i < r.positions.size() && fits; ++i) {
        const int want = static_cast<int>((mask >> i) & 1u);
        const int have = letters_[r.positions[i]];
        fits = have < 0 || have == want;
      }
      if (!fits) continue;
      newly.clear();
      for (std::size_t i = 0; i < r.positions.size(); ++i)
        if (letters_[r.positions[i]] < 0) {
          letters_[r.positions[i]] = static_cast<int>((mask >> i) & 1u);
          newly.push_back(r.positions[i]);
        }
      path_.push_back(static_cast<int>(choice));
      vertex_step(k + 1);
      path_.pop_back();
      for (int p : newly) letters_[p] = -1;
      if (stopped()) return;
    }
  }

  void free_step(std::size_t k) {
    if (stopped()) return;
    if (k == free_.size()) {
      leaf();
      return;
    }
    for (int l : {0, 1}) {
      letters_[free_[k]] = l;
      free_step(k + 1);
      letters_[free_[k]] = -1;
      if (stopped()) return;
    }
  }

  void leaf() {
    if (out_.assignments >= options_.max_assignments) {
      out_.complete = false;
      return;
    }
    ++out_.assignments;
    if ((out_.assignments & 0xFFFF) == 0)
      report_progress(options_.progress, [&] {
        return "assignments: " + std::to_string(out_.assignments) + " found, " + std::to_string(out_.class_count) + " classes";
      });
    // Smallest of its orbit? Image under (g, flip): b[j] = a[perm_g[j]] ^ flip.
    int stabiliser = 0;
    const int n = static_cast<int>(letters_.size());
    for (const auto& perm : perms_)
      for (int flip : {0, 1}) {
        int j = 0;
        while (j < n && (letters_[perm[j]] ^ flip) == letters_[j]) ++j;
        if (j == n) {
          ++stabiliser;
          continue;
        }
        if ((letters_[perm[j]] ^ flip) < letters_[j]) return;  // a smaller image: not the representative
      }
    const int orbit = static_cast<int>(2 * perms_.size()) / stabiliser;
    orbit_total_ += orbit;
    ++out_.class_count;
    AssignmentClass c;
    c.orbit_size = orbit;
    for (int l : letters_) c.letters.push_back(l ? 'V' : 'M');
    if (out_.verdicts < options_.max_verdicts) {
      for (int i = 0; i < n; ++i) work_.assignments[out_.creases[i]] = letters_[i] ? Assignment::Valley : Assignment::Mountain;
      FoldabilityOptions fo;
      fo.use_assignment = true;
      fo.explore_branches = false;
      fo.family_samples = 2;
      const FoldabilityReport rep = check_foldability(work_, topology_, fo);
      c.verdict_run = true;
      c.verdict = rep.verdict;
      c.is_proof = rep.is_proof;
      c.dof = rep.dof;
      c.reason = rep.reason;
      ++out_.verdicts;
      if (rep.foldable()) ++out_.foldable_classes;
      else if (rep.not_foldable()) ++out_.not_foldable_classes;
      else ++out_.undecided_classes;
    }
    if (static_cast<int>(out_.classes.size()) < options_.max_listed) out_.classes.push_back(std::move(c));
  }

  const Topology& topology_;
  const AssignmentEnumerationOptions& options_;
  AssignmentEnumeration& out_;
  std::vector<VertexRule> rules_;
  std::vector<int> free_;
  std::vector<std::vector<int>> perms_;
  std::vector<int> letters_;
  CreasePattern work_;
  long orbit_total_ = 0;
  std::vector<int> path_;  // the letter set chosen at each vertex so far
  bool listing_ = false;
  std::size_t list_depth_ = 0;
  std::vector<std::vector<int>> listed_;
};

// Per interior vertex: its creases in CCW order and the sectors between them (sectors across
// F/J edges merged), then the letter sets that fold it flat; on_vertex marks the creases met.
// A vertex off Kawasaki or of odd degree is recorded in out.blocking_vertex instead.
std::vector<VertexRule> vertex_rules(const Topology& topology, const std::vector<int>& position,
                                     const AssignmentEnumerationOptions& options, const std::string& source,
                                     AssignmentEnumeration& out, std::vector<bool>& on_vertex) {
  std::vector<VertexRule> rules;
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans[0];
    const int m = static_cast<int>(fan.edges.size());
    int first = -1;
    for (int i = 0; i < m && first < 0; ++i)
      if (position[fan.edges[i]] >= 0) first = i;
    if (first < 0) continue;  // no crease: the vertex stays flat whatever the letters
    VertexRule r;
    r.vertex = v;
    std::vector<double> sectors;
    for (int k = 0; k < m; ++k) {
      const int i = (first + k) % m;
      if (position[fan.edges[i]] >= 0) {
        r.positions.push_back(position[fan.edges[i]]);
        sectors.push_back(0.0);
      }
      sectors.back() += fan.sectors[i];
    }
    const int d = static_cast<int>(sectors.size());
    if (d > kMaxLetterDegree)
      throw InputError(source + ": vertex " + std::to_string(v),
                       std::to_string(d) + " creases; at most " + std::to_string(kMaxLetterDegree) + " are enumerated");
    double sum = 0.0, alternating = 0.0;
    for (int i = 0; i < d; ++i) {
      sum += sectors[i];
      alternating += i % 2 ? -sectors[i] : sectors[i];
    }
    if (d % 2 != 0 || std::fabs(alternating) > options.sector_tolerance ||
        std::fabs(sum - 2 * std::numbers::pi) > options.sector_tolerance) {
      if (out.blocking_vertex < 0) {
        out.blocking_vertex = v;
        out.blocking_reason = d % 2 != 0 ? "vertex " + std::to_string(v) + " has an odd number of creases (" + std::to_string(d) + ")"
                                         : "vertex " + std::to_string(v) + " misses Kawasaki (alternating sector sum " +
                                               round_trip_text(alternating) + " rad, sector sum - 2 pi " +
                                               round_trip_text(sum - 2 * std::numbers::pi) + " rad)";
      }
      continue;
    }
    r.masks = flat_folding_letter_masks(sectors, options.sector_tolerance);
    for (int p : r.positions) on_vertex[p] = true;
    rules.push_back(std::move(r));
  }
  return rules;
}

// Fills out.creases, the symmetry counts and, for a vertex that blocks every assignment,
// out.blocking_vertex (then the plan is not used).
SearchPlan plan_search(const CreasePattern& pattern, const Topology& topology, const AssignmentEnumerationOptions& options,
                       const std::string& source, AssignmentEnumeration& out) {
  for (int v = 0; v < pattern.num_vertices(); ++v)
    if (pattern.vertices[v].z() != 0.0)
      throw InputError(source + ": vertices_coords[" + std::to_string(v) + "]",
                       "z = " + round_trip_text(pattern.vertices[v].z()) + ": assignments are enumerated on a flat crease pattern");
  std::vector<int> position(pattern.num_edges(), -1);
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (is_foldable_crease(pattern.assignments[e])) {
      position[e] = static_cast<int>(out.creases.size());
      out.creases.push_back(e);
    }

  std::vector<bool> on_vertex(out.creases.size(), false);
  const std::vector<VertexRule> rules = vertex_rules(topology, position, options, source, out, on_vertex);
  SearchPlan plan;
  if (out.blocking_vertex >= 0) return plan;
  // Breadth-first order over shared creases, so that each vertex meets letters already set.
  std::vector<std::vector<int>> rules_of(out.creases.size());
  for (int k = 0; k < static_cast<int>(rules.size()); ++k)
    for (int p : rules[k].positions) rules_of[p].push_back(k);
  std::vector<bool> seen(rules.size(), false);
  for (int s = 0; s < static_cast<int>(rules.size()); ++s) {
    if (seen[s]) continue;
    std::queue<int> q;
    q.push(s);
    seen[s] = true;
    while (!q.empty()) {
      const int k = q.front();
      q.pop();
      plan.rules.push_back(rules[k]);
      for (int p : rules[k].positions)
        for (int j : rules_of[p])
          if (!seen[j]) {
            seen[j] = true;
            q.push(j);
          }
    }
  }
  for (int p = 0; p < static_cast<int>(out.creases.size()); ++p)
    if (!on_vertex[p]) plan.free_positions.push_back(p);

  std::vector<PatternSymmetry> group;
  if (options.symmetry) group = pattern_symmetries(pattern);
  else group.resize(1);
  out.symmetry_order = static_cast<int>(group.size());
  out.symmetry_rotations = 0;
  for (const auto& g : group) {
    if (!g.reflection) ++out.symmetry_rotations;
    std::vector<int> perm(out.creases.size());
    for (int i = 0; i < static_cast<int>(out.creases.size()); ++i) {
      const int image = g.edge_map.empty() ? out.creases[i] : g.edge_map[out.creases[i]];
      perm[position[image]] = i;
    }
    plan.perms.push_back(std::move(perm));
  }
  for (std::size_t k = 0; k < options.branch.size(); ++k)
    if (k >= plan.rules.size() || options.branch[k] < 0 ||
        options.branch[k] >= static_cast<int>(plan.rules[k].masks.size()))
      throw InputError(source + ": branch[" + std::to_string(k) + "]",
                       std::to_string(options.branch[k]) + ": the search's vertex " + std::to_string(k) +
                           (k < plan.rules.size() ? " has " + std::to_string(plan.rules[k].masks.size()) + " letter sets"
                                                  : " does not exist (" + std::to_string(plan.rules.size()) + " vertices)"));
  return plan;
}

}  // namespace

AssignmentEnumeration enumerate_assignments(const CreasePattern& pattern, const Topology& topology,
                                            const AssignmentEnumerationOptions& options, const std::string& source) {
  const auto start = std::chrono::steady_clock::now();
  AssignmentEnumeration out;
  SearchPlan plan = plan_search(pattern, topology, options, source, out);
  if (out.blocking_vertex < 0) Search(pattern, topology, options, out, std::move(plan)).run();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<std::vector<int>> assignment_search_branches(const CreasePattern& pattern, const Topology& topology, int depth,
                                                         const AssignmentEnumerationOptions& options,
                                                         const std::string& source) {
  if (depth < 0) throw InputError(source + ": depth", std::to_string(depth) + ": must be >= 0");
  AssignmentEnumeration out;
  SearchPlan plan = plan_search(pattern, topology, options, source, out);
  if (out.blocking_vertex >= 0) return {};
  return Search(pattern, topology, options, out, std::move(plan)).branches(static_cast<std::size_t>(depth));
}

}  // namespace rigidfold
