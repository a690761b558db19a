#pragma once
// Tessellation of double-corrugated units (seed 003 §3.2.3, Fig 3-9): the 5 x 5-panel sheet of
// the double-corrugated parallelogram mesh (double_corrugated.hpp) with 4 x 4 interior
// degree-4 vertices, read as 3 x 3 overlapping unit windows.
//
// Geometry (lengths a, b; sectors alpha, beta, gamma = pi - alpha, delta = pi - beta as in
// double_corrugated.hpp): parallelogram_lattice with
//   u = (u1, u0, u1, u0, u1), v = (vb, va, vb, va, vb),
//   u0 = a (1, 0), u1 = a (cos z, sin z), z = alpha + beta + pi, va = b (cos alpha, sin alpha),
//   vb = b (cos beta, sin beta),
// so node (i, j) of the sheet is node (i - w_a, j - w_b) of window (w_a, w_b).
// Windows: window (w_a, w_b), w_a, w_b in {0, 1, 2}, is the 3 x 3-panel block of panels
// i = w_a .. w_a + 2, j = w_b .. w_b + 2 (central panel (w_a + 1, w_b + 1)), with the four
// interior vertices around its central panel. Its central panel has angles alpha/gamma (a
// "P-shaped" window: w_a, w_b both even or both odd) or beta/delta (a "Q-shaped" window).
// The four corner windows (0, 0), (2, 0), (0, 2), (2, 2) are translated copies of unit P of
// corrugated_unit (same u, v); they are disjoint and hold all 16 interior vertices, so their
// letters decide every crease (the seed: "after giving the M-V distribution of these four P
// patterns, the whole M-V distribution of the tessellation are decided"); the five other
// windows are derived. Windows (1, 0) and (1, 2) are translated copies of unit Q.
// The thesis's figure is lost; which letters make "Fig 3-9(b)" is the caller's choice
// (tests/metamaterial/corrugated_tessellation_test.cpp searches them: of the 8192 consistent
// sheets (the kernel's enumeration finds as many), 224 have four rigid corner windows; 60 of
// those fold (all nine windows rigid), 164 do not). Bundled, alpha 135, beta 60 deg:
// data/metamaterial/corrugated_fig3-9b.fold (two corner assignments, two windows each; a
// derived P-shaped and a derived Q-shaped window non-rigid: not foldable, loop gain 97.99)
// and corrugated_all_p1_rigid.fold (every corner the bundled rigid P: foldable, 1 DOF).
//
// Edge order: that of parallelogram_lattice (ni = nj = 5): i-edges j * 5 + i, then j-edges
// 30 + j * 6 + i.
#include <array>
#include <string>
#include <vector>

#include "data/generators/double_corrugated.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct CorrugatedTessellationWindow {
  int wa = 0, wb = 0;
  bool p_shaped = true;          // central panel angles alpha/gamma (else beta/delta)
  std::array<int, 4> vertices{}; // sheet vertices around the central panel
  std::array<int, 24> edges{};   // sheet edge of each edge of the window's own 3 x 3 lattice
                                 // (parallelogram_lattice order, ni = nj = 3)
};

// The 9 windows, (w_a, w_b) = (0, 0), (1, 0), (2, 0), (0, 1), ... (row by row).
std::vector<CorrugatedTessellationWindow> corrugated_tessellation_windows();

// Sheet edges of a corner window's 12 interior creases, in unit P's order
// (corrugated_interior_edges(P): AB BC CD DA a3 a4 b1 b2 c3 c4 d1 d2). corner in 0..3 for
// windows (0, 0), (2, 0), (0, 2), (2, 2).
std::array<int, 12> corrugated_tessellation_corner_edges(int corner);

// The sheet with every corner window's 12 letters (unit P's order; M or V). Throws
// InputError: place "alpha", "beta", "a", "b" as corrugated_unit; "corners" for a letter
// other than M or V, or for two corner windows giving a shared crease different letters
// (the message names the crease and the windows).
CreasePattern corrugated_tessellation(const CorrugatedParams& params,
                                      const std::array<std::vector<Assignment>, 4>& corners);

// Window (w_a, w_b) of a sheet made by corrugated_tessellation, as its own 3 x 3-panel
// pattern with the sheet's letters on its 12 interior creases. Throws InputError("window")
// for w_a or w_b outside 0..2, or a sheet that is not a 5 x 5-panel corrugated tessellation.
CreasePattern corrugated_tessellation_window(const CorrugatedParams& params, const CreasePattern& sheet, int wa, int wb);

}  // namespace rigidfold::generators
