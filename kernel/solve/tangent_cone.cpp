#include "kernel/solve/tangent_cone.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <exception>
#include <thread>

#include "kernel/closure/closure_second_order.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {
namespace {

// Random unit vectors from a portable stream (Box-Muller): the same starts on every platform.
struct Starts {
  SplitMix64 stream;
  Eigen::VectorXd unit(int k) {
    Eigen::VectorXd c(k);
    for (int i = 0; i < k; ++i)
      c[i] = std::sqrt(-2 * std::log(stream.open_uniform())) * std::cos(6.283185307179586 * stream.open_uniform());
    return c.normalized();
  }
};

Eigen::VectorXd quadratics(const std::vector<Eigen::MatrixXd>& H, const Eigen::VectorXd& c) {
  Eigen::VectorXd q(H.size());
  for (std::size_t j = 0; j < H.size(); ++j) q[static_cast<int>(j)] = c.dot(H[j] * c);
  return q;
}

// Rank of the quadratics' gradients projected on the sphere's tangent space at c.
int tangent_rank(const std::vector<Eigen::MatrixXd>& H, const Eigen::VectorXd& c, double tol) {
  const int k = static_cast<int>(c.size());
  if (k <= 1) return 0;
  Eigen::MatrixXd G(H.size(), k);
  for (std::size_t j = 0; j < H.size(); ++j) G.row(static_cast<int>(j)) = 2.0 * (H[j] * c).transpose();
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(k, k) - c * c.transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(G * P);
  const auto& s = svd.singularValues();
  int r = 0;
  for (int i = 0; i < s.size(); ++i) r += s[i] > tol;
  return r;
}

// One Gauss-Newton start on [q(c); |c|^2 - 1] = 0 from r.c; on return r.c is where it
// ended and r.ok whether |q|_inf <= accept there.
struct StartResult {
  Eigen::VectorXd c;
  bool ok = false;
};

void converge_start(const std::vector<Eigen::MatrixXd>& H, double accept, StartResult& r) {
  const int k = static_cast<int>(r.c.size()), p = static_cast<int>(H.size());
  Eigen::VectorXd& c = r.c;
  Eigen::MatrixXd Hc(k, p);  // column j: H_j c, for both q_j = c . H_j c and the Jacobian row 2 (H_j c)^T
  std::vector<double> history;  // |q|_inf per iteration
  for (int it = 0; it < 60; ++it) {
    for (int j = 0; j < p; ++j) Hc.col(j).noalias() = H[j] * c;
    const Eigen::VectorXd q = Hc.transpose() * c;
    history.push_back(q.lpNorm<Eigen::Infinity>());
    if (history.back() <= 1e-3 * accept) {
      r.ok = true;
      return;
    }
    // A plateau: the least |q| of the last kStallWindow iterations is not 10% below the least
    // before them. A start that converges, even linearly at a singular solution (ratio 1/2
    // per step), falls far more; the first steps may oscillate, hence the long window. On the
    // hypar (kernel 93, 93 quadratics) 195 of 240 starts sat on plateaus for 45 of their 60
    // steps.
    constexpr int kStallWindow = 10;
    if (it >= kStallWindow) {
      const auto split = history.end() - kStallWindow;
      if (*std::min_element(split, history.end()) > 0.9 * *std::min_element(history.begin(), split)) break;
    }
    // Minimum-norm Gauss-Newton step on [q(c); |c|^2 - 1] = 0.
    Eigen::MatrixXd A(p + 1, k);
    Eigen::VectorXd b(p + 1);
    A.topRows(p) = 2.0 * Hc.transpose();
    A.row(p) = 2.0 * c.transpose();
    b.head(p) = q;
    b[p] = c.squaredNorm() - 1.0;
    const Eigen::VectorXd dc = A.completeOrthogonalDecomposition().solve(b);
    c -= dc;
    c.normalize();
    if (dc.norm() < 1e-15) break;
  }
  r.ok = quadratics(H, c).lpNorm<Eigen::Infinity>() <= accept;
}

// A one-dimensional kernel with no second-order condition is itself the one tangent line.
void add_single_kernel_line(TangentCone& cone) {
  if (cone.kernel_dimension != 1) return;
  TangentLine line;
  Eigen::VectorXd d = cone.kernel.col(0);
  Eigen::Index big;
  d.cwiseAbs().maxCoeff(&big);
  line.direction = (d[big] < 0 ? -d : d).normalized();
  line.isolated = true;
  cone.lines.push_back(line);
}

}  // namespace

