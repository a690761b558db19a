#pragma once
// Bordered determinant along a 1-DOF branch: the test function of bifurcation detection
// (docs/DESIGN.md, "Bifurcations: detection").
//
//   g(x) = det [ U^T J(x) ; t(x)^T ]
// U (n x ... : m x (n-1)) holds the n-1 leading left singular vectors of J at a reference point
// of the branch, t(x) the unit null direction of J(x) (its last right singular vector),
// oriented along the travel. Near the reference point U^T J(x) has full rank n-1 and t(x) is
// transverse to its rows, so g != 0; g changes sign where the branch crosses another one
// (J drops to rank n-2 and the oriented null direction swings through the other branch).
//
// Inputs: dense Jacobians (m x n, m >= n - 1), unknowns in radians. Outputs: determinants
// (no unit), a fraction in [0, 1] for linear interpolation between two points.
#include <Eigen/Core>

namespace rigidfold {

// g for given U (m x (n-1)), J (m x n) and unit t (n).
double bordered_determinant(const Eigen::MatrixXd& U, const Eigen::MatrixXd& J, const Eigen::VectorXd& t);

// Follows g along accepted points of a branch. U is chosen afresh at every point (the earlier
// point of each pair), so it stays well conditioned along the whole branch.
class BorderedDeterminantMonitor {
 public:
  struct Step {
    bool applicable = false;    // J has >= n-1 rows and sigma_{n-1} > dof_tolerance * sigma_max
    bool sign_changed = false;  // g changed sign since the previous point
    double fraction = 0.0;      // where, by linear interpolation of g (0 = previous point)
  };
  BorderedDeterminantMonitor() = default;
  explicit BorderedDeterminantMonitor(double dof_tolerance) : dof_tolerance_(dof_tolerance) {}
  // Moves to the point whose dense Jacobian is J; `along` orients its tangent (travel
  // direction). The first point after construction or reset() only records itself.
  Step step(const Eigen::MatrixXd& J, const Eigen::VectorXd& along);
  void reset() { ready_ = false; }
  // Unit tangent at the last point (oriented along the travel); empty before the first step.
  const Eigen::VectorXd& tangent() const { return t_; }

 private:
  Step svd_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& along);
  // The common end of both forms at an applicable point: g's sign test against the last
  // point, then (J, t, U) become the reference of the next pair.
  Step advance(const Eigen::MatrixXd& J, Eigen::VectorXd t, Eigen::MatrixXd U, const Eigen::VectorXd& along);

  double dof_tolerance_ = 1e-9;  // relative to sigma_max, as jacobian_rank's default cut
  bool ready_ = false;
  Eigen::MatrixXd U_, J_;
  Eigen::VectorXd t_;
};

}  // namespace rigidfold
