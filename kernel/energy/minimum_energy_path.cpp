#include "kernel/energy/minimum_energy_path.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernel/closure/closure_second_order.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::VectorXd free_entries(const ClosureSystem& system, const Eigen::VectorXd& per_edge) {
  Eigen::VectorXd out(system.num_unknowns());
  for (int k = 0; k < system.num_unknowns(); ++k) out[k] = per_edge[system.edge_of_unknown(k)];
  return out;
}

// Tangent space of the manifold at x and the least-squares multipliers of J^T lambda = -g
// (the same construction as constrained_equilibrium.cpp).
struct Tangent {
  Eigen::MatrixXd N;       // unknowns x dof, orthonormal
  Eigen::VectorXd lambda;  // one per row
};

Tangent tangent_at(const ClosureSystem& system, const Eigen::VectorXd& x, const Eigen::VectorXd& g, double rank_tolerance) {
  const int n = system.num_unknowns(), m = system.num_rows();
  Tangent t;
  t.lambda = Eigen::VectorXd::Zero(m);
  if (m == 0 || n == 0) {
    t.N = Eigen::MatrixXd::Identity(n, n);
    return t;
  }
  const Eigen::MatrixXd J = dense_jacobian(system, x);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double cut = rank_tolerance * (s.size() ? s[0] : 0.0);
  int rank = 0;
  while (rank < s.size() && s[rank] > cut) ++rank;
  t.N = svd.matrixV().rightCols(n - rank);
  const Eigen::VectorXd coeff = (svd.matrixV().leftCols(rank).transpose() * g).cwiseQuotient(s.head(rank));
  t.lambda = -svd.matrixU().leftCols(rank) * coeff;
  return t;
}

struct Image {
  Eigen::VectorXd x;
  double energy = 0.0;
};

class PathProblem {
 public:
  PathProblem(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
              const MinimumEnergyPathOptions& options)
      : system_(system), topology_(topology), springs_(springs), options_(options) {
    projection_.tolerance = options.equilibrium.closure_tolerance;
    projection_.max_iterations = 60;
  }

  double energy(const Eigen::VectorXd& x) const { return crease_energy(springs_, system_.edges_from_unknowns(x)); }
  Eigen::VectorXd gradient(const Eigen::VectorXd& x) const {
    return free_entries(system_, crease_energy_gradient(springs_, system_.edges_from_unknowns(x)));
  }
  // Onto the manifold; false when the corrector does not converge.
  bool project(Eigen::VectorXd& x) const {
    const NewtonResult r = newton_project(system_, x, projection_);
    if (!r.converged) return false;
    x = r.x;
    return true;
  }
  Tangent tangent(const Eigen::VectorXd& x, const Eigen::VectorXd& g) const {
    return tangent_at(system_, x, g, options_.equilibrium.rank_tolerance);
  }
  // Reduced Hessian of the Lagrangian at x in the basis N (symmetric).
  Eigen::MatrixXd reduced_hessian(const Eigen::VectorXd& x, const Tangent& t) const {
    const int n = system_.num_unknowns();
    Eigen::MatrixXd HL = system_.num_rows() > 0 ? closure_weighted_hessian(system_, topology_, x, t.lambda)
                                                : Eigen::MatrixXd::Zero(n, n);
    HL.diagonal() += free_entries(system_, springs_.stiffness);
    Eigen::MatrixXd H = t.N.transpose() * HL * t.N;
    return 0.5 * (H + H.transpose());
  }

 private:
  const ClosureSystem& system_;
  const Topology& topology_;
  const CreaseSprings& springs_;
  const MinimumEnergyPathOptions& options_;
  NewtonOptions projection_;
};

