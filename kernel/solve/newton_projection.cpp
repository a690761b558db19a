#include "kernel/solve/newton_projection.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/solve/preconditioned_cgls.hpp"

namespace rigidfold {

namespace {

int cholmod_ordering(FactorOrdering o) {
  switch (o) {
    case FactorOrdering::kAmd: return CHOLMOD_AMD;
    case FactorOrdering::kMetis: return CHOLMOD_METIS;
    case FactorOrdering::kNestedDissection: return CHOLMOD_NESDIS;
    case FactorOrdering::kDefault: break;
  }
  return -1;
}

// CHOLMOD's factorisation with the simplicial/supernodal choice made by its own rule
// (supernodal iff flops / nnz(L) >= supernodal_switch), and the choice readable afterwards.
// A simplicial factor is converted to LL^T as CholmodSimplicialLLT does (final_ll).
class CholmodFactor : public Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, CholmodFactor> {
 public:
  explicit CholmodFactor(double supernodal_flops_per_entry) {
    m_cholmod.final_asis = 0;
    m_cholmod.final_ll = 1;
    if (std::isinf(supernodal_flops_per_entry)) {
      m_cholmod.supernodal = CHOLMOD_SIMPLICIAL;
    } else {
      m_cholmod.supernodal = CHOLMOD_AUTO;
      m_cholmod.supernodal_switch = supernodal_flops_per_entry;
    }
  }
  bool supernodal() const { return m_cholmodFactor != nullptr && m_cholmodFactor->is_super; }
};

}  // namespace

// The symbolic side is built once from J's pattern:
//   - free[c]: index of unknown c among the kept columns (-1 if held);
//   - rows of J grouped into runs of consecutive rows with the same kept columns (the 3
//     rows of a vertex share its creases), each with its column list and, for every pair
//     (a >= b) of that list, the slot of entry (col a, col b) in G's lower triangle;
//   - for each row, the positions in J's value array of its entries, in the run's order.
struct MinimumNormSolver::Impl {
  int m = 0, n = 0, nf = 0;
  std::vector<int> free;                 // n
  std::vector<int> kept;                 // nf: unknown of each kept column
  std::vector<int> run_begin;            // runs + 1: first row of each run
  std::vector<int> run_cols_begin;       // runs + 1: into run_cols
  std::vector<int> run_cols;             // kept-column indices of each run
  std::vector<int> run_pairs_begin;      // runs + 1: into pair_slot
  std::vector<int> pair_slot;            // G value slot of each pair (a, b <= a), row-major
  std::vector<int> row_vals;             // per row, J value positions, in its run's column order
  std::vector<int> row_vals_begin;       // m + 1
  std::vector<int> diag_slot;            // nf: G value slot of each diagonal entry
  Eigen::SparseMatrix<double> G;         // nf x nf, lower triangle, fixed pattern
  CholmodFactor llt;
  bool analysed = false;
  explicit Impl(double supernodal_flops_per_entry) : llt(supernodal_flops_per_entry) {}

