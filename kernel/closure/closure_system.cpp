#include "kernel/closure/closure_system.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {

namespace {

void check_edge(int e, int num_edges, const char* what) {
  if (e < 0 || e >= num_edges)
    throw std::invalid_argument(std::string("closure system: ") + what + " edge " + std::to_string(e) +
                                " out of range [0, " + std::to_string(num_edges) + ")");
}

}  // namespace

ClosureSystem::ClosureSystem(const CreasePattern& pattern, const Topology& topology, const ClosureOptions& options)
    : num_edges_(pattern.num_edges()),
      unknown_of_edge_(pattern.num_edges(), -1),
      constant_angle_(pattern.num_edges(), 0.0),
      is_fixed_(pattern.num_edges(), false) {
  for (std::size_t c = 0; c < topology.components.size(); ++c) {
    const Component& comp = topology.components[c];
    if (comp.genus > 0 || (comp.holes > 0 && !options.close_holes))
      throw std::runtime_error("closure system: component " + std::to_string(c) + " has " +
                               std::to_string(comp.holes) + " hole(s) and genus " + std::to_string(comp.genus) +
                               "; SE(3) loop closure around holes not supported yet" +
                               (comp.genus > 0 ? " for handles" : " unless ClosureOptions::close_holes is set"));
  }
  auto foldable_hinge = [&](int e) {
    return topology.edge_is_hinge[e] && is_foldable_crease(pattern.assignments[e]);
  };
  for (const auto& [e, value] : options.fixed) {
    check_edge(e, num_edges_, "fixed");
    if (!foldable_hinge(e))
      throw std::invalid_argument("closure system: fixed edge " + std::to_string(e) +
                                  " is not a foldable hinge (M, V or U between two faces)");
    if (is_fixed_[e]) throw std::invalid_argument("closure system: edge " + std::to_string(e) + " fixed twice");
    is_fixed_[e] = true;
    constant_angle_[e] = value;
  }
  for (int e = 0; e < num_edges_; ++e) {
    if (foldable_hinge(e) && !is_fixed_[e]) {
      unknown_of_edge_[e] = static_cast<int>(free_edges_.size());
      free_edges_.push_back(e);
    }
  }
  for (const CreaseEquality& q : options.equalities) {
    check_edge(q.edge_a, num_edges_, "equality");
    check_edge(q.edge_b, num_edges_, "equality");
    if (q.sign != 1.0 && q.sign != -1.0)
      throw std::invalid_argument("closure system: equality sign must be +1 or -1");
    equalities_.push_back(q);
  }
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans.at(0);
    vertices_.push_back(VertexRow{v, fan.edges, fan.sectors});
  }
  if (options.close_holes) {
    holes_ = find_hole_loops(pattern, topology);
    if (!holes_.empty()) {
      hole_geometry_.vertices = pattern.vertices;
      hole_geometry_.edges = pattern.edges;
      hole_geometry_.faces = pattern.faces;
      const Eigen::VectorXd ref = reference_fold_angles(pattern, topology);
      reference_angle_.assign(ref.data(), ref.data() + ref.size());
      is_rigid_hinge_.assign(num_edges_, false);
      for (int e = 0; e < num_edges_; ++e)
        is_rigid_hinge_[e] = topology.edge_is_hinge[e] && !is_foldable_crease(pattern.assignments[e]);
      Eigen::Vector3d lo = pattern.vertices[0], hi = pattern.vertices[0];
      for (const auto& v : pattern.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
      length_scale_ = std::max((hi - lo).norm(), 1e-300);
    }
  }
  build_jacobian_pattern();
}

