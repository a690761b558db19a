#pragma once
// Closed-form input-output of a spherical 4R linkage (a degree-4 vertex) with arbitrary
// twists, in the kernel's convention (see vertex_closure.hpp):
//     Rx(rho_0) Rz(alpha_0) Rx(rho_1) Rz(alpha_1) Rx(rho_2) Rz(alpha_2) Rx(rho_3) Rz(alpha_3) = I
// Joint i of the linkage is crease i, its joint angle is the fold angle rho_i
// (radians, > 0 valley). alpha_i (the twist / sector between crease i and i+1) may be any
// real number: sum != 2 pi (non-developable), alpha > pi/2, alpha < 0 are all legal.
// Indices are 0-based here; crease i is the papers' crease/joint i+1, alpha_i the papers'
// alpha_{(i+1)(i+2)}.
//
// Relation for one pair of adjacent creases (input crease k, output crease k+1), with
// a1 = alpha_k, a2 = alpha_{k+1}, a3 = alpha_{k+2}, a4 = alpha_{k+3}, c_j/s_j = cos/sin a_j:
//   the axes of crease k+2 and crease k+3 make the angle a3, i.e.
//     A cos rho_{k+1} + B sin rho_{k+1} = C,
//     A = -s2 (s1 c4 + c1 s4 cos rho_k),  B = s2 s4 sin rho_k,
//     C = c3 - c2 (c1 c4 - s1 s4 cos rho_k).
//   (c1 c4 - s1 s4 cos rho_k is the cosine of the angle between creases k+3 and k+1.)
//
// Mapping to the seeds. Seed 003 eq. (2-1)/(2-2) (with the matrix of (2-2), see the digest)
// and seed 001 eq. (1)/(2) close the loop prod_i Rz(theta_i) Rx(alpha_{i(i+1)}) = I, with
// theta > 0 mountain. The half-turn H about (e_x + e_z)/sqrt(2) swaps x and z
// (H Rz(t) H^T = Rx(t), H Rx(t) H^T = Rz(t)), so that loop is exactly the kernel's loop with
// rho_i = theta_i: seed 003 eq. (2-5) and seed 001 eq. (3) are, term by term, -1 times the
// relation above with rho -> theta. Both loops are also invariant under rho -> -rho (the
// mirror z -> -z; the seeds' central symmetry (2-10)), so the M/V-correct adapter
//     rho_i = -theta_i,  alpha_i = alpha_{(i+1)(i+2)} (same twists, same numbering)
// maps closed configurations to closed configurations; it only relabels which sign is
// mountain. Relations that are odd or even in all angles at once (tan-half multipliers,
// (2-6)/(2-13b), (2-10)) read identically in both conventions.
#include <array>
#include <vector>

namespace rigidfold {

using S4RSectors = std::array<double, 4>;     // alpha_0..alpha_3 (radians)
using S4RFoldAngles = std::array<double, 4>;  // rho_0..rho_3 (radians)

// Roots of A cos x + B sin x = C, for coefficients of order one.
// Inputs:
//   A, B, C  coefficients
//   tol      |C| <= hypot(A,B) (1 + tol) counts as solvable (C/hypot is clamped to
//            [-1, 1]); within 1 - tol of |C/hypot| = 1 the two roots are reported as one
//            double root. hypot(A,B) <= tol with |C| <= tol means every x is a root.
// Output: count = 0, 1 or 2 roots in [-pi, pi]:
//   x[0] = atan2(B, A) + acos(C / hypot(A, B)),  x[1] = atan2(B, A) - acos(...), wrapped.
struct CosSinRoots {
  int count = 0;
  std::array<double, 2> x{};
  bool any = false;  // A = B = C = 0 within tol: every x solves (count stays 0)
};
CosSinRoots solve_cos_sin(double A, double B, double C, double tol = 1e-12);

// Coefficients of the pair relation A cos rho_{k+1} + B sin rho_{k+1} = C (see above).
struct S4RPairCoefficients {
  double A = 0, B = 0, C = 0;
};
S4RPairCoefficients s4r_pair_coefficients(const S4RSectors& sectors, int k, double rho_k);

// Residual of the pair relation between crease k and crease k+1 (mod 4):
// A cos rho_{k+1} + B sin rho_{k+1} - C. Zero on every closed configuration.
// It is the kernel form of seed 003 eq. (2-5) for i = k+1 (times -1).
double s4r_pair_residual(const S4RSectors& sectors, int k, double rho_k, double rho_next);

// Every closed configuration for a given angle of one crease.
// Inputs:
//   sectors       alpha_0..alpha_3 (radians, any real)
//   rho_in        angle of the input crease (radians)
//   input_crease  which crease is driven (0..3), default 0
//   tol           feasibility / double-root tolerance of solve_cos_sin
// Output:
//   branches    0, 1 or 2 distinct configurations (rho_0..rho_3), each in [-pi, pi], with
//               rho[input_crease] = rho_in (wrapped). branches[0] takes the + root
//               (atan2(B,A) + acos) for crease input_crease+1, branches[1] the - root.
//               At a motion limit the two coincide and one branch is returned.
//   feasible    a real configuration exists at this input
//   degenerate  the input does not determine the others (two axes coaxial at this input,
//               or sin alpha_{in+1} / sin alpha_{in+2} below tol); branches is then empty.
// Throws std::invalid_argument if input_crease is not in 0..3.
struct S4RBranches {
  std::vector<S4RFoldAngles> branches;
  bool feasible = false;
  bool degenerate = false;
};
S4RBranches s4r_branches(const S4RSectors& sectors, double rho_in, int input_crease = 0,
                         double tol = 1e-12);

// Closure tolerance of s4r_branches_checked (rad): |log R| of each returned branch.
inline constexpr double kS4RClosureTolerance = 1e-10;

// s4r_branches (default tol), every branch verified before it is returned: its closure
// residual |log R| (vertex_closure.hpp) must be at most kS4RClosureTolerance. A branch that
// misses (near a motion limit the closed form's double root is only located to ~sqrt(tol))
// is refined by Gauss-Newton on the loop closure with the input crease held (the general
// route); if it still misses, throws NoAnswerError (kernel/pattern/no_answer_error.hpp)
// carrying the residual. Never returns a branch above the tolerance.
S4RBranches s4r_branches_checked(const S4RSectors& sectors, double rho_in, int input_crease = 0);

// Range of the input angle over which the linkage closes (its motion limits).
// The set of feasible inputs is always symmetric, {rho : min_abs <= |rho| <= max_abs}:
// the cosine of the angle between creases in+1 and in+3 is affine in cos(rho_in) and has
// to lie in [cos(a2 + a3), cos(a2 - a3)] (spherical triangle inequality), with
// a2 = alpha_{in+1}, a3 = alpha_{in+2}.
// Output:
//   feasible          some input closes the loop
//   min_abs, max_abs  bounds on |rho_in| in [0, pi] (radians), valid when feasible
//   limits()          the motion limits: +-min_abs when min_abs > 0, +-max_abs when
//                     max_abs < pi; at those inputs the two branches coincide
//   intervals()       the feasible set as closed intervals within [-pi, pi], ascending
//   contains(rho)     rho (any real, taken mod 2 pi) is feasible
struct S4RInputRange {
  bool feasible = false;
  double min_abs = 0.0;
  double max_abs = 0.0;
  std::vector<double> limits() const;
  std::vector<std::array<double, 2>> intervals() const;
  bool contains(double rho) const;
};
S4RInputRange s4r_input_range(const S4RSectors& sectors, int input_crease = 0);

}  // namespace rigidfold