  void kept_transpose_times(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r, Eigen::VectorXd& out) const {
    out.resize(nf);
    for (int f = 0; f < nf; ++f) {
      const int c = kept[f];
      double s = 0.0;
      for (int p = J.outerIndexPtr()[c]; p < J.outerIndexPtr()[c + 1]; ++p) s += J.valuePtr()[p] * r[J.innerIndexPtr()[p]];
      out[f] = s;
    }
  }
  // y = J_f z, z over kept columns.
  void kept_times(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& z, Eigen::VectorXd& y) const {
    y.setZero(m);
    for (int f = 0; f < nf; ++f) {
      const int c = kept[f];
      for (int p = J.outerIndexPtr()[c]; p < J.outerIndexPtr()[c + 1]; ++p) y[J.innerIndexPtr()[p]] += J.valuePtr()[p] * z[f];
    }
  }
  // Minimum-norm z over kept columns with J_f z = r: z = G^-1 J_f^T r plus one refinement.
  Eigen::VectorXd solve_kept(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r) const {
    Eigen::VectorXd rhs, lin;
    kept_transpose_times(J, r, rhs);
    Eigen::VectorXd z = llt.solve(rhs);
    kept_times(J, z, lin);
    lin = r - lin;
    kept_transpose_times(J, lin, rhs);
    z += llt.solve(rhs);
    return z;
  }
};

MinimumNormSolver::MinimumNormSolver(const Eigen::SparseMatrix<double>& J, const std::vector<int>& held,
                                     FactorOrdering ordering, double supernodal_flops_per_entry)
    : impl_(std::make_unique<Impl>(supernodal_flops_per_entry)) {
  if (!(supernodal_flops_per_entry >= 0))
    throw std::invalid_argument("MinimumNormSolver: supernodal_flops_per_entry must be >= 0");
  Impl& s = *impl_;
  if (!J.isCompressed()) throw std::invalid_argument("MinimumNormSolver: the Jacobian must be compressed");
  s.m = static_cast<int>(J.rows());
  s.n = static_cast<int>(J.cols());
  s.free.assign(s.n, 0);
  for (int k : held) {
    if (k < 0 || k >= s.n) throw std::invalid_argument("MinimumNormSolver: held unknown " + std::to_string(k) + " out of range");
    s.free[k] = -1;
  }
  for (int c = 0; c < s.n; ++c)
    if (s.free[c] >= 0) {
      s.free[c] = s.nf++;
      s.kept.push_back(c);
    }
  // Row-wise view of the kept entries (J is CSC): per row, (kept column, value position).
  std::vector<int> row_count(s.m + 1, 0);
  for (int c = 0; c < s.n; ++c)
    if (s.free[c] >= 0)
      for (int p = J.outerIndexPtr()[c]; p < J.outerIndexPtr()[c + 1]; ++p) ++row_count[J.innerIndexPtr()[p] + 1];
  for (int i = 0; i < s.m; ++i) row_count[i + 1] += row_count[i];
  s.row_vals_begin = row_count;
  s.row_vals.resize(row_count[s.m]);
  std::vector<int> row_cols(row_count[s.m]);
  {
    std::vector<int> next(row_count.begin(), row_count.end() - 1);
    for (int c = 0; c < s.n; ++c)  // columns in increasing order: each row's list is sorted by column
      if (s.free[c] >= 0)
        for (int p = J.outerIndexPtr()[c]; p < J.outerIndexPtr()[c + 1]; ++p) {
          const int i = J.innerIndexPtr()[p];
          row_cols[next[i]] = s.free[c];
          s.row_vals[next[i]++] = p;
        }
  }
  auto same_cols = [&](int a, int b) {
    return std::equal(row_cols.begin() + row_count[a], row_cols.begin() + row_count[a + 1],
                      row_cols.begin() + row_count[b], row_cols.begin() + row_count[b + 1]);
  };
  // Runs of rows with the same columns.
  for (int i = 0; i < s.m;) {
    int j = i + 1;
    while (j < s.m && same_cols(i, j)) ++j;
    s.run_begin.push_back(i);
    s.run_cols_begin.push_back(static_cast<int>(s.run_cols.size()));
    for (int p = row_count[i]; p < row_count[i + 1]; ++p) s.run_cols.push_back(row_cols[p]);
    i = j;
  }
  s.run_begin.push_back(s.m);
  s.run_cols_begin.push_back(static_cast<int>(s.run_cols.size()));
  const int runs = static_cast<int>(s.run_begin.size()) - 1;
  // The lower-triangle pattern of G, column by column, in flat arrays (one vector per column
  // cost ~0.3 s of allocations at 2M unknowns): the diagonal (always there, lambda) and, per
  // run, every pair (a > b) of its sorted columns; counted, filled, then sorted and made unique
  // per column.
  std::vector<int> outer(s.nf + 1, 0), inner;
  {
    std::vector<int> start(s.nf + 1, 0);
    for (int f = 0; f < s.nf; ++f) start[f + 1] = 1;
    for (int g = 0; g < runs; ++g)
      for (int b = s.run_cols_begin[g]; b < s.run_cols_begin[g + 1]; ++b)
        start[s.run_cols[b] + 1] += s.run_cols_begin[g + 1] - 1 - b;  // the later columns of the run
    for (int f = 0; f < s.nf; ++f) start[f + 1] += start[f];
    std::vector<int> rows(start[s.nf]);
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int f = 0; f < s.nf; ++f) rows[next[f]++] = f;
    for (int g = 0; g < runs; ++g)
      for (int b = s.run_cols_begin[g]; b < s.run_cols_begin[g + 1]; ++b)
        for (int a = b + 1; a < s.run_cols_begin[g + 1]; ++a) rows[next[s.run_cols[b]]++] = s.run_cols[a];
    inner.reserve(start[s.nf]);
    for (int f = 0; f < s.nf; ++f) {
      auto first = rows.begin() + start[f], last = rows.begin() + start[f + 1];
      std::sort(first, last);
      inner.insert(inner.end(), first, std::unique(first, last));
      outer[f + 1] = static_cast<int>(inner.size());
    }
  }
  s.G.resize(s.nf, s.nf);
  s.G.resizeNonZeros(outer[s.nf]);
  std::copy(outer.begin(), outer.end(), s.G.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), s.G.innerIndexPtr());
  std::fill(s.G.valuePtr(), s.G.valuePtr() + outer[s.nf], 0.0);
  auto slot = [&](int row, int col) {  // row >= col
    const int* first = inner.data() + outer[col];
    const int* last = inner.data() + outer[col + 1];
    return static_cast<int>(std::lower_bound(first, last, row) - inner.data());
  };
  s.diag_slot.resize(s.nf);
  for (int f = 0; f < s.nf; ++f) s.diag_slot[f] = outer[f];  // rows sorted, diagonal first
  s.run_pairs_begin.assign(1, 0);
  for (int g = 0; g < runs; ++g) {
    const int* cols = s.run_cols.data() + s.run_cols_begin[g];
    const int d = s.run_cols_begin[g + 1] - s.run_cols_begin[g];
    for (int a = 0; a < d; ++a)
      for (int b = 0; b <= a; ++b) s.pair_slot.push_back(slot(cols[a], cols[b]));
    s.run_pairs_begin.push_back(static_cast<int>(s.pair_slot.size()));
  }
  s.llt.cholmod().print = 0;  // a failed (non-positive) pivot is handled here, not printed
  if (const int ord = cholmod_ordering(ordering); ord >= 0) {
    s.llt.cholmod().nmethods = 1;
    s.llt.cholmod().method[0].ordering = ord;
  }
}

