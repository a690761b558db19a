#include "kernel/energy/constrained_equilibrium.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernel/closure/closure_second_order.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {

namespace {

// Everything the Newton step needs at one point, beside the reported Equilibrium.
struct LocalModel {
  Eigen::MatrixXd null_space;     // N (unknowns x dof)
  Eigen::VectorXd gradient;       // g (unknowns)
  Eigen::MatrixXd reduced_hessian;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig;
};

Eigen::VectorXd free_entries(const ClosureSystem& system, const Eigen::VectorXd& per_edge) {
  Eigen::VectorXd out(system.num_unknowns());
  for (int k = 0; k < system.num_unknowns(); ++k) out[k] = per_edge[system.edge_of_unknown(k)];
  return out;
}

double stiffness_scale(const CreaseSprings& springs) {
  return springs.stiffness.size() ? springs.stiffness.maxCoeff() : 0.0;
}

Equilibrium evaluate(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                     const Eigen::VectorXd& x, const EquilibriumOptions& options, LocalModel& model) {
  const int n = system.num_unknowns();
  if (x.size() != n) throw std::invalid_argument("equilibrium: x needs num_unknowns() entries");
  if (springs.stiffness.size() != system.num_edges() || springs.rest_angles.size() != system.num_edges())
    throw std::invalid_argument("equilibrium: the springs need one entry per edge of the system's pattern");
  Equilibrium eq;
  eq.x = x;
  eq.edge_angles = system.edges_from_unknowns(x);
  eq.energy = crease_energy(springs, eq.edge_angles);
  model.gradient = free_entries(system, crease_energy_gradient(springs, eq.edge_angles));
  const Eigen::VectorXd& g = model.gradient;

  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Js;
  system.evaluate(x, r, Js);
  eq.closure_residual = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
  const int m = system.num_rows();

  int rank = 0;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
  if (m > 0 && n > 0) {
    const Eigen::MatrixXd J(Js);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double cut = options.rank_tolerance * (s.size() ? s[0] : 0.0);
    while (rank < s.size() && s[rank] > cut) ++rank;
    model.null_space = svd.matrixV().rightCols(n - rank);
    // Least-squares multipliers of J^T lambda = -g: lambda = -U_r S_r^-1 V_r^T g.
    const Eigen::VectorXd coeff = (svd.matrixV().leftCols(rank).transpose() * g).cwiseQuotient(s.head(rank));
    lambda = -svd.matrixU().leftCols(rank) * coeff;
  } else {
    model.null_space = Eigen::MatrixXd::Identity(n, n);
  }
  eq.multipliers = lambda;
  eq.tangent_dimension = static_cast<int>(model.null_space.cols());
  const Eigen::VectorXd reduced_gradient = model.null_space.transpose() * g;
  eq.stationarity_residual = reduced_gradient.size() ? reduced_gradient.lpNorm<Eigen::Infinity>() : 0.0;

  Eigen::MatrixXd HL = (m > 0) ? closure_weighted_hessian(system, topology, x, lambda) : Eigen::MatrixXd::Zero(n, n);
  HL.diagonal() += free_entries(system, springs.stiffness);
  model.reduced_hessian = model.null_space.transpose() * HL * model.null_space;
  model.reduced_hessian = 0.5 * (model.reduced_hessian + model.reduced_hessian.transpose());
  if (eq.tangent_dimension > 0) {
    model.eig.compute(model.reduced_hessian);
    eq.reduced_hessian_eigenvalues = model.eig.eigenvalues();
    eq.min_eigenvalue = eq.reduced_hessian_eigenvalues[0];
  } else {
    eq.min_eigenvalue = std::numeric_limits<double>::infinity();
  }

  const double kmax = stiffness_scale(springs);
  const double gscale = std::max(kmax, g.size() ? g.lpNorm<Eigen::Infinity>() : 0.0);
  eq.converged = eq.closure_residual <= options.closure_tolerance &&
                 eq.stationarity_residual <= options.stationarity_tolerance * gscale;
  eq.stable = eq.converged && eq.min_eigenvalue > options.stability_tolerance * kmax;
  return eq;
}

}  // namespace

