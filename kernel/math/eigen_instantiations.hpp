#pragma once
// Eigen's dense decompositions of dynamic double matrices, compiled once for the whole project
// (eigen_instantiations.cpp) instead of once in every file that uses them: `extern template`
// keeps a file from instantiating a decomposition's out-of-line members (compute() and what it
// calls, the bulk of the code), and the linker takes them from the kernel library. Every target
// of cmake/compile_time.cmake includes this header first; a file compiled without it still
// builds, instantiating its own copy. Measured on kernel/solve/tangent_cone.cpp (clang 14,
// ASan + UBSan, -O2): 87 s -> 28 s.
#include <Eigen/Dense>

extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::BDCSVD<Eigen::MatrixXd>;
extern template class Eigen::HouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>;
extern template class Eigen::FullPivLU<Eigen::MatrixXd>;
extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
extern template class Eigen::LLT<Eigen::MatrixXd>;
extern template class Eigen::LDLT<Eigen::MatrixXd>;
extern template class Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>;
extern template class Eigen::EigenSolver<Eigen::MatrixXd>;