MinimumNormSolver::~MinimumNormSolver() = default;

int MinimumNormSolver::unknowns() const { return impl_->n; }
bool MinimumNormSolver::supernodal() const { return impl_->analysed && impl_->llt.supernodal(); }
int MinimumNormSolver::kept_unknowns() const { return impl_->nf; }

bool MinimumNormSolver::factorize(const Eigen::SparseMatrix<double>& J, double lambda_relative) {
  Impl& s = *impl_;
  double* gv = s.G.valuePtr();
  std::fill(gv, gv + s.G.nonZeros(), 0.0);
  const double* jv = J.valuePtr();
  double row[64];
  const int runs = static_cast<int>(s.run_begin.size()) - 1;
  for (int g = 0; g < runs; ++g) {
    const int d = s.run_cols_begin[g + 1] - s.run_cols_begin[g];
    const int* slots = s.pair_slot.data() + s.run_pairs_begin[g];
    for (int i = s.run_begin[g]; i < s.run_begin[g + 1]; ++i) {
      const int* pos = s.row_vals.data() + s.row_vals_begin[i];
      if (d <= 64) {
        for (int a = 0; a < d; ++a) row[a] = jv[pos[a]];
        int q = 0;
        for (int a = 0; a < d; ++a)
          for (int b = 0; b <= a; ++b) gv[slots[q++]] += row[a] * row[b];
      } else {
        int q = 0;
        for (int a = 0; a < d; ++a)
          for (int b = 0; b <= a; ++b) gv[slots[q++]] += jv[pos[a]] * jv[pos[b]];
      }
    }
  }
  double scale = 1.0;
  for (int slot : s.diag_slot) scale = std::max(scale, gv[slot]);
  double lambda = lambda_relative * scale;
  double added = 0.0;
  if (!s.analysed) {
    s.llt.analyzePattern(s.G);
    s.analysed = true;
    ++symbolic_analyses_;
  }
  for (int attempt = 0;; ++attempt) {
    for (int slot : s.diag_slot) gv[slot] += lambda - added;
    added = lambda;
    s.llt.factorize(s.G);
    ++factorizations_;
    lambda_ = lambda;
    if (s.llt.info() == Eigen::Success) return true;
    if (attempt >= 12) return false;  // lambda grew by 1e24: give up
    lambda *= 100.0;
  }
}

