#include "kernel/thick/panel_compatibility.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rigidfold {

namespace {

// Checks the vertex and its degree; returns its name for messages.
std::string checked_vertex_name(const ThickVertexModel& model, const Topology& topology, int vertex) {
  const std::string name = "vertex " + std::to_string(vertex) + " (" + model.name + ")";
  if (vertex < 0 || vertex >= static_cast<int>(topology.stars.size()) || !topology.stars[vertex].interior())
    throw std::invalid_argument(name + ": not an interior vertex");
  const Fan& fan = topology.stars[vertex].fans[0];
  if (fan.sectors.size() != model.sectors.size())
    throw std::invalid_argument(name + ": degree " + std::to_string(fan.sectors.size()) + ", the model has " +
                                std::to_string(model.sectors.size()));
  return name;
}

bool sectors_match(const ThickVertexModel& model, const Fan& fan, int shift, double angle_tolerance) {
  const int n = static_cast<int>(model.sectors.size());
  for (int i = 0; i < n; ++i)
    if (!(std::abs(fan.sectors[(i + shift) % n] - model.sectors[i]) <= angle_tolerance)) return false;
  return true;
}

std::vector<PanelThicknessClaim> claims_at(const ThickVertexModel& model, const Fan& fan, const std::string& name, int shift) {
  const int n = static_cast<int>(model.sectors.size());
  const ThickLoop& loop = model.thick.loops.at(0);
  std::vector<PanelThicknessClaim> claims;
  for (int i = 0; i < n; ++i) {
    const double a = std::abs(loop.joints[i].link.length);
    if (a == 0.0) continue;  // both hinges on one face: no claim on the thickness
    claims.push_back(PanelThicknessClaim{name, i, fan.faces[(i + shift) % n], a});
  }
  return claims;
}

}  // namespace

std::vector<PanelThicknessClaim> vertex_panel_claims(const ThickVertexModel& model, const Topology& topology, int vertex,
                                                     double angle_tolerance) {
  const std::string name = checked_vertex_name(model, topology, vertex);
  const Fan& fan = topology.stars[vertex].fans[0];
  const int n = static_cast<int>(model.sectors.size());
  for (int shift = 0; shift < n; ++shift)
    if (sectors_match(model, fan, shift, angle_tolerance)) return claims_at(model, fan, name, shift);
  throw std::invalid_argument(name + ": its sectors do not match the model's in any cyclic order");
}

std::vector<PanelThicknessClaim> vertex_panel_claims_at(const ThickVertexModel& model, const Topology& topology, int vertex,
                                                        int start, double angle_tolerance) {
  const std::string name = checked_vertex_name(model, topology, vertex);
  const Fan& fan = topology.stars[vertex].fans[0];
  const int n = static_cast<int>(model.sectors.size());
  if (start < 0 || start >= n)
    throw std::invalid_argument(name + ": fan position " + std::to_string(start) + " out of range (degree " + std::to_string(n) + ")");
  if (!sectors_match(model, fan, start, angle_tolerance))
    throw std::invalid_argument(name + ": its sectors do not match the model's with crease 0 at fan position " +
                                std::to_string(start));
  return claims_at(model, fan, name, start);
}

std::vector<double> agreed_panel_thickness(int num_panels, const std::vector<PanelThicknessClaim>& claims,
                                           double relative_tolerance) {
  std::vector<double> agreed(std::max(num_panels, 0), 0.0);
  std::vector<const PanelThicknessClaim*> first(agreed.size(), nullptr);
  for (const PanelThicknessClaim& claim : claims) {
    if (claim.panel < 0 || claim.panel >= num_panels)
      throw std::invalid_argument(claim.vertex + ": panel " + std::to_string(claim.panel) + " out of range (" +
                                  std::to_string(num_panels) + " panels)");
    if (!(claim.thickness > 0))
      throw std::invalid_argument(claim.vertex + ": thickness of panel " + std::to_string(claim.panel) + " must be > 0");
    const PanelThicknessClaim*& earlier = first[claim.panel];
    if (!earlier) {
      earlier = &claim;
      agreed[claim.panel] = claim.thickness;
      continue;
    }
    if (std::abs(claim.thickness - earlier->thickness) > relative_tolerance * std::max(claim.thickness, earlier->thickness)) {
      std::ostringstream message;
      message.precision(12);
      message << "panel " << claim.panel << ": " << earlier->vertex << " asks for thickness " << earlier->thickness
              << " (sector " << earlier->sector << "), " << claim.vertex << " for " << claim.thickness << " (sector "
              << claim.sector << ")";
      throw PanelThicknessConflict(*earlier, claim, message.str());
    }
  }
  return agreed;
}

}  // namespace rigidfold
