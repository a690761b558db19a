// rigidfold repair PATTERN --out REPAIRED.fold [--keep-boundary] [--fix V,...] [--max-move D] [--letters keep|free] [--json]
// rigidfold repair PATTERN --out REPAIRED.fold --add-creases [--max-added K] [--json]
// The least vertex move that makes a flat pattern of degree-4 vertices rigidly foldable with
// its letters (design/repair/pattern_repair.hpp), or the fewest face diagonals to add
// (design/repair/crease_addition.hpp). Exit 0 with REPAIRED.fold written when the repaired
// (or unchanged) pattern's check says foldable; otherwise the report is printed, no file is
// written, and the exit status is 3.
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "app/terminal_progress.hpp"
#include "design/repair/crease_addition.hpp"
#include "design/repair/pattern_repair.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "report/repair_json.hpp"
#include "report/repair_text.hpp"

namespace rigidfold::cli {
namespace {



struct RepairArgs {
  std::string pattern, out;
  bool keep_boundary = false, json = false, add_creases = false;
  int max_added = 2;
  std::string letters = "keep";
  std::vector<int> fix;
  std::optional<double> max_move;
};

// What one front door gave: the pattern to write (none: exit 3), its JSON and its text.
struct RepairOutcome {
  std::optional<CreasePattern> result;
  nlohmann::ordered_json json;
  std::string text;
  std::string failure;  // the stderr line when there is no result
};

RepairOutcome move_vertices(const RepairArgs& a, const CreasePattern& p, const Topology& t) {
  RepairOptions options;
  options.keep_boundary = a.keep_boundary;
  options.fixed_vertices = a.fix;
  options.max_move = a.max_move;
  options.use_letters = a.letters == "keep";
  if (std::string why; !options.IsValid(p.num_vertices(), &why)) throw InputError(a.max_move && why.starts_with("max") ? "--max-move" : "--fix", why);
  const RepairSummary s = [&] {
    TerminalProgress progress("repair");
    options.check.progress = progress.sink();
    return repair_pattern(p, t, options);
  }();
  RepairOutcome out;
  if (succeeded(s.termination)) out.result = s.repaired;
  out.json = report::repair_json(s);
  out.text = report::repair_text(a.pattern, s);
  out.failure = "repair: " + std::string(to_string(s.termination));
  return out;
}

RepairOutcome add_diagonals(const RepairArgs& a, const CreasePattern& p, const Topology& t) {
  CreaseAdditionOptions options;
  options.max_added = a.max_added;
  const CreaseAdditionSummary s = [&] {
    TerminalProgress progress("repair");
    options.check.progress = progress.sink();
    return add_creases(p, t, options);
  }();
  RepairOutcome out;
  if (s.already_foldable) out.result = p;
  if (!s.found.empty()) out.result = s.found[0].pattern;
  out.json = report::crease_addition_json(s);
  out.text = report::crease_addition_text(a.pattern, s);
  out.failure = "repair --add-creases: undecided";
  return out;
}

}  // namespace

void add_repair_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("repair", "Least change (vertex move, or added creases) that makes a pattern fold with its letters");
  auto a = std::make_shared<RepairArgs>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, .svg, .cp, .opx)")->required();
  cmd->add_option("--out", a->out, "the repaired pattern (FOLD); written only when it folds")->required();
  cmd->add_flag("--keep-boundary", a->keep_boundary, "keep the vertices on the sheet's boundary where they are");
  cmd->add_option("--fix", a->fix, "vertices that stay where they are (comma-separated indices)")->delimiter(',');
  cmd->add_option("--max-move", a->max_move, "largest distance a vertex may move (the pattern's length unit)");
  cmd->add_option("--letters", a->letters, "keep (default: the move keeps each vertex's mode and the repaired pattern folds with "
                                           "its letters) or free (letters ignored)")
      ->check(CLI::IsMember({"keep", "free"}));
  cmd->add_flag("--add-creases", a->add_creases, "add the fewest face diagonals (M or V) that make it fold, instead of moving vertices");
  cmd->add_option("--max-added", a->max_added, "with --add-creases: the most creases added together (1 or 2)")->check(CLI::Range(1, 2));
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->callback([a, cmd] {
    for (const char* flag : {"--keep-boundary", "--fix", "--max-move", "--letters"})
      if (a->add_creases && cmd->count(flag) > 0) throw InputError(flag, "moves vertices; --add-creases adds creases and moves none");
    if (!a->add_creases && cmd->count("--max-added") > 0) throw InputError("--max-added", "needs --add-creases");
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    outputs.add_output("--out", a->out);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    const RepairOutcome r = a->add_creases ? add_diagonals(*a, p, t) : move_vertices(*a, p, t);
    if (r.result) {
      outputs.stage(a->out, write_fold_string(*r.result));
      outputs.commit();
    }
    if (a->json) {
      nlohmann::ordered_json j = {{"file", a->pattern}, {"out", r.result ? nlohmann::ordered_json(a->out) : nullptr}};
      j.update(r.json);
      std::cout << document_text(j) << "\n";
    } else {
      std::cout << r.text;
      if (r.result) std::cout << "  wrote " << a->out << "\n";
    }
    if (!r.result) throw NoAnswerError(r.failure + " (the report above says why); " + a->out + " not written");
  });
}

}  // namespace rigidfold::cli
