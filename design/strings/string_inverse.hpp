#pragma once
// Closed-form inverse design of Miura strings (no optimiser).
//
// 1. Deflection targets: (phi_i, psi_i) per vertex at one fold state -> (alpha1_i,
//    alpha2_i). For a given theta_i the answer is unique (string_vertex_inverse); over
//    theta the solutions of one vertex form a one-parameter family. The choice made here:
//    theta_i is not free per vertex but fixed by the string's mode:
//      Transmitted: theta_i = (-1)^i theta_0 (the one-DOF sheet, string_kinematics.hpp);
//      Independent: theta_i as given.
//    Since phi has the sign of theta, a transmitted string needs phi_i alternating in sign;
//    a vertex whose target lies outside its cone (see string_vertex_inverse_direction) or
//    whose alphas leave [alpha_min, alpha_max] is reported infeasible, never clamped.
//
// 2. Curve targets: points Q_0 .. Q_{N+1} of the spine (S, V_0..V_{N-1}, E) -> the
//    string whose spine passes through them. Segment lengths are |Q_{k+1} - Q_k|. Walking
//    along the chain, each vertex's outgoing direction expressed in its frame C_i fixes
//    (alpha1_i, alpha2_i) by the per-vertex inverse at theta_i = (-1)^i theta_0, and the
//    closed-form rotation then gives C_{i+1}. What is left free is theta_0 and the roll
//    beta of frame C_0 about the first segment (its x axis is Q_1 - Q_0): the choice made
//    is the pair (theta_0, beta), from the given values or a grid search when absent, that
//    maximises the smallest distance of any alpha to the fabrication bounds (and keeps a
//    theta margin). If no pair makes every vertex feasible the target is not reachable
//    exactly: use the NLopt fit (string_fit_nlopt.hpp), which this result seeds.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_kinematics.hpp"
#include "kernel/analysis/progress.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::design {

// Fabrication bounds shared by every design method. Radians / length units.
struct StringBounds {
  double alpha_min = to_radians(10.0);    // alpha in [alpha_min, alpha_max]
  double alpha_max = to_radians(80.0);
  double theta_margin = to_radians(2.0);  // |theta_i| <= theta_limit_i - margin
  double min_segment = 1e-3;              // every spine segment >= this
};

struct VertexDesign {
  bool feasible = false;
  std::string reason;        // why not, when infeasible
  double alpha1 = 0, alpha2 = 0, theta = 0;  // radians
  double phi_error = 0, psi_error = 0;       // closed form forward minus target (radians), feasible vertices
};

struct DeflectionDesign {
  std::vector<VertexDesign> vertices;
  bool feasible = false;  // every vertex feasible
};

// Inputs: phi, psi per vertex (radians); theta per vertex (radians, nonzero; use
// transmitted_thetas for the one-DOF string). Output per vertex as above.
DeflectionDesign design_from_deflections(const std::vector<double>& phi, const std::vector<double>& psi,
                                         const std::vector<double>& theta, const StringBounds& bounds = {});

// theta_i = (-1)^i theta0, n values.
std::vector<double> transmitted_thetas(double theta0, int n);

struct CurveDesignOptions {
  std::optional<double> theta0;  // radians; grid-searched in (0, pi/2) when absent
  std::optional<double> roll;    // beta (radians); grid-searched in [-pi, pi) when absent
  int theta_samples = 24, roll_samples = 72;  // grid sizes of the search
  StringBounds bounds;
  ProgressSink progress;         // each (theta0, roll) cell of the grid; NLopt: each evaluation
};

struct CurveDesign {
  bool feasible = false;          // every vertex feasible with the chosen (theta0, roll)
  MiuraString string;             // alphas (infeasible vertices clamped into bounds), lengths; width left 0
  double theta0 = 0, roll = 0;    // the choice made (radians)
  StringPose pose;                // world pose of S and C_0 for string_forward(string, theta0, pose)
  std::vector<VertexDesign> vertices;
  int first_infeasible = -1;      // first vertex that failed (-1 if none)
  double alpha_margin = 0;        // min distance of any alpha to its bounds (radians; < 0 infeasible)
};

// points: N + 2 target spine points (world, length units), N >= 1, consecutive points at
// least bounds.min_segment apart. Throws std::invalid_argument otherwise.
CurveDesign design_from_curve(const std::vector<Eigen::Vector3d>& points, const CurveDesignOptions& options = {});

// Frame C_0 for the first segment direction d (unit) and roll beta: x = d, y = the unit
// vector perpendicular to d closest to world +y (world +z if d is along y) turned by beta
// about d.
Eigen::Matrix3d initial_frame(const Eigen::Vector3d& d, double roll);

}  // namespace rigidfold::design
