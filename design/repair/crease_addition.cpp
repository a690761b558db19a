#include "design/repair/crease_addition.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <sstream>
#include <utility>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace {

struct Diagonal {
  int face, i, j;  // positions i < j on the face's cycle, not neighbours
};

std::vector<Diagonal> face_diagonals(const CreasePattern& pattern) {
  std::vector<Diagonal> out;
  for (int f = 0; f < pattern.num_faces(); ++f) {
    const int n = static_cast<int>(pattern.faces[f].size());
    for (int i = 0; i < n; ++i)
      for (int j = i + 2; j < n; ++j)
        if (!(i == 0 && j == n - 1)) out.push_back({f, i, j});
  }
  return out;
}

// The pattern with the given diagonals added as creases (each splitting its face), with its
// topology, or nullopt when that is no valid pattern. The diagonals lie in different faces.
std::optional<std::pair<CreasePattern, Topology>> with_creases(const CreasePattern& pattern, const std::vector<std::pair<Diagonal, Assignment>>& added) {
  CreasePattern p = pattern;
  p.position_bounds = {};
  for (const auto& [d, letter] : added) {
    const std::vector<int> face = pattern.faces[d.face];
    p.edges.push_back({face[d.i], face[d.j]});
    p.assignments.push_back(letter);
    p.fold_angles.push_back(std::nullopt);
    std::vector<int> first(face.begin() + d.i, face.begin() + d.j + 1);
    std::vector<int> second(face.begin() + d.j, face.end());
    second.insert(second.end(), face.begin(), face.begin() + d.i + 1);
    p.faces[d.face] = std::move(first);
    p.faces.push_back(std::move(second));
  }
  try {
    complete_and_validate(p, "pattern with added creases");
    Topology t = build_topology(p, "pattern with added creases");
    return std::pair{std::move(p), std::move(t)};
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

bool CreaseAdditionOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  if (max_added < 1 || max_added > 2) return fail("max added creases must be 1 or 2");
  if (max_checks < 1) return fail("max checks must be >= 1");
  if (max_results < 1) return fail("max results must be >= 1");
  return true;
}

CreaseAdditionSummary add_creases(const CreasePattern& pattern, const Topology& topology, const CreaseAdditionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (std::string why; !options.IsValid(&why)) throw InputError("crease addition options", why);
  CreaseAdditionSummary out;
  FoldabilityOptions check = options.check;
  check.use_assignment = true;
  out.before = check_foldability(pattern, topology, check);
  auto finish = [&](std::string message) {
    out.message = std::move(message);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  if (out.before.verdict == FoldabilityClass::kFoldable) {
    out.already_foldable = true;
    return finish("the pattern already folds with its letters; no crease added");
  }
  const std::vector<Diagonal> diagonals = face_diagonals(pattern);
  out.candidates = static_cast<int>(diagonals.size());
  // Tries one addition; false when the budget is spent.
  auto attempt = [&](const std::vector<std::pair<Diagonal, Assignment>>& added) {
    if (out.checks >= options.max_checks) {
      out.budget_exhausted = true;
      return false;
    }
    std::optional<std::pair<CreasePattern, Topology>> p = with_creases(pattern, added);
    if (!p) return true;
    ++out.checks;
    FoldabilityReport r = check_foldability(p->first, p->second, check);
    if (r.verdict != FoldabilityClass::kFoldable) return true;
    CreaseAddition a;
    for (const auto& [d, letter] : added)
      a.creases.push_back({pattern.faces[d.face][d.i], pattern.faces[d.face][d.j], d.face, letter});
    a.pattern = std::move(p->first);
    a.check = std::move(r);
    out.found.push_back(std::move(a));
    return true;
  };
  const Assignment letters[2] = {Assignment::Mountain, Assignment::Valley};
  for (int count = 1; count <= options.max_added && out.found.empty() && !out.budget_exhausted; ++count) {
    bool complete = true;
    if (count == 1) {
      for (const Diagonal& d : diagonals)
        for (Assignment l : letters) complete = complete && attempt({{d, l}});
    } else {
      for (std::size_t a = 0; a < diagonals.size() && complete; ++a)
        for (std::size_t b = a + 1; b < diagonals.size() && complete; ++b) {
          if (diagonals[a].face == diagonals[b].face) continue;
          for (Assignment la : letters)
            for (Assignment lb : letters) complete = complete && attempt({{diagonals[a], la}, {diagonals[b], lb}});
        }
    }
    if (complete) out.searched_up_to = count;
  }
  std::stable_sort(out.found.begin(), out.found.end(), [](const CreaseAddition& a, const CreaseAddition& b) { return a.check.dof > b.check.dof; });
  const int total = static_cast<int>(out.found.size());
  if (total > options.max_results) out.found.resize(options.max_results);
  std::ostringstream msg;
  if (total > 0) {
    msg << total << " addition(s) of " << out.found[0].creases.size() << " crease(s) make the pattern fold with its letters ("
        << out.checks << " checked)";
  } else {
    msg << "undecided: no addition of up to " << std::max(out.searched_up_to, 0) << " face diagonal(s) makes the pattern fold with its letters ("
        << out.checks << " checked" << (out.budget_exhausted ? "; the budget of checks ran out before the next count was searched in full" : "")
        << "); other creases might";
  }
  return finish(msg.str());
}

}  // namespace rigidfold
