#include "kernel/solve/bordered_determinant.hpp"

#include <Eigen/Dense>

namespace rigidfold {

double bordered_determinant(const Eigen::MatrixXd& U, const Eigen::MatrixXd& J, const Eigen::VectorXd& t) {
  const Eigen::Index n = J.cols();
  Eigen::MatrixXd B(n, n);
  B.topRows(n - 1) = U.transpose() * J;
  B.row(n - 1) = t.transpose();
  return B.determinant();
}

BorderedDeterminantMonitor::Step BorderedDeterminantMonitor::step(const Eigen::MatrixXd& J, const Eigen::VectorXd& along) {
  Step out;
  const Eigen::Index n = J.cols();
  if (n < 2 || J.rows() < n - 1) {  // fewer rows than a DOF-1 path needs: no bordered determinant
    ready_ = false;
    return out;
  }
  // Divide and conquer: at every point of every traced branch, on Jacobians of a few hundred
  // columns Jacobi's one-sided rotations took most of a check's time (hypar.svg: 63%).
  // Thin factors hold everything used here (n-1 left vectors, the last right vector) when
  // m >= n; the full m x m U cost a quarter of a hypar.svg check.
  const unsigned int factors = J.rows() >= n ? Eigen::ComputeThinU | Eigen::ComputeThinV : Eigen::ComputeFullU | Eigen::ComputeFullV;
  Eigen::BDCSVD<Eigen::MatrixXd> svd(J, factors);
  const Eigen::VectorXd& s = svd.singularValues();
  if (!(s[n - 2] > dof_tolerance_ * s[0])) {  // DOF above 1 here: the point itself is singular
    ready_ = false;
    return out;
  }
  out.applicable = true;
  Eigen::VectorXd t = svd.matrixV().col(n - 1);
  if (t.dot(along) < 0) t = -t;
  if (ready_) {
    Eigen::VectorXd t_here = t;
    if (t_here.dot(t_) < 0) t_here = -t_here;
    const double d0 = bordered_determinant(U_, J_, t_), d1 = bordered_determinant(U_, J, t_here);
    if ((d0 > 0) != (d1 > 0)) {
      out.sign_changed = true;
      out.fraction = d0 / (d0 - d1);
    }
  }
  U_ = svd.matrixU().leftCols(n - 1);
  J_ = J;
  t_ = t;
  ready_ = true;
  return out;
}

}  // namespace rigidfold
