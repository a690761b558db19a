#include "kernel/thick/thick_mobility.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

ThickMobilityReport thick_mobility(const ThickHeightSheet& sheet, const Eigen::VectorXd& state,
                                   const std::vector<Eigen::VectorXd>& zero_thickness_states, double closure_tolerance,
                                   const RankOptions& rank_options) {
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(system.unknowns_from_edges(sheet.sheet_edge_angles(state)), r, J);
  ThickMobilityReport report;
  report.state_residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  if (!(report.state_residual <= closure_tolerance)) {
    std::ostringstream message;
    message << "thick mobility: the state does not close (residual " << report.state_residual << ")";
    throw std::invalid_argument(message.str());
  }
  report.rank = jacobian_rank(J, rank_options);
  report.dof = report.rank.dof;

  const Eigen::MatrixXd dense = Eigen::MatrixXd(J);
  std::vector<Eigen::VectorXd> zero_residuals;
  for (const Eigen::VectorXd& z : zero_thickness_states)
    zero_residuals.push_back(system.residual(system.unknowns_from_edges(sheet.sheet_edge_angles(z))));
  RankOptions alone_options = rank_options;
  alone_options.method = RankMethod::kDenseSvd;
  for (int k = 0; k < system.num_holes(); ++k) {
    ThickVertexMobility v;
    v.vertex = k < static_cast<int>(sheet.vertex_of_hole.size()) ? sheet.vertex_of_hole[k] : -1;
    v.hole = k;
    const int row = system.hole_row_begin() + 6 * k;
    std::vector<int> columns;
    for (int c = 0; c < system.num_unknowns(); ++c)
      if (dense.block(row, c, 6, 1).cwiseAbs().maxCoeff() > 0.0) columns.push_back(c);
    Eigen::MatrixXd block(6, columns.size());
    for (std::size_t j = 0; j < columns.size(); ++j) block.col(j) = dense.block(row, columns[j], 6, 1);
    v.creases = static_cast<int>(columns.size());
    v.dof_alone = jacobian_rank(block.sparseView(0.0, 0.0), alone_options).dof;
    for (const Eigen::VectorXd& z : zero_residuals) v.off_motion = std::max(v.off_motion, z.segment<6>(row).cwiseAbs().maxCoeff());
    if (v.dof_alone == 0) report.locked_vertices.push_back(v.vertex);
    if (v.off_motion > closure_tolerance) report.off_motion_vertices.push_back(v.vertex);
    report.vertices.push_back(v);
  }
  std::sort(report.locked_vertices.begin(), report.locked_vertices.end());
  std::sort(report.off_motion_vertices.begin(), report.off_motion_vertices.end());
  return report;
}

}  // namespace rigidfold
