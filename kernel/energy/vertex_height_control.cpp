#include "kernel/energy/vertex_height_control.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernel/closure/closure_second_order.hpp"
#include "kernel/math/so3.hpp"

namespace rigidfold {

namespace {

struct FanGeometry {
  std::vector<Eigen::Vector3d> axis;  // u_j, body frame
  Eigen::Vector3d mean_normal = Eigen::Vector3d::Zero();
};

FanGeometry fan_geometry(const Fan& fan, const Eigen::VectorXd& rho) {
  FanGeometry g;
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  for (std::size_t j = 0; j < fan.edges.size(); ++j) {
    g.axis.push_back(P.col(0));
    const Eigen::Matrix3d F = P * rot_x(rho[fan.edges[j]]);
    g.mean_normal += F.col(2);  // normal of sector j's face
    P = F * rot_z(fan.sectors[j]);
  }
  return g;
}

}  // namespace

namespace {

// The load's geometry on the vertex fan, checked once.
struct LoadSetup {
  const Fan* fan = nullptr;
  std::vector<int> slot_unknown, support_slot;
  std::vector<double> length;
  int nx = 0, ns = 0, mr = 0, N = 0, M = 0;
};

LoadSetup make_setup(const CreasePattern& pattern, const ClosureSystem& system, const Topology& topology,
                     const CreaseSprings& springs, const VertexHeightLoad& load) {
  if (springs.stiffness.size() != system.num_edges() || springs.rest_angles.size() != system.num_edges())
    throw std::invalid_argument("vertex_height_equilibrium: springs need one entry per edge");
  bool has_block = false;
  for (int k = 0; k < system.num_vertices(); ++k) has_block = has_block || system.vertex_of_block(k) == load.vertex;
  if (!has_block) throw std::invalid_argument("vertex_height_equilibrium: the vertex has no closure rows");
  LoadSetup st;
  st.fan = &topology.stars[load.vertex].fans.at(0);
  const int d = static_cast<int>(st.fan->edges.size());
  st.slot_unknown.resize(d);
  for (int j = 0; j < d; ++j) st.slot_unknown[j] = system.unknown_of_edge(st.fan->edges[j]);
  for (int e : load.support_edges) {
    const auto it = std::find(st.fan->edges.begin(), st.fan->edges.end(), e);
    if (it == st.fan->edges.end()) throw std::invalid_argument("vertex_height_equilibrium: support edge not at the vertex");
    st.support_slot.push_back(static_cast<int>(it - st.fan->edges.begin()));
    const auto& ev = pattern.edges[e];
    st.length.push_back((pattern.vertices[ev[0]] - pattern.vertices[ev[1]]).norm());
  }
  st.nx = system.num_unknowns();
  st.ns = static_cast<int>(st.support_slot.size());
  st.mr = system.num_rows();
  st.N = st.nx + 3;
  st.M = st.mr + st.ns + 1;
  return st;
}

void assemble_kkt(const LoadSetup& st, const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                  const VertexHeightLoad& load, const Eigen::VectorXd& x, const Eigen::Vector3d& nu,
                  const Eigen::VectorXd& w, bool with_hessian, HeightControlKkt& k) {
  const Fan& fan = *st.fan;
  const int nx = st.nx, ns = st.ns, mr = st.mr, N = st.N, M = st.M;
  const std::vector<int>& slot_unknown = st.slot_unknown;
  const std::vector<int>& support_slot = st.support_slot;
  const std::vector<double>& length = st.length;
  Eigen::MatrixXd& A = k.jacobian;
  Eigen::MatrixXd& H = k.hessian;
  Eigen::VectorXd& c = k.constraints;
  Eigen::VectorXd& gradL = k.gradient;
  A.resize(M, N);
  H.resize(N, N);
  c.resize(M);
  gradL.resize(N);
  const Eigen::VectorXd rho = system.edges_from_unknowns(x);
  const FanGeometry g = fan_geometry(fan, rho);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  A.setZero();
  A.topLeftCorner(mr, nx) = Eigen::MatrixXd(J);
  c.head(mr) = r;
  Eigen::VectorXd gE(nx);
  const Eigen::VectorXd ge = crease_energy_gradient(springs, rho);
  for (int k = 0; k < nx; ++k) gE[k] = ge[system.edge_of_unknown(k)];
  if (with_hessian) {
    H.setZero();
    H.topLeftCorner(nx, nx) = closure_weighted_hessian(system, topology, x, w.head(mr));
    for (int k = 0; k < nx; ++k) H(k, k) += springs.stiffness[system.edge_of_unknown(k)];
    H.bottomRightCorner(3, 3) += w[M - 1] * Eigen::Matrix3d::Identity();
  }
  for (int s = 0; s < ns; ++s) {
    const int i = support_slot[s];
    const double L = length[s], mu = w[mr + s];
    const Eigen::Vector3d& ui = g.axis[i];
    c[mr + s] = L * nu.dot(ui) + load.height;
    A.block<1, 3>(mr + s, nx) = L * ui.transpose();
    for (int j = 0; j < i; ++j) {
      const int cj = slot_unknown[j];
      if (cj < 0) continue;
      const Eigen::Vector3d dj = g.axis[j].cross(ui);  // du_i / drho_j
      A(mr + s, cj) += L * nu.dot(dj);
      if (!with_hessian) continue;
      H.block<1, 3>(cj, nx) += mu * L * dj.transpose();
      H.block<3, 1>(nx, cj) += mu * L * dj;
      for (int k = j; k < i; ++k) {
        const int ck = slot_unknown[k];
        if (ck < 0) continue;
        const Eigen::Vector3d& uj = g.axis[j];
        const Eigen::Vector3d& uk = g.axis[k];
        // d2 u_i / drho_j drho_k, j <= k < i (u_k does not depend on rho_k).
        const Eigen::Vector3d second = (j == k) ? Eigen::Vector3d(uj.cross(uj.cross(ui)))
                                                : Eigen::Vector3d(uj.cross(uk).cross(ui) + uk.cross(uj.cross(ui)));
        const double v = mu * L * nu.dot(second);
        H(cj, ck) += v;
        if (ck != cj) H(ck, cj) += v;
      }
    }
  }
  c[M - 1] = 0.5 * (nu.squaredNorm() - 1.0);
  A.block<1, 3>(M - 1, nx) = nu.transpose();
  gradL.setZero();
  gradL.head(nx) = gE;
  gradL += A.transpose() * w;
}

}  // namespace

namespace {

// How far rounding alone can put the computed grad L = grad E + A^T w from its true value:
// each entry sums M products a_ji w_j and the energy term, so its error is at most
// gamma_(M+1) (|grad E|_i + (|A|^T |w|)_i) (gamma_k = k u / (1 - k u), u the unit roundoff;
// Higham, Accuracy and Stability, 3.1), plus the entries' own rounding (a few u relative:
// products of rotations), allowed for by 8 more terms. Near the flat state the reactions
// reach ~1e5 (n = 60, theta = 0.18 deg): this bound is then 2.6e-9 (1.6e-14 of the force),
// and Newton's iterates stalled at ~1e-11, above the 1e-12 x k test, however long it ran.
double gradient_rounding_bound(const Eigen::VectorXd& gradL, const Eigen::MatrixXd& A, const Eigen::VectorXd& w, int M) {
  const Eigen::VectorXd energy = gradL - A.transpose() * w;
  const Eigen::VectorXd terms = energy.cwiseAbs() + A.cwiseAbs().transpose() * w.cwiseAbs();
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double k = M + 1 + 8;
  return k * u / (1 - k * u) * terms.maxCoeff();
}

Eigen::Vector3d start_normal(const LoadSetup& st, const FanGeometry& g, double height) {
  const Eigen::Vector3d mean = g.mean_normal.normalized();
  if (st.ns < 3) return mean;
  Eigen::MatrixXd P(st.ns, 3);
  for (int s = 0; s < st.ns; ++s) P.row(s) = st.length[s] * g.axis[st.support_slot[s]].transpose();
  const Eigen::RowVector3d centre = P.colwise().mean();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(P.rowwise() - centre, Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (!(sv[1] > 1e-9 * sv[0])) return mean;  // the ends are collinear: no plane
  Eigen::Vector3d nu = svd.matrixV().col(2);
  if (nu.dot(mean) < 0.0) nu = -nu;
  // The start's height with nu is -nu . centre; flip when -nu puts it closer to `height`.
  const double own = -centre.dot(nu);
  if (std::fabs(-own - height) < std::fabs(own - height) - 1e-12 * std::max(1.0, std::fabs(height))) nu = -nu;
  return nu;
}

}  // namespace

HeightControlKkt height_control_kkt(const CreasePattern& pattern, const ClosureSystem& system, const Topology& topology,
                                   const CreaseSprings& springs, const VertexHeightLoad& load, const Eigen::VectorXd& x,
                                   const Eigen::Vector3d& nu, const Eigen::VectorXd& multipliers) {
  const LoadSetup st = make_setup(pattern, system, topology, springs, load);
  if (x.size() != st.nx || multipliers.size() != st.M) throw std::invalid_argument("height_control_kkt: wrong sizes");
  HeightControlKkt k;
  assemble_kkt(st, system, topology, springs, load, x, nu, multipliers, true, k);
  return k;
}

HeightControlledEquilibrium vertex_height_equilibrium(const CreasePattern& pattern, const ClosureSystem& system,
                                                      const Topology& topology, const CreaseSprings& springs,
                                                      const VertexHeightLoad& load, const Eigen::VectorXd& x0,
                                                      const HeightControlOptions& options) {
  if (x0.size() != system.num_unknowns()) throw std::invalid_argument("vertex_height_equilibrium: x0 needs num_unknowns() entries");
  const LoadSetup st = make_setup(pattern, system, topology, springs, load);
  const Fan& fan = *st.fan;
  const int nx = st.nx, ns = st.ns, mr = st.mr, N = st.N, M = st.M;
  const double kmax = springs.stiffness.size() ? std::max(springs.stiffness.maxCoeff(), 1e-300) : 1.0;

  HeightControlledEquilibrium out;
  Eigen::VectorXd x = x0;
  // Start normal: the plane through the supports' far ends at x0, on the side that puts the
  // start's own height closest to the prescribed one (ties: the mean face normal's side). The
  // mean face normal alone can point far from the support plane's normal, even flip, when
  // big facets are folded nearly shut (split fold, n = 3, b > 44 deg near theta_max): Newton
  // then had to turn nu by ~pi and wandered off the solution.
  Eigen::Vector3d nu = start_normal(st, fan_geometry(fan, system.edges_from_unknowns(x)), load.height);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(M);  // (lambda, mu, kappa)

  HeightControlKkt kkt;
  Eigen::MatrixXd& A = kkt.jacobian;
  Eigen::MatrixXd& H = kkt.hessian;
  Eigen::VectorXd& c = kkt.constraints;
  Eigen::VectorXd& gradL = kkt.gradient;
  auto assemble = [&](bool with_hessian) { assemble_kkt(st, system, topology, springs, load, x, nu, w, with_hessian, kkt); };

  // Least-squares multipliers for the start.
  assemble(false);
  {
    Eigen::VectorXd gE = gradL - A.transpose() * w;
    w = A.transpose().completeOrthogonalDecomposition().solve(-gE);
  }
  int it = 0;
  for (; it <= options.max_iterations; ++it) {
    assemble(true);
    out.stationarity_residual = gradL.lpNorm<Eigen::Infinity>();
    out.constraint_residual = c.lpNorm<Eigen::Infinity>();
    out.stationarity_bound = std::max(options.tolerance * kmax, gradient_rounding_bound(gradL, A, w, M));
    if (out.stationarity_residual <= out.stationarity_bound && out.constraint_residual <= options.tolerance) {
      out.converged = true;
      break;
    }
    if (it == options.max_iterations) break;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N + M, N + M);
    K.topLeftCorner(N, N) = H;
    K.topRightCorner(N, M) = A.transpose();
    K.bottomLeftCorner(M, N) = A;
    Eigen::VectorXd rhs(N + M);
    rhs << -gradL, -c;
    const Eigen::VectorXd step = K.completeOrthogonalDecomposition().solve(rhs);
    Eigen::VectorXd dz = step.head(N);
    const double cap = 0.2, norm = dz.lpNorm<Eigen::Infinity>();
    const double t = norm > cap ? cap / norm : 1.0;
    x += t * dz.head(nx);
    nu += t * dz.tail(3);
    w += t * step.tail(M);
  }
  out.iterations = it;
  if (!out.converged) out.message = "no convergence of the KKT Newton iteration";
  out.x = x;
  out.edge_angles = system.edges_from_unknowns(x);
  out.plane_normal = nu;
  out.support_reactions = w.segment(mr, ns);
  out.force = -out.support_reactions.sum();
  out.energy = crease_energy(springs, out.edge_angles);

  if (!options.compute_stability) return out;
  // Stability: H reduced to null(A).
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  int rank = 0;
  while (rank < s.size() && s[rank] > options.rank_tolerance * s[0]) ++rank;
  const Eigen::MatrixXd Z = svd.matrixV().rightCols(N - rank);
  out.tangent_dimension = static_cast<int>(Z.cols());
  if (Z.cols() > 0) {
    Eigen::MatrixXd Hr = Z.transpose() * H * Z;
    Hr = 0.5 * (Hr + Hr.transpose());
    out.reduced_hessian_eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Hr).eigenvalues();
    out.min_eigenvalue = out.reduced_hessian_eigenvalues[0];
  } else {
    out.min_eigenvalue = INFINITY;
  }
  out.stable = out.converged && out.min_eigenvalue > options.stability_tolerance * kmax;
  return out;
}

}  // namespace rigidfold
