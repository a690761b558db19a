#include "kernel/solve/amplitude_search.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rigidfold {
namespace {

double inf_norm(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

struct Point {
  Eigen::VectorXd x, r;
  Eigen::SparseMatrix<double> J;
  double a = 0.0;          // ||x|| - amplitude
  Eigen::VectorXd g;       // d||x||/dx
  double objective = 0.0;  // ||r||^2 + a^2
};

Point evaluate(const ClosureSystem& sys, const Eigen::VectorXd& x, double amplitude) {
  Point p;
  p.x = x;
  sys.evaluate(x, p.r, p.J);
  const double nx = x.norm();
  p.a = nx - amplitude;
  p.g = nx > 0 ? Eigen::VectorXd(x / nx) : Eigen::VectorXd::Zero(x.size());
  p.objective = p.r.squaredNorm() + p.a * p.a;
  return p;
}

}  // namespace

AmplitudeSearchResult amplitude_search(const ClosureSystem& sys, const Eigen::VectorXd& x0,
                                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                       const AmplitudeSearchOptions& opt) {
  const int n = sys.num_unknowns();
  if (x0.size() != n || lower.size() != n || upper.size() != n)
    throw std::invalid_argument("amplitude_search: x0 and bounds must have one entry per unknown");
  if ((lower.array() > upper.array()).any()) throw std::invalid_argument("amplitude_search: a lower bound exceeds its upper bound");
  if (!(opt.amplitude > 0)) throw std::invalid_argument("amplitude_search: the amplitude must be positive");

  AmplitudeSearchResult out;
  Point p = evaluate(sys, x0.cwiseMax(lower).cwiseMin(upper), opt.amplitude);
  Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  // The pattern the symbolic analysis was done for (Eigen keeps structural zeros in these
  // products, so it stays the same between steps; compared in full to be sure).
  std::vector<int> analysed_outer, analysed_inner;
  auto same_pattern = [&](const Eigen::SparseMatrix<double>& A) {
    return std::equal(analysed_outer.begin(), analysed_outer.end(), A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1) &&
           std::equal(analysed_inner.begin(), analysed_inner.end(), A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  };
  double mu = 1e-6;
  std::vector<double> history{p.objective};
  auto done = [&](const Point& q) { return inf_norm(q.r) <= opt.tolerance && std::abs(q.a) <= opt.tolerance; };

  while (out.iterations < opt.max_iterations && !done(p) && mu <= 1e8) {
    const Eigen::VectorXd grad = p.J.transpose() * p.r + p.g * p.a;
    // Projected: held unknowns (at a bound, the descent pointing out of the box) get no step.
    // Logarithmic: an unknown strictly on the far side of a bound at 0 (a lettered crease) is
    // stepped in y = log|x| (column scaled by x, update x exp(dy)); the others additively.
    Eigen::VectorXd free_mask(n), scale(n);
    std::vector<char> in_log(n, 0);
    for (int i = 0; i < n; ++i) {
      const bool held = (p.x[i] <= lower[i] && grad[i] > 0) || (p.x[i] >= upper[i] && grad[i] < 0);
      in_log[i] = opt.logarithmic && ((lower[i] == 0.0 && p.x[i] > 0.0) || (upper[i] == 0.0 && p.x[i] < 0.0));
      free_mask[i] = held && !in_log[i] ? 0.0 : 1.0;
      scale[i] = in_log[i] ? p.x[i] : free_mask[i];
    }
    if (free_mask.sum() == 0) break;
    const Eigen::SparseMatrix<double> Jf = p.J * scale.asDiagonal();  // held columns scaled to 0, pattern kept
    const Eigen::SparseMatrix<double> JtJ = Jf.transpose() * Jf;
    const Eigen::VectorXd b = -(grad.cwiseProduct(scale));
    const Eigen::VectorXd gf = p.g.cwiseProduct(scale);
    bool accepted = false;
    while (mu <= 1e8) {
      // Free unknowns get the damping mu, held ones a unit diagonal (their step is 0: b and gf are 0 there).
      Eigen::SparseMatrix<double> I(n, n);
      I.setIdentity();
      const Eigen::VectorXd diag = free_mask * mu + (Eigen::VectorXd::Ones(n) - free_mask);
      const Eigen::SparseMatrix<double> A = JtJ + Eigen::SparseMatrix<double>(I * diag.asDiagonal());
      if (!A.isCompressed() || !same_pattern(A)) {
        llt.analyzePattern(A);
        analysed_outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
        analysed_inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      }
      llt.factorize(A);
      ++out.factorizations;
      if (llt.info() != Eigen::Success) {
        mu *= 4;
        continue;
      }
      const Eigen::VectorXd y = llt.solve(b), z = llt.solve(gf);
      const Eigen::VectorXd d = y - z * (gf.dot(y) / (1.0 + gf.dot(z)));
      if (!d.allFinite()) {
        mu *= 4;
        continue;
      }
      Eigen::VectorXd next = p.x + d.cwiseProduct(scale);
      for (int i = 0; i < n; ++i)
        if (in_log[i]) next[i] = p.x[i] * std::exp(std::clamp(d[i], -30.0, 2.0));
      Point q = evaluate(sys, next.cwiseMax(lower).cwiseMin(upper), opt.amplitude);
      if (q.objective < p.objective) {
        p = std::move(q);
        mu = std::max(mu / 3, 1e-15);
        accepted = true;
        break;
      }
      mu *= 4;
    }
    if (!accepted) break;
    ++out.iterations;
    history.push_back(p.objective);
    const int w = opt.stall_window;
    if (w > 0 && static_cast<int>(history.size()) > w &&
        p.objective > opt.stall_factor * history[history.size() - 1 - static_cast<std::size_t>(w)])
      break;
  }
  out.x = p.x;
  out.closure_residual = inf_norm(p.r);
  out.amplitude = p.x.norm();
  out.converged = done(p);
  return out;
}

}  // namespace rigidfold
