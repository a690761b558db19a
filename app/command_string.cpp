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
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "design/strings/miura_string.hpp"
#include "design/strings/string_fit_ceres.hpp"
#include "design/strings/string_fit_nlopt.hpp"
#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"
#include "design/strings/string_verify.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::cli {
namespace {

using nlohmann::json;
using namespace rigidfold::design;
constexpr double kDeg = std::numbers::pi / 180;

// Reads values from a JSON document and names the file and JSON pointer on every error.
class Reader {
 public:
  Reader(std::string file) : file_(std::move(file)) {
    const std::string text = read_text_file(file_);
    try {
      doc_ = json::parse(text);
    } catch (const json::parse_error& e) {
      throw InputError(file_, std::string("malformed JSON: ") + e.what());
    }
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
  if (o.contains("alpha_min_deg")) b.alpha_min = r.number_in(o, "/bounds", "alpha_min_deg", 0, 90, "(0, 90)") * kDeg;
  if (o.contains("alpha_max_deg")) b.alpha_max = r.number_in(o, "/bounds", "alpha_max_deg", 0, 90, "(0, 90)") * kDeg;
  if (!(b.alpha_min < b.alpha_max)) r.fail("/bounds", "alpha_min_deg must be below alpha_max_deg");
  if (o.contains("theta_margin_deg")) b.theta_margin = r.number_in(o, "/bounds", "theta_margin_deg", -1e-300, 45, "[0, 45)") * kDeg;
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
                        {"fold_angle_deg", 2 * st.theta[0] / kDeg}};
  j["transmission"] = st.mode == ThetaMode::Transmitted
                          ? "shared spinal creases: theta_i = (-1)^i theta_0 (rho_spinal_out = -2 theta exactly)"
                          : "independent per-vertex theta: only alternating equal magnitudes are a rigid motion of the sheet";
  j["shared_crease_mismatch_deg"] = st.shared_crease_mismatch / kDeg;
  j["min_theta_margin_deg"] = st.min_theta_margin / kDeg;
  j["limiting_vertex"] = st.limiting_vertex;
  json verts = json::array();
  for (int i = 0; i < s.size(); ++i) {
    const auto& v = st.vertices[i];
    verts.push_back({{"alpha1_deg", s.alpha1[i] / kDeg},
                     {"alpha2_deg", s.alpha2[i] / kDeg},
                     {"theta_deg", st.theta[i] / kDeg},
                     {"theta_limit_deg", v.theta_limit / kDeg},
                     {"phi_deg", v.phi / kDeg},
                     {"psi_deg", v.psi / kDeg},
                     {"fold_angles_deg",
                      {{"spinal_in", v.rho_c / kDeg}, {"spinal_out", v.rho_a / kDeg}, {"peripheral_1", v.rho_b / kDeg},
                       {"peripheral_2", v.rho_d / kDeg}}}});
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
    const double step = r.number_in(o, ptr, "step_deg", -360, 360, "(-360, 360)") * kDeg;
    const double count = r.number(o, ptr, "count");
    if (count != std::floor(count) || count < 3 || count > 1e6) r.fail(ptr + "/count", "must be an integer in [3, 1e6]");
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
  if (as_json) std::cout << j.dump(2) << "\n";
  else std::cout << text;
}

}  // namespace

void add_string_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("string", "Origami strings of asymmetric Miura vertices: forward kinematics and inverse design");
  cmd->require_subcommand(1);

