#include "kernel/thick/thick_network_mobility.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace rigidfold {

namespace {

std::set<int> loop_creases(const ThickPattern& pattern) {
  std::set<int> used;
  for (const ThickLoop& loop : pattern.loops)
    for (const ThickJoint& j : loop.joints) used.insert(j.crease);
  return used;
}

// Every crease in no loop (and `also`, if >= 0) held at its value in `state`.
ThickClosureOptions holding_free(const ThickPattern& pattern, const Eigen::VectorXd& state, int also) {
  const std::set<int> used = loop_creases(pattern);
  ThickClosureOptions options;
  for (int c = 0; c < pattern.num_creases; ++c)
    if (!used.count(c) || c == also) options.fixed.emplace_back(c, state[c]);
  return options;
}

std::vector<double> per_loop_inf(const Eigen::VectorXd& r, int loops) {
  std::vector<double> out(loops, 0.0);
  for (int k = 0; k < loops; ++k) out[k] = r.segment(6 * k, 6).cwiseAbs().maxCoeff();
  return out;
}

}  // namespace

ThickNetworkMobility thick_network_mobility(const ThickPattern& pattern, const Eigen::VectorXd& creases,
                                            double closure_tolerance, const RankOptions& rank_options) {
  if (creases.size() != pattern.num_creases)
    throw std::invalid_argument(std::string("thick network mobility: expected ") + std::to_string(pattern.num_creases) + " fold angles");
  const ThickClosureSystem system(pattern, holding_free(pattern, creases, -1));
  const Eigen::VectorXd x = system.unknowns_from_creases(creases);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  ThickNetworkMobility report;
  report.state_residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  if (!(report.state_residual <= closure_tolerance)) {
    std::ostringstream message;
    message << "thick network mobility: the state does not close (residual " << report.state_residual << ")";
    throw std::invalid_argument(message.str());
  }
  report.free_creases = system.num_unknowns();
  report.rank = jacobian_rank(J, rank_options);
  report.dof = report.rank.dof;
  const Eigen::MatrixXd dense(J);
  const int loops = static_cast<int>(pattern.loops.size());
  const std::vector<double> inf = per_loop_inf(r, loops);
  for (int k = 0; k < loops; ++k) {
    std::vector<int> columns;
    for (const ThickJoint& j : pattern.loops[k].joints) {
      const int u = system.unknown_of_crease(j.crease);
      if (u >= 0 && std::find(columns.begin(), columns.end(), u) == columns.end()) columns.push_back(u);
    }
    Eigen::MatrixXd block(6, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c) block.col(static_cast<Eigen::Index>(c)) = dense.block(6 * k, columns[c], 6, 1);
    ThickLoopMobility m;
    m.loop = k;
    m.creases = static_cast<int>(columns.size());
    m.dof_alone = m.creases;
    if (m.creases > 0) {
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(block);
      const Eigen::VectorXd s = svd.singularValues();
      // The network's cut (absolute) so that a loop is judged as it is inside the network.
      for (Eigen::Index i = 0; i < s.size(); ++i)
        if (s[i] > report.rank.threshold) --m.dof_alone;
    }
    m.residual = inf[k];
    report.loops.push_back(m);
    if (m.dof_alone == 0) report.locked_loops.push_back(k);
  }
  return report;
}

ThickHoldResult thick_network_hold(const ThickPattern& pattern, int held_crease, double value, const Eigen::VectorXd& start,
                                   double tolerance, int max_iterations) {
  if (start.size() != pattern.num_creases)
    throw std::invalid_argument(std::string("thick network hold: expected ") + std::to_string(pattern.num_creases) + " fold angles");
  if (held_crease < 0 || held_crease >= pattern.num_creases) throw std::invalid_argument("thick network hold: held crease out of range");
  Eigen::VectorXd state = start;
  state[held_crease] = value;
  const ThickClosureSystem system(pattern, holding_free(pattern, state, held_crease));
  Eigen::VectorXd x = system.unknowns_from_creases(state);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Js;
  system.evaluate(x, r, Js);
  double lambda = 1e-3;
  ThickHoldResult result;
  for (int it = 0; it < max_iterations; ++it) {
    const Eigen::MatrixXd J(Js);
    const Eigen::VectorXd g = J.transpose() * r;
    result.iterations = it;
    const double scale = std::max(1.0, J.norm()) * std::max(r.norm(), 1e-300);
    if (r.norm() <= 1e-15 || g.norm() <= 1e-12 * scale) {
      result.stationary = true;
      break;
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal().array() += lambda * (1.0 + JtJ.diagonal().array());
      const Eigen::VectorXd step = A.ldlt().solve(-g);
      const Eigen::VectorXd trial = x + step;
      const Eigen::VectorXd r_trial = system.residual(trial);
      if (r_trial.squaredNorm() < r.squaredNorm()) {
        x = trial;
        improved = true;
        lambda = std::max(lambda / 10, 1e-12);
      } else {
        lambda *= 10;
      }
    }
    system.evaluate(x, r, Js);
    if (!improved) {
      result.stationary = g.norm() <= 1e-8 * scale;
      break;
    }
  }
  result.creases = system.creases_from_unknowns(x);
  result.residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  result.residual_norm = r.norm();
  const int loops = static_cast<int>(pattern.loops.size());
  result.loop_residual = per_loop_inf(r, loops);
  for (int k = 0; k < loops; ++k)
    if (result.loop_residual[k] > tolerance) result.open_loops.push_back(k);
  return result;
}

}  // namespace rigidfold