TangentCone tangent_cone(const ClosureSystem& system, const Topology& topology, const Eigen::VectorXd& x,
                         const TangentConeOptions& options) {
  TangentCone cone;
  const Eigen::MatrixXd J = dense_jacobian(system, x);
  const int m = static_cast<int>(J.rows()), n = static_cast<int>(J.cols());
  if (m == 0) {
    // No closure rows (no interior vertex, no hole): every direction is free and there are
    // no second-order conditions (Eigen's SVD must not see an empty matrix: it crashes).
    cone.kernel_dimension = n;
    cone.kernel = Eigen::MatrixXd::Identity(n, n);
    cone.quadratics_vanish = true;
    add_single_kernel_line(cone);
    return cone;
  }
  Eigen::BDCSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  cone.sigma_max = sv.size() ? sv[0] : 0.0;
  const double cut = options.rank_tolerance * std::max(cone.sigma_max, 1e-300);
  int rank = 0;
  while (rank < sv.size() && sv[rank] > cut) ++rank;
  cone.sigma_smallest_kept = rank > 0 ? sv[rank - 1] : 0.0;
  cone.sigma_largest_dropped = rank < sv.size() ? sv[rank] : 0.0;
  const int k = n - rank, p = m - rank;
  cone.kernel_dimension = k;
  cone.left_null_dimension = p;
  cone.kernel = svd.matrixV().rightCols(k);
  if (k == 0) return cone;
  const Eigen::MatrixXd U = svd.matrixU().rightCols(p);

  // H_j by polarisation of the exact quadratic q(c) = U^T D^2 r[N c, N c].
  auto q_of = [&](const Eigen::VectorXd& c) -> Eigen::VectorXd {
    return U.transpose() * closure_second_derivative(system, topology, x, cone.kernel * c);
  };
  std::vector<Eigen::MatrixXd> H(p, Eigen::MatrixXd::Zero(k, k));
  for (int a = 0; a < k; ++a) {
    const Eigen::VectorXd qa = q_of(Eigen::VectorXd::Unit(k, a));
    for (int j = 0; j < p; ++j) H[j](a, a) = qa[j];
    for (int b = a + 1; b < k; ++b) {
      const Eigen::VectorXd ep = Eigen::VectorXd::Unit(k, a) + Eigen::VectorXd::Unit(k, b);
      const Eigen::VectorXd em = Eigen::VectorXd::Unit(k, a) - Eigen::VectorXd::Unit(k, b);
      const Eigen::VectorXd qab = 0.25 * (q_of(ep) - q_of(em));
      for (int j = 0; j < p; ++j) H[j](a, b) = H[j](b, a) = qab[j];
    }
  }
  // Scale: D^2 r is O(|J|) for unit directions (the vertex rows are products of rotations).
  const double scale = std::max(1.0, cone.sigma_max);
  double hmax = 0.0;
  for (const auto& h : H) hmax = std::max(hmax, h.cwiseAbs().maxCoeff());
  if (hmax <= options.quadratic_tolerance * scale) {
    cone.quadratics_vanish = true;
    add_single_kernel_line(cone);
    return cone;
  }
  const double accept = options.quadratic_tolerance * scale;

  // The starts are independent: they run in batches on up to two threads when the
  // quadratics are large enough to pay for a thread (hypar.svg: k = p = 93, ~1 M flops per
  // iteration), and their results are taken in start order, so the lines found are the
  // same, in the same order, as one thread would find them.
  Starts gen{options.seed};
  const int threads = static_cast<double>(k) * k * p >= 1e5 ? 2 : 1;
  const int batch = 4 * threads;
  std::vector<Eigen::VectorXd> found;
  for (int first = 0; first < options.starts && static_cast<int>(found.size()) < options.max_lines; first += batch) {
    const int count = std::min(batch, options.starts - first);
    std::vector<StartResult> results(count);
    for (int i = 0; i < count; ++i) results[i].c = k == 1 ? Eigen::VectorXd::Ones(1) : gen.unit(k);
    const auto run = [&](int from) {
      for (int i = from; i < count; i += threads) converge_start(H, accept, results[i]);
    };
    if (threads > 1) {
      // An exception in the helper (std::bad_alloc under a memory limit) must reach the caller,
      // not std::terminate: it is carried over and rethrown after the join.
      std::exception_ptr helper_failed;
      std::thread helper([&] {
        try {
          run(1);
        } catch (...) {
          helper_failed = std::current_exception();
        }
      });
      try {
        run(0);
      } catch (...) {
        helper.join();
        throw;
      }
      helper.join();
      if (helper_failed) std::rethrow_exception(helper_failed);
    } else {
      run(0);
    }
    for (int i = 0; i < count && static_cast<int>(found.size()) < options.max_lines; ++i) {
      if (!results[i].ok) continue;
      Eigen::VectorXd c = k == 1 ? Eigen::VectorXd::Ones(1) : results[i].c;
      bool seen = false;
      for (const auto& f : found) seen = seen || 1.0 - std::abs(f.dot(c)) < options.same_line;
      if (seen) continue;
      found.push_back(c);
      TangentLine line;
      Eigen::VectorXd d = cone.kernel * c;
      Eigen::Index big;
      d.cwiseAbs().maxCoeff(&big);
      if (d[big] < 0) d = -d;
      line.direction = d.normalized();
      line.quadratic_residual = quadratics(H, c).lpNorm<Eigen::Infinity>() / hmax;
      line.isolated = tangent_rank(H, c, 1e-6 * hmax) >= k - 1;
      cone.lines.push_back(line);
      if (k == 1) return cone;
    }
  }
  return cone;
}

}  // namespace rigidfold
