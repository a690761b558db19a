#pragma once
// The Miura-ori instance the scaling benchmarks share (scaling_bench, amg_bench): n x n cells,
// sector angle pi/3, its closed-form state at rho_s = 1.2 (radians) and a start perturbed by
// uniform noise of 1e-4 rad on every unknown but unknown 0 (the one the correctors hold).
#include <Eigen/Core>
#include <random>

#include "data/generators/miura.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::bench {

struct MiuraCase {
  generators::MiuraParams params;
  CreasePattern pattern;
  Topology topology;
  ClosureSystem system;
  Eigen::VectorXd exact, start;
  explicit MiuraCase(int n)
      : params(make_params(n)),
        pattern(generators::miura_ori(params)),
        topology(build_topology(pattern)),
        system(pattern, topology),
        exact(closed_form(1.2)) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
    start = exact;
    for (int k = 1; k < start.size(); ++k) start[k] += noise(rng);  // unknown 0 is held
  }
  static generators::MiuraParams make_params(int n) {
    generators::MiuraParams m;
    m.rows = m.cols = n;
    m.alpha = kPi / 3;
    return m;
  }
  // The unknowns at fold angle rho_s of the straight creases (radians).
  Eigen::VectorXd closed_form(double rho_s) const {
    return system.unknowns_from_edges(fold_angle_vector(generators::miura_fold_angles(pattern, params, rho_s)));
  }
  // Unknown of a straight crease (the trace's driver): edge (0, 1).
  int driver() const { return system.unknown_of_edge(params.cols + 0); }
};

}  // namespace rigidfold::bench
