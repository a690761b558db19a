// rigidfold vertex s4r --twists A,B,C,D --input DEG [--json]
// rigidfold vertex miura --alpha1 DEG --alpha2 DEG --theta DEG [--json]
// Spherical 4R linkage (a degree-4 vertex) in the kernel's convention: twists alpha12,
// alpha23, alpha34, alpha41 in degrees (any values), joint angles = fold angles
// (valley > 0), closure Rx(t1) Rz(a12) Rx(t2) Rz(a23) Rx(t3) Rz(a34) Rx(t4) Rz(a41) = I.
// Seeds 001/003 write theta with mountain positive: theta_seed = -theta here.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::cli {
namespace {

// The closed range of --alpha1/--alpha2 (degrees), documented in the README.
constexpr double kMinAlphaDeg = 1e-300;
constexpr double kMaxAlphaDeg = 90.0 - 1e-12;
// The closed range of each --twists value (degrees): one turn either way.
constexpr double kMaxTwistDeg = 360.0;

// Asymmetric Miura vertex closed form (kernel/vertex/miura_vertex.hpp). theta is half the
// fold angle of the incoming spinal crease; flags are in degrees, checked here so that the
// error names the flag.
void add_miura_command(CLI::App& vertex) {
  auto* miura = vertex.add_subcommand("miura", "Asymmetric Miura vertex: phi, psi and fold angles from alpha1, alpha2, theta");
  struct Args {
    double alpha1 = 0, alpha2 = 0, theta = 0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  miura->add_option("--alpha1", a->alpha1, "angle between the outgoing spinal crease and peripheral crease b, degrees in [1e-300, 90 - 1e-12]")->required();
  miura->add_option("--alpha2", a->alpha2, "angle between the outgoing spinal crease and peripheral crease d, degrees in [1e-300, 90 - 1e-12]")->required();
  miura->add_option("--theta", a->theta, "half the fold angle of the incoming spinal crease, degrees, valley > 0, |theta| <= theta_limit")->required();
  miura->add_flag("--json", a->json, "print JSON");
  miura->callback([a] {
    // Closed range: below 1e-300 deg the angle in radians is subnormal (not even its
    // value is accurate); 90 deg itself is a degenerate vertex (b or d across the spine).
    for (const auto& [flag, v] : {std::pair{"--alpha1", a->alpha1}, std::pair{"--alpha2", a->alpha2}})
      if (!std::isfinite(v) || !(v >= kMinAlphaDeg) || !(v <= kMaxAlphaDeg))
        throw InputError(flag, "must be in [1e-300, 90 - 1e-12] degrees");
    if (!std::isfinite(a->theta)) throw InputError("--theta", "must be finite");
    const double limit = miura_theta_limit(to_radians(a->alpha1), to_radians(a->alpha2));
    // Compared in degrees, as printed: --theta equal to the printed limit is accepted
    // (and clamped to the limit in radians against the last-bit rounding of the conversion).
    if (std::fabs(a->theta) > to_degrees(limit))
      throw InputError("--theta", "|theta| must not exceed theta_limit = " + std::to_string(to_degrees(limit)) + " degrees");
    const double theta = std::clamp(to_radians(a->theta), -limit, limit);
    // Verified before printing: closure residual and sign claims (NoAnswerError -> exit 3).
    const MiuraVertexState st = miura_vertex_checked(to_radians(a->alpha1), to_radians(a->alpha2), theta);
    nlohmann::ordered_json j;
    j["alpha1_deg"] = a->alpha1;
    j["alpha2_deg"] = a->alpha2;
    j["theta_deg"] = a->theta;
    j["phi_deg"] = to_degrees(st.phi);
    j["psi_deg"] = to_degrees(st.psi);
    j["theta_limit_deg"] = to_degrees(st.theta_limit);
    nlohmann::ordered_json folds = nlohmann::ordered_json::array();
    for (int i = 0; i < 4; ++i)
      folds.push_back({{"crease", std::string(kMiuraCreaseNames[i])},
                       {"direction_deg", to_degrees(st.flat_directions[i])},
                       {"fold_angle_deg", to_degrees(st.fold_angles[i])}});
    j["fold_angles_deg"] = folds;
    j["sectors_deg"] = {to_degrees(st.sectors[0]), to_degrees(st.sectors[1]), to_degrees(st.sectors[2]), to_degrees(st.sectors[3])};
    j["closure_residual_rad"] =
        vertex_closure_residual(std::span<const double>(st.sectors.data(), 4), std::span<const double>(st.fold_angles.data(), 4)).norm();
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    char line[256];
    std::snprintf(line, sizeof line, "Miura vertex, alpha1 = %.12g deg, alpha2 = %.12g deg, theta = %.12g deg (limit +-%.12g deg)\n",
                  a->alpha1, a->alpha2, a->theta, to_degrees(st.theta_limit));
    std::cout << line;
    std::snprintf(line, sizeof line, "  phi = %.12g deg, psi = %.12g deg\n", to_degrees(st.phi), to_degrees(st.psi));
    std::cout << line;
    std::cout << "  fold angles (valley > 0), creases CCW:\n";
    for (int i = 0; i < 4; ++i) {
      std::snprintf(line, sizeof line, "    %-13s at %8.4f deg: %.12g deg\n", std::string(kMiuraCreaseNames[i]).c_str(),
                    to_degrees(st.flat_directions[i]), to_degrees(st.fold_angles[i]));
      std::cout << line;
    }
    std::snprintf(line, sizeof line, "  closure residual %.2e rad\n", j["closure_residual_rad"].get<double>());
    std::cout << line;
  });
}

}  // namespace

void add_vertex_command(CLI::App& app) {
  auto* vertex = app.add_subcommand("vertex", "Closed forms for a single vertex");
  vertex->require_subcommand(1);
  auto* s4r = vertex->add_subcommand("s4r", "Spherical 4R linkage: every branch for a given input joint angle");
  struct Args {
    std::vector<double> twists;
    double input = 0;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  s4r->add_option("--twists", a->twists, "alpha12,alpha23,alpha34,alpha41 in degrees, each in [-360, 360]")->required()->delimiter(',')->expected(4);
  s4r->add_option("--input", a->input, "joint angle 1 (fold angle of crease 1) in degrees, valley > 0")->required();
  s4r->add_flag("--json", a->json, "print JSON");
  add_miura_command(*vertex);
  s4r->callback([a] {
    if (a->twists.size() != 4) throw InputError("--twists", "needs exactly 4 values, got " + std::to_string(a->twists.size()));
    for (std::size_t i = 0; i < 4; ++i)
      if (!std::isfinite(a->twists[i]) || !(std::fabs(a->twists[i]) <= kMaxTwistDeg))
        throw InputError("--twists[" + std::to_string(i) + "]", "must be in [-360, 360] degrees");
    if (!std::isfinite(a->input) || std::fabs(a->input) > 180.0) throw InputError("--input", "must be within [-180, 180] degrees");
    const S4RSectors tw{to_radians(a->twists[0]), to_radians(a->twists[1]), to_radians(a->twists[2]), to_radians(a->twists[3])};
    // Every branch verified (closure residual) before printing: NoAnswerError -> exit 3.
    const S4RBranches b = s4r_branches_checked(tw, to_radians(a->input), 0);
    const S4RInputRange range = s4r_input_range(tw, 0);
    nlohmann::ordered_json j;
    j["twists_deg"] = a->twists;
    j["input_deg"] = a->input;
    j["feasible"] = b.feasible;
    nlohmann::ordered_json branches = nlohmann::ordered_json::array();
    for (const auto& br : b.branches) {
      std::vector<double> deg(4), rho(br.begin(), br.end());
      for (int i = 0; i < 4; ++i) deg[i] = to_degrees(br[i]);
      const double residual = vertex_closure_residual(std::span<const double>(tw.data(), 4), rho).norm();
      branches.push_back({{"angles_deg", deg}, {"closure_residual_rad", residual}});
    }
    j["branches"] = branches;
    j["degenerate"] = b.degenerate;
    j["input_range_deg"] = {{"feasible", range.feasible}, {"min_abs", to_degrees(range.min_abs)}, {"max_abs", to_degrees(range.max_abs)}};
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    std::cout << "spherical 4R, twists " << a->twists[0] << ", " << a->twists[1] << ", " << a->twists[2] << ", " << a->twists[3]
              << " deg; input theta1 = " << a->input << " deg\n";
    if (!range.feasible) std::cout << "  the linkage cannot be assembled for any input\n";
    else std::cout << "  input range: " << to_degrees(range.min_abs) << " <= |theta1| <= " << to_degrees(range.max_abs) << " deg\n";
    if (!b.feasible) std::cout << "  no branch at this input (outside the motion limits)\n";
    int k = 0;
    for (const auto& br : j["branches"]) {
      char line[200];
      std::snprintf(line, sizeof line, "  branch %d: theta = (%.12g, %.12g, %.12g, %.12g) deg, closure residual %.2e rad\n", k++,
                    br["angles_deg"][0].get<double>(), br["angles_deg"][1].get<double>(), br["angles_deg"][2].get<double>(),
                    br["angles_deg"][3].get<double>(), br["closure_residual_rad"].get<double>());
      std::cout << line;
    }
  });
}

}  // namespace rigidfold::cli
