#include "kernel/solve/bordered_determinant.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <utility>

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
  // Column-pivoted QR, J P = Q R, in place of an SVD (a quarter of the cost; every accepted
  // point of every traced branch pays it: hypar.svg traces 64 branches of 279 unknowns). With
  // rank n-1 the dependent column is pivoted last: |R_(n-2,n-2)| stands for sigma_(n-1) in
  // the DOF test, the null vector is P [-R11^-1 r12; 1], and the first n-1 columns of Q span
  // the range of J. That basis differs from the SVD's leading left vectors by an orthogonal
  // (n-1) x (n-1) factor O: g changes by det(O) = +-1, the same for both determinants of a
  // pair (they share U), so neither the sign test nor the fraction changes.
  if (J.rows() < n) return svd_step(J, along);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::MatrixXd& R = qr.matrixQR();
  if (!(std::abs(R(n - 2, n - 2)) > dof_tolerance_ * std::abs(R(0, 0)))) {  // DOF above 1 here
    ready_ = false;
    return out;
  }
  Eigen::VectorXd permuted(n);
  permuted.head(n - 1) = -R.topLeftCorner(n - 1, n - 1).triangularView<Eigen::Upper>().solve(R.col(n - 1).head(n - 1));
  permuted[n - 1] = 1.0;
  Eigen::VectorXd t = qr.colsPermutation() * permuted;
  t.normalize();
  if (!t.allFinite()) return svd_step(J, along);
  return advance(J, t, qr.householderQ() * Eigen::MatrixXd::Identity(J.rows(), n - 1), along);
}

// The SVD form of step(): for m = n - 1 rows, and as the fallback when the QR's null vector
// is not finite.
BorderedDeterminantMonitor::Step BorderedDeterminantMonitor::svd_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& along) {
  Step out;
  const Eigen::Index n = J.cols();
  Eigen::BDCSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  if (!(s[n - 2] > dof_tolerance_ * s[0])) {  // DOF above 1 here: the point itself is singular
    ready_ = false;
    return out;
  }
  return advance(J, svd.matrixV().col(n - 1), svd.matrixU().leftCols(n - 1), along);
}

BorderedDeterminantMonitor::Step BorderedDeterminantMonitor::advance(const Eigen::MatrixXd& J, Eigen::VectorXd t,
                                                                     Eigen::MatrixXd U, const Eigen::VectorXd& along) {
  Step out;
  out.applicable = true;
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
  U_ = std::move(U);
  J_ = J;
  t_ = std::move(t);
  ready_ = true;
  return out;
}

}  // namespace rigidfold