  struct ForwardArgs {
    std::string spec, out, svg;
    double theta = 0;
    bool theta_given = false, json = false;
  };
  auto fa = std::make_shared<ForwardArgs>();
  auto* fwd = cmd->add_subcommand("forward", "Fold a string spec at drive angle theta (closed form), optionally write the folded FOLD");
  fwd->add_option("spec", fa->spec, "SPEC.json (see the header of app/command_string.cpp)")->required();
  auto* theta_opt = fwd->add_option("--theta", fa->theta, "drive: half fold angle of the lead-in spinal crease, degrees (valley > 0)");
  fwd->add_option("--out", fa->out, "folded FOLD output (crease pattern + foldedForm frame)");
  fwd->add_option("--svg", fa->svg, "crease pattern SVG for cutting");
  fwd->add_flag("--json", fa->json, "print JSON");
  fwd->callback([fa, theta_opt] {
    fa->theta_given = theta_opt->count() > 0;
    Reader r(fa->spec);
    const std::string mode = r.string_of(r.doc(), "mode", "transmitted", {"transmitted", "independent"});
    const json& verts = r.array(r.doc(), "", "vertices");
    MiuraString s;
    std::vector<double> theta;
    if (fa->theta_given && !(std::isfinite(fa->theta) && std::fabs(fa->theta) < 90)) throw InputError("--theta", "must be in (-90, 90) degrees");
    for (std::size_t i = 0; i < verts.size(); ++i) {
      const std::string ptr = "/vertices/" + std::to_string(i);
      s.alpha1.push_back(r.number_in(verts[i], ptr, "alpha1_deg", 0, 90, "(0, 90)") * kDeg);
      s.alpha2.push_back(r.number_in(verts[i], ptr, "alpha2_deg", 0, 90, "(0, 90)") * kDeg);
      if (mode == "independent") {
        if (verts[i].contains("theta_deg")) theta.push_back(r.number_in(verts[i], ptr, "theta_deg", -90, 90, "(-90, 90)") * kDeg);
        else if (fa->theta_given) theta.push_back(fa->theta * kDeg);
        else r.fail(ptr + "/theta_deg", "missing (independent mode needs theta_deg per vertex or --theta)");
      }
    }
    if (mode == "transmitted" && !fa->theta_given) throw InputError("--theta", "required in transmitted mode");
    s.lengths = read_lengths(r, s.size());
    apply_width(r, s, read_width(r));
    StringState st;
    try {
      st = mode == "transmitted" ? string_forward(s, fa->theta * kDeg) : string_forward_independent(s, theta);
    } catch (const std::invalid_argument& e) {
      throw InputError(mode == "transmitted" ? "--theta" : fa->spec, e.what());
    }
    const CreasePattern pattern = build_string_pattern(s, st.edge_fold_angles);
    const FoldedGeometry folded = fold_string_pattern(pattern, st);
    json j = string_state_json(s, st);
    j["spec"] = fa->spec;
    j["width"] = s.width;
    j["placement_mismatch"] = folded.max_mismatch;
    if (!fa->out.empty()) {
      write_text_file_atomically(fa->out, folded_fold_text(pattern, folded, st.edge_fold_angles, "string folded at theta = " +
                                                                                                   std::to_string(fa->theta) + " deg"));
      j["out"] = fa->out;
    }
    if (!fa->svg.empty()) write_text_file_atomically(fa->svg, string_pattern_svg(pattern));
    std::ostringstream t;
    t.precision(10);
    t << "origami string, " << s.size() << " Miura vertices, mode " << mode << "\n"
      << "  driven crease: edge 0 (s_0, lead-in spinal crease = crease c of vertex 0), fold angle " << 2 * st.theta[0] / kDeg
      << " deg\n"
      << "  transmission: " << j["transmission"].get<std::string>() << "\n"
      << "  spine end: (" << st.spine.back().x() << ", " << st.spine.back().y() << ", " << st.spine.back().z() << ")\n"
      << "  min theta margin " << st.min_theta_margin / kDeg << " deg at vertex " << st.limiting_vertex
      << "; shared crease mismatch " << st.shared_crease_mismatch / kDeg << " deg; face placement mismatch "
      << folded.max_mismatch << "\n";
    if (!fa->out.empty()) t << "  wrote " << fa->out << "\n";
    print_or_json(j, fa->json, t.str());
  });

