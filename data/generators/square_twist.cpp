#include "data/generators/square_twist.hpp"

#include <cmath>
#include <cstdio>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::generators {
namespace {

using A = Assignment;

A opposite(A a) { return a == A::Mountain ? A::Valley : A::Mountain; }

const char* diagonal_name(SquareTwistDiagonal d) {
  switch (d) {
    case SquareTwistDiagonal::None: return "none";
    case SquareTwistDiagonal::BD: return "BD";
    case SquareTwistDiagonal::AC: return "AC";
  }
  return "?";
}

CreasePattern build(const SquareTwistParams& params, const std::vector<Assignment>& interior, const std::string& title,
                    const std::string& frame_title, const std::string& type_name) {
  const double t = params.twist;
  require(std::isfinite(t) && t > 0 && t < kPi / 2, "twist",
          "the twist angle must lie strictly between 0 and 90 deg, got " + std::to_string(to_degrees(t)) + " deg");
  require(std::isfinite(params.side) && params.side > 0, "side", "the central square's side must be positive");
  require(std::isfinite(params.pleat) && params.pleat > 0, "pleat", "the outer crease length must be positive");
  const bool has_diagonal = params.diagonal != SquareTwistDiagonal::None;
  const std::size_t expected = has_diagonal ? 13 : 12;
  require(interior.size() == expected, "assignment",
          "needs " + std::to_string(expected) + " letters (sides AB BC CD DA, then o_a o_b of A, B, C, D" +
              (has_diagonal ? std::string(", then the diagonal") : std::string()) + "), got " +
              std::to_string(interior.size()));
  for (std::size_t k = 0; k < interior.size(); ++k)
    require(interior[k] == A::Mountain || interior[k] == A::Valley || interior[k] == A::Flat ||
                interior[k] == A::Unassigned,
            "assignment", "letter " + std::to_string(k) + " must be M, V, F or U for an interior crease");

  // Vertex k of the square at angle phi0 + k*pi/2; phi0 puts A's crease o_b along +x:
  // o_b(k) = d_next(k) - t with d_next(0) = phi0 + 3pi/4.
  const double r = params.side / std::sqrt(2.0);
  const double phi0 = t - 3 * kPi / 4;
  CreasePattern p;
  p.coords_2d = true;
  std::array<Eigen::Vector2d, 4> V;
  for (int k = 0; k < 4; ++k) V[k] = r * unit_vector(phi0 + k * kPi / 2);
  for (int k = 0; k < 4; ++k) p.vertices.emplace_back(V[k].x(), V[k].y(), 0.0);
  auto add_vertex = [&](const Eigen::Vector2d& x) {
    p.vertices.emplace_back(x.x(), x.y(), 0.0);
    return p.num_vertices() - 1;
  };
  std::array<int, 4> Pa{}, Pb{}, Q{};
  for (int k = 0; k < 4; ++k) {
    const double d_next = phi0 + 3 * kPi / 4 + k * kPi / 2;
    const double o_b = d_next - t, o_a = o_b - kPi / 2;
    const Eigen::Vector2d ea = params.pleat * unit_vector(o_a), eb = params.pleat * unit_vector(o_b);
    Pa[k] = add_vertex(V[k] + ea);
    Pb[k] = add_vertex(V[k] + eb);
    Q[k] = add_vertex(V[k] + ea + eb);
  }
  auto add_edge = [&](int a, int b, A assignment) {
    p.edges.push_back({a, b});
    p.assignments.push_back(assignment);
  };
  for (int k = 0; k < 4; ++k) add_edge(k, (k + 1) % 4, interior[k]);
  for (int k = 0; k < 4; ++k) {
    add_edge(k, Pa[k], interior[4 + 2 * k]);
    add_edge(k, Pb[k], interior[5 + 2 * k]);
  }
  if (params.diagonal == SquareTwistDiagonal::BD) add_edge(1, 3, interior[12]);
  if (params.diagonal == SquareTwistDiagonal::AC) add_edge(0, 2, interior[12]);
  for (int k = 0; k < 4; ++k) {
    add_edge(Pa[k], Q[k], A::Boundary);
    add_edge(Q[k], Pb[k], A::Boundary);
    add_edge(Pb[k], Pa[(k + 1) % 4], A::Boundary);
  }
  // Faces are derived from the planar embedding by complete_and_validate.

  nlohmann::ordered_json g;
  g["kind"] = "square-twist";
  g["type"] = type_name;
  g["twist_deg"] = deg_rounded(t);
  g["side"] = params.side;
  g["pleat"] = params.pleat;
  g["diagonal"] = diagonal_name(params.diagonal);
  g["interior_assignment"] = assignment_letters(interior);
  g["interior_order"] = has_diagonal ? "AB BC CD DA, A:o_a o_b, B:o_a o_b, C:o_a o_b, D:o_a o_b, diagonal"
                                     : "AB BC CD DA, A:o_a o_b, B:o_a o_b, C:o_a o_b, D:o_a o_b";
  return finish_pattern(std::move(p), title, frame_title, g);
}

std::string twist_title(const char* what, double t) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "Square twist %s, twist %g deg", what, to_degrees(t));
  return buf;
}

}  // namespace