Equilibrium analyse_equilibrium(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                                const Eigen::VectorXd& x, const EquilibriumOptions& options) {
  LocalModel model;
  return evaluate(system, topology, springs, x, options, model);
}

Equilibrium find_equilibrium(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                             const Eigen::VectorXd& x0, const EquilibriumOptions& options) {
  if (x0.size() != system.num_unknowns()) throw std::invalid_argument("find_equilibrium: x0 needs num_unknowns() entries");
  NewtonOptions projection;
  projection.tolerance = options.closure_tolerance;
  const NewtonResult start = newton_project(system, x0, projection);
  LocalModel model;
  Equilibrium eq = evaluate(system, topology, springs, start.x, options, model);
  if (!start.converged) {
    eq.converged = eq.stable = false;
    eq.message = "the start could not be projected onto the closure manifold";
    return eq;
  }
  for (int it = 0; it < options.max_iterations && !eq.converged; ++it) {
    if (eq.tangent_dimension == 0) break;  // an isolated point: nothing to move along
    // Newton step in tangent coordinates; |eigenvalue| (floored) where H_r is not positive,
    // so the step still descends.
    const Eigen::VectorXd rg = model.null_space.transpose() * model.gradient;
    const Eigen::VectorXd& ev = model.eig.eigenvalues();
    const double floor = 1e-8 * std::max(stiffness_scale(springs), ev.cwiseAbs().maxCoeff());
    const Eigen::VectorXd c = model.eig.eigenvectors().transpose() * rg;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(c.size());
    for (Eigen::Index i = 0; i < c.size(); ++i) y[i] = -c[i] / std::max(std::fabs(ev[i]), floor);
    Eigen::VectorXd p = model.null_space * (model.eig.eigenvectors() * y);
    const double norm = p.lpNorm<Eigen::Infinity>();
    if (norm > options.max_step) p *= options.max_step / norm;
    const double slope = model.gradient.dot(p);  // < 0 for a descent direction

    // Backtracking on E along the projected step; tiny steps (the Newton region) are taken
    // whole, where E changes below its rounding.
    double t = 1.0;
    bool accepted = false;
    Equilibrium next;
    LocalModel next_model;
    for (int ls = 0; ls < 40; ++ls, t *= 0.5) {
      const NewtonResult proj = newton_project(system, eq.x + t * p, projection);
      if (!proj.converged) continue;
      const double e = crease_energy(springs, system.edges_from_unknowns(proj.x));
      if (t * norm < 1e-6 || e <= eq.energy + 1e-4 * t * slope) {
        next = evaluate(system, topology, springs, proj.x, options, next_model);
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      eq.message = "line search failed";
      break;
    }
    eq = std::move(next);
    std::swap(model, next_model);
    eq.iterations = it + 1;
  }
  if (!eq.converged && eq.message.empty())
    eq.message = eq.tangent_dimension == 0 ? "the manifold has no tangent directions here"
                                           : "no convergence within max_iterations";
  return eq;
}

std::vector<Equilibrium> stable_states(const ClosureSystem& system, const Topology& topology,
                                       const CreaseSprings& springs, const std::vector<Eigen::VectorXd>& starts,
                                       const EquilibriumOptions& options, double same_state_tolerance) {
  std::vector<Equilibrium> out;
  for (const Eigen::VectorXd& s : starts) {
    Equilibrium eq = find_equilibrium(system, topology, springs, s, options);
    if (!eq.stable) continue;
    const bool seen = std::any_of(out.begin(), out.end(), [&](const Equilibrium& o) {
      return (o.edge_angles - eq.edge_angles).lpNorm<Eigen::Infinity>() <= same_state_tolerance;
    });
    if (!seen) out.push_back(std::move(eq));
  }
  std::sort(out.begin(), out.end(), [](const Equilibrium& a, const Equilibrium& b) { return a.energy < b.energy; });
  return out;
}

}  // namespace rigidfold