  struct DesignArgs {
    std::string target, out, svg;
    bool json = false;
  };
  auto da = std::make_shared<DesignArgs>();
  auto* des = cmd->add_subcommand("design", "Design a string for a target (deflections, trajectories or a 3D curve)");
  des->add_option("target", da->target, "TARGET.json (see the header of app/command_string.cpp)")->required();
  des->add_option("--out", da->out, "designed string: crease pattern + folded frame (FOLD)")->required();
  des->add_option("--svg", da->svg, "crease pattern SVG for cutting");
  des->add_flag("--json", da->json, "print JSON");
  des->callback([da] {
    Reader r(da->target);
    const std::string kind = r.string_of(r.doc(), "kind", "", {"deflections", "trajectories", "curve"});
    if (kind.empty()) r.fail("/kind", "missing (deflections, trajectories or curve)");
    const StringBounds bounds = read_bounds(r);
    const std::optional<double> width = read_width(r);
    json j;
    j["target"] = da->target;
    j["kind"] = kind;
    MiuraString s;
    double theta0 = 0;
    StringPose design_pose;
    bool have_pose = false;
    std::vector<Eigen::Vector3d> curve;
    std::ostringstream t;
    t.precision(10);
    if (kind == "deflections" || kind == "trajectories") {
      const std::string mode = r.string_of(r.doc(), "mode", "transmitted", {"transmitted", "independent"});
      const json& verts = r.array(r.doc(), "", "vertices");
      const int n = static_cast<int>(verts.size());
      j["mode"] = mode;
      if (kind == "deflections") {
        theta0 = r.number_in(r.doc(), "", "theta_deg", -90, 90, "(-90, 90)") * kDeg;
        if (theta0 == 0) r.fail("/theta_deg", "must be nonzero (the flat state has no deflection)");
        std::vector<double> phi, psi, theta = transmitted_thetas(theta0, n);
        for (int i = 0; i < n; ++i) {
          const std::string ptr = "/vertices/" + std::to_string(i);
          phi.push_back(r.number_in(verts[i], ptr, "phi_deg", -180, 180, "(-180, 180)") * kDeg);
          psi.push_back(r.number_in(verts[i], ptr, "psi_deg", -90, 90, "(-90, 90)") * kDeg);
          if (mode == "independent")
            theta[i] = verts[i].contains("theta_deg") ? r.number_in(verts[i], ptr, "theta_deg", -90, 90, "(-90, 90)") * kDeg : theta0;
        }
        const DeflectionDesign d = design_from_deflections(phi, psi, theta, bounds);
        j["method"] = "closed-form inverse per vertex (unique alpha1, alpha2 for the given theta_i)";
        json vj = json::array();
        for (int i = 0; i < n; ++i) {
          const auto& v = d.vertices[i];
          vj.push_back({{"feasible", v.feasible}, {"reason", v.reason}, {"theta_deg", v.theta / kDeg}, {"alpha1_deg", v.alpha1 / kDeg},
                        {"alpha2_deg", v.alpha2 / kDeg}, {"phi_residual_deg", v.phi_error / kDeg}, {"psi_residual_deg", v.psi_error / kDeg}});
        }
        j["vertices"] = vj;
        if (!d.feasible) {
          for (int i = 0; i < n; ++i)
            if (!d.vertices[i].feasible)
              r.fail("/vertices/" + std::to_string(i), "unreachable at theta_i = " + std::to_string(theta[i] / kDeg) + " deg: " + d.vertices[i].reason);
        }
        for (const auto& v : d.vertices) {
          s.alpha1.push_back(v.alpha1);
          s.alpha2.push_back(v.alpha2);
        }
        if (mode == "independent") {
          // A sheet is built only for what one actuation can fold.
          for (int i = 0; i + 1 < n; ++i)
            if (std::fabs(theta[i + 1] + theta[i]) > 1e-12)
              r.fail("/vertices/" + std::to_string(i + 1) + "/theta_deg",
                     "independent thetas that do not alternate (theta_{i+1} = -theta_i) are not a rigid motion of one strip; "
                     "the FOLD output would not fold");
        }
      } else {
        TrajectoryTarget tt;
        tt.mode = mode == "transmitted" ? ThetaMode::Transmitted : ThetaMode::Independent;
        tt.theta = r.numbers(r.at(r.doc(), "", "theta_deg"), "/theta_deg");
        if (tt.theta.empty()) r.fail("/theta_deg", "needs at least one sample");
        for (std::size_t k = 0; k < tt.theta.size(); ++k) {
          if (!(std::fabs(tt.theta[k]) < 90) || tt.theta[k] == 0) r.fail("/theta_deg/" + std::to_string(k), "must be in (-90, 90), nonzero");
          tt.theta[k] *= kDeg;
        }
        for (int i = 0; i < n; ++i) {
          const std::string ptr = "/vertices/" + std::to_string(i);
          auto ph = r.numbers(r.at(verts[i], ptr, "phi_deg"), ptr + "/phi_deg");
          auto ps = r.numbers(r.at(verts[i], ptr, "psi_deg"), ptr + "/psi_deg");
          if (ph.size() != tt.theta.size()) r.fail(ptr + "/phi_deg", "needs one value per theta sample");
          if (ps.size() != tt.theta.size()) r.fail(ptr + "/psi_deg", "needs one value per theta sample");
          for (auto& v : ph) v *= kDeg;
          for (std::size_t k = 0; k < ps.size(); ++k) {
            if (!(std::fabs(ps[k]) < 90)) r.fail(ptr + "/psi_deg/" + std::to_string(k), "must be in (-90, 90)");
            ps[k] *= kDeg;
          }
          tt.phi.push_back(ph);
          tt.psi.push_back(ps);
        }
        const TrajectoryFitResult fit = fit_string_trajectories(tt, bounds);
        j["method"] = "Ceres least squares over the theta samples (automatic derivatives, alpha bounds)";
        j["ceres"] = fit.report;
        j["converged"] = fit.converged;
        j["max_residual_deg"] = fit.max_residual / kDeg;
        j["binding_bounds"] = fit.binding;
        json vj = json::array();
        for (int i = 0; i < n; ++i)
          vj.push_back({{"alpha1_deg", fit.alpha1[i] / kDeg}, {"alpha2_deg", fit.alpha2[i] / kDeg}, {"rms_residual_deg", fit.vertex_rms[i] / kDeg}});
        j["vertices"] = vj;
        s.alpha1 = fit.alpha1;
        s.alpha2 = fit.alpha2;
        theta0 = tt.theta[0];
        for (double th : tt.theta)
          if (std::fabs(th) > std::fabs(theta0)) theta0 = th;
        if (mode == "independent" && n > 1)
          j["note"] = "independent mode: the folded FOLD frame shows the transmitted (one-DOF) state at the largest sample";
      }
      s.lengths = read_lengths(r, n);
    } else {
      curve = read_curve(r);
      CurveDesignOptions co;
      co.bounds = bounds;
      if (r.doc().contains("theta_deg")) {
        co.theta0 = r.number_in(r.doc(), "", "theta_deg", -90, 90, "(-90, 90)") * kDeg;
        if (*co.theta0 == 0) r.fail("/theta_deg", "must be nonzero");
      }
      if (r.doc().contains("roll_deg")) co.roll = r.number(r.doc(), "", "roll_deg") * kDeg;
      const std::string method = r.string_of(r.doc(), "method", "auto", {"auto", "closed_form", "nlopt"});
      for (std::size_t k = 0; k + 1 < curve.size(); ++k)
        if (!((curve[k + 1] - curve[k]).norm() >= bounds.min_segment))
          r.fail("/points/" + std::to_string(k + 1), "segment shorter than bounds.min_segment");
      const CurveDesign cd = design_from_curve(curve, co);
      j["closed_form"] = {{"exact", cd.feasible}, {"first_unreachable_vertex", cd.first_infeasible},
                          {"theta0_deg", cd.theta0 / kDeg}, {"roll_deg", cd.roll / kDeg}, {"alpha_margin_deg", cd.alpha_margin / kDeg}};
      if (method == "closed_form" || (method == "auto" && cd.feasible)) {
        if (!cd.feasible)
          r.fail("/points/" + std::to_string(cd.first_infeasible + 2),
                 "not reachable in closed form (vertex " + std::to_string(cd.first_infeasible) + ": " +
                     cd.vertices[cd.first_infeasible].reason + "); use \"method\": \"nlopt\" for the best fit");
        j["method"] = "closed-form sequential inverse (theta0 and roll chosen by grid search for the largest bound margin)";
        s = cd.string;
        theta0 = cd.theta0;
        design_pose = cd.pose;
      } else {
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
        NloptFitResult fit;
        try {
          fit = fit_string_to_curve(curve, no);
        } catch (const std::invalid_argument& e) {
          r.fail("/algorithm", e.what());
        }
        j["method"] = "NLopt " + fit.algorithm + " from the closed-form seed (bounds: alpha, theta limit with margin, min segment)";
        j["nlopt"] = {{"status", fit.status}, {"evaluations", fit.evaluations}};
        j["reachable"] = fit.reachable;
        j["max_error"] = fit.max_error;
        j["rms_error"] = fit.rms_error;
        j["max_error_per_segment"] = fit.max_error / fit.mean_segment;
        j["binding_bounds"] = fit.binding;
        j["point_errors"] = fit.point_errors;
        s = fit.string;
        theta0 = fit.theta0;
        design_pose = fit.pose;
      }
      have_pose = true;
    }
    apply_width(r, s, width);
    StringState st;
    try {
      st = string_forward(s, theta0);  // the pattern pose (face 0 fixed)
    } catch (const std::invalid_argument& e) {
      r.fail("", std::string("designed string cannot fold at the design theta: ") + e.what());
    }
    const CreasePattern pattern = build_string_pattern(s, st.edge_fold_angles);
    // Newton starts 1e-6 rad away from the closed form, so the solver has to converge on its own.
    const StringVerification v = verify_string_with_general_solver(s, pattern, st, 1e-6);
    j["theta0_deg"] = theta0 / kDeg;
    j["width"] = s.width;
    j["driven_crease"] = {{"edge", 0}, {"fold_angle_deg", 2 * theta0 / kDeg}, {"name", "s_0: lead-in spinal crease"}};
    j["string"] = {{"alpha1_deg", json::array()}, {"alpha2_deg", json::array()}, {"segment_lengths", s.lengths}};
    for (int i = 0; i < s.size(); ++i) {
      j["string"]["alpha1_deg"].push_back(s.alpha1[i] / kDeg);
      j["string"]["alpha2_deg"].push_back(s.alpha2[i] / kDeg);
    }
    json ver = {{"solver", "general loop closure, Newton projection from the closed form + 1e-6 rad, s_0 fixed"},
                {"converged", v.converged},
                {"iterations", v.iterations},
                {"closure_residual_rad", v.closure_residual},
                {"max_angle_difference_rad", v.max_angle_error},
                {"max_spine_difference", v.max_spine_error}};
    if (have_pose) {
      // Folded pattern (pattern pose) -> target frame: the rigid map taking the pattern's
      // C_0 to the design's C_0; no fitting.
      const StringPose pp = pattern_pose(theta0);
      const Eigen::Matrix3d Rm = design_pose.frame * pp.frame.transpose();
      double worst = 0;
      for (int k = 0; k < s.size() + 2; ++k) {
        const Eigen::Vector3d q = Rm * (v.folded.vertices[k] - pp.start) + design_pose.start;
        worst = std::max(worst, (q - curve[k]).norm());
      }
      double total = 0;  // mean TARGET segment, the same scale as the NLopt report
      for (std::size_t k = 0; k + 1 < curve.size(); ++k) total += (curve[k + 1] - curve[k]).norm();
      ver["max_target_error"] = worst;
      ver["max_target_error_per_segment"] = worst / (total / (curve.size() - 1));
    }
    j["verification"] = ver;
    // Outputs only after everything succeeded.
    write_text_file_atomically(da->out, folded_fold_text(pattern, v.folded, v.solver_angles, "designed origami string"));
    if (!da->svg.empty()) write_text_file_atomically(da->svg, string_pattern_svg(pattern));
    j["out"] = da->out;
    t << "designed origami string (" << kind << "), " << s.size() << " vertices, theta0 = " << theta0 / kDeg << " deg\n"
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
    t << "  wrote " << da->out << "\n";
    print_or_json(j, da->json, t.str());
  });
}

}  // namespace rigidfold::cli