Eigen::VectorXd MinimumNormSolver::solve(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r) const {
  const Impl& s = *impl_;
  const Eigen::VectorXd z = s.solve_kept(J, r);
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(s.n);
  for (int f = 0; f < s.nf; ++f) dx[s.kept[f]] = z[f];
  return dx;
}

StaleSolveResult MinimumNormSolver::solve_with_stale_factor(const Eigen::SparseMatrix<double>& J,
                                                            const Eigen::VectorXd& r, double relative_tolerance,
                                                            int max_iterations) const {
  const Impl& s = *impl_;
  // CGLS on J_f z = r (z over the kept columns), residual s_res = r - J_f z, M = G_o^-1.
  Eigen::VectorXd s_res = r;
  const CglsResult cg = preconditioned_cgls(
      s.nf, [&](Eigen::VectorXd& g) { s.kept_transpose_times(J, s_res, g); },
      [&](const Eigen::VectorXd& p, Eigen::VectorXd& q) {
        s.kept_times(J, p, q);
        return q.squaredNorm();
      },
      [&](double alpha, const Eigen::VectorXd& q) { s_res -= alpha * q; },
      [&](const Eigen::VectorXd& g, Eigen::VectorXd& y) { y = s.llt.solve(g); }, relative_tolerance, max_iterations);
  StaleSolveResult out;
  out.dx = Eigen::VectorXd::Zero(s.n);
  out.iterations = cg.iterations;
  out.converged = cg.converged;
  out.relative_residual = cg.relative_residual;
  if (out.converged)
    for (int f = 0; f < s.nf; ++f) out.dx[s.kept[f]] = cg.x[f];
  return out;
}

Eigen::VectorXd MinimumNormSolver::null_vector(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& guess) const {
  const Impl& s = *impl_;
  Eigen::VectorXd g(s.nf);
  for (int f = 0; f < s.nf; ++f) g[f] = guess[s.kept[f]];
  // Two inverse iterations: G^-1 magnifies the null direction by 1/lambda against
  // 1/sigma^2 for the others, so the second iterate is the null vector to round-off.
  Eigen::VectorXd w = s.llt.solve(g);
  w /= w.norm();
  w = s.llt.solve(w);
  w /= w.norm();
  // Remove what is left of J_f w with a minimum-norm correction.
  Eigen::VectorXd Jw;
  s.kept_times(J, w, Jw);
  w -= s.solve_kept(J, Jw);
  w /= w.norm();
  if (w.dot(g) < 0) w = -w;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(s.n);
  for (int f = 0; f < s.nf; ++f) out[s.kept[f]] = w[f];
  return out;
}

Eigen::MatrixXd MinimumNormSolver::inverse_times(const Eigen::MatrixXd& V) const {
  const Impl& s = *impl_;
  if (V.rows() != s.n) throw std::invalid_argument("MinimumNormSolver::inverse_times: V needs one row per unknown");
  Eigen::MatrixXd kept_block(s.nf, V.cols());
  for (int f = 0; f < s.nf; ++f) kept_block.row(f) = V.row(s.kept[f]);
  const Eigen::MatrixXd solved = s.llt.solve(kept_block);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(s.n, V.cols());
  for (int f = 0; f < s.nf; ++f) out.row(s.kept[f]) = solved.row(f);
  return out;
}