// Redistributes images[first..last] (ends kept) at equal arc length along their polyline and
// projects the new interior points. False when a projection fails.
bool redistribute(const PathProblem& problem, std::vector<Image>& images, int first, int last) {
  if (last - first < 2) return true;
  std::vector<double> s(last - first + 1, 0.0);
  for (int i = first + 1; i <= last; ++i) s[i - first] = s[i - 1 - first] + (images[i].x - images[i - 1].x).norm();
  const double total = s.back();
  if (!(total > 0.0)) return true;
  std::vector<Eigen::VectorXd> placed;
  int seg = 0;
  for (int i = first + 1; i < last; ++i) {
    const double target = total * (i - first) / double(last - first);
    while (seg + 1 < static_cast<int>(s.size()) - 1 && s[seg + 1] < target) ++seg;
    const double len = s[seg + 1] - s[seg];
    const double u = len > 0.0 ? std::clamp((target - s[seg]) / len, 0.0, 1.0) : 0.0;
    Eigen::VectorXd x = (1.0 - u) * images[first + seg].x + u * images[first + seg + 1].x;
    if (!problem.project(x)) return false;
    placed.push_back(std::move(x));
  }
  for (int i = first + 1; i < last; ++i) {
    images[i].x = std::move(placed[i - first - 1]);
    images[i].energy = problem.energy(images[i].x);
  }
  return true;
}

}  // namespace

const char* to_string(PathTop top) {
  switch (top) {
    case PathTop::kSaddle: return "index-1 saddle";
    case PathTop::kSingularPoint: return "singular point (flat state, cusp)";
    case PathTop::kNone: break;
  }
  return "none";
}