void ClosureSystem::build_jacobian_pattern() {
  // (row, col) of every entry evaluate() emits, in its emission order.
  std::vector<std::pair<int, int>> entries;
  for (int k = 0; k < num_vertices(); ++k)
    for (int e : vertices_[k].edges)
      if (const int col = unknown_of_edge_[e]; col >= 0)
        for (int d = 0; d < 3; ++d) entries.emplace_back(3 * k + d, col);
  const int base = 3 * num_vertices();
  for (std::size_t q = 0; q < equalities_.size(); ++q) {
    const int rowi = base + static_cast<int>(q);
    if (const int ca = unknown_of_edge_[equalities_[q].edge_a]; ca >= 0) entries.emplace_back(rowi, ca);
    if (const int cb = unknown_of_edge_[equalities_[q].edge_b]; cb >= 0) entries.emplace_back(rowi, cb);
  }
  for (int h = 0; h < num_holes(); ++h)
    for (const auto& step : holes_[h].steps)
      if (const int col = unknown_of_edge_[step.edge]; col >= 0 && !is_rigid_hinge_[step.edge])
        for (int d = 0; d < 6; ++d) entries.emplace_back(hole_row_begin() + 6 * h + d, col);

  // Counting sort by column, then by row inside each (short) column; repeated (row, col)
  // pairs share one slot, so their contributions add up as the triplets used to.
  const int n = num_unknowns();
  std::vector<int> count(n + 1, 0);
  for (const auto& rc : entries) ++count[rc.second + 1];
  for (int c = 0; c < n; ++c) count[c + 1] += count[c];
  std::vector<int> order(entries.size());
  {
    std::vector<int> next(count.begin(), count.end() - 1);
    for (std::size_t t = 0; t < entries.size(); ++t) order[next[entries[t].second]++] = static_cast<int>(t);
  }
  jac_outer_.assign(n + 1, 0);
  jac_inner_.clear();
  jac_slot_.assign(entries.size(), -1);
  for (int c = 0; c < n; ++c) {
    auto first = order.begin() + count[c], last = order.begin() + count[c + 1];
    std::sort(first, last, [&](int a, int b) { return entries[a].first < entries[b].first || (entries[a].first == entries[b].first && a < b); });
    for (auto it = first; it != last; ++it) {
      const int row = entries[*it].first;
      if (jac_inner_.size() == static_cast<std::size_t>(jac_outer_[c]) || jac_inner_.back() != row)
        jac_inner_.push_back(row);
      jac_slot_[*it] = static_cast<int>(jac_inner_.size()) - 1;
    }
    jac_outer_[c + 1] = static_cast<int>(jac_inner_.size());
  }
}

void ClosureSystem::gather_hole(const HoleLoop& loop, const Eigen::VectorXd& x, std::vector<double>& theta) const {
  theta.resize(loop.steps.size());
  for (std::size_t i = 0; i < loop.steps.size(); ++i) {
    const int e = loop.steps[i].edge;
    theta[i] = is_rigid_hinge_[e] ? 0.0 : angle_of_edge(e, x) - reference_angle_[e];
  }
}

void ClosureSystem::set_fixed_value(int edge, double value) {
  check_edge(edge, num_edges_, "fixed");
  if (!is_fixed_[edge]) throw std::invalid_argument("closure system: edge " + std::to_string(edge) + " is not fixed");
  constant_angle_[edge] = value;
}

double ClosureSystem::fixed_value(int edge) const {
  check_edge(edge, num_edges_, "queried");
  return constant_angle_[edge];
}

Eigen::VectorXd ClosureSystem::unknowns_from_edges(const Eigen::VectorXd& edge_angles) const {
  if (edge_angles.size() != num_edges_)
    throw std::invalid_argument("closure system: expected " + std::to_string(num_edges_) + " edge angles");
  Eigen::VectorXd x(num_unknowns());
  for (int k = 0; k < num_unknowns(); ++k) x[k] = edge_angles[free_edges_[k]];
  return x;
}

Eigen::VectorXd ClosureSystem::edges_from_unknowns(const Eigen::VectorXd& x) const {
  Eigen::VectorXd rho(num_edges_);
  for (int e = 0; e < num_edges_; ++e) rho[e] = angle_of_edge(e, x);
  return rho;
}

double ClosureSystem::angle_of_edge(int e, const Eigen::VectorXd& x) const {
  const int k = unknown_of_edge_[e];
  return k >= 0 ? x[k] : constant_angle_[e];
}

void ClosureSystem::gather(const VertexRow& row, const Eigen::VectorXd& x, std::vector<double>& angles) const {
  angles.resize(row.edges.size());
  for (std::size_t i = 0; i < row.edges.size(); ++i) angles[i] = angle_of_edge(row.edges[i], x);
}

Eigen::VectorXd ClosureSystem::residual(const Eigen::VectorXd& x) const {
  if (x.size() != num_unknowns())
    throw std::invalid_argument("closure system: expected " + std::to_string(num_unknowns()) + " unknowns");
  Eigen::VectorXd r(num_rows());
  std::vector<double> angles;
  for (int k = 0; k < num_vertices(); ++k) {
    const VertexRow& row = vertices_[k];
    gather(row, x, angles);
    r.segment<3>(3 * k) = vertex_closure_residual(std::span<const double>(row.sectors), std::span<const double>(angles));
  }
  for (std::size_t q = 0; q < equalities_.size(); ++q) {
    const CreaseEquality& eq = equalities_[q];
    r[3 * num_vertices() + static_cast<int>(q)] = angle_of_edge(eq.edge_a, x) - eq.sign * angle_of_edge(eq.edge_b, x);
  }
  std::vector<double> theta;
  for (int h = 0; h < num_holes(); ++h) {
    gather_hole(holes_[h], x, theta);
    r.segment<6>(hole_row_begin() + 6 * h) =
        hole_closure_residual(hole_geometry_, holes_[h], std::span<const double>(theta), length_scale_);
  }
  return r;
}

