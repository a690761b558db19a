#include "report/repair_json.hpp"

#include "report/foldability_json.hpp"

namespace rigidfold::report {

nlohmann::ordered_json repair_json(const RepairSummary& s) {
  nlohmann::ordered_json j;
  j["termination"] = to_string(s.termination);
  j["succeeded"] = succeeded(s.termination);
  j["message"] = s.message;
  j["before"] = foldability_json(s.before);
  j["after"] = s.after ? foldability_json(*s.after) : nlohmann::ordered_json(nullptr);
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < s.modes.size(); ++k) modes.push_back({s.interior_vertices[k], to_string(s.modes[k])});
  j["letters"] = s.letters_used ? "keep" : "free";
  j["modes"] = {{"per_vertex", modes}, {"chosen_without_letters", s.modes_chosen_without_letters}};
  j["constraints"] = {{"kawasaki", s.kawasaki_rows},
                      {"loop_gain", s.gain_rows},
                      {"free_coordinates", s.free_coordinates},
                      {"fixed_vertices", s.fixed_vertex_count}};
  j["violation"] = {{"kawasaki_before", s.kawasaki_before},
                    {"kawasaki_after", s.kawasaki_after},
                    {"loop_gain_before", s.gain_before},
                    {"loop_gain_after", s.gain_after}};
  nlohmann::ordered_json moved = nlohmann::ordered_json::array();
  for (std::size_t v = 0; v < s.vertex_move.size(); ++v)
    if (s.vertex_move[v] > 0) moved.push_back({static_cast<int>(v), s.vertex_move[v]});
  const double size = s.pattern_size > 0 ? s.pattern_size : 1.0;
  j["move"] = {{"max", s.max_move},
               {"rms", s.rms_move},
               {"worst_vertex", s.worst_vertex},
               {"pattern_size", s.pattern_size},
               {"max_relative", s.max_move / size},
               {"rms_relative", s.rms_move / size},
               {"per_vertex", moved}};
  nlohmann::ordered_json costliest = nlohmann::ordered_json::array();
  for (const RepairConstraint& c : s.costliest)
    costliest.push_back({{"kind", c.kind}, {"vertices", c.vertices}, {"before", c.before}, {"lambda", c.lambda}});
  j["costliest"] = costliest;
  j["iterations"] = s.iterations;
  j["least_move_converged"] = s.least_move_converged;
  j["stationarity"] = s.stationarity;
  j["seconds"] = s.seconds;
  return j;
}

nlohmann::ordered_json crease_addition_json(const CreaseAdditionSummary& s) {
  nlohmann::ordered_json j;
  j["termination"] = s.already_foldable ? "already foldable" : (s.found.empty() ? "undecided" : "creases added");
  j["succeeded"] = s.already_foldable || !s.found.empty();
  j["message"] = s.message;
  j["before"] = foldability_json(s.before);
  j["candidates"] = s.candidates;
  j["checks"] = s.checks;
  j["searched_up_to"] = s.searched_up_to;
  j["budget_exhausted"] = s.budget_exhausted;
  nlohmann::ordered_json found = nlohmann::ordered_json::array();
  for (const CreaseAddition& a : s.found) {
    nlohmann::ordered_json creases = nlohmann::ordered_json::array();
    for (const AddedCrease& c : a.creases)
      creases.push_back({{"vertices", {c.v0, c.v1}}, {"face", c.face}, {"letter", std::string(1, assignment_letter(c.letter))}});
    found.push_back({{"creases", creases},
                     {"verdict_class", to_string(a.check.verdict)},
                     {"dof", a.check.dof},
                     {"certificate_mismatch", a.check.certificate_mismatch ? nlohmann::ordered_json(*a.check.certificate_mismatch) : nullptr}});
  }
  j["found"] = found;
  j["seconds"] = s.seconds;
  return j;
}

nlohmann::ordered_json tolerance_study_json(const ToleranceStudy& s, const ToleranceStudyOptions& o) {
  nlohmann::ordered_json j;
  j["sigma"] = o.sigma;
  j["distribution"] = to_string(o.distribution);
  j["seed"] = o.seed;
  j["samples"] = s.samples;
  j["on_flat_development"] = s.on_flat_development;
  j["foldable"] = s.foldable;
  j["fraction"] = s.fraction;
  j["interval_95"] = {s.interval_low, s.interval_high};
  j["verdicts"] = s.verdicts;
  j["degree4_model"] = s.degree4_model;
  nlohmann::ordered_json loops = nlohmann::ordered_json::array();
  for (const LoopSensitivity& l : s.loops) loops.push_back({{"vertices", l.vertices}, {"mean_abs_log_gain", l.mean_log_gain}});
  j["loops"] = loops;
  j["repairs"] = s.repairs;
  j["repair_move_over_sigma"] = {{"median", s.repair_move_median}, {"max", s.repair_move_max}};
  j["message"] = s.message;
  j["seconds"] = s.seconds;
  return j;
}

}  // namespace rigidfold::report
