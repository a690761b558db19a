// rigidfold string forward SPEC.json --theta DEG [--out FOLDED.fold] [--svg CP.svg] [--json]
// rigidfold string design TARGET.json --out STRING.fold [--svg STRING.svg] [--json]
//
// Origami strings: a strip of asymmetric Miura vertices along a spine (design/strings,
// seed 000). Angles in DEGREES in every file and flag (keys end in _deg); lengths in the
// user's units. Examples: data/strings/*.json.
//
// Driven crease: the lead-in spinal crease s_0 (edge 0 of the pattern, crease c of vertex
// 0), folded to 2 theta (theta = --theta, valley > 0). Transmitted mode: the fold is passed
// along the shared spinal creases, theta_i = (-1)^i theta. Independent mode: theta_i per
// vertex (not a rigid motion of the connected sheet unless they alternate; the mismatch
// is reported).
//
// SPEC.json (forward):
//   {
//     "vertices": [ {"alpha1_deg": A1, "alpha2_deg": A2, "theta_deg": T (independent mode only)}, ... ],
//     "segment_lengths": [L_0, ..., L_N]        (N + 1 values > 0: lead-in, between vertices, lead-out)
//       or "segment_length": L                  (all equal),
//     "width": W                                (optional; default 0.9 x the largest valid width),
//     "mode": "transmitted" | "independent"     (optional, default transmitted)
//   }
//   alpha in (0, 90). In independent mode a vertex without theta_deg takes --theta.
//
// TARGET.json (design), "kind" selects the problem:
//   common, optional: "width", "bounds": {"alpha_min_deg": 10, "alpha_max_deg": 80,
//                     "theta_margin_deg": 2, "min_segment": 0.001}
//   "kind": "deflections"   per-vertex closed-form inverse at one fold state
//       "theta_deg": T0 (drive, nonzero), "mode": "transmitted" | "independent",
//       "vertices": [ {"phi_deg": P, "psi_deg": Q, "theta_deg": T (independent, optional)}, ... ],
//       "segment_lengths" | "segment_length" as in SPEC
//   "kind": "trajectories"  Ceres least squares over a range of theta
//       "theta_deg": [T_1, ..., T_M] (drive samples, nonzero), "mode" as above,
//       "vertices": [ {"phi_deg": [M values], "psi_deg": [M values]}, ... ],
//       "segment_lengths" | "segment_length"; the folded output is at the sample of largest |theta|
//   "kind": "curve"         a 3D spine through N + 2 points (S, V_0..V_{N-1}, E)
//       "points": [[x, y, z], ...]                                    or
//       "helix": {"radius": R, "rise": H (per point), "step_deg": W (turn per point), "count": N + 2} or
//       "spiral": {"radius": R0, "growth": G (radius added per point), "rise": H, "step_deg": W, "count": N + 2},
//       "theta_deg": T0 (optional; searched when absent), "roll_deg": B (optional),
//       "method": "closed_form" | "nlopt" (default: closed form, NLopt when it is not exact),
//       "algorithm": "LD_SLSQP" | "LD_MMA" | "LD_CCSAQ" | "LN_COBYLA" (optional), "global": true|false
//
// Bad input -> "FILE: /json/pointer: what" on stderr, exit 2, no output file written.
// The design is verified by the general solver: the output pattern with s_0 fixed at the
// design theta, Newton projection from the closed-form angles, face placement, and the
// folded spine compared with the closed form (and, for curves, with the target points).
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/terminal_progress.hpp"
#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "design/strings/miura_string.hpp"
#include "design/strings/string_fit_ceres.hpp"
#include "design/strings/string_fit_nlopt.hpp"
#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"
#include "design/strings/string_verify.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {
namespace {

using nlohmann::json;
using namespace rigidfold::design;

// Reads values from a JSON document and names the file and JSON pointer on every error.
class Reader {
 public:
  Reader(std::string file) : file_(std::move(file)) {
    doc_ = parse_json_input(read_input_file(file_), file_);
    if (!doc_.is_object()) fail("", "must be a JSON object");
  }
  const json& doc() const { return doc_; }
  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    throw InputError(file_ + ": " + (ptr.empty() ? "/" : ptr), what);
  }
  const json& at(const json& obj, const std::string& ptr, const std::string& key) const {
    if (!obj.is_object()) fail(ptr, "must be an object");
    if (!obj.contains(key)) fail(ptr + "/" + key, "missing");
    return obj.at(key);
  }
  double number(const json& v, const std::string& ptr) const {
    if (!v.is_number()) fail(ptr, "must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(ptr, "must be finite");
    return x;
  }
  double number(const json& obj, const std::string& ptr, const std::string& key) const {
    return number(at(obj, ptr, key), ptr + "/" + key);
  }
  double number_in(const json& obj, const std::string& ptr, const std::string& key, double lo, double hi,
                   const char* range) const {
    const double x = number(obj, ptr, key);
    if (!(x > lo && x < hi)) fail(ptr + "/" + key, std::string("must be in ") + range);
    return x;
  }
  std::vector<double> numbers(const json& v, const std::string& ptr) const {
    if (!v.is_array()) fail(ptr, "must be an array of numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], ptr + "/" + std::to_string(i)));
    return out;
  }
  const json& array(const json& obj, const std::string& ptr, const std::string& key) const {
    const json& v = at(obj, ptr, key);
    if (!v.is_array() || v.empty()) fail(ptr + "/" + key, "must be a non-empty array");
    return v;
  }
  std::string string_of(const json& obj, const std::string& key, const std::string& fallback,
                        const std::vector<std::string>& allowed) const {
    if (!obj.contains(key)) return fallback;
    const json& v = obj.at(key);
    if (!v.is_string()) fail("/" + key, "must be a string");
    const std::string s = v.get<std::string>();
    for (const auto& a : allowed)
      if (a == s) return s;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    fail("/" + key, "must be one of " + list);
  }
  // Refuses an array longer than a documented limit (input_limits.hpp) before any work on it.
  void check_size(const json& v, const std::string& ptr, std::int64_t limit, const std::string& what) const {
    if (static_cast<std::int64_t>(v.size()) > limit)
      fail(ptr, "has " + std::to_string(v.size()) + " " + what + "; the limit is " + std::to_string(limit));
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  json doc_;
};

std::vector<double> read_lengths(const Reader& r, int n) {
  const json& d = r.doc();
  std::vector<double> L;
  if (d.contains("segment_lengths")) {
    L = r.numbers(d["segment_lengths"], "/segment_lengths");
    if (static_cast<int>(L.size()) != n + 1)
      r.fail("/segment_lengths", "needs N + 1 = " + std::to_string(n + 1) + " values (lead-in, between vertices, lead-out)");
    for (std::size_t k = 0; k < L.size(); ++k)
      if (!(L[k] > 0)) r.fail("/segment_lengths/" + std::to_string(k), "must be > 0");
  } else {
    const double l = r.number(d, "", "segment_length");
    if (!(l > 0)) r.fail("/segment_length", "must be > 0");
    L.assign(n + 1, l);
  }
  return L;
}

std::optional<double> read_width(const Reader& r) {
  if (!r.doc().contains("width")) return std::nullopt;
  const double w = r.number(r.doc(), "", "width");
  if (!(w > 0)) r.fail("/width", "must be > 0");
  return w;
}

// Sets s.width from the file (checked against the crossing limit) or 0.9 x the limit.
void apply_width(const Reader& r, MiuraString& s, std::optional<double> width) {
  const double wmax = max_string_width(s);
  if (width) {
    if (!(*width < wmax))
      r.fail("/width", "too wide for these angles: peripheral creases would cross or leave the strip (must be < " +
                           std::to_string(wmax) + ")");
    s.width = *width;
  } else {
    s.width = std::isfinite(wmax) ? 0.9 * wmax : 1.0;
  }
}

StringBounds read_bounds(const Reader& r) {
  StringBounds b;
  if (!r.doc().contains("bounds")) return b;
  const json& o = r.doc()["bounds"];
  if (!o.is_object()) r.fail("/bounds", "must be an object");
  if (o.contains("alpha_min_deg")) b.alpha_min = to_radians(r.number_in(o, "/bounds", "alpha_min_deg", 0, 90, "(0, 90)"));
  if (o.contains("alpha_max_deg")) b.alpha_max = to_radians(r.number_in(o, "/bounds", "alpha_max_deg", 0, 90, "(0, 90)"));
  if (!(b.alpha_min < b.alpha_max)) r.fail("/bounds", "alpha_min_deg must be below alpha_max_deg");
  if (o.contains("theta_margin_deg")) b.theta_margin = to_radians(r.number_in(o, "/bounds", "theta_margin_deg", -1e-300, 45, "[0, 45)"));
  if (o.contains("min_segment")) {
    b.min_segment = r.number(o, "/bounds", "min_segment");
    if (!(b.min_segment > 0)) r.fail("/bounds/min_segment", "must be > 0");
  }
  return b;
}

json vec3(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json string_state_json(const MiuraString& s, const StringState& st) {
  json j;
  j["mode"] = st.mode == ThetaMode::Transmitted ? "transmitted" : "independent";
  j["model"] = "closed form per vertex (seed 000, kernel/vertex/miura_vertex)";
  j["driven_crease"] = {{"edge", 0},
                        {"name", "s_0: lead-in spinal crease = crease c (spinal_in) of vertex 0"},
                        {"fold_angle_deg", 2 * to_degrees(st.theta[0])}};
  j["transmission"] = st.mode == ThetaMode::Transmitted
                          ? "shared spinal creases: theta_i = (-1)^i theta_0 (rho_spinal_out = -2 theta exactly)"
                          : "independent per-vertex theta: only alternating equal magnitudes are a rigid motion of the sheet";
  j["shared_crease_mismatch_deg"] = to_degrees(st.shared_crease_mismatch);
  j["min_theta_margin_deg"] = to_degrees(st.min_theta_margin);
  j["limiting_vertex"] = st.limiting_vertex;
  json verts = json::array();
  for (int i = 0; i < s.size(); ++i) {
    const auto& v = st.vertices[i];
    verts.push_back({{"alpha1_deg", to_degrees(s.alpha1[i])},
                     {"alpha2_deg", to_degrees(s.alpha2[i])},
                     {"theta_deg", to_degrees(st.theta[i])},
                     {"theta_limit_deg", to_degrees(v.theta_limit)},
                     {"phi_deg", to_degrees(v.phi)},
                     {"psi_deg", to_degrees(v.psi)},
                     {"fold_angles_deg",
                      {{"spinal_in", to_degrees(v.rho_c)}, {"spinal_out", to_degrees(v.rho_a)}, {"peripheral_1", to_degrees(v.rho_b)},
                       {"peripheral_2", to_degrees(v.rho_d)}}}});
  }
  j["vertices"] = verts;
  json spine = json::array(), frames = json::array();
  for (const auto& p : st.spine) spine.push_back(vec3(p));
  for (const auto& F : st.frames) frames.push_back(json::array({vec3(F.col(0)), vec3(F.col(1)), vec3(F.col(2))}));
  j["spine"] = spine;
  j["frames_columns"] = frames;
  return j;
}

// The output FOLD: crease pattern at the design state plus the folded frame from `angles`.
std::string folded_fold_text(const CreasePattern& pattern, const FoldedGeometry& folded, const Eigen::VectorXd& angles,
                             const std::string& title) {
  return write_fold_string(with_folded_frame(pattern, folded, angles, title));
}

std::vector<Eigen::Vector3d> read_curve(const Reader& r) {
  const json& d = r.doc();
  std::vector<Eigen::Vector3d> pts;
  if (d.contains("points")) {
    const json& a = r.array(d, "", "points");
    r.check_size(a, "/points", kMaxCurveDesignVertices + 2, "points (N + 2 for N vertices)");
    for (std::size_t k = 0; k < a.size(); ++k) {
      const std::string ptr = "/points/" + std::to_string(k);
      const auto v = r.numbers(a[k], ptr);
      if (v.size() != 3) r.fail(ptr, "must be [x, y, z]");
      pts.emplace_back(v[0], v[1], v[2]);
    }
  } else if (d.contains("helix") || d.contains("spiral")) {
    const bool helix = d.contains("helix");
    const std::string key = helix ? "helix" : "spiral";
    const json& o = d[key];
    const std::string ptr = "/" + key;
    const double radius = r.number(o, ptr, "radius");
    if (!(radius > 0)) r.fail(ptr + "/radius", "must be > 0");
    const double growth = helix ? 0.0 : r.number(o, ptr, "growth");
    const double rise = r.number(o, ptr, "rise");
    const double step = to_radians(r.number_in(o, ptr, "step_deg", -360, 360, "(-360, 360)"));
    const double count = r.number(o, ptr, "count");
    if (count != std::floor(count) || count < 3 || count > kMaxCurveDesignVertices + 2)
      r.fail(ptr + "/count", "must be an integer in [3, " + std::to_string(kMaxCurveDesignVertices + 2) +
                                 "] (N + 2 points for N vertices; the limit is " + std::to_string(kMaxCurveDesignVertices) +
                                 " vertices)");
    for (int k = 0; k < static_cast<int>(count); ++k) {
      const double rad = radius + growth * k;
      pts.emplace_back(rad * std::cos(k * step), rad * std::sin(k * step), rise * k);
    }
  } else {
    r.fail("/points", "missing (give \"points\", \"helix\" or \"spiral\")");
  }
  if (pts.size() < 3) r.fail("/points", "needs at least 3 points (N + 2 for N vertices)");
  return pts;
}

void print_or_json(const json& j, bool as_json, const std::string& text) {
  if (as_json) std::cout << document_text(j) << "\n";
  else std::cout << text;
}

// ---- string forward ----------------------------------------------------------------

struct ForwardArgs {
  std::string spec, out, svg;
  double theta = 0;
  bool theta_given = false, json = false;
};

// The closed range of a spec's alpha1_deg/alpha2_deg, [1e-300, 90 - 1e-12] (as `vertex miura`),
// as the open bounds number_in takes: the next doubles outside it.
const double kMinAlphaBelow = std::nextafter(1e-300, 0.0);
const double kMaxAlphaAbove = std::nextafter(90.0 - 1e-12, 90.0);

// Forward step 1: the spec's vertices. Fills s.alpha1, s.alpha2 and, in independent mode,
// theta (one drive angle per vertex); all radians.
void read_forward_vertices(const Reader& r, const ForwardArgs& fa, const std::string& mode, MiuraString& s,
                           std::vector<double>& theta) {
  const json& verts = r.array(r.doc(), "", "vertices");
  r.check_size(verts, "/vertices", kMaxStringVertices, "vertices");
  if (fa.theta_given && !(std::isfinite(fa.theta) && std::fabs(fa.theta) < 90)) throw InputError("--theta", "must be in (-90, 90) degrees");
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const std::string ptr = "/vertices/" + std::to_string(i);
    s.alpha1.push_back(to_radians(r.number_in(verts[i], ptr, "alpha1_deg", kMinAlphaBelow, kMaxAlphaAbove, "[1e-300, 90 - 1e-12]")));
    s.alpha2.push_back(to_radians(r.number_in(verts[i], ptr, "alpha2_deg", kMinAlphaBelow, kMaxAlphaAbove, "[1e-300, 90 - 1e-12]")));
    if (mode == "independent") {
      if (verts[i].contains("theta_deg")) theta.push_back(to_radians(r.number_in(verts[i], ptr, "theta_deg", -90, 90, "(-90, 90)")));
      else if (fa.theta_given) theta.push_back(to_radians(fa.theta));
      else r.fail(ptr + "/theta_deg", "missing (independent mode needs theta_deg per vertex or --theta)");
    }
  }
  if (mode == "transmitted" && !fa.theta_given) throw InputError("--theta", "required in transmitted mode");
}

// Forward step 2: the closed-form fold; a string that cannot reach the drive names the flag
// (transmitted) or the spec (independent).
StringState forward_state(const MiuraString& s, const std::vector<double>& theta, const ForwardArgs& fa,
                          const std::string& mode) {
  try {
    return mode == "transmitted" ? string_forward(s, to_radians(fa.theta)) : string_forward_independent(s, theta);
  } catch (const std::invalid_argument& e) {
    throw InputError(mode == "transmitted" ? "--theta" : fa.spec, e.what());
  }
}

// Forward step 3: the text report.
std::string forward_text(const MiuraString& s, const StringState& st, const FoldedGeometry& folded, const json& j,
                         const std::string& mode, const std::string& out) {
  std::ostringstream t;
  t.precision(10);
  t << "origami string, " << s.size() << " Miura vertices, mode " << mode << "\n"
    << "  driven crease: edge 0 (s_0, lead-in spinal crease = crease c of vertex 0), fold angle " << 2 * to_degrees(st.theta[0])
    << " deg\n"
    << "  transmission: " << j["transmission"].get<std::string>() << "\n"
    << "  spine end: (" << st.spine.back().x() << ", " << st.spine.back().y() << ", " << st.spine.back().z() << ")\n"
    << "  min theta margin " << to_degrees(st.min_theta_margin) << " deg at vertex " << st.limiting_vertex
    << "; shared crease mismatch " << to_degrees(st.shared_crease_mismatch) << " deg; face placement mismatch "
    << folded.max_mismatch << "\n";
  if (!out.empty()) t << "  wrote " << out << "\n";
  return t.str();
}

void run_forward(const ForwardArgs& fa) {
  // Every path checked against the others before any work; the outputs committed together.
  OutputSet outputs;
  outputs.add_input("SPEC", fa.spec);
  if (!fa.out.empty()) outputs.add_output("--out", fa.out);
  if (!fa.svg.empty()) outputs.add_output("--svg", fa.svg);
  const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
  Reader r(fa.spec);
  const std::string mode = r.string_of(r.doc(), "mode", "transmitted", {"transmitted", "independent"});
  MiuraString s;
  std::vector<double> theta;
  read_forward_vertices(r, fa, mode, s, theta);
  s.lengths = read_lengths(r, s.size());
  apply_width(r, s, read_width(r));
  const StringState st = forward_state(s, theta, fa, mode);
  const CreasePattern pattern = build_string_pattern(s, st.edge_fold_angles);
  const FoldedGeometry folded = fold_string_pattern(pattern, st);
  json j = string_state_json(s, st);
  j["spec"] = fa.spec;
  j["width"] = s.width;
  j["placement_mismatch"] = folded.max_mismatch;
  if (!fa.out.empty()) {
    outputs.stage(fa.out, folded_fold_text(pattern, folded, st.edge_fold_angles, "string folded at theta = " +
                                                                                     std::to_string(fa.theta) + " deg"));
    j["out"] = fa.out;
  }
  if (!fa.svg.empty()) outputs.stage(fa.svg, string_pattern_svg(pattern));
  outputs.commit();
  print_or_json(j, fa.json, forward_text(s, st, folded, j, mode, fa.out));
}

void add_forward_subcommand(CLI::App& cmd) {
  auto fa = std::make_shared<ForwardArgs>();
  auto* fwd = cmd.add_subcommand("forward", "Fold a string spec at drive angle theta (closed form), optionally write the folded FOLD");
  fwd->add_option("spec", fa->spec, "SPEC.json (see the header of app/command_string.cpp)")->required();
  auto* theta_opt = fwd->add_option("--theta", fa->theta, "drive: half fold angle of the lead-in spinal crease, degrees (valley > 0)");
  fwd->add_option("--out", fa->out, "folded FOLD output (crease pattern + foldedForm frame)");
  fwd->add_option("--svg", fa->svg, "crease pattern SVG for cutting");
  fwd->add_flag("--json", fa->json, "print JSON");
  fwd->callback([fa, theta_opt] {
    fa->theta_given = theta_opt->count() > 0;
    run_forward(*fa);
  });
}

// ---- string design -----------------------------------------------------------------

struct DesignArgs {
  std::string target, out, svg;
  bool json = false;
};

// What a design method produced: the string (segment lengths set, width not yet), its drive
// angle theta0 (radians) and, for curve targets, the target points and the pose that places
// the designed string on them.
struct DesignedString {
  MiuraString s;
  double theta0 = 0;
  bool have_pose = false;
  StringPose pose;
  std::vector<Eigen::Vector3d> curve;
};

// "kind": "deflections": per-vertex closed-form inverse at one fold state.
DesignedString design_deflections(const Reader& r, const std::string& mode, const json& verts, const StringBounds& bounds,
                                  json& j) {
  const int n = static_cast<int>(verts.size());
  DesignedString out;
  out.theta0 = to_radians(r.number_in(r.doc(), "", "theta_deg", -90, 90, "(-90, 90)"));
  if (out.theta0 == 0) r.fail("/theta_deg", "must be nonzero (the flat state has no deflection)");
  std::vector<double> phi, psi, theta = transmitted_thetas(out.theta0, n);
  for (int i = 0; i < n; ++i) {
    const std::string ptr = "/vertices/" + std::to_string(i);
    phi.push_back(to_radians(r.number_in(verts[i], ptr, "phi_deg", -180, 180, "(-180, 180)")));
    psi.push_back(to_radians(r.number_in(verts[i], ptr, "psi_deg", -90, 90, "(-90, 90)")));
    if (mode == "independent")
      theta[i] = verts[i].contains("theta_deg") ? to_radians(r.number_in(verts[i], ptr, "theta_deg", -90, 90, "(-90, 90)")) : out.theta0;
  }
  const DeflectionDesign d = design_from_deflections(phi, psi, theta, bounds);
  j["method"] = "closed-form inverse per vertex (unique alpha1, alpha2 for the given theta_i)";
  json vj = json::array();
  for (int i = 0; i < n; ++i) {
    const auto& v = d.vertices[i];
    vj.push_back({{"feasible", v.feasible}, {"reason", v.reason}, {"theta_deg", to_degrees(v.theta)}, {"alpha1_deg", to_degrees(v.alpha1)},
                  {"alpha2_deg", to_degrees(v.alpha2)}, {"phi_residual_deg", to_degrees(v.phi_error)}, {"psi_residual_deg", to_degrees(v.psi_error)}});
  }
  j["vertices"] = vj;
  if (!d.feasible) {
    for (int i = 0; i < n; ++i)
      if (!d.vertices[i].feasible)
        r.fail("/vertices/" + std::to_string(i), "unreachable at theta_i = " + std::to_string(to_degrees(theta[i])) + " deg: " + d.vertices[i].reason);
  }
  for (const auto& v : d.vertices) {
    out.s.alpha1.push_back(v.alpha1);
    out.s.alpha2.push_back(v.alpha2);
  }
  if (mode == "independent") {
    // A sheet is built only for what one actuation can fold.
    for (int i = 0; i + 1 < n; ++i)
      if (std::fabs(theta[i + 1] + theta[i]) > 1e-12)
        r.fail("/vertices/" + std::to_string(i + 1) + "/theta_deg",
               "independent thetas that do not alternate (theta_{i+1} = -theta_i) are not a rigid motion of one strip; "
               "the FOLD output would not fold");
  }
  return out;
}

// "kind": "trajectories": the drive samples and per-vertex phi/psi samples, in radians.
TrajectoryTarget read_trajectory_target(const Reader& r, const std::string& mode, const json& verts) {
  const int n = static_cast<int>(verts.size());
  TrajectoryTarget tt;
  tt.mode = mode == "transmitted" ? ThetaMode::Transmitted : ThetaMode::Independent;
  const json& samples = r.at(r.doc(), "", "theta_deg");
  if (samples.is_array()) {
    r.check_size(samples, "/theta_deg", kMaxTrajectorySamples, "samples");
    if (static_cast<std::int64_t>(samples.size()) * n > kMaxTrajectoryValues)
      r.fail("/theta_deg", std::to_string(samples.size()) + " samples x " + std::to_string(n) +
                               " vertices is over the limit of " + std::to_string(kMaxTrajectoryValues) + " fitted values");
  }
  tt.theta = r.numbers(samples, "/theta_deg");
  if (tt.theta.empty()) r.fail("/theta_deg", "needs at least one sample");
  for (std::size_t k = 0; k < tt.theta.size(); ++k) {
    if (!(std::fabs(tt.theta[k]) < 90) || tt.theta[k] == 0) r.fail("/theta_deg/" + std::to_string(k), "must be in (-90, 90), nonzero");
    tt.theta[k] = to_radians(tt.theta[k]);
  }
  for (int i = 0; i < n; ++i) {
    const std::string ptr = "/vertices/" + std::to_string(i);
    auto ph = r.numbers(r.at(verts[i], ptr, "phi_deg"), ptr + "/phi_deg");
    auto ps = r.numbers(r.at(verts[i], ptr, "psi_deg"), ptr + "/psi_deg");
    if (ph.size() != tt.theta.size()) r.fail(ptr + "/phi_deg", "needs one value per theta sample");
    if (ps.size() != tt.theta.size()) r.fail(ptr + "/psi_deg", "needs one value per theta sample");
    for (auto& v : ph) v = to_radians(v);
    for (std::size_t k = 0; k < ps.size(); ++k) {
      if (!(std::fabs(ps[k]) < 90)) r.fail(ptr + "/psi_deg/" + std::to_string(k), "must be in (-90, 90)");
      ps[k] = to_radians(ps[k]);
    }
    tt.phi.push_back(ph);
    tt.psi.push_back(ps);
  }
  return tt;
}

// "kind": "trajectories": Ceres least squares over the theta samples.
DesignedString design_trajectories(const Reader& r, const std::string& mode, const json& verts, const StringBounds& bounds,
                                   json& j) {
  const int n = static_cast<int>(verts.size());
  const TrajectoryTarget tt = read_trajectory_target(r, mode, verts);
  const TrajectoryFitResult fit = fit_string_trajectories(tt, bounds);
  j["method"] = "Ceres least squares over the theta samples (automatic derivatives, alpha bounds)";
  j["ceres"] = fit.report;
  j["converged"] = fit.converged;
  j["max_residual_deg"] = to_degrees(fit.max_residual);
  j["binding_bounds"] = fit.binding;
  json vj = json::array();
  for (int i = 0; i < n; ++i)
    vj.push_back({{"alpha1_deg", to_degrees(fit.alpha1[i])}, {"alpha2_deg", to_degrees(fit.alpha2[i])}, {"rms_residual_deg", to_degrees(fit.vertex_rms[i])}});
  j["vertices"] = vj;
  DesignedString out;
  out.s.alpha1 = fit.alpha1;
  out.s.alpha2 = fit.alpha2;
  out.theta0 = tt.theta[0];
  for (double th : tt.theta)
    if (std::fabs(th) > std::fabs(out.theta0)) out.theta0 = th;
  if (mode == "independent" && n > 1)
    j["note"] = "independent mode: the folded FOLD frame shows the transmitted (one-DOF) state at the largest sample";
  return out;
}

// "kind": "deflections" | "trajectories": the shared "mode" and "vertices", then the method,
// then the segment lengths.
DesignedString design_from_vertex_targets(const Reader& r, const std::string& kind, const StringBounds& bounds, json& j) {
  const std::string mode = r.string_of(r.doc(), "mode", "transmitted", {"transmitted", "independent"});
  const json& verts = r.array(r.doc(), "", "vertices");
  r.check_size(verts, "/vertices", kMaxStringVertices, "vertices");
  const int n = static_cast<int>(verts.size());
  j["mode"] = mode;
  DesignedString out =
      kind == "deflections" ? design_deflections(r, mode, verts, bounds, j) : design_trajectories(r, mode, verts, bounds, j);
  out.s.lengths = read_lengths(r, n);
  return out;
}

// "kind": "curve", NLopt: "algorithm" and "global" from the file, seeded by the closed form.
NloptFitResult fit_curve_with_nlopt(const Reader& r, const std::vector<Eigen::Vector3d>& curve, const CurveDesignOptions& co) {
  const int vertices = static_cast<int>(curve.size()) - 2;
  if (vertices > kMaxNloptCurveVertices)
    r.fail(r.doc().contains("points") ? "/points" : (r.doc().contains("helix") ? "/helix/count" : "/spiral/count"),
           std::to_string(vertices) + " vertices: the NLopt fit (\"method\": \"nlopt\", or the default where the closed form "
               "is not exact) is limited to " + std::to_string(kMaxNloptCurveVertices) + " vertices; the closed form takes up to " +
               std::to_string(kMaxCurveDesignVertices));
  NloptFitOptions no;
  no.seed = co;
  if (r.doc().contains("algorithm")) {
    if (!r.doc()["algorithm"].is_string()) r.fail("/algorithm", "must be a string");
    no.algorithm = r.doc()["algorithm"].get<std::string>();
  }
  if (r.doc().contains("global")) {
    if (!r.doc()["global"].is_boolean()) r.fail("/global", "must be true or false");
    no.global = r.doc()["global"].get<bool>();
  }
  try {
    return fit_string_to_curve(curve, no);
  } catch (const std::invalid_argument& e) {
    r.fail("/algorithm", e.what());
  }
}

// "kind": "curve": closed-form sequential inverse, or NLopt where it is not exact (or asked for).
DesignedString design_curve(const Reader& r, const StringBounds& bounds, json& j) {
  DesignedString out;
  out.curve = read_curve(r);
  const std::vector<Eigen::Vector3d>& curve = out.curve;
  CurveDesignOptions co;
  co.bounds = bounds;
  TerminalProgress progress("string design");  // erased when the design is done, before any output
  co.progress = progress.sink();
  if (r.doc().contains("theta_deg")) {
    co.theta0 = to_radians(r.number_in(r.doc(), "", "theta_deg", -90, 90, "(-90, 90)"));
    if (*co.theta0 == 0) r.fail("/theta_deg", "must be nonzero");
  }
  if (r.doc().contains("roll_deg")) co.roll = to_radians(r.number(r.doc(), "", "roll_deg"));
  const std::string method = r.string_of(r.doc(), "method", "auto", {"auto", "closed_form", "nlopt"});
  for (std::size_t k = 0; k + 1 < curve.size(); ++k)
    if (!((curve[k + 1] - curve[k]).norm() >= bounds.min_segment))
      r.fail("/points/" + std::to_string(k + 1), "segment shorter than bounds.min_segment");
  const CurveDesign cd = design_from_curve(curve, co);
  j["closed_form"] = {{"exact", cd.feasible}, {"first_unreachable_vertex", cd.first_infeasible},
                      {"theta0_deg", to_degrees(cd.theta0)}, {"roll_deg", to_degrees(cd.roll)}, {"alpha_margin_deg", to_degrees(cd.alpha_margin)}};
  if (method == "closed_form" || (method == "auto" && cd.feasible)) {
    if (!cd.feasible)
      r.fail("/points/" + std::to_string(cd.first_infeasible + 2),
             "not reachable in closed form (vertex " + std::to_string(cd.first_infeasible) + ": " +
                 cd.vertices[cd.first_infeasible].reason + "); use \"method\": \"nlopt\" for the best fit");
    j["method"] = "closed-form sequential inverse (theta0 and roll chosen by grid search for the largest bound margin)";
    out.s = cd.string;
    out.theta0 = cd.theta0;
    out.pose = cd.pose;
  } else {
    const NloptFitResult fit = fit_curve_with_nlopt(r, curve, co);
    j["method"] = "NLopt " + fit.algorithm + " from the closed-form seed (bounds: alpha, theta limit with margin, min segment)";
    j["nlopt"] = {{"status", fit.status}, {"evaluations", fit.evaluations}};
    j["reachable"] = fit.reachable;
    j["max_error"] = fit.max_error;
    j["rms_error"] = fit.rms_error;
    j["max_error_per_segment"] = fit.max_error / fit.mean_segment;
    j["binding_bounds"] = fit.binding;
    j["point_errors"] = fit.point_errors;
    out.s = fit.string;
    out.theta0 = fit.theta0;
    out.pose = fit.pose;
  }
  out.have_pose = true;
  return out;
}

// The general solver's check of a design, as JSON; for curve targets also the distance of
// the folded spine, moved rigidly onto the design pose (no fitting), to the target points.
json verification_json(const StringVerification& v, const DesignedString& d) {
  json ver = {{"solver", "general loop closure, Newton projection from the closed form + 1e-6 rad, s_0 fixed"},
              {"converged", v.converged},
              {"iterations", v.iterations},
              {"closure_residual_rad", v.closure_residual},
              {"max_angle_difference_rad", v.max_angle_error},
              {"max_spine_difference", v.max_spine_error}};
  if (d.have_pose) {
    // Folded pattern (pattern pose) -> target frame: the rigid map taking the pattern's
    // C_0 to the design's C_0; no fitting.
    const StringPose pp = pattern_pose(d.theta0);
    const Eigen::Matrix3d Rm = d.pose.frame * pp.frame.transpose();
    const std::vector<Eigen::Vector3d>& curve = d.curve;
    double worst = 0;
    for (int k = 0; k < d.s.size() + 2; ++k) {
      const Eigen::Vector3d q = Rm * (v.folded.vertices[k] - pp.start) + d.pose.start;
      worst = std::max(worst, (q - curve[k]).norm());
    }
    double total = 0;  // mean TARGET segment, the same scale as the NLopt report
    for (std::size_t k = 0; k + 1 < curve.size(); ++k) total += (curve[k + 1] - curve[k]).norm();
    ver["max_target_error"] = worst;
    ver["max_target_error_per_segment"] = worst / (total / (curve.size() - 1));
  }
  return ver;
}

// The text report of a design.
std::string design_text(const std::string& kind, const DesignedString& d, const StringVerification& v, const json& j,
                        const std::string& out) {
  const json& ver = j["verification"];
  std::ostringstream t;
  t.precision(10);
  t << "designed origami string (" << kind << "), " << d.s.size() << " vertices, theta0 = " << to_degrees(d.theta0) << " deg\n"
    << "  method: " << j["method"].get<std::string>() << "\n"
    << "  verification (general solver): converged " << (v.converged ? "yes" : "no") << ", residual " << v.closure_residual
    << " rad, max angle difference " << v.max_angle_error << " rad, max spine difference " << v.max_spine_error << "\n";
  if (ver.contains("max_target_error")) t << "  max distance to the target points: " << ver["max_target_error"].get<double>() << "\n";
  if (j.contains("binding_bounds") && !j["binding_bounds"].empty()) {
    t << "  binding bounds:";
    for (const auto& b : j["binding_bounds"]) t << " " << b.get<std::string>() << ";";
    t << "\n";
  }
  if (j.contains("reachable") && !j["reachable"].get<bool>()) t << "  target NOT reachable: best fit written\n";
  t << "  wrote " << out << "\n";
  return t.str();
}

void run_design(const DesignArgs& da) {
  // Every path checked against the others before any work; the outputs committed together.
  OutputSet outputs;
  outputs.add_input("TARGET", da.target);
  outputs.add_output("--out", da.out);
  if (!da.svg.empty()) outputs.add_output("--svg", da.svg);
  const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
  // Step 1: the target's kind and the settings every kind shares.
  Reader r(da.target);
  const std::string kind = r.string_of(r.doc(), "kind", "", {"deflections", "trajectories", "curve"});
  if (kind.empty()) r.fail("/kind", "missing (deflections, trajectories or curve)");
  const StringBounds bounds = read_bounds(r);
  const std::optional<double> width = read_width(r);
  json j;
  j["target"] = da.target;
  j["kind"] = kind;
  // Step 2: the design method of the kind.
  DesignedString d = kind == "curve" ? design_curve(r, bounds, j) : design_from_vertex_targets(r, kind, bounds, j);
  MiuraString& s = d.s;
  apply_width(r, s, width);
  // Step 3: fold the designed string in closed form and check it with the general solver.
  StringState st;
  try {
    st = string_forward(s, d.theta0);  // the pattern pose (face 0 fixed)
  } catch (const std::invalid_argument& e) {
    r.fail("", std::string("designed string cannot fold at the design theta: ") + e.what());
  }
  const CreasePattern pattern = build_string_pattern(s, st.edge_fold_angles);
  // Newton starts 1e-6 rad away from the closed form, so the solver has to converge on its own.
  const StringVerification v = verify_string_with_general_solver(s, pattern, st, 1e-6);
  // Step 4: the report, then the outputs (only after everything succeeded).
  j["theta0_deg"] = to_degrees(d.theta0);
  j["width"] = s.width;
  j["driven_crease"] = {{"edge", 0}, {"fold_angle_deg", 2 * to_degrees(d.theta0)}, {"name", "s_0: lead-in spinal crease"}};
  j["string"] = {{"alpha1_deg", json::array()}, {"alpha2_deg", json::array()}, {"segment_lengths", s.lengths}};
  for (int i = 0; i < s.size(); ++i) {
    j["string"]["alpha1_deg"].push_back(to_degrees(s.alpha1[i]));
    j["string"]["alpha2_deg"].push_back(to_degrees(s.alpha2[i]));
  }
  j["verification"] = verification_json(v, d);
  outputs.stage(da.out, folded_fold_text(pattern, v.folded, v.solver_angles, "designed origami string"));
  if (!da.svg.empty()) outputs.stage(da.svg, string_pattern_svg(pattern));
  outputs.commit();
  j["out"] = da.out;
  print_or_json(j, da.json, design_text(kind, d, v, j, da.out));
}

void add_design_subcommand(CLI::App& cmd) {
  auto da = std::make_shared<DesignArgs>();
  auto* des = cmd.add_subcommand("design", "Design a string for a target (deflections, trajectories or a 3D curve)");
  des->add_option("target", da->target, "TARGET.json (see the header of app/command_string.cpp)")->required();
  des->add_option("--out", da->out, "designed string: crease pattern + folded frame (FOLD)")->required();
  des->add_option("--svg", da->svg, "crease pattern SVG for cutting");
  des->add_flag("--json", da->json, "print JSON");
  des->callback([da] { run_design(*da); });
}

}  // namespace

void add_string_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("string", "Origami strings of asymmetric Miura vertices: forward kinematics and inverse design");
  cmd->require_subcommand(1);
  add_forward_subcommand(*cmd);
  add_design_subcommand(*cmd);
}

}  // namespace rigidfold::cli
