#include "kernel/network/relation_types.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rigidfold {

double apply_variant(AngleVariant v, double x) {
  constexpr double pi = std::numbers::pi;
  switch (v) {
    case AngleVariant::kSame: return x;
    case AngleVariant::kPiMinus: return pi - x;
    case AngleVariant::kMinusPiPlus: return -pi + x;
    case AngleVariant::kMinus: return -x;
  }
  return x;
}

const char* variant_text(AngleVariant v) {
  switch (v) {
    case AngleVariant::kSame: return "x";
    case AngleVariant::kPiMinus: return "pi-x";
    case AngleVariant::kMinusPiPlus: return "-pi+x";
    case AngleVariant::kMinus: return "-x";
  }
  return "?";
}

const std::array<RelationType, 16>& relation_types() {
  using V = AngleVariant;
  // Table 2-1 of seed 003, row by row.
  static const std::array<RelationType, 16> table{{
      {1, V::kSame, V::kSame},           {2, V::kSame, V::kPiMinus},
      {3, V::kSame, V::kMinusPiPlus},    {4, V::kSame, V::kMinus},
      {5, V::kPiMinus, V::kSame},        {6, V::kPiMinus, V::kPiMinus},
      {7, V::kPiMinus, V::kMinusPiPlus}, {8, V::kPiMinus, V::kMinus},
      {9, V::kMinus, V::kMinus},         {10, V::kMinus, V::kMinusPiPlus},
      {11, V::kMinus, V::kPiMinus},      {12, V::kMinus, V::kSame},
      {13, V::kMinusPiPlus, V::kMinus},  {14, V::kMinusPiPlus, V::kMinusPiPlus},
      {15, V::kMinusPiPlus, V::kPiMinus}, {16, V::kMinusPiPlus, V::kSame},
  }};
  return table;
}

AngleVariant twist_variant_of(int code, int k) { return static_cast<AngleVariant>((code >> (2 * k)) & 3); }

S4RSectors twist_variant(const S4RSectors& base, int code) {
  if (code < 0 || code > 255) throw std::invalid_argument("twist_variant: code must be in 0..255");
  S4RSectors v;
  for (int k = 0; k < 4; ++k) v[k] = apply_variant(twist_variant_of(code, k), base[k]);
  return v;
}

namespace {

// Inputs spread over the interior of the feasible set of joint 0 (motion limits excluded:
// there the two branches merge and the closed form loses half its digits).
std::vector<double> sample_inputs(const S4RSectors& twists, int samples) {
  const S4RInputRange range = s4r_input_range(twists, 0);
  if (!range.feasible) throw std::invalid_argument("classify_twist_variant: a linkage has no feasible input");
  const auto intervals = range.intervals();
  double total = 0.0;
  for (const auto& iv : intervals) total += iv[1] - iv[0];
  std::vector<double> out;
  for (int i = 0; i < samples; ++i) {
    double s = total * (i + 0.5) / samples;
    for (const auto& iv : intervals) {
      if (s <= iv[1] - iv[0]) {
        out.push_back(iv[0] + s);
        break;
      }
      s -= iv[1] - iv[0];
    }
  }
  return out;
}

}  // namespace

VariantRelation classify_twist_variant(const S4RSectors& base, const S4RSectors& variant, int samples,
                                       double tolerance) {
  if (samples < 2) throw std::invalid_argument("classify_twist_variant: samples must be >= 2");
  // Configurations (theta_0, theta_1) of one linkage, to be substituted into the other's relation.
  struct Pair {
    double in, out;
    bool from_base;
  };
  std::vector<Pair> pairs;
  for (const bool from_base : {true, false}) {
    const S4RSectors& src = from_base ? base : variant;
    for (double x : sample_inputs(src, samples))
      for (const S4RFoldAngles& b : s4r_branches(src, x, 0).branches) pairs.push_back({b[0], b[1], from_base});
  }
  VariantRelation out;
  out.samples = static_cast<int>(pairs.size());
  out.rejected_margin = INFINITY;
  for (const RelationType& type : relation_types()) {
    double worst = 0.0;
    for (const Pair& p : pairs) {
      // The substitutions are involutions mod 2 pi, so the converse uses the same pair.
      const S4RSectors& dst = p.from_base ? variant : base;
      const double r = s4r_pair_residual(dst, 0, apply_variant(type.input, p.in), apply_variant(type.output, p.out));
      worst = std::max(worst, std::isnan(r) ? INFINITY : std::fabs(r));
    }
    if (!pairs.empty() && worst <= tolerance) {
      out.realised.push_back(type.number);
      out.realised_residual = std::max(out.realised_residual, worst);
    } else {
      out.rejected_margin = std::min(out.rejected_margin, worst);
    }
  }
  std::sort(out.realised.begin(), out.realised.end());
  return out;
}

