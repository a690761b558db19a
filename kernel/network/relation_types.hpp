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

}  // namespace rigidfold
