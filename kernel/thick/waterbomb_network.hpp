#pragma once
// The traditional waterbomb pattern (data/generators/traditional_waterbomb.hpp, seed 003
// §4.4.2) as a network of thick vertex linkages, the seed's own view of a thick pattern: every
// interior vertex is one closed DH loop (thick_pattern.hpp) and loops share the fold angle of
// every crease they share. No panel geometry is checked across vertices: hinge heights
// of these models do not agree across the pattern for any D thickness, even at mu = 1
// (tests/thick/waterbomb_network_test.cpp, HingeHeightsOfTheModelsDisagreeAcrossThePattern),
// so the pattern cannot be run as a ThickHeightSheet (hinge_heights.hpp).
//
//   D vertices (sectors 45, 90, 45, 45, 90, 45 deg from a midline crease): the plane-symmetric
//     Bricard diamond model diamond_vertex(pi/4, t1, t2), crease 0 on the first midline
//     crease of the fan that matches, with the model's letters (midline V, diagonals M).
//   W vertices (sectors 90, 45, 45, 45, 45, 90 deg from the crease between the two right
//     angles, which runs to a D): waterbomb_vertex(mu, t) seen from the other side (its
//     mirror image: DH twists and joint angles negated, lengths kept), so that its letters
//     are the pattern's (lines V, diagonals M) and its crease 0 agrees with the D midline
//     and its diagonals with the D diagonals.
// Any other interior vertex: std::invalid_argument naming it.
//
// Inputs: the flat pattern and its topology; mu > 0 and t > 0 (W link lengths t(1+mu, 1, mu,
// mu, 1, 1+mu)); t1, t2 > 0 (D link lengths (t1, t2, t1+t2, t1+t2, t2, t1)). Pattern units.
// Output: a ThickPattern with num_creases = flat edges (crease c = edge c; boundary edges
// are in no loop), loop k for interior vertex vertex_of_loop[k]; the kind of each loop.
// Fold angles: kernel convention (radians, > 0 valley).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_pattern.hpp"

namespace rigidfold {

enum class WaterbombVertexKind { kD, kW };

struct WaterbombNetwork {
  ThickPattern thick;
  std::vector<int> vertex_of_loop;            // flat-pattern vertex of each loop
  std::vector<WaterbombVertexKind> kind;      // per loop
  std::vector<std::vector<int>> creases;      // per loop, its creases in model order (crease 0 first)
};

WaterbombNetwork waterbomb_network(const CreasePattern& flat, const Topology& topology, double mu, double t, double t1,
                                   double t2);

// The pattern's uniform zero-thickness fold angles (one per flat edge, boundary 0): every W
// on the waterbomb relation (4-54) and every D on the diamond relation (4-39) with a = pi/4,
// from the midline fold angle rho_line (radians, > 0: valley, < pi).
Eigen::VectorXd waterbomb_network_uniform_state(const CreasePattern& flat, const WaterbombNetwork& network, double rho_line);

}  // namespace rigidfold
