#pragma once
// Layer sheets of the stacked double-corrugated metamaterials 1-4 of seed 003 §3.2.3
// (Figs 3-10 ... 3-12; the figures are lost, the construction below is our reconstruction).
//
// Every layer is one flat-foldable parallelogram mesh (parallelogram_lattice.hpp) with all
// creases of length l: i-edges alternate the directions -beta and -alpha, j-edges the
// directions 0 and pi - alpha - beta (angles from the first j-edge), so every interior vertex
// has the sectors pi - beta, alpha, beta, pi - alpha (alpha + gamma = beta + delta = pi).
// Node (1, 0) is the seed's A2 of elements 1 and 2: sector pi - beta between A2A1 and A2B2,
// alpha between A2B2 and A2A3 (3-24).
//
// Folded, such a mesh is a translational surface: node (i, j) = U_0 + ... + U_{i-1} + V_0 +
// ... + V_{j-1} with one 3D vector per i-edge column and per j-edge row. The seed's elements
// are the motions in which one direction stays in a plane ("base plane") and the other climbs
// in levels (reconstruction):
//   element 1: i-edges in the base plane, j-levels 0 1 0 (rows A, B, C; the seed's H = height
//              of B2, W = |A1A3|, L = |A2C2|);
//   element 2: j-levels 0 1 2 1 0 (C' the mirror of C: H and L doubled, (3-25));
//   element 3: j-edges in the base plane, i-levels 0 1 2 1 0 (H = 2 B4B4', W over four
//              i-edges, L = |A5C5|, (3-27)).
// Layers, all 4 x 8 panels (identical-sized, as the seed requires):
//   metamaterial 1: j-levels 0 1 0 1 0 1 0 1 0  (four element-1 cells along L)
//   metamaterial 2: j-levels 0 1 2 1 0 1 2 1 0  (two element-2 cells)
//   metamaterial 3: j-levels 0 1 2 1 0 1 0 1 0  (one element-2 and two element-1 cells)
//   metamaterial 4: i-levels 0 1 2 1 0          (one element-3 cell along W, four along L)
// Metamaterials 1-3 have two element cells along W (four i-edges).
// Stacking: layer k + 1 has the reverse M-V assignment of layer k (its folded shape is the
// mirror image) and is bonded to it along the top-level lines (the bonding vertices).
// The letters are those of the analytic motion above at a folded state; they select that
// motion's branch at the flat state.
//
// Inputs: metamaterial 1..4; alpha, beta (radians, in (0, pi), alpha + beta != pi for 4: its
// element is locked there); l > 0; reversed: the reverse M-V assignment.
// Output: the flat pattern (z = 0) with letters, and the indices below.
// Throws InputError with place "metamaterial", "alpha", "beta" or "l".
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct StackedMetamaterialParams {
  int metamaterial = 1;   // 1..4
  double alpha = 1.0;     // radians
  double beta = 0.8;      // radians
  double l = 1.0;         // crease length
};

struct StackedLayerSheet {
  CreasePattern pattern;
  int ni = 0, nj = 0;               // panels along i (W) and j (L)
  bool levels_along_j = true;       // metamaterials 1-3; 4: levels along i
  std::vector<int> levels;          // level of each node row j (1-3) or column i (4)
  // The seed's A2B2, whose dihedral is the input phi: j-edge (1, 0) for 1-3 (sectors pi - beta
  // and alpha beside it, as (3-24)); for 4 the j-edge (2, 0) of the peak column (our choice,
  // the figure is lost: the only j-creases tied to theta by the cos form of (3-26) - inverted,
  // tan(phi/2) = |k| tan(theta/2), see stacked_metamaterial_check.hpp).
  int phi_edge = -1;
  int theta_edge = -1;              // metamaterial 4: the seed's B4B5 (dihedral theta); else -1
  std::vector<int> bonding_vertices;  // nodes on the top level
  // The layer's closed-form dimensions: (cells_W W_e, cells_L L_e, H_e) of element e
  // (1: metamaterial 1; 2: metamaterials 2 and 3, whose two element-1 cells are as long as one
  // element-2 cell; 3: metamaterial 4), W_e, L_e, H_e of corrugated_elements.hpp.
  int element = 1;
  int cells_W = 0;
  int cells_L = 0;
  int node(int i, int j) const { return j * (ni + 1) + i; }
  int i_edge(int i, int j) const { return j * ni + i; }
  int j_edge(int i, int j) const { return ni * (nj + 1) + j * (ni + 1) + i; }
};

StackedLayerSheet stacked_layer_sheet(const StackedMetamaterialParams& params, bool reversed = false);

// The fold angle rho of every edge (radians, > 0 valley; 0 on the boundary) of the layer's
// analytic motion at parameter t: the dihedral of A2B2 (metamaterials 1-3) or of B4B5 (4),
// radians in (0, pi], pi flat; the reversed layer's are their negatives. A start for the
// general solver's continuation (trace_motion's own start, small equal folds the letters'
// way, lands on another branch of these many-vertex sheets: it disagrees with 11 of the 52
// letters of metamaterial 1). Throws as stacked_layer_sheet.
std::vector<double> stacked_layer_fold_angles(const StackedMetamaterialParams& params, bool reversed, double t);

}  // namespace rigidfold::generators
