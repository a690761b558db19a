#pragma once
// Diamond (Yoshimura-type) arch of seed 003 §4.4.1 (Fig. 4-12, lost; reconstructed here): one
// row of N identical six-crease diamond vertices (sectors (4-29) a, pi - 2a, a, a, pi - 2a, a,
// 0 < a <= pi/4; the seed's figure uses a = pi/6) whose symmetric motion (4-39) bends the row
// into an arch.
//
// Reconstruction (the figure is lost): the vertices V_1..V_N sit on one straight valley line
// y = 0, spaced `length` apart; V_0 and V_{N+1} end it on the boundary. From V_i the four
// mountain diagonals at angles a, pi - a, pi + a, -a run to the apexes T_{i-1}, T_i (above, y = h)
// and B_{i-1}, B_i (below, y = -h), h = (length / 2) tan a, T_j, B_j at x = (j + 1/2) length. The
// sheet is the band between the zig-zags T_0..T_N and B_0..B_N (straight lines y = +-h),
// closed at the ends by V_0 and V_{N+1}: diamonds V_j T_j V_{j+1} B_j split by the valley line,
// with the triangles T_{j-1} V_j T_j and B_{j-1} V_j B_j between them.
// At V_i the creases, counter-clockwise from the valley to V_{i+1}: c0 V_i V_{i+1} (V),
// c1 V_i T_i (M), c2 V_i T_{i-1} (M), c3 V_i V_{i-1} (V), c4 V_i B_{i-1} (M), c5 V_i B_i (M) -
// the letters of the diamond model (kernel/thick/thick_vertex_models.hpp, creases 0 and 3 valley).
// Vertex order: V_0..V_{N+1}, T_0..T_N, B_0..B_N. Edge order: the valley creases V_j V_{j+1},
// j = 0..N; per interior vertex i = 1..N its diagonals c1, c2, c4, c5; then the boundary.
// Faces: derived, 4N + 2 triangles (two per diamond, j = 0..N, and two per interior vertex).
//
// Thick model (diamond_arch_thick): one plane-symmetric Bricard loop per vertex (4-40, 4-41,
// lengths (t1, t2, t1 + t2, t1 + t2, t2, t1) across the model's sectors 0..5) made of hinge
// heights (vertex_height_steps.hpp). The model's crease 0 alternates: at odd i it is c0 (to
// V_{i+1}), at even i it is c3 (to V_{i-1}, the model turned by pi, which the sectors allow).
// Only then do the shared triangles agree on a thickness (panel_compatibility.hpp): a diamond
// half between V_i and V_{i+1} is the model's sector 0 or 5 at both ends (thickness t1) for odd
// i, sector 2 or 3 at both ends (t1 + t2) for even i; the triangles at one vertex are sector 1
// or 4 (t2). With one orientation everywhere a diamond half would be asked t1 by one vertex
// and t1 + t2 by the other.
//
// Units: lengths in pattern units, angles in radians.
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_vertex_models.hpp"

namespace rigidfold::generators {

struct DiamondArchParams {
  int vertices = 6;                  // N interior vertices (1 .. 1000)
  double a = 0.5235987755982988;     // sector a (radians), 0 < a <= pi/4; default pi/6 (the seed's)
  double length = 1.0;               // valley segment V_i V_{i+1} (> 0)
};

// Validated pattern; throws InputError (place "vertices", "a" or "length").
CreasePattern diamond_arch(const DiamondArchParams& params);

// Flat-pattern vertex index of V_i (i = 0..N+1).
inline int diamond_arch_valley_vertex(int i) { return i; }
// Edge index of the valley crease V_j V_{j+1} (j = 0..N).
inline int diamond_arch_valley_edge(int j) { return j; }

struct DiamondArchThick {
  ThickVertexModel model;                  // diamond_vertex(a, t1, t2)
  std::vector<int> model_start;            // per flat vertex: fan position (topology.stars[v].fans[0]) of the model's crease 0; -1 if not interior
  std::vector<std::vector<double>> steps;  // per flat vertex: signed height step per fan sector (hinge_heights_from_steps)
  std::vector<double> edge_heights;        // per flat edge (pattern units), hinge_heights_from_steps
  std::vector<double> panel_thickness;     // per flat face: agreed_panel_thickness of every vertex's claims
};

// The thick model of diamond_arch(params) (pattern and its topology as built from it), panel
// thicknesses t1, t2 > 0 (pattern units). Throws std::invalid_argument (from the kernel) if a
// vertex does not match the model, the heights disagree on a shared crease
// (HingeHeightConflict) or two vertices ask one panel for different thicknesses
// (PanelThicknessConflict).
DiamondArchThick diamond_arch_thick(const CreasePattern& pattern, const Topology& topology, const DiamondArchParams& params,
                                    double t1, double t2);

// Zero-thickness fold angles (per flat edge, radians, FOLD sign) of the symmetric motion (4-39)
// with every valley crease at rho_valley (> 0): diagonals from tan(phi2/2) = cos a tan(phi1/2),
// phi = pi - |rho|.
Eigen::VectorXd diamond_arch_symmetric_state(const CreasePattern& pattern, const DiamondArchParams& params, double rho_valley);

}  // namespace rigidfold::generators