namespace {

MinimumEnergyPath path_from_start(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                                  const Eigen::VectorXd& x_a, const Eigen::VectorXd& x_b,
                                  const MinimumEnergyPathOptions& options, bool via_flat) {
  const int n = system.num_unknowns();
  if (x_a.size() != n || x_b.size() != n) throw std::invalid_argument("minimum_energy_path: x_a and x_b need num_unknowns() entries");
  if (springs.stiffness.size() != system.num_edges() || springs.rest_angles.size() != system.num_edges())
    throw std::invalid_argument("minimum_energy_path: the springs need one entry per edge of the system's pattern");
  if (options.images < 5) throw std::invalid_argument("minimum_energy_path: images must be >= 5");
  if (!(options.singular_top_radius >= 0.0)) throw std::invalid_argument("minimum_energy_path: singular_top_radius must be >= 0");
  if (!(options.initial_perturbation >= 0.0)) throw std::invalid_argument("minimum_energy_path: initial_perturbation must be >= 0");
  if (!(options.step_fraction > 0.0) || !(options.max_image_step > 0.0) || !(options.string_tolerance > 0.0) ||
      !(options.climb_tolerance > 0.0) || !(options.max_newton_step > 0.0) || !(options.descent_offset > 0.0) ||
      options.max_iterations < 0 || options.newton_iterations < 0 || options.stall_iterations < 1)
    throw std::invalid_argument("minimum_energy_path: steps, tolerances and iteration counts must be positive");

  MinimumEnergyPath out;
  out.barrier_from_a = out.barrier_from_b = kNaN;
  const PathProblem problem(system, topology, springs, options);
  const double kmax = springs.stiffness.size() ? springs.stiffness.maxCoeff() : 0.0;
  if (!(kmax > 0.0)) {
    out.message = "every crease has stiffness 0: the energy is flat";
    return out;
  }
  auto store_images = [&](const std::vector<Image>& images) {
    out.images.clear();
    for (const Image& im : images) out.images.push_back({system.edges_from_unknowns(im.x), im.energy});
  };

  // The ends: on the manifold, and their stiffest reduced direction sets the step.
  Eigen::VectorXd a = x_a, b = x_b;
  if (!problem.project(a) || !problem.project(b)) {
    out.message = "an end state could not be projected onto the closure manifold";
    return out;
  }
  out.energy_a = problem.energy(a);
  out.energy_b = problem.energy(b);
  double curvature = kmax;
  for (const Eigen::VectorXd* e : {&a, &b}) {
    const Tangent t = problem.tangent(*e, problem.gradient(*e));
    if (t.N.cols() == 0) {
      out.message = "an end state is an isolated point of the manifold (no tangent directions)";
      return out;
    }
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(problem.reduced_hessian(*e, t)).eigenvalues();
    curvature = std::max(curvature, ev.cwiseAbs().maxCoeff());
  }
  const double dt = options.step_fraction / curvature;

  // The straight start, projected.
  const int M = options.images - 1;
  std::vector<Image> images(options.images);
  SplitMix64 rng{options.seed};
  for (int i = 0; i <= M; ++i) {
    const double u = double(i) / M;
    Eigen::VectorXd x = i == 0 ? a : i == M ? b : Eigen::VectorXd((1.0 - u) * a + u * b);
    if (via_flat && i > 0 && i < M) x = u <= 0.5 ? Eigen::VectorXd((1.0 - 2.0 * u) * a) : Eigen::VectorXd((2.0 * u - 1.0) * b);
    if (i > 0 && i < M)
      for (int k = 0; k < n; ++k) x[k] += options.initial_perturbation * std::sin(M_PI * u) * (2.0 * rng.uniform() - 1.0);
    if (!problem.project(x)) {
      out.message = "the straight start between the states could not be projected onto the manifold (image " + std::to_string(i) + ")";
      return out;
    }
    images[i] = {x, problem.energy(x)};
  }
  if (!redistribute(problem, images, 0, M)) {
    out.message = "a string image could not be projected onto the manifold";
    return out;
  }

  int climbing = -1;
  const double tol = options.string_tolerance * kmax;
  // String iterations. With `pinned` the climbing image stays where it is (a singular top).
  // Returns "" or why the string stopped.
  auto relax = [&](bool pinned, int& iterations, bool& converged, double& force_left) -> std::string {
    converged = false;
    double best = std::numeric_limits<double>::infinity();
    int best_at = 0;
    for (int it = 0; it < options.max_iterations; ++it) {
      std::vector<Eigen::VectorXd> force(options.images, Eigen::VectorXd::Zero(n));
      double perpendicular = 0.0, climb_force = 0.0;
      for (int i = 1; i < M; ++i) {
        if (pinned && i == climbing) continue;
        const Eigen::VectorXd g = problem.gradient(images[i].x);
        const Tangent t = problem.tangent(images[i].x, g);
        const Eigen::VectorXd pg = t.N * (t.N.transpose() * g);
        Eigen::VectorXd tau = t.N * (t.N.transpose() * (images[i + 1].x - images[i - 1].x));
        const double tn = tau.norm();
        if (tn > 0.0) tau /= tn;
        if (i == climbing) {
          force[i] = -pg + 2.0 * tau.dot(pg) * tau;
          climb_force = force[i].lpNorm<Eigen::Infinity>();
        } else {
          force[i] = -pg;
          perpendicular = std::max(perpendicular, (pg - tau.dot(pg) * tau).lpNorm<Eigen::Infinity>());
        }
      }
      force_left = std::max(perpendicular, climb_force);
      iterations = it;
      if (climbing >= 0 && force_left <= tol) {
        converged = true;
        return "";
      }
      // A climbing image on a cusp never settles: stop once the force has not halved for
      // stall_iterations iterations (the checks after the string decide).
      if (climbing >= 0) {
        if (force_left < 0.5 * best) {
          best = force_left;
          best_at = it;
        } else if (it - best_at >= options.stall_iterations) {
          return "";
        }
      }
      // Climb once the string is near a path; also when its force has stopped halving.
      const bool stalled = it - best_at >= options.stall_iterations;
      if (climbing < 0) {
        if (perpendicular < 0.5 * best) {
          best = perpendicular;
          best_at = it;
        }
        if (perpendicular <= options.climb_tolerance * kmax || stalled) {
          climbing = 1;
          for (int i = 2; i < M; ++i)
            if (images[i].energy > images[climbing].energy) climbing = i;
          best = std::numeric_limits<double>::infinity();
          best_at = it;
          continue;  // recompute the forces with the climbing image's
        }
      }
      for (int i = 1; i < M; ++i) {
        if (pinned && i == climbing) continue;
        Eigen::VectorXd step = dt * force[i];
        const double size = step.lpNorm<Eigen::Infinity>();
        if (size > options.max_image_step) step *= options.max_image_step / size;
        // Near a singular point the corrector may throw an image far from where it was sent
        // (onto another sheet of the manifold): halve the step until it lands near its target;
        // an image that cannot move stays.
        for (int tries = 0; tries < 6; ++tries, step *= 0.5) {
          Eigen::VectorXd x = images[i].x + step;
          const Eigen::VectorXd target = x;
          if (!problem.project(x) || x.lpNorm<Eigen::Infinity>() > M_PI) continue;
          if ((x - target).lpNorm<Eigen::Infinity>() > std::max(options.max_image_step, 2.0 * step.lpNorm<Eigen::Infinity>())) continue;
          images[i] = {x, problem.energy(x)};
          break;
        }
      }
      const bool ok = climbing < 0 ? redistribute(problem, images, 0, M)
                                   : redistribute(problem, images, 0, climbing) && redistribute(problem, images, climbing, M);
      if (!ok) return "a string image could not be projected onto the manifold (iteration " + std::to_string(it) + ")";
      iterations = it + 1;
    }
    return "";
  };
  {
    const std::string stopped = relax(false, out.string_iterations, out.string_converged, out.string_force);
    store_images(images);
    if (!stopped.empty()) {
      out.message = stopped;
      return out;
    }
  }
  if (climbing < 0) {
    climbing = 1;
    for (int i = 2; i < M; ++i)
      if (images[i].energy > images[climbing].energy) climbing = i;
  }
  out.climbing_image = climbing;
  // A string that did not converge still hands its climbing image to Newton: the checks below
  // decide, not the string.

  // Newton on the Lagrangian's stationarity, in tangent coordinates, then the checks.
  // Returns "" when the point passed every check, else why not.
  auto refine_saddle = [&]() -> std::string {
    Eigen::VectorXd x = images[climbing].x;
    out.saddle = analyse_equilibrium(system, topology, springs, x, options.equilibrium);
    for (int it = 0; it < options.newton_iterations && !out.saddle.converged; ++it) {
      const Eigen::VectorXd g = problem.gradient(x);
      const Tangent t = problem.tangent(x, g);
      if (t.N.cols() == 0) break;
      const Eigen::MatrixXd H = problem.reduced_hessian(x, t);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H);
      const Eigen::VectorXd& ev = eig.eigenvalues();
      const double floor = 1e-12 * std::max(kmax, ev.cwiseAbs().maxCoeff());
      if (ev.cwiseAbs().minCoeff() <= floor) break;  // singular reduced Hessian: no Newton step
      Eigen::VectorXd p =
          -t.N * (eig.eigenvectors() * ((eig.eigenvectors().transpose() * (t.N.transpose() * g)).cwiseQuotient(ev)));
      const double size = p.lpNorm<Eigen::Infinity>();
      if (size > options.max_newton_step) p *= options.max_newton_step / size;
      Eigen::VectorXd next = x + p;
      if (!problem.project(next)) break;
      x = next;
      out.newton_iterations = it + 1;
      out.saddle = analyse_equilibrium(system, topology, springs, x, options.equilibrium);
    }
    const Equilibrium& s = out.saddle;
    if (!s.converged)
      return "the refinement of the climbing image did not converge to a stationary point (reduced gradient " +
             std::to_string(s.stationarity_residual) + ", closure " + std::to_string(s.closure_residual) + " rad after " +
             std::to_string(out.newton_iterations) + " Newton steps)";
    const double threshold = options.equilibrium.stability_tolerance * kmax;
    out.negative_eigenvalues = 0;
    int near_zero = 0;
    for (Eigen::Index i = 0; i < s.reduced_hessian_eigenvalues.size(); ++i) {
      const double e = s.reduced_hessian_eigenvalues[i];
      if (e < -threshold) ++out.negative_eigenvalues;
      else if (e <= threshold) ++near_zero;
    }
    if (out.negative_eigenvalues != 1 || near_zero != 0)
      return "the stationary point is not an index-1 saddle: " + std::to_string(out.negative_eigenvalues) + " negative and " +
             std::to_string(near_zero) + " near-zero reduced Hessian eigenvalue(s)";
    // The descents from the saddle along its unstable direction must reach the two states.
    const Eigen::VectorXd g = problem.gradient(x);
    const Tangent t = problem.tangent(x, g);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(problem.reduced_hessian(x, t));
    Eigen::VectorXd v = t.N * eig.eigenvectors().col(0);
    v /= v.lpNorm<Eigen::Infinity>();
    const Eigen::VectorXd ea = system.edges_from_unknowns(a), eb = system.edges_from_unknowns(b);
    int reached_a = 0, reached_b = 0;
    out.descent_ends.clear();
    for (double sign : {1.0, -1.0}) {
      const Equilibrium d = find_equilibrium(system, topology, springs, x + sign * options.descent_offset * v, options.equilibrium);
      if (!d.converged || !d.stable) continue;
      out.descent_ends.push_back(d.edge_angles);
      if ((d.edge_angles - ea).lpNorm<Eigen::Infinity>() <= options.same_state_tolerance) ++reached_a;
      else if ((d.edge_angles - eb).lpNorm<Eigen::Infinity>() <= options.same_state_tolerance) ++reached_b;
    }
    out.connects = reached_a == 1 && reached_b == 1;
    if (!out.connects)
      return "the index-1 saddle found does not lie between the two states: its two descents reach " +
             std::to_string(reached_a) + " time(s) the first and " + std::to_string(reached_b) + " time(s) the second";
    return "";
  };