std::vector<std::vector<int>> closing_transmissions(int length) {
  if (length < 2 || length > 6) throw std::invalid_argument("closing_transmissions: length must be in 2..6");
  std::vector<std::vector<int>> out;
  std::vector<int> chain;
  // Depth-first over the 16 types; `carried` is the substitution carried by the shared joint.
  auto extend = [&](auto&& self, AngleVariant carried) -> void {
    const bool last = static_cast<int>(chain.size()) == length - 1;
    for (const RelationType& t : relation_types()) {
      if (t.number == 1 || t.input != carried) continue;
      const bool back = t.output == AngleVariant::kSame;
      if (back != last) continue;
      chain.push_back(t.number);
      if (last) out.push_back(chain);
      else self(self, t.output);
      chain.pop_back();
    }
  };
  extend(extend, AngleVariant::kSame);
  return out;
}

int reversed_relation(int k) {
  if (k < 1 || k > 16) throw std::invalid_argument("reversed_relation: type must be in 1..16");
  const RelationType& t = relation_types()[k - 1];
  for (const RelationType& r : relation_types())
    if (r.input == t.output && r.output == t.input) return r.number;
  return k;  // unreachable: the table holds every pair
}

bool two_fold_compatible(const std::array<int, 4>& types) {
  for (int k : types)
    if (k < 1 || k > 16) throw std::invalid_argument("two_fold_compatible: type must be in 1..16");
  const auto& t = relation_types();
  const RelationType &A = t[types[0] - 1], &B = t[types[1] - 1], &C = t[types[2] - 1], &D = t[types[3] - 1];
  // Shared joints: a2-b2 (tau), b1-c1 (sigma), c2-d2 (tau), d1-a1 (sigma).
  return A.output == B.output && B.input == C.input && C.output == D.output && D.input == A.input;
}

std::vector<std::vector<int>> two_fold_transmissions(int length) {
  if (length != 2 && length != 3) throw std::invalid_argument("two_fold_transmissions: length must be 2 or 3");
  std::vector<std::vector<int>> out;
  for (int start = 0; start < 4; ++start) {
    // Variants at start, start+1, ... (mod 4); the others are the base R1.
    std::vector<int> chain(length, 2);
    auto next = [&]() {  // odometer over types 2..16
      for (int i = length - 1; i >= 0; --i) {
        if (++chain[i] <= 16) return true;
        chain[i] = 2;
      }
      return false;
    };
    do {
      std::array<int, 4> types{1, 1, 1, 1};
      for (int i = 0; i < length; ++i) types[(start + i) % 4] = chain[i];
      if (!two_fold_compatible(types)) continue;
      std::vector<int> rev(chain.rbegin(), chain.rend());
      out.push_back(std::min(chain, rev));
    } while (next());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

LinkageNetwork two_fold_assembly(const std::array<S4RSectors, 4>& twists) {
  LinkageNetwork net;
  net.joint_names = {"a1", "a2", "b1", "c2", "a3", "a4", "b3", "b4", "c3", "c4", "d3", "d4"};
  const char* names[4] = {"A", "B", "C", "D"};
  // Joints 1 and 2 of each linkage (network joint, sign) per (2-15); joints 3, 4 are its own.
  const int j1[4] = {0, 2, 2, 0}, j2[4] = {1, 1, 3, 3};
  const double s1[4] = {1, 1, -1, -1}, s2[4] = {1, -1, 1, -1};
  for (int k = 0; k < 4; ++k) {
    NetworkLinkage l;
    l.name = names[k];
    l.twists.assign(twists[k].begin(), twists[k].end());
    l.joints = {{j1[k], s1[k], 0.0}, {j2[k], s2[k], 0.0}, {4 + 2 * k, 1.0, 0.0}, {5 + 2 * k, 1.0, 0.0}};
    net.linkages.push_back(l);
  }
  validate_network(net);
  return net;
}

}  // namespace rigidfold
