// rigidfold assignments PATTERN [--json] [--list N] [--no-symmetry] [--max-assignments N]
// Every mountain-valley assignment that folds each interior vertex flat, in classes under
// the pattern's symmetry group and the global flip, each class with its rigid-foldability
// verdict (kernel/analysis/assignment_enumeration.hpp).
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/terminal_progress.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "report/assignments_json.hpp"

namespace rigidfold::cli {

void add_assignments_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "assignments", "Enumerate the flat-folding M-V assignments, in classes under symmetry and flip, each with its verdict");
  struct Args {
    std::string pattern;
    bool json = false, no_symmetry = false;
    int list = 50;
    long max_assignments = 50'000'000;
    long max_verdicts = 100'000;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "flat crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->add_option("--list", a->list, "classes listed with their letters (0..100000, default 50)");
  cmd->add_flag("--no-symmetry", a->no_symmetry, "classes under the global M/V flip only");
  cmd->add_option("--max-assignments", a->max_assignments, "stop the search after this many assignments (1..1e9)");
  cmd->add_option("--max-verdicts", a->max_verdicts, "classes given a verdict at most (0..1e7)");
  cmd->callback([a] {
    if (a->list < 0 || a->list > 100000) throw InputError("--list", "must be between 0 and 100000");
    if (a->max_assignments < 1 || a->max_assignments > 1'000'000'000)
      throw InputError("--max-assignments", "must be between 1 and 1000000000");
    if (a->max_verdicts < 0 || a->max_verdicts > 10'000'000) throw InputError("--max-verdicts", "must be between 0 and 10000000");
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    AssignmentEnumerationOptions o;
    o.symmetry = !a->no_symmetry;
    o.max_listed = a->list;
    o.max_assignments = a->max_assignments;
    o.max_verdicts = a->max_verdicts;
    const AssignmentEnumeration r = [&] {
      TerminalProgress progress("assignments");
      o.progress = progress.sink();
      return enumerate_assignments(p, t, o, a->pattern);
    }();
    const nlohmann::ordered_json j = report::assignment_enumeration_json(r, a->pattern, {});
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    std::cout << a->pattern << "\n";
    if (r.blocking_vertex >= 0) {
      std::cout << "  no assignment folds flat: " << r.blocking_reason << "\n";
      return;
    }
    std::cout << "  " << r.creases.size() << " creases; symmetry group of order " << r.symmetry_order << " ("
              << r.symmetry_rotations << " rotations" << (a->no_symmetry ? ", not used" : "") << "), and the global flip\n";
    if (r.complete)
      std::cout << "  " << r.assignments << " flat-folding assignments in " << r.class_count << " classes\n";
    else
      std::cout << "  search stopped: at least " << r.assignments << " flat-folding assignments; class count unknown ("
                << r.class_count << " classes' representatives reached)\n";
    std::cout << "  verdicts on " << r.verdicts << " classes: " << r.foldable_classes << " rigidly foldable, "
              << r.not_foldable_classes << " not, " << r.undecided_classes << " undecided\n";
    std::cout << "  creases (edge indices, the order of the letters):";
    for (int e : r.creases) std::cout << " " << e;
    std::cout << "\n";
    for (std::size_t i = 0; i < r.classes.size(); ++i) {
      const auto& c = r.classes[i];
      std::cout << "  class " << i + 1 << "  " << c.letters << "  (" << c.orbit_size << " assignments)";
      if (c.verdict_run) std::cout << "  " << to_string(c.verdict) << ", DOF " << c.dof << ": " << c.reason;
      std::cout << "\n";
    }
    if (r.complete && static_cast<long>(r.classes.size()) < r.class_count)
      std::cout << "  ... " << r.class_count - static_cast<long>(r.classes.size()) << " more classes (raise --list)\n";
    char line[80];
    std::snprintf(line, sizeof line, "  %.3f s\n", r.seconds);
    std::cout << line;
  });
}

}  // namespace rigidfold::cli
