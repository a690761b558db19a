#include "report/assignments_json.hpp"

namespace rigidfold::report {

nlohmann::ordered_json assignment_enumeration_json(const AssignmentEnumeration& r, const std::string& file,
                                                   const std::vector<int>& branch) {
  nlohmann::ordered_json j;
  j["file"] = file;
  j["creases"] = r.creases;
  j["symmetry_order"] = r.symmetry_order;
  j["symmetry_rotations"] = r.symmetry_rotations;
  j["branch"] = branch;
  j["complete"] = r.complete;
  j["search_steps"] = r.search_steps;
  j["assignments"] = r.assignments;
  // A stopped search has seen only the representatives it reached: the class count is unknown.
  j["classes"] = r.complete ? nlohmann::ordered_json(r.class_count) : nlohmann::ordered_json(nullptr);
  j["classes_reached"] = r.class_count;
  j["classes_with_verdict"] = r.verdicts;
  j["foldable_classes"] = r.foldable_classes;
  j["not_foldable_classes"] = r.not_foldable_classes;
  j["undecided_classes"] = r.undecided_classes;
  if (r.blocking_vertex >= 0) j["no_assignment_because"] = {{"vertex", r.blocking_vertex}, {"reason", r.blocking_reason}};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const AssignmentClass& c : r.classes) {
    nlohmann::ordered_json cj = {{"letters", c.letters}, {"orbit_size", c.orbit_size}};
    if (c.verdict_run) {
      cj["verdict"] = to_string(c.verdict);
      cj["is_proof"] = c.is_proof;
      cj["dof"] = c.dof;
      cj["reason"] = c.reason;
    }
    list.push_back(std::move(cj));
  }
  j["listed"] = std::move(list);
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace rigidfold::report
