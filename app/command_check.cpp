// rigidfold check PATTERN.fold [--ignore-assignment] [--json]
// Rigid-foldability verdict. Exit 0 whether or not it folds; 2 on bad input.
#include <iostream>

#include "app/commands.hpp"
#include "app/foldability_json.hpp"
#include "kernel/pattern/fold_io.hpp"

namespace rigidfold::cli {

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Rigid-foldability verdict with certificate or obstruction");
  struct Args {
    std::string pattern;
    bool ignore = false, json = false, general = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold)")->required();
  cmd->add_flag("--ignore-assignment", a->ignore, "ignore the M-V assignment (any signs)");
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->add_flag("--general", a->general, "force the general loop-closure solver (skip multiplier propagation)");
  cmd->callback([a] {
    const CreasePattern p = read_fold(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    nlohmann::ordered_json j = {{"file", a->pattern}};
    j.update(foldability_json(p, t, a->ignore, a->general));
    if (a->json) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::cout << a->pattern << ": " << j["verdict"].get<std::string>() << " (model: " << j["model"].get<std::string>() << ")\n";
    std::cout << "  " << j["reason"].get<std::string>() << "\n";
    if (j["rigidly_foldable"] == true)
    {
      std::cout << "  DOF " << j["dof"] << ", max closure residual along the branch " << j["max_residual"].get<double>() << " rad";
      if (j.contains("certificate_mismatch")) std::cout << ", certificate mismatch " << j["certificate_mismatch"].get<double>();
      std::cout << "\n";
    }
    if (!j["obstruction"].is_null()) std::cout << "  obstruction: " << j["obstruction"]["message"].get<std::string>() << "\n";
    if (j.contains("holes_closed"))
      for (const auto& b : j["branches"])
        std::cout << "  branch " << b["id"] << " from the given state: crease " << b["driving_crease"] << " "
                  << b["range_deg"][0].get<double>() << " -> " << b["range_deg"][1].get<double>() << " deg, stopped by "
                  << b["stopped_by"].get<std::string>() << "\n";
    if (j.contains("branch_exploration") && j["branch_exploration"].is_object()) {
      int keep = 0;
      for (const auto& b : j["branches"]) keep += b.value("signs_match_assignment", false) == true;
      std::cout << "  branches: " << j["branches"].size() << " traced through " << j["branch_exploration"]["points"]
                << " points; " << keep << " keep every letter from their start\n";
      for (const auto& b : j["bifurcations"])
        if (b["kind"] == "bifurcation")
          std::cout << "  bifurcation where crease " << b["parameter_crease"] << " is at " << b["parameter"].get<double>() << " deg (+-" << b["location_uncertainty_rad"].get<double>()
                    << " rad), " << b["tangent_lines"] << " tangent lines\n";
    }
  });
}

}  // namespace rigidfold::cli
