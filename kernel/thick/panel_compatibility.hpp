#pragma once
// Compatibility of adjacent thick vertices (seed 003 ch. 4, §4.2: "shared panels must agree
// on thickness"). Each thick vertex model (thick_vertex_models.hpp) asks for a thickness on
// every panel around it: the link length a_{i(i+1)} between the hinges of sector i, whose
// hinges sit on opposite faces of the panel. A panel shared by several vertices must get
// the same thickness from all of them. A link of length 0 (Myard's a34) puts both hinges
// on one face and asks nothing of the thickness.
//
// Units: thicknesses in pattern units.
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_vertex_models.hpp"

namespace rigidfold {

struct PanelThicknessClaim {
  std::string vertex;      // who asks (a name for messages, e.g. "vertex 3 (Bennett)")
  int sector = -1;         // the vertex's sector (model numbering) that lies on the panel
  int panel = -1;          // face index of the pattern
  double thickness = 0.0;  // asked thickness (> 0), pattern units
};

// Thrown by agreed_panel_thickness when two claims on one panel differ.
struct PanelThicknessConflict : std::invalid_argument {
  PanelThicknessConflict(const PanelThicknessClaim& first, const PanelThicknessClaim& second, const std::string& message)
      : std::invalid_argument(message), first(first), second(second) {}
  PanelThicknessClaim first, second;
};

// The claims of one thick vertex model placed at an interior vertex of a pattern: the
// model's sectors are matched to the vertex's fan (topology.stars[vertex]) by a cyclic shift
// (each sector within angle_tolerance radians). Throws std::invalid_argument naming the
// vertex if it is not interior, has another degree, or no shift matches its sectors.
std::vector<PanelThicknessClaim> vertex_panel_claims(const ThickVertexModel& model, const Topology& topology, int vertex,
                                                     double angle_tolerance = 1e-9);

// The same with the placement given: the model's crease 0 on fan position `start` of
// topology.stars[vertex].fans[0] (for models whose sectors repeat, e.g. the diamond vertex
// turned by pi). Throws std::invalid_argument naming the vertex if the sectors do not match
// at that position (or as vertex_panel_claims).
std::vector<PanelThicknessClaim> vertex_panel_claims_at(const ThickVertexModel& model, const Topology& topology, int vertex,
                                                        int start, double angle_tolerance = 1e-9);

// Checks every panel's claims against each other: |t1 - t2| <= relative_tolerance * max(t1, t2).
// Returns the agreed thickness per panel (num_panels entries; 0 where no vertex asks).
// Throws PanelThicknessConflict for the first disagreement, e.g.
//   "panel 4: vertex 0 (Bennett) asks for thickness 0.2 (sector 1), vertex 2 (Bennett) for 0.3 (sector 3)"
// and std::invalid_argument for a panel index out of range or a thickness that is not > 0.
std::vector<double> agreed_panel_thickness(int num_panels, const std::vector<PanelThicknessClaim>& claims,
                                           double relative_tolerance = 1e-9);

}  // namespace rigidfold