NewtonResult newton_project(const ClosureSystem& system, const Eigen::VectorXd& x0, const NewtonOptions& options) {
  const int n = system.num_unknowns();
  const int m = system.num_rows();
  if (x0.size() != n)
    throw std::invalid_argument("newton_project: x0 has " + std::to_string(x0.size()) + " entries, expected " +
                                std::to_string(n));
  for (int k : options.held_unknowns)
    if (k < 0 || k >= n) throw std::invalid_argument("newton_project: held unknown " + std::to_string(k) + " out of range");
  if (!options.sign_bounds.empty() && static_cast<int>(options.sign_bounds.size()) != n)
    throw std::invalid_argument("newton_project: sign_bounds has " + std::to_string(options.sign_bounds.size()) +
                                " entries, expected " + std::to_string(n));

  NewtonResult result;
  result.x = x0;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(result.x, r, J);
  double rnorm = m > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0;
  result.residual_history.push_back(rnorm);
  // Nothing to solve for: no rows, no unknowns, or every unknown held (an empty factorisation).
  std::vector<int> held = options.held_unknowns;
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  if (m == 0 || n == 0 || static_cast<int>(held.size()) == n) {
    result.converged = rnorm <= options.tolerance;
    return result;
  }

  std::unique_ptr<MinimumNormSolver> solver;
  auto record = [&] {
    result.factorizations = solver->factorizations();
    result.symbolic_analyses = solver->symbolic_analyses();
    result.lambda = solver->lambda();
    result.supernodal = solver->supernodal();
  };
  // A factor from the previous step that may precondition this one (see NewtonOptions).
  bool stale_usable = false;
  while (rnorm > options.tolerance && result.iterations < options.max_iterations) {
    if (!solver) solver = std::make_unique<MinimumNormSolver>(J, options.held_unknowns, options.ordering);
    Eigen::VectorXd dx;
    bool stale = false;
    if (stale_usable && solver->kept_unknowns() >= options.stale_factor_min_unknowns) {
      // Forcing term: the linear error should leave about rnorm^2, and never need to go
      // below 1% of the tolerance.
      const double forcing = std::min(0.1, std::max(rnorm, 0.01 * options.tolerance / rnorm));
      StaleSolveResult st = solver->solve_with_stale_factor(J, r, forcing, options.stale_max_iterations);
      result.stale_iterations += st.iterations;
      if (st.converged) {
        dx = std::move(st.dx);
        stale = true;
      } else {
        ++result.stale_rejections;
      }
    }
    if (!stale) {
      const bool ok = solver->factorize(J, options.lambda_relative);
      record();
      if (!ok) return result;
      dx = solver->solve(J, r);
    }
    const double step = dx.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(step)) {
      if (stale) {  // try again on a fresh factor
        ++result.stale_rejections;
        stale_usable = false;
        continue;
      }
      return result;
    }
    if (step > options.max_step) dx *= options.max_step / step;
    const Eigen::VectorXd x_before = stale ? result.x : Eigen::VectorXd();
    result.x -= dx;
    // Projection onto the sign box; held unknowns have dx = 0 and stay where they were.
    for (int k = 0; k < static_cast<int>(options.sign_bounds.size()); ++k)
      if (options.sign_bounds[k] * result.x[k] < 0) result.x[k] = 0.0;
    const double rnorm_before = rnorm;
    system.evaluate(result.x, r, J);
    rnorm = r.lpNorm<Eigen::Infinity>();
    if (stale && !(rnorm < rnorm_before)) {
      // The stale step did not reduce the residual: undo it; a fresh factorisation follows.
      ++result.stale_rejections;
      stale_usable = false;
      result.x = x_before;
      system.evaluate(result.x, r, J);
      rnorm = rnorm_before;
      continue;
    }
    if (stale) ++result.stale_steps;
    // The factor preconditions the next step while it keeps Newton fast: a fresh one always,
    // a stale one only if its step contracted the residual at least 10-fold.
    stale_usable = !stale || rnorm <= 0.1 * rnorm_before;
    ++result.iterations;
    result.residual_history.push_back(rnorm);
    const int w = options.stall_window;
    if (w > 0 && result.iterations >= w && rnorm > options.tolerance) {
      const double before = result.residual_history[result.residual_history.size() - 1 - w];
      if (rnorm > options.stall_factor * before) break;  // on a plateau
    }
  }
  result.converged = rnorm <= options.tolerance;
  return result;
}

}  // namespace rigidfold