const char* to_string(SquareTwistType type) {
  switch (type) {
    case SquareTwistType::Type1: return "type1";
    case SquareTwistType::Type2: return "type2";
    case SquareTwistType::Type3: return "type3";
    case SquareTwistType::Type4: return "type4";
  }
  return "?";
}

const char* to_string(SquareTwistModifiedType type) {
  return type == SquareTwistModifiedType::Type1M ? "type1m" : "type2m";
}

std::array<Assignment, 4> square_twist_sides(SquareTwistType type) {
  const A M = A::Mountain, Vv = A::Valley;
  switch (type) {
    case SquareTwistType::Type1: return {M, M, M, M};
    case SquareTwistType::Type2: return {Vv, M, Vv, M};
    case SquareTwistType::Type3: return {M, Vv, Vv, M};
    case SquareTwistType::Type4: return {Vv, Vv, Vv, M};
  }
  return {M, M, M, M};
}

std::vector<Assignment> square_twist_assignment(const std::array<Assignment, 4>& sides) {
  for (int k = 0; k < 4; ++k)
    require(sides[k] == A::Mountain || sides[k] == A::Valley, "sides", "each side must be M or V");
  std::vector<Assignment> out(sides.begin(), sides.end());
  for (int k = 0; k < 4; ++k) {
    const A previous = sides[(k + 3) % 4], twist_side = sides[k];
    if (previous == twist_side) {  // odd crease o_b (seed 001 eq. 5a)
      out.push_back(previous);            // o_a
      out.push_back(opposite(previous));  // o_b
    } else {                       // odd crease: the twist side (eq. 5b)
      out.push_back(previous);
      out.push_back(previous);
    }
  }
  return out;
}

std::vector<Assignment> square_twist_assignment(SquareTwistType type) {
  return square_twist_assignment(square_twist_sides(type));
}

std::vector<Assignment> square_twist_modified_assignment(SquareTwistModifiedType type) {
  std::vector<Assignment> out = square_twist_assignment(
      type == SquareTwistModifiedType::Type1M ? SquareTwistType::Type1 : SquareTwistType::Type2);
  out.push_back(A::Valley);  // diagonal BD, seed 001 eqs. (15) and (19): theta_2 = phi_2 - pi (valley)
  return out;
}

CreasePattern square_twist(const SquareTwistParams& params, const std::vector<Assignment>& interior) {
  return build(params, interior, twist_title("(explicit assignment)", params.twist),
               "explicit assignment " + assignment_letters(interior), "explicit");
}

CreasePattern square_twist(const SquareTwistParams& params, SquareTwistType type) {
  require(params.diagonal == SquareTwistDiagonal::None, "diagonal", "the four types have no diagonal crease");
  static const char* names[] = {"Type 1", "Type 2", "Type 3", "Type 4"};
  static const char* frames[] = {
      "seed 001 Type 1: sides all alike; every vertex odd on o_b; not rigidly foldable",
      "seed 001 Type 2: sides alternate; every vertex odd on its twist side; not rigidly foldable",
      "seed 001 Type 3 (seed 003 T1): sides two and two; rigidly foldable",
      "seed 001 Type 4 (seed 003 T2): sides three and one; rigidly foldable"};
  const int i = static_cast<int>(type);
  return build(params, square_twist_assignment(type), twist_title(names[i], params.twist), frames[i], to_string(type));
}

CreasePattern square_twist_modified(const SquareTwistParams& params, SquareTwistModifiedType type) {
  SquareTwistParams q = params;
  q.diagonal = SquareTwistDiagonal::BD;
  const bool one = type == SquareTwistModifiedType::Type1M;
  return build(q, square_twist_modified_assignment(type), twist_title(one ? "Type 1M" : "Type 2M", params.twist),
               one ? "seed 001 Type 1M: Type 1 with valley diagonal BD; rigid, bifurcating"
                   : "seed 001 Type 2M: Type 2 with valley diagonal BD; rigid, bifurcating",
               to_string(type));
}

}  // namespace rigidfold::generators
