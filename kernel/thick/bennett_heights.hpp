#pragma once
// Hinge heights that make every flat-foldable degree-4 vertex of a pattern a Bennett linkage
// folding with the zero-thickness fold angles (seed 003 §4.2, eqs 4-3, 4-4), for
// thick_sheet_from_hinge_heights (hinge_heights.hpp).
//
// Per vertex with sectors alpha_0..alpha_3 (alpha_2 = pi - alpha_0, alpha_3 = pi - alpha_1)
// the Bennett link lengths are a_i = thickness * sin(alpha_i) (4-4: a12 : a23 = sin a12 : sin a23,
// opposite links equal). As hinge heights around the vertex they are a "staircase": from
// the start crease k, up a_k, up a_{k+1}, down a_{k+2}, down a_{k+3} (tests/thick/
// hinge_heights_test.cpp: the zigzag order up, down, down, up is not a Bennett). Which of the
// four start creases is right depends on the branch the vertex folds on: it is chosen as the
// one whose thick vertex closes at the given zero-thickness folded state (residual
// <= 1e-10). Heights of a pattern are then the per-vertex staircases shifted so that every
// crease shared by two vertices gets one height (hinge_heights_from_steps); a crease where
// two shifted staircases disagree means no uniform-thickness Bennett design of this kind
// exists for that pattern and branch.
//
// Units: heights and thickness in pattern units; angles in radians.
#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/vertex_height_steps.hpp"  // HingeHeightConflict

namespace rigidfold {

// Inputs: a flat pattern whose interior vertices are all flat-foldable degree-4 vertices;
// its topology; fold angles (one per edge, radians) of a zero-thickness folded state on the
// branch to keep, away from the flat state (|rho| of the folding creases >~ 0.1); the
// thickness scale t > 0.
// Output: one height per edge (0 for edges at no interior vertex).
// Throws std::invalid_argument naming the vertex when it is not a flat-foldable degree-4
// vertex or no start crease closes at the given state; HingeHeightConflict naming the
// crease and the two vertices when the staircases disagree.
std::vector<double> bennett_hinge_heights(const CreasePattern& flat, const Topology& topology,
                                          const Eigen::VectorXd& folded_state, double thickness);

}  // namespace rigidfold
