#include "kernel/solve/bifurcation.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <limits>

#include "kernel/solve/bordered_determinant.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {
LocatedSingularPoint locate_singular_point(const ClosureSystem& system, const Topology& topology,
                                           const Eigen::VectorXd& xa, const Eigen::VectorXd& xb,
                                           double parameter_tolerance) {
  LocatedSingularPoint out;
  out.error_bound = std::numeric_limits<double>::infinity();
  const int n = system.num_unknowns();
  if (n < 2 || xa.size() != n || xb.size() != n) return out;
  const Eigen::MatrixXd Ja = dense_jacobian(system, xa);
  if (Ja.rows() < n - 1) return out;  // a DOF-1 path needs n - 1 independent rows
  Eigen::JacobiSVD<Eigen::MatrixXd> svd_a(Ja, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::MatrixXd Ua = svd_a.matrixU().leftCols(n - 1);
  Eigen::VectorXd ta = svd_a.matrixV().col(n - 1);
  if (ta.dot(xb - xa) < 0) ta = -ta;
  auto bordered = [&](const Eigen::VectorXd& x) {
    const Eigen::MatrixXd J = dense_jacobian(system, x);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    Eigen::VectorXd t = svd.matrixV().col(n - 1);
    if (t.dot(ta) < 0) t = -t;
    return bordered_determinant(Ua, J, t);
  };
  const double ga = bordered(xa), gb = bordered(xb);
  if (!(ga * gb < 0)) return out;
  const double sb = ta.dot(xb - xa);

  // Point of the branch at pseudo-arclength s, by Newton on [r(x); ta.(x - xa) - s] from x0.
  auto correct = [&](Eigen::VectorXd x, double s, bool& ok) {
    ok = false;
    for (int it = 0; it < 30; ++it) {
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> Js;
      system.evaluate(x, r, Js);
      Eigen::MatrixXd A(Js.rows() + 1, n);
      A.topRows(Js.rows()) = Eigen::MatrixXd(Js);
      A.row(Js.rows()) = ta.transpose();
      Eigen::VectorXd ra(Js.rows() + 1);
      ra.head(Js.rows()) = r;
      ra[Js.rows()] = ta.dot(x - xa) - s;
      if (ra.lpNorm<Eigen::Infinity>() <= 1e-13) {
        ok = true;
        return x;
      }
      x -= A.completeOrthogonalDecomposition().solve(ra);
    }
    return x;
  };
  // Second smallest of the n singular values of J (zero-padded when J has fewer rows).
  auto sigma2 = [&](const Eigen::VectorXd& x, Eigen::VectorXd* tangent) {
    const Eigen::MatrixXd J = dense_jacobian(system, x);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    if (tangent) {
      *tangent = svd.matrixV().col(n - 1);
      if (tangent->dot(ta) < 0) *tangent = -*tangent;
    }
    const auto& sv = svd.singularValues();
    return n - 2 < sv.size() ? sv[n - 2] : 0.0;
  };
  // Stage 1 (header): march from xa (s = 0) toward the root, never past `hi`, the smallest
  // s known to lie beyond s* (where g has the sign of gb).
  double s = 0.0, hi = sb, estimate = sb * ga / (ga - gb), last_move = 0.0;
  Eigen::VectorXd x = xa, t;
  double f = sigma2(x, &t);
  for (int step = 0; step < 200; ++step) {
    const double s_next = s + 0.5 * (std::min(estimate, hi) - s);
    bool ok = false;
    const Eigen::VectorXd x_next = correct(x + (s_next - s) * t, s_next, ok);
    if (!ok) return out;
    ++out.steps;
    Eigen::VectorXd t_next;
    const double f_next = sigma2(x_next, &t_next);
    if ((bordered(x_next) > 0) != (ga > 0) || f_next >= f) {
      // Passed s*: tighten the bound and retry from the same point.
      hi = s_next;
      estimate = 0.5 * (s + hi);
      continue;
    }
    // Linear extrapolation of f (which falls linearly to 0 at s*) through the last two points.
    const double new_estimate = std::min(s_next + f_next * (s_next - s) / (f - f_next), hi);
    last_move = std::abs(new_estimate - estimate);
    s = s_next;
    x = x_next;
    t = t_next;
    f = f_next;
    estimate = new_estimate;
    if (last_move <= parameter_tolerance && std::abs(estimate - s) <= 1e3 * parameter_tolerance) break;
  }
  bool ok = false;
  const Eigen::VectorXd start = correct(x + (estimate - s) * t, estimate, ok);
  if (!ok || !(last_move <= parameter_tolerance)) return out;

  // Stage 2: the regular extended system, with Ua as the basis of the left null vector.
  out.refinement = solve_branch_point(system, topology, start, Ua);
  out.x = out.refinement.x;
  out.error_bound = out.refinement.error_bound;
  out.parameter = ta.dot(out.x - xa);
  out.residual = system.residual(out.x).lpNorm<Eigen::Infinity>();
  // Inside the bracket (up to the bound): not a branch point found beyond it.
  const double slack = out.error_bound;
  out.found = out.refinement.converged && out.parameter >= -slack && out.parameter <= sb + slack;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense_jacobian(system, out.x));
  const auto& sv = svd.singularValues();
  out.sigma_max = sv.size() ? sv[0] : 0.0;
  out.sigma_second_smallest = n - 2 < sv.size() ? sv[n - 2] : 0.0;
  return out;
}

BranchDeparture leave_singular_point(const ClosureSystem& system, const Eigen::VectorXd& x_star,
                                     const Eigen::VectorXd& d, double h) {
  BranchDeparture out;
  Eigen::Index j;
  d.cwiseAbs().maxCoeff(&j);
  out.held_unknown = static_cast<int>(j);
  NewtonOptions nopt;
  nopt.held_unknowns = {static_cast<int>(j)};
  const NewtonResult nr = newton_project(system, x_star + h * d, nopt);
  out.converged = nr.converged;
  out.x = nr.x;
  out.residual = nr.residual_history.empty() ? 0.0 : nr.residual_history.back();
  const Eigen::VectorXd chord = out.x - x_star;
  out.chord_alignment = chord.norm() > 0 ? chord.dot(d) / (chord.norm() * d.norm()) : 0.0;
  return out;
}

}  // namespace rigidfold
