#pragma once
// Multiplier propagation: the exact, O(creases) rigid-foldability model for crease patterns
// whose interior vertices are all flat-foldable degree-4 vertices (docs/DESIGN.md, "Model only
// what a scene needs"; seed 003 §3.2-3.3, seed 001 §2).
//
// Model. Each interior vertex v folds in one of its two modes m_v (flat_foldable_multipliers.hpp),
// on which tan(rho_e / 2) = w_{v,e} * tau_v for its four creases e. A crease shared by two
// interior vertices u, v ties their parameters, tau_v = (w_{u,e} / w_{v,e}) * tau_u, when both
// multipliers are non-zero ("tie"); when exactly one of them is zero the crease must stay flat
// and pins the other vertex to tau = 0 ("pin"); when both are zero it stays flat and ties
// nothing. A crease on one interior vertex only is free. Along any cycle of ties the product
// of the ratios (the loop gain K, seed 003: K = prod k) must be 1; otherwise the cycle, and
// every vertex tied to it, stays flat. Each connected component of the tie graph that is
// consistent and unpinned moves with one parameter t_c, so components multiply DOF; hinges
// that touch no interior vertex are one more DOF each.
//
// Applicability (else use the general solver): every interior vertex has exactly four
// folding creases (M, V, U) and no F/J hinge, is flat-foldable (Kawasaki, sectors in (0, pi))
// within the flat tolerance, and every component of the sheet is a disk (no holes, genus 0:
// a hole needs an SE(3) closure around it that this model does not express).
//
// Units: radians. Fold angles use the kernel convention (rho > 0 valley, < 0 mountain).
// Indices: "vertex" and "edge"/"crease" are pattern indices unless named "model vertex".
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

