// rigidfold check PATTERN.fold [--ignore-assignment] [--general] [--tolerance auto|exact|U] [--json]
// rigidfold check PATTERN.fold --tolerance-study SIGMA [--samples N] [--seed S] [--distribution gaussian|uniform] [--json]
// Rigid-foldability verdict (kernel/analysis/foldability_report.hpp: check_foldability).
// Exit 0 whether or not it folds; 2 on bad input. A thick FOLD (rigidfold thick --out) is
// answered with the thick model (kernel/thick/thick_check.hpp: DOF at flat, SE(3) trace).
#include <cstdint>
#include <iostream>
#include <optional>

#include "app/terminal_progress.hpp"
#include "app/thick_flags.hpp"
#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "report/foldability_json.hpp"
#include "report/foldability_text.hpp"
#include "report/repair_json.hpp"
#include "report/repair_text.hpp"
#include "design/repair/tolerance_study.hpp"
#include "app/number_flags.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/thick/thick_check.hpp"

namespace rigidfold::cli {
namespace {

struct StudyFlags {
  std::optional<double> sigma;
  int samples = 100;
  std::uint64_t seed = 1;
  std::string distribution = "gaussian";
};

void add_study_flags(CLI::App* cmd, StudyFlags& f) {
  auto* study = cmd->add_option("--tolerance-study", f.sigma,
                                "instead of the verdict: the fraction of patterns made with vertex errors of this size (the file's length "
                                "unit) that fold, over --samples random samples");
  cmd->add_option("--samples", f.samples, "with --tolerance-study: how many samples (1 .. 100000)")->needs(study);
  cmd->add_option("--seed", f.seed, "with --tolerance-study: the seed of the errors")->needs(study);
  cmd->add_option("--distribution", f.distribution, "with --tolerance-study: gaussian (sigma the standard deviation) or uniform (within +-sigma)")
      ->check(CLI::IsMember({"gaussian", "uniform"}))
      ->needs(study);
}

// --tolerance-study: its own front door (design/repair/tolerance_study.hpp).
void run_tolerance_study(const std::string& file, const CreasePattern& p, const Topology& t, const StudyFlags& flags, bool json) {
  ToleranceStudyOptions options;
  options.sigma = *flags.sigma;
  options.samples = flags.samples;
  options.seed = flags.seed;
  options.distribution = flags.distribution == "uniform" ? ErrorDistribution::kUniform : ErrorDistribution::kGaussian;
  if (std::string why; !options.IsValid(&why)) throw InputError(why.starts_with("sigma") ? "--tolerance-study" : "--samples", why);
  const ToleranceStudy s = [&] {
    TerminalProgress progress("check");
    options.check.progress = progress.sink();
    return tolerance_study(p, t, options);
  }();
  if (json) {
    nlohmann::ordered_json j = {{"file", file}};
    j["tolerance_study"] = report::tolerance_study_json(s, options);
    std::cout << document_text(j) << "\n";
  } else {
    std::cout << report::tolerance_study_text(file, s);
  }
}

}  // namespace

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Rigid-foldability verdict with certificate or obstruction");
  struct Args {
    std::string pattern;
    bool ignore = false, json = false, general = false;
    std::string tolerance = "auto";
    StudyFlags study;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_flag("--ignore-assignment", a->ignore, "ignore the M-V assignment (any signs)");
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->add_flag("--general", a->general, "force the general loop-closure solver (skip multiplier propagation)");
  CLI::Option* tolerance_option = cmd->add_option("--tolerance", a->tolerance,
                  "how far each coordinate may lie from the true one, in the file's length unit: auto (default: read off "
                  "the file's digits, float32 or drawn points), exact (judge the numbers as they are), or a number >= 0");
  add_study_flags(cmd, a->study);
  cmd->callback([a, tolerance_option] {
    const std::optional<double> tolerance = coordinate_tolerance_flag("--tolerance", a->tolerance);
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    if (a->study.sigma) {
      if (a->ignore || a->general || tolerance_option->count() > 0 || is_thick_fold(p))
        throw InputError("--tolerance-study", "checks flat patterns with their letters, on exact numbers: it takes none of --ignore-assignment, "
                                              "--general, --tolerance, nor a thick FOLD");
      return run_tolerance_study(a->pattern, p, t, a->study, a->json);
    }
    if (is_thick_fold(p)) {  // `rigidfold thick --out`'s FOLD: the thick model answers (kernel/thick/thick_check.hpp)
      refuse_flags_a_thick_fold_ignores({a->ignore, a->general, tolerance_option->count() > 0});
      const ThickCheckReport r = thick_check(p, t);
      nlohmann::ordered_json j = {{"file", a->pattern}};
      j.update(thick_check_json(p, r, false));
      std::cout << (a->json ? document_text(j) + "\n" : a->pattern + ": " + to_string(r.verdict_class) + " (model: thick; as a mechanism: " + r.verdict + ")\n" + thick_check_text(p, r, false));
      return;
    }
    FoldabilityOptions options;
    options.use_assignment = !a->ignore;
    options.force_general = a->general;
    options.coordinate_tolerance = tolerance;
    const FoldabilityReport r = [&] {
      TerminalProgress progress("check");  // its line is erased before the result is printed
      options.progress = progress.sink();
      return check_foldability(p, t, options);
    }();
    if (a->json) {
      nlohmann::ordered_json j = {{"file", a->pattern}};
      j.update(report::foldability_json(r));
      std::cout << document_text(j) << "\n";
      return;
    }
    std::cout << report::foldability_text(a->pattern, r);
  });
}

}  // namespace rigidfold::cli
