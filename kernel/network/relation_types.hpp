#pragma once
// Input-output relation types R1..R16 of a spherical 4R linkage and its 256 twist variants
// (seed 003 §2.2, Table 2-1).
//
// A twist variant replaces each twist alpha_k of a base 4R by one of
//     alpha, pi - alpha, -pi + alpha, -alpha            (AngleVariant 0..3)
// giving 4^4 = 256 variants, numbered by code = sum_k v_k 4^k (v_k the variant of twist k,
// twist k = the seed's alpha_{(k+1)(k+2)}; code 0 is the base itself).
// A joint angle admits the same four substitutions. Relation type Rk (k = 1..16) is a pair
// (sigma, tau) of them (Table 2-1, e.g. R3 = (theta, -pi + theta'), R12 = (-theta, theta')).
// A variant REALISES Rk for the joint pair (0, 1) (the seed's theta_1, theta_2) when
//     (theta_0, theta_1) closes the base's pair relation  <=>  (sigma(theta_0), tau(theta_1))
//     closes the variant's,
// i.e. the variant's theta_1 - theta_2 curve is the base's under the substitution.
// Angles in radians; the pair relation is s4r_pair_residual (spherical_4r.hpp), the seed's
// (2-5) for i = 1 in the kernel's loop (the same solution set, see spherical_4r.hpp).
#include <array>
#include <vector>

#include "kernel/network/linkage_network.hpp"
#include "kernel/vertex/spherical_4r.hpp"

namespace rigidfold {

// The four substitutions x -> x, pi - x, -pi + x, -x.
enum class AngleVariant { kSame = 0, kPiMinus = 1, kMinusPiPlus = 2, kMinus = 3 };
double apply_variant(AngleVariant v, double x);
const char* variant_text(AngleVariant v);  // "x", "pi-x", "-pi+x", "-x"

struct RelationType {
  int number = 0;                   // k of Rk, 1..16
  AngleVariant input, output;       // (sigma, tau): the input and output substitutions
};
// Table 2-1 in its order: element k-1 is Rk.
const std::array<RelationType, 16>& relation_types();

// The twists of variant `code` (0..255) of `base`. Throws std::invalid_argument if out of range.
S4RSectors twist_variant(const S4RSectors& base, int code);
// v_k of a code (twist k's substitution).
AngleVariant twist_variant_of(int code, int k);

struct VariantRelation {
  std::vector<int> realised;       // every k (1..16) the variant realises, ascending
  int samples = 0;                 // configurations compared, both directions
  // Largest pair residual over the samples for each realised type (the evidence that it
  // holds), and the smallest over types not realised of their largest residual (how clearly
  // the others fail).
  double realised_residual = 0.0;
  double rejected_margin = 0.0;
};

// Classifies variant `variant` against `base` with the closed form (s4r_branches): at
// `samples` inputs spread over the base's input range (and the variant's, for the converse),
// both branches, it evaluates each Rk's substituted pair residual; Rk is realised when every
// one is <= tolerance.
// Throws std::invalid_argument if samples < 2 or either linkage has no feasible input.
VariantRelation classify_twist_variant(const S4RSectors& base, const S4RSectors& variant, int samples = 24,
                                       double tolerance = 1e-9);

// Transmission chains of the rotation case (seed 003 §2.4, Table 2-4): sequences of
// `length` relation types Rk_1 - ... - Rk_L along the path theta_1^a -> ... -> theta_1^a
// whose substitutions cancel, so the loop of variant linkages closes whenever the base loop
// does: Rk_1's input is x, each output equals the next type's input, the last output is x;
// non-trivial (no R1, and no partial chain already back at x before the end).
// Returned in lexicographic order of the type numbers. Throws std::invalid_argument if
// length < 2 or > 6.
std::vector<std::vector<int>> closing_transmissions(int length);

// The type of the same variant read from joint 2 to joint 1: Rk = (sigma, tau) -> (tau, sigma).
int reversed_relation(int k);

// ---- Two-fold symmetric case (seed 003 §2.3-2.4, Fig 2-5, Table 2-2) ----
// Linkages A, B, C, D (loop order) joined a2-b2, b1-c1, c2-d2, d1-a1 with (2-15)
//     theta_2^a = -theta_2^b, theta_1^b = -theta_1^c, theta_2^c = -theta_2^d, theta_1^d = -theta_1^a.
// The seed's compatibility equations (2-16)-(2-22) are lost; derived here the way the
// rotation rule was. The identical assembly closes for every input t on the branch
//     A: (t, f(t)),  B: (-t, -f(t)),  C: (t, f(t)),  D: (-t, -f(t))
// (central symmetry (2-10) gives B's and D's). Give linkage K a variant realising
// R(sigma_K, tau_K) at its base configuration. Every substitution commutes with the sign
// flips of (2-15) mod 2 pi (-(pi - (-x)) = -pi - x = pi - x, and likewise for the others), so
// (2-15) holds for every t iff the shared joints carry the same substitution:
//     tau_A = tau_B,  sigma_B = sigma_C,  tau_C = tau_D,  sigma_D = sigma_A.
// types[K] is the Rk number (1..16) of A, B, C, D; R1 is the base linkage.
// Throws std::invalid_argument for a number outside 1..16.
bool two_fold_compatible(const std::array<int, 4>& types);

// Table 2-2 by enumeration: every assignment of types to A..D with exactly `length`
// linkages not R1, consecutive around the loop, that two_fold_compatible accepts, written
// as the chain of types in loop order from the first variant after the base linkage(s).
// A chain and its reverse describe the same assembly read the other way round the loop;
// the lexicographically smaller one is kept. Sorted, no duplicates.
// Against the printed Table 2-2: the six 2R rows are exactly this set (length 2). The nine
// 3R rows are this set (length 3) only with each row's FIRST type reversed (reversed_relation:
// (sigma, tau) printed as (tau, sigma), i.e. that linkage read from joint 2 to joint 1).
// Built literally as twists, only the three printed rows starting with R4 are mobile (R4
// reversed is R12, realised by the same twists); the six starting with R2 or R3 are not
// (tests/network/two_fold_transmissions_test.cpp: closed-form loop over every branch,
// network solver DOF, exhaustive over the twist classes at A, B, C).
// Throws std::invalid_argument unless length is 2 or 3.
std::vector<std::vector<int>> two_fold_transmissions(int length);

// The two-fold assembly of four linkages as a LinkageNetwork (linkage_network.hpp) with
// the joints of (2-15): 12 network joints "a1" (= -d1), "a2" (= -b2), "b1" (= -c1),
// "c2" (= -d2), then a3, a4, b3, b4, c3, c4, d3, d4. twists[K] are linkage K's (radians;
// joint i of a linkage is the seed's theta_{i+1}).
LinkageNetwork two_fold_assembly(const std::array<S4RSectors, 4>& twists);

}  // namespace rigidfold
