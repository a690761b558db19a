#include "report/sorce_json.hpp"

#include <cmath>
#include <vector>

namespace rigidfold::report {

using Json = nlohmann::ordered_json;
using namespace rigidfold::sorce;

namespace {

Json spans_json(const std::vector<Span>& s) {
  Json a = Json::array();
  for (const Span& x : s) a.push_back({x.begin, x.end});
  return a;
}

}  // namespace

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(); }

Json crease_json(const CreaseJoint& j) {
  const FoldReport& r = j.report;
  Json c;
  c["edge"] = j.edge;
  c["left_face"] = j.left_face;
  c["right_face"] = j.right_face;
  c["folds"] = j.folds;
  if (!j.folds) return c;
  c["s0"] = r.s0;
  c["arc_length"] = {r.arc_length_left, r.arc_length_right};
  c["convexity_left"] = {finite_or_null(r.min_convexity_left), finite_or_null(r.max_convexity_left)};
  c["convexity_right"] = {finite_or_null(r.min_convexity_right), finite_or_null(r.max_convexity_right)};
  c["concave_left"] = spans_json(r.concave_left);
  c["concave_right"] = spans_json(r.concave_right);
  c["cusps"] = r.cusps;
  c["ill_behaved"] = r.ill_behaved;
  c["stationary"] = r.stationary;
  c["pivot_at_start"] = r.pivot_at_start;
  c["pivot_at_end"] = r.pivot_at_end;
  c["protrusion"] = {r.protrusion_left, r.protrusion_right};
  c["rolling_residual"] = r.max_rolling_residual;
  c["contact_residual"] = r.max_contact_residual;
  c["end_separation"] = r.end_separation;
  c["stacks"] = r.stacks;
  c["consistency"] = j.consistency;
  c["pitch"] = j.pitch;
  c["contact_3d"] = j.contact;
  c["rolled_gamma"] = finite_or_null(j.rolled_gamma);
  c["rolled_translation"] = finite_or_null(j.rolled_translation);
  return c;
}

Json checks_json(const PatternChecks& k) {
  Json c;
  c["consistency"] = k.consistency;
  c["pitch"] = k.pitch;
  c["closure_knots"] = k.closure_knots;
  c["closure_samples"] = k.closure_samples;
  c["contact_3d"] = k.contact;
  c["rolling_residual"] = k.rolling;
  c["contact_residual"] = k.contact_planar;
  c["rolled_gamma"] = k.rolled_gamma;
  c["rolled_translation"] = k.rolled_translation;
  c["not_rolled"] = k.not_rolled;
  c["flat_folded_end"] = k.flat_folded_end;
  c["all_stack"] = k.all_stack;
  Json inter = Json::array();
  for (const SlabInterference& s : k.interference)
    for (const auto& [a, b] : s.face_pairs) inter.push_back({{"t", s.t}, {"faces", {a, b}}});
  c["slab_interference"] = inter;
  c["interference_skipped_faces"] = k.skipped_faces;
  return c;
}

Json cam_interference_json(const CamInterference& c) {
  Json out;
  out["checked"] = true;
  out["samples"] = c.times.size();
  out["passed"] = c.collisions.empty();
  out["pairs_tested"] = c.pairs_tested;
  out["rolling_partner_pairs_skipped"] = c.partner_pairs_skipped;
  Json hits = Json::array();
  for (const CamCollision& h : c.collisions)
    hits.push_back({{"t", h.t}, {"faces", {h.face_a, h.face_b}}, {"cam_edges", {h.edge_a, h.edge_b}}});
  out["collisions"] = hits;  // edge -1: that shell is the panel's slab
  if (!c.collisions.empty()) out["first"] = hits[0];
  return out;
}

Json optimization_json(const OffsetDesign& o, const std::vector<int>& faces) {
  Json opt;
  opt["algorithm"] = o.algorithm;
  opt["stop_reason"] = o.stop_reason;
  opt["evaluations"] = o.evaluations;
  opt["feasible"] = o.feasible;
  opt["improved"] = o.improved;
  opt["figure_of_merit"] = finite_or_null(o.fom);
  opt["min_convexity"] = finite_or_null(o.min_convexity);
  opt["faces"] = faces;
  opt["coefficients"] = o.b;
  Json binding = Json::array();
  for (const BindingConstraint& b : o.binding)
    binding.push_back({{"name", b.name}, {"index", b.index}, {"value", b.value}, {"bound", b.bound}});
  opt["binding"] = binding;
  return opt;
}

}  // namespace rigidfold::report