  // The top of the path at the flat state (free fold angles 0), a singular point of the
  // manifold where the energy has a cusp: the climbing image pinned there, the rest of the
  // string relaxed, then checked. Returns "" when it passed, else why not.
  auto singular_top = [&]() -> std::string {
    const Eigen::VectorXd flat = Eigen::VectorXd::Zero(n);
    if ((images[climbing].x - flat).lpNorm<Eigen::Infinity>() > options.singular_top_radius)
      return "the climbing image is not near the flat state";
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system.evaluate(flat, r, J);
    if (r.size() && r.lpNorm<Eigen::Infinity>() > options.equilibrium.closure_tolerance) return "the flat state does not close";
    const Eigen::MatrixXd Jd(J);
    const int rank_flat = Jd.size() ? static_cast<int>(Eigen::JacobiSVD<Eigen::MatrixXd>(Jd).setThreshold(options.equilibrium.rank_tolerance).rank()) : 0;
    const Eigen::MatrixXd Ja = dense_jacobian(system, a);
    const int rank_a = Ja.size() ? static_cast<int>(Eigen::JacobiSVD<Eigen::MatrixXd>(Ja).setThreshold(options.equilibrium.rank_tolerance).rank()) : 0;
    if (rank_flat >= rank_a) return "the flat state is a regular point of the manifold";
    images[climbing] = {flat, problem.energy(flat)};
    int iterations = 0;
    bool converged = false;
    double force = 0.0;
    const std::string stopped = relax(true, iterations, converged, force);
    out.string_iterations += iterations;
    out.string_force = force;
    out.string_converged = converged;
    store_images(images);
    if (!stopped.empty()) return stopped;
    if (!converged) return "the string pinned at the flat state did not converge";
    // Energy rises monotonically from each end to the flat state along the relaxed string.
    for (int i = 1; i <= climbing; ++i)
      if (!(images[i].energy > images[i - 1].energy)) return "the pinned string does not rise monotonically to the flat state";
    for (int i = climbing; i < M; ++i)
      if (!(images[i].energy > images[i + 1].energy)) return "the pinned string does not fall monotonically from the flat state";
    out.saddle = analyse_equilibrium(system, topology, springs, flat, options.equilibrium);
    out.negative_eigenvalues = -1;
    out.connects = true;
    return "";
  };

