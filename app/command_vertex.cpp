// rigidfold vertex s4r --twists A,B,C,D --input DEG [--json]
// Spherical 4R linkage (a degree-4 vertex) in the kernel's convention: twists alpha12,
// alpha23, alpha34, alpha41 in degrees (any values), joint angles = fold angles
// (valley > 0), closure Rx(t1) Rz(a12) Rx(t2) Rz(a23) Rx(t3) Rz(a34) Rx(t4) Rz(a41) = I.
// Seeds 001/003 write theta with mountain positive: theta_seed = -theta here.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::cli {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

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
  s4r->add_option("--twists", a->twists, "alpha12,alpha23,alpha34,alpha41 in degrees")->required()->delimiter(',')->expected(4);
  s4r->add_option("--input", a->input, "joint angle 1 (fold angle of crease 1) in degrees, valley > 0")->required();
  s4r->add_flag("--json", a->json, "print JSON");
  s4r->callback([a] {
    if (a->twists.size() != 4) throw InputError("--twists", "needs exactly 4 values, got " + std::to_string(a->twists.size()));
    for (std::size_t i = 0; i < 4; ++i)
      if (!std::isfinite(a->twists[i])) throw InputError("--twists[" + std::to_string(i) + "]", "must be finite");
    if (!std::isfinite(a->input) || std::fabs(a->input) > 180.0) throw InputError("--input", "must be within [-180, 180] degrees");
    const S4RSectors tw{a->twists[0] / kDeg, a->twists[1] / kDeg, a->twists[2] / kDeg, a->twists[3] / kDeg};
    const S4RBranches b = s4r_branches(tw, a->input / kDeg, 0);
    const S4RInputRange range = s4r_input_range(tw, 0);
    nlohmann::ordered_json j;
    j["twists_deg"] = a->twists;
    j["input_deg"] = a->input;
    j["feasible"] = b.feasible;
    nlohmann::ordered_json branches = nlohmann::ordered_json::array();
    for (const auto& br : b.branches) {
      std::vector<double> deg(4), rho(br.begin(), br.end());
      for (int i = 0; i < 4; ++i) deg[i] = br[i] * kDeg;
      const double residual = vertex_closure_residual(std::span<const double>(tw.data(), 4), rho).norm();
      branches.push_back({{"angles_deg", deg}, {"closure_residual_rad", residual}});
    }
    j["branches"] = branches;
    j["degenerate"] = b.degenerate;
    j["input_range_deg"] = {{"feasible", range.feasible}, {"min_abs", range.min_abs * kDeg}, {"max_abs", range.max_abs * kDeg}};
    if (a->json) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::cout << "spherical 4R, twists " << a->twists[0] << ", " << a->twists[1] << ", " << a->twists[2] << ", " << a->twists[3]
              << " deg; input theta1 = " << a->input << " deg\n";
    if (!range.feasible) std::cout << "  the linkage cannot be assembled for any input\n";
    else std::cout << "  input range: " << range.min_abs * kDeg << " <= |theta1| <= " << range.max_abs * kDeg << " deg\n";
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
