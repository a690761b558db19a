#pragma once
// Tan-half-angle multipliers of a flat-foldable degree-4 vertex.
//
// Convention: as vertex_closure.hpp, 0-based. Creases 0..3 counter-clockwise, sector i
// (alpha_i) between crease i and i+1, rho > 0 valley. The vertex is flat-foldable when
// alpha_0 + alpha_2 = alpha_1 + alpha_3 = pi (Kawasaki; the sum is then 2 pi), each
// sector in (0, pi).
//
// Such a vertex folds in two modes (the two branches through the flat state), on each of
// which every tan(rho_i / 2) is a fixed multiple of one parameter tau:
//     tan(rho_i / 2) = w_i * tau,
// with, for d = (alpha_1 - alpha_0)/2 and s = (alpha_1 + alpha_0)/2,
//   FlatFoldMode::kEqual13: w = ( sin d, -sin s, -sin d, -sin s)
//       rho_3 = rho_1, rho_2 = -rho_0. Creases 1 and 3 fold alike, 0 and 2 opposite; the
//       odd crease (the one whose sign differs from the other three) is crease 0 if
//       alpha_1 > alpha_0, crease 2 if alpha_1 < alpha_0: the crease between the two
//       smaller sectors of the pairs (alpha_0, alpha_1) and (alpha_2, alpha_3).
//       Seed 003 branch "S", eq. (3-3a).
//   FlatFoldMode::kEqual02: w = ( cos d, -cos s,  cos d,  cos s)
//       rho_2 = rho_0, rho_3 = -rho_1. Creases 0 and 2 fold alike; the odd crease is
//       crease 1 if alpha_0 + alpha_1 < pi, crease 3 if alpha_0 + alpha_1 > pi: the crease
//       between the two sectors whose sum is below pi.
//       Seed 003 branch "C", eq. (3-3b).
// Example, a Miura vertex with acute sectors alpha_0 = alpha_1 = a < pi/2 (crease 1
// between them, creases 1 and 3 collinear, 0 and 2 the zig-zag): kEqual02 is the Miura
// mode, the zig-zag creases 0, 2 fold alike and crease 1 is the odd one
// (e.g. M on the zig-zag, V on crease 1, M on crease 3); kEqual13 is the fold along the
// straight line 1-3 alone (d = 0: rho_0 = rho_2 = 0, rho_1 = rho_3).
// Degenerate cases (d = 0 in kEqual13, s = pi/2 in kEqual02) keep one pair of creases flat;
// there is then no odd crease (odd_crease = -1) and Maekawa's 3-1 count does not apply.
//
// The multipliers are the same in the seeds' convention (theta = -rho) since they are
// ratios of tan-halves; only the M/V meaning of a sign differs.
#include <array>

namespace rigidfold {

enum class FlatFoldMode {
  kEqual13,  // rho_3 = rho_1, rho_2 = -rho_0; odd crease 0 or 2 (seed 003 branch S)
  kEqual02,  // rho_2 = rho_0, rho_3 = -rho_1; odd crease 1 or 3 (seed 003 branch C)
};

const char* to_string(FlatFoldMode mode);

// Checks that a degree-4 vertex is flat-foldable: every sector in (0, pi),
// |alpha_0 + alpha_2 - pi| <= tol and |alpha_1 + alpha_3 - pi| <= tol (radians).
// Throws std::invalid_argument naming the violated condition otherwise.
void validate_flat_foldable(const std::array<double, 4>& sectors, double tol = 1e-9);

// Multipliers of one mode.
//   direction   w: tan(rho_i/2) = w_i * tau (never all zero; |w_i| <= 1)
//   step        k_i = tan(rho_{i+1}/2) / tan(rho_i/2) = w_{i+1} / w_i, i = 0..3 (crease 4 =
//               crease 0); +-infinity where w_i = 0 (that crease stays flat); prod k_i = 1
//   from_first  m_i = tan(rho_i/2) / tan(rho_0/2) = w_i / w_0 (m_0 = 1); infinite if w_0 = 0
//   odd_crease  index of the crease whose sign differs from the other three for every
//               tau != 0, or -1 in the degenerate case where one pair stays flat
struct FlatFoldMultipliers {
  std::array<double, 4> direction{};
  std::array<double, 4> step{};
  std::array<double, 4> from_first{};
  int odd_crease = -1;
};

// The directions w of both modes ([0] kEqual13, [1] kEqual02; each equal to
// flat_fold_multipliers(sectors, mode).direction), for callers that have already validated the
// sectors (validate_flat_foldable) and need nothing more: no check here.
std::array<std::array<double, 4>, 2> flat_fold_directions(const std::array<double, 4>& sectors);

// Inputs: sectors alpha_0..alpha_3 (radians), mode, tol for validate_flat_foldable.
// Throws std::invalid_argument if the vertex is not flat-foldable.
FlatFoldMultipliers flat_fold_multipliers(const std::array<double, 4>& sectors,
                                          FlatFoldMode mode, double tol = 1e-9);

// The four fold angles of a mode, driven by one crease.
// Inputs:
//   sectors     alpha_0..alpha_3 (radians), flat-foldable within tol
//   mode        which branch
//   rho_driver  fold angle of the driving crease (radians, in [-pi, pi])
//   driver      index of the driving crease (0..3), default 0
// Returns rho_0..rho_3 in [-pi, pi], rho[driver] = rho_driver. Computed as
// 2 atan2(w_i sin(rho/2), w_driver cos(rho/2)) (sign-adjusted), exact through rho = +-pi.
// Throws std::invalid_argument if not flat-foldable, driver is out of range, or the
// driving crease stays flat in this mode (w_driver = 0) and so cannot drive it.
std::array<double, 4> flat_fold_angles(const std::array<double, 4>& sectors, FlatFoldMode mode,
                                       double rho_driver, int driver = 0, double tol = 1e-9);

}  // namespace rigidfold