  out.climbing_image = climbing;
  const std::string saddle_failure = refine_saddle();
  if (saddle_failure.empty()) {
    out.top = PathTop::kSaddle;
  } else {
    const std::string singular_failure = singular_top();
    if (!singular_failure.empty()) {
      out.message = saddle_failure + "; no singular top either: " + singular_failure;
      return out;
    }
    out.top = PathTop::kSingularPoint;
  }
  out.found = true;
  out.barrier_from_a = out.saddle.energy - out.energy_a;
  out.barrier_from_b = out.saddle.energy - out.energy_b;
  return out;
}

}  // namespace

MinimumEnergyPath minimum_energy_path(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                                      const Eigen::VectorXd& x_a, const Eigen::VectorXd& x_b,
                                      const MinimumEnergyPathOptions& options) {
  MinimumEnergyPath straight = path_from_start(system, topology, springs, x_a, x_b, options, false);
  straight.start = "straight";
  // The second start, through the flat state, only where the flat state closes.
  const Eigen::VectorXd flat = Eigen::VectorXd::Zero(system.num_unknowns());
  const Eigen::VectorXd r = system.residual(flat);
  if (r.size() && r.lpNorm<Eigen::Infinity>() > options.equilibrium.closure_tolerance) return straight;
  MinimumEnergyPath through = path_from_start(system, topology, springs, x_a, x_b, options, true);
  through.start = "through the flat state";
  if (straight.found && (!through.found || straight.saddle.energy <= through.saddle.energy)) return straight;
  if (through.found) return through;
  straight.message = "straight start: " + straight.message + "; start through the flat state: " + through.message;
  return straight;
}

}  // namespace rigidfold
