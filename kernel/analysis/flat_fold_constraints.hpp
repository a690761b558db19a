#pragma once
// The conditions, as smooth functions of a flat pattern's vertex coordinates, under which a
// pattern of degree-4 interior vertices is rigidly foldable in given vertex modes (the
// multiplier model, multiplier_propagation.hpp):
//   - Kawasaki at each interior vertex v: k_v(x) = alpha_0 + alpha_2 - pi = 0, written with
//     the directions theta_i of its creases (counter-clockwise, as the topology's fan):
//     theta_1 - theta_0 + theta_3 - theta_2 - pi, wrapped to (-pi, pi];
//   - loop gain 1 around each independent cycle of ties: log |K_c(x)| = 0, where a crease
//     joining interior vertices u and v ties their parameters by w_u / w_v and K_c is the
//     product of those ratios around cycle c. The cycles are the faces whose corners are all
//     interior vertices (on a disk, a basis of the tie graph's cycles, each one panel round),
//     or, where those are no basis, the cycles a spanning forest of the ties closes.
// The multipliers w are those of flat_foldable_multipliers.hpp, written with the first two
// sectors only (w is a function of alpha_0 and alpha_1), so they extend smoothly to vertices
// that miss Kawasaki; on a flat-foldable vertex they are the model's.
//
// The Jacobian is exact: d theta_i / d(neighbour i) = (-dy, dx) / |d|^2 (the centre gets
// the opposite), and d log|sin u| = cot u du, d log|cos u| = -tan u du for the half-sums
// d = (alpha_1 - alpha_0) / 2, s = (alpha_1 + alpha_0) / 2 (tests check it against central
// differences).
//
// Used by the least move to a flat-foldable pattern (flat_foldable_witness.hpp, within the
// input's rounding) and by the repair to rigid foldability (design/repair).
// Units: radians for the Kawasaki rows, natural log of a ratio for the gain rows; columns
// (x_0, y_0, x_1, y_1, ...) in the pattern's coordinates (z ignored).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

namespace rigidfold {

// The four multipliers of a degree-4 vertex in a mode from its first two sectors (radians),
// with no flat-foldability check: flat_fold_multipliers' direction where the vertex is
// flat-foldable, its smooth extension elsewhere.
std::array<double, 4> mode_multipliers(double alpha_0, double alpha_1, FlatFoldMode mode);

class FlatFoldConstraints {
 public:
  // Every interior vertex of `topology` must have four creases (else std::invalid_argument
  // naming it). modes: one per interior vertex (topology order) for the gain rows, or empty
  // for Kawasaki rows only. Gain rows are left out (gains_usable() false, why_no_gains() says
  // why) when a tie has a zero multiplier at x0 or a cycle's gain is negative there: no small
  // move of the coordinates turns a gain of -1 into +1.
  FlatFoldConstraints(const CreasePattern& pattern, const Topology& topology, std::vector<FlatFoldMode> modes = {});

  int kawasaki_rows() const { return static_cast<int>(centre_.size()); }
  int gain_rows() const { return static_cast<int>(cycles_.size()); }
  int rows() const { return kawasaki_rows() + gain_rows(); }
  bool gains_usable() const { return gains_usable_; }
  const std::string& why_no_gains() const { return why_no_gains_; }
  const std::vector<int>& centres() const { return centre_; }
  // Pattern vertices around gain row c's cycle, in order.
  std::vector<int> cycle_vertices(int c) const;

  // values: the Kawasaki rows then the gain rows (an infinite gain row where a tie's
  // multiplier is 0 at x). J (if given): their Jacobian, rows() x 2 * x.size().
  void evaluate(const std::vector<Eigen::Vector3d>& x, Eigen::VectorXd& values, Eigen::SparseMatrix<double>* J) const;

 private:
  struct Tie {
    int u, i, v, j;  // model vertex u's slot i and model vertex v's slot j are one crease
  };
  void build_cycles(const CreasePattern& pattern);
  bool face_cycles(const CreasePattern& pattern, const std::vector<int>& model_of);  // false: not a basis
  void fundamental_cycles();

  std::vector<int> centre_;                  // pattern vertex of each model vertex
  std::vector<std::array<int, 4>> ring_;     // its four neighbours, counter-clockwise
  std::vector<FlatFoldMode> modes_;
  std::vector<Tie> ties_;
  std::vector<std::vector<std::pair<int, double>>> cycles_;  // (tie, +-1 orientation)
  bool gains_usable_ = false;
  std::string why_no_gains_;
};

}  // namespace rigidfold