namespace rigidfold {

struct MultiplierApplicability {
  bool applicable = false;
  std::string reason;  // empty when applicable; otherwise names the vertex / edge / component
  int vertex = -1;     // offending vertex, if any
  int edge = -1;       // offending edge, if any
};

// flat_tolerance: radians, for Kawasaki (|alpha_0 + alpha_2 - pi|, |alpha_1 + alpha_3 - pi|).
MultiplierApplicability multiplier_model_applicable(const CreasePattern& pattern, const Topology& topology,
                                                    double flat_tolerance = 1e-9);

// The per-vertex data of the model. Model vertex k is topology.interior_vertices[k].
struct MultiplierModel {
  int num_edges = 0;
  std::vector<int> vertices;                 // pattern vertex of each model vertex
  std::vector<std::array<int, 4>> creases;   // its creases, CCW (as the topology's fan)
  // w[k][mode][i]: multiplier of crease i of model vertex k in mode (0 = kEqual13, 1 = kEqual02).
  std::vector<std::array<std::array<double, 4>, 2>> w;
  // For each edge: the model vertices it touches (-1 if none) and the crease position there.
  std::vector<std::array<int, 2>> edge_vertex;
  std::vector<std::array<int, 2>> edge_slot;
  std::vector<bool> free_hinge;  // a folding hinge (M/V/U) touching no interior vertex
};

// Throws std::invalid_argument with the applicability reason if the model does not apply.
MultiplierModel build_multiplier_model(const CreasePattern& pattern, const Topology& topology,
                                       double flat_tolerance = 1e-9);

inline int mode_index(FlatFoldMode m) { return m == FlatFoldMode::kEqual13 ? 0 : 1; }
inline FlatFoldMode mode_from_index(int i) { return i == 0 ? FlatFoldMode::kEqual13 : FlatFoldMode::kEqual02; }

// Why a mode choice / assignment does not fold.
struct Obstruction {
  enum class Kind {
    kLoopGain,        // a cycle of ties with loop gain != 1
    kPin,             // a crease flat on one side and folding on the other
    kVertexAssignment,  // the M-V letters of a vertex match neither mode
    kSign,            // a U crease forces a vertex to fold against its assigned signs
  };
  Kind kind = Kind::kLoopGain;
  std::vector<int> cycle_vertices;  // kLoopGain: pattern vertices around the cycle, in order
  std::vector<int> cycle_creases;   // kLoopGain: cycle_creases[i] joins cycle_vertices[i] and [i+1] (cyclic)
  int vertex = -1;                  // kPin: the pinned vertex; kVertexAssignment / kSign: the vertex
  int crease = -1;                  // kPin / kSign: the crease; kLoopGain: the closing crease
  double loop_gain = 1.0;           // kLoopGain: product of the tie ratios around the cycle
  double defect = 0.0;              // |loop_gain - 1| (relative loop-gain defect)
  std::string message;
};
const char* to_string(Obstruction::Kind kind);

// The folding family: tan(rho_e / 2) = multiplier[e] * t[component[e]], one parameter per
// component; component[e] = -1 for edges that stay flat (and non-hinges).
struct FoldFamily {
  int num_components = 0;
  std::vector<int> component;
  std::vector<double> multiplier;
  // rho for every edge (radians, in [-pi, pi]); t has one entry per component. An infinite
  // parameter is the fully folded state of its component: every folding crease at +-pi.
  Eigen::VectorXd angles(const std::vector<double>& t) const;
  // The same parameter for every component.
  Eigen::VectorXd angles(double t) const;
  // Component c at parameter t, every other component flat.
  Eigen::VectorXd component_angles(int c, double t) const;
  // The crease of component c with the largest |multiplier|: the first to reach 180 deg as the
  // component folds. -1 if the component has no folding crease.
  int fastest_crease(int c) const;
  // The parameter of edge e's component that gives edge e the fold angle rho (|rho| < pi).
  // Throws std::invalid_argument if edge e stays flat in this family.
  double parameter_for(int edge, double rho) const;
};

// Consistency of one mode choice.
struct ModeCheck {
  bool consistent = true;       // no tie cycle with loop gain off by more than the tolerance
  double max_defect = 0.0;      // largest |loop gain - 1| over the independent cycles (0 if none)
  int cycles_checked = 0;       // independent cycles (non-tree ties)
  int tie_components = 0;       // components of the tie graph (isolated vertices included)
  int pinned_components = 0;    // components forced flat by a pin
  int inconsistent_components = 0;
  int dof = 0;                  // mobile tie components + free hinges (= family.num_components)
  FoldFamily family;            // the mobile components only
  std::vector<int> vertex_component;  // per model vertex: tie component
  std::optional<Obstruction> obstruction;  // the worst failing cycle (or first pin) if any
};

// modes: one per model vertex. gain_tolerance: allowed relative loop-gain defect.
ModeCheck check_modes(const MultiplierModel& model, const std::vector<FlatFoldMode>& modes,
                      double gain_tolerance = 1e-9);

// The global sign sigma with which a vertex mode of multipliers w (one per crease, CCW)
// folds every M/V crease its letter's way: tan(rho_i/2) = sigma * w_i * tau, tau > 0. Returns
// 0 when no crease has a letter (either sign), nullopt when no sign does (an M/V crease with
// w_i = 0 would stay flat, or the letters disagree). The one letter test of the model.
std::optional<int> mode_sign_matching_letters(const std::array<double, 4>& w, const std::array<Assignment, 4>& letters);

// The modes of a flat-foldable degree-4 vertex (its closed fan of four creases) that fold
// every M/V crease its letter's way, kEqual13 first.
std::vector<FlatFoldMode> modes_matching_letters(const CreasePattern& pattern, const Fan& fan);

struct VerdictOptions {
  double flat_tolerance = 1e-9;      // radians, Kawasaki test of applicability
  double gain_tolerance = 1e-9;      // relative loop-gain defect taken as 1
  double certificate_fold = 1.5707963267948966;  // largest |rho| of each component at the certificate (radians)
  double mismatch_tolerance = 1e-12; // place_faces relative mismatch a certificate must reach
  long max_search_steps = 2'000'000; // mode-choice search budget (vertex visits); then kUndecided
};

enum class Verdict { kRigidlyFoldable, kNotRigidlyFoldable, kNotApplicable, kUndecided };
const char* to_string(Verdict v);

struct FoldabilityVerdict {
  Verdict verdict = Verdict::kNotApplicable;
  const char* model = "multiplier-propagation";
  std::string reason;                 // one line for the user
  MultiplierApplicability applicability;
  std::vector<FlatFoldMode> modes;    // per model vertex: the modes found (foldable) or tried first (not)
  std::vector<int> vertices;          // pattern vertex of each model vertex
  int dof = 0;                        // components of the family that fold
  double max_loop_defect = 0.0;       // over the independent cycles of `modes`
  int cycles_checked = 0;
  std::optional<FoldFamily> family;
  // Certificate (kRigidlyFoldable): fold angles at a finite fold (every component at
  // certificate_fold), their face-placement relative mismatch, and the largest fold.
  Eigen::VectorXd certificate_angles;
  double certificate_mismatch = -1.0;
  double certificate_max_fold = 0.0;
  std::optional<Obstruction> obstruction;  // kNotRigidlyFoldable
  long search_steps = 0;
};

// Rigid foldability respecting the pattern's M-V letters: every M crease folds with rho < 0,
// every V crease with rho > 0 (U: either sign). Per vertex only the modes whose multiplier
// signs match the letters (up to the vertex's global sign) are candidates; fully assigned
// vertices have at most one, so for an assigned pattern the search is one BFS, O(creases).
FoldabilityVerdict verdict_with_assignment(const CreasePattern& pattern, const Topology& topology,
                                           const VerdictOptions& options = {});

// Rigid foldability with the letters ignored: is there a mode choice in which every interior
// vertex folds (no tie cycle fails, nothing pinned)? Modes without flat creases are tried
// first. Backtracking search over at most options.max_search_steps vertex visits.
FoldabilityVerdict verdict_ignoring_assignment(const CreasePattern& pattern, const Topology& topology,
                                               const VerdictOptions& options = {});

}  // namespace rigidfold