void ClosureSystem::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& residual,
                             Eigen::SparseMatrix<double>& jacobian) const {
  if (x.size() != num_unknowns())
    throw std::invalid_argument("closure system: expected " + std::to_string(num_unknowns()) + " unknowns");
  residual.resize(num_rows());
  // Give the caller's matrix the fixed pattern unless it already has it (the usual case in
  // a Newton loop), then zero its values and accumulate every entry into its slot.
  const int nnz = static_cast<int>(jac_inner_.size());
  const bool has_pattern = jacobian.rows() == num_rows() && jacobian.cols() == num_unknowns() &&
                           jacobian.isCompressed() && jacobian.nonZeros() == nnz &&
                           std::equal(jac_outer_.begin(), jac_outer_.end(), jacobian.outerIndexPtr()) &&
                           std::equal(jac_inner_.begin(), jac_inner_.end(), jacobian.innerIndexPtr());
  if (!has_pattern) {
    jacobian.resize(num_rows(), num_unknowns());
    jacobian.resizeNonZeros(nnz);
    std::copy(jac_outer_.begin(), jac_outer_.end(), jacobian.outerIndexPtr());
    std::copy(jac_inner_.begin(), jac_inner_.end(), jacobian.innerIndexPtr());
  }
  double* values = jacobian.valuePtr();
  std::fill(values, values + nnz, 0.0);
  std::size_t t = 0;  // entry counter, in build_jacobian_pattern's emission order

  std::vector<double> angles;
  Eigen::Vector3d r;
  Eigen::Matrix3Xd jv;
  for (int k = 0; k < num_vertices(); ++k) {
    const VertexRow& row = vertices_[k];
    gather(row, x, angles);
    vertex_closure_jacobian(std::span<const double>(row.sectors), std::span<const double>(angles), r, jv);
    residual.segment<3>(3 * k) = r;
    for (std::size_t i = 0; i < row.edges.size(); ++i) {
      if (unknown_of_edge_[row.edges[i]] < 0) continue;
      // A crease met twice in one fan (degenerate input) contributes twice: slots add up.
      for (int d = 0; d < 3; ++d) values[jac_slot_[t++]] += jv(d, static_cast<int>(i));
    }
  }
  const int base = 3 * num_vertices();
  for (std::size_t q = 0; q < equalities_.size(); ++q) {
    const CreaseEquality& eq = equalities_[q];
    const int rowi = base + static_cast<int>(q);
    residual[rowi] = angle_of_edge(eq.edge_a, x) - eq.sign * angle_of_edge(eq.edge_b, x);
    if (unknown_of_edge_[eq.edge_a] >= 0) values[jac_slot_[t++]] += 1.0;
    if (unknown_of_edge_[eq.edge_b] >= 0) values[jac_slot_[t++]] += -eq.sign;
  }
  std::vector<double> theta;
  Eigen::Matrix<double, 6, 1> rh;
  Eigen::Matrix<double, 6, Eigen::Dynamic> jh;
  for (int h = 0; h < num_holes(); ++h) {
    const HoleLoop& loop = holes_[h];
    const int row0 = hole_row_begin() + 6 * h;
    gather_hole(loop, x, theta);
    hole_closure_jacobian(hole_geometry_, loop, std::span<const double>(theta), length_scale_, rh, jh);
    residual.segment<6>(row0) = rh;
    for (std::size_t i = 0; i < loop.steps.size(); ++i) {
      const int e = loop.steps[i].edge;
      if (unknown_of_edge_[e] < 0 || is_rigid_hinge_[e]) continue;
      // A crease crossed twice in one loop contributes twice: slots add up.
      for (int d = 0; d < 6; ++d) values[jac_slot_[t++]] += jh(d, static_cast<int>(i));
    }
  }
}

Eigen::MatrixXd dense_jacobian(const ClosureSystem& system, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  return Eigen::MatrixXd(J);
}

}  // namespace rigidfold
