// The flat-fold conditions as functions of the coordinates (flat_fold_constraints.hpp): zero
// on an exact Miura-ori in its letters' modes, non-zero once its vertices move, and an exact
// Jacobian that central differences confirm.
#include <gtest/gtest.h>

#include <cmath>

#include "data/generators/miura.hpp"
#include "kernel/analysis/flat_fold_constraints.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<FlatFoldMode> letter_modes(const CreasePattern& p, const Topology& t) {
  std::vector<FlatFoldMode> modes;
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    std::array<Assignment, 4> letters{};
    for (int i = 0; i < 4; ++i) letters[i] = p.assignments[fan.edges[i]];
    int found = 0;
    for (FlatFoldMode m : {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02})
      if (mode_sign_matching_letters(mode_multipliers(fan.sectors[0], fan.sectors[1], m), letters)) {
        modes.push_back(m);
        ++found;
      }
    EXPECT_EQ(found, 1) << "vertex " << v;
  }
  return modes;
}

generators::MiuraParams miura(double perturbation) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  m.alpha = 1.1;
  m.b = 1.3;
  m.perturbation = perturbation;
  m.seed = 7;
  return m;
}

TEST(FlatFoldConstraints, VanishOnAnExactMiuraAndCountItsCycles) {
  const CreasePattern p = generators::miura_ori(miura(0.0));
  const Topology t = build_topology(p);
  const FlatFoldConstraints c(p, t, letter_modes(p, t));
  ASSERT_TRUE(c.gains_usable()) << c.why_no_gains();
  EXPECT_EQ(c.kawasaki_rows(), 3 * 4);  // (rows - 1) x (cols - 1) interior vertices
  EXPECT_EQ(c.gain_rows(), 2 * 3);      // one cycle per panel between four interior vertices
  Eigen::VectorXd values;
  c.evaluate(p.vertices, values, nullptr);
  EXPECT_LE(values.lpNorm<Eigen::Infinity>(), 1e-14);
  // Each cycle goes round one panel: four vertices.
  for (int r = 0; r < c.gain_rows(); ++r) EXPECT_EQ(c.cycle_vertices(r).size(), 4u);
}

TEST(FlatFoldConstraints, JacobianMatchesCentralDifferences) {
  const CreasePattern exact = generators::miura_ori(miura(0.0));
  const Topology t = build_topology(exact);
  const std::vector<FlatFoldMode> modes = letter_modes(exact, t);
  const CreasePattern p = generators::miura_ori(miura(0.05));
  const FlatFoldConstraints c(p, build_topology(p), modes);
  Eigen::VectorXd values;
  Eigen::SparseMatrix<double> J;
  c.evaluate(p.vertices, values, &J);
  EXPECT_GT(values.head(c.kawasaki_rows()).lpNorm<Eigen::Infinity>(), 1e-3);
  EXPECT_GT(values.tail(c.gain_rows()).lpNorm<Eigen::Infinity>(), 1e-3);
  const Eigen::MatrixXd dense = J;
  const double h = 1e-6;
  double worst = 0;
  for (int col = 0; col < J.cols(); ++col) {
    std::vector<Eigen::Vector3d> plus = p.vertices, minus = p.vertices;
    plus[col / 2][col % 2] += h;
    minus[col / 2][col % 2] -= h;
    Eigen::VectorXd vp, vm;
    c.evaluate(plus, vp, nullptr);
    c.evaluate(minus, vm, nullptr);
    const Eigen::VectorXd fd = (vp - vm) / (2 * h);
    worst = std::max(worst, (fd - dense.col(col)).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LE(worst, 1e-8);  // central differences: error ~ h^2 |f'''|, far below the entries (~1)
  EXPECT_GT(dense.lpNorm<Eigen::Infinity>(), 0.1);
}

TEST(FlatFoldConstraints, RefusesAVertexOfOtherDegreeNamingIt) {
  CreasePattern p = generators::miura_ori(miura(0.0));
  const Topology t = build_topology(p);
  Topology changed = t;
  const int v = t.interior_vertices[0];
  changed.stars[v].fans[0].edges.pop_back();
  try {
    FlatFoldConstraints c(p, changed);
    FAIL() << "accepted a vertex with three creases";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("vertex " + std::to_string(v)), std::string::npos) << e.what();
  }
}

}}  // namespace
}  // namespace rigidfold
