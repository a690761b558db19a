#include "data/generators/corrugated_tessellation.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::generators {
namespace {

constexpr int kPanels = 5;  // sheet panels per direction
constexpr int kWindow = 3;  // window panels per direction

// parallelogram_lattice index maps for an n x n-panel lattice.
int node(int n, int i, int j) { return j * (n + 1) + i; }
int i_edge(int n, int i, int j) { return j * n + i; }
int j_edge(int n, int i, int j) { return n * (n + 1) + j * (n + 1) + i; }

constexpr std::array<std::array<int, 2>, 4> kCorners{{{0, 0}, {2, 0}, {0, 2}, {2, 2}}};

void check_params(const CorrugatedParams& params) {
  const double al = params.alpha, be = params.beta;
  require(std::isfinite(al) && al > kPi / 2 && al < kPi, "alpha",
          "must lie strictly between 90 and 180 deg (gamma = 180 - alpha is the smallest sector), got " +
              std::to_string(to_degrees(al)) + " deg");
  require(std::isfinite(be) && be > kPi - al && be < al, "beta",
          "must lie strictly between 180 - alpha and alpha (gamma smallest), got " + std::to_string(to_degrees(be)) +
              " deg");
  require(std::isfinite(params.a) && params.a > 0, "a", "must be positive");
  require(std::isfinite(params.b) && params.b > 0, "b", "must be positive");
}

// The u, v of panels first .. first + count - 1 of the sheet.
void lattice_vectors(const CorrugatedParams& params, int first_i, int first_j, int count, std::vector<Eigen::Vector2d>& u,
                     std::vector<Eigen::Vector2d>& v) {
  const Eigen::Vector2d u0 = params.a * unit_vector(0.0), u1 = params.a * unit_vector(params.alpha + params.beta + kPi);
  const Eigen::Vector2d va = params.b * unit_vector(params.alpha), vb = params.b * unit_vector(params.beta);
  u.clear();
  v.clear();
  for (int k = 0; k < count; ++k) {
    u.push_back((first_i + k) % 2 == 0 ? u1 : u0);
    v.push_back((first_j + k) % 2 == 0 ? vb : va);
  }
}

std::string window_name(int wa, int wb) { return "window (" + std::to_string(wa) + ", " + std::to_string(wb) + ")"; }

}  // namespace

std::vector<CorrugatedTessellationWindow> corrugated_tessellation_windows() {
  std::vector<CorrugatedTessellationWindow> out;
  for (int wb = 0; wb < 3; ++wb)
    for (int wa = 0; wa < 3; ++wa) {
      CorrugatedTessellationWindow w;
      w.wa = wa;
      w.wb = wb;
      w.p_shaped = (wa + wb) % 2 == 0;
      w.vertices = {node(kPanels, wa + 1, wb + 1), node(kPanels, wa + 2, wb + 1), node(kPanels, wa + 2, wb + 2),
                    node(kPanels, wa + 1, wb + 2)};
      for (int j = 0; j <= kWindow; ++j)
        for (int i = 0; i < kWindow; ++i) w.edges[i_edge(kWindow, i, j)] = i_edge(kPanels, i + wa, j + wb);
      for (int j = 0; j < kWindow; ++j)
        for (int i = 0; i <= kWindow; ++i) w.edges[j_edge(kWindow, i, j)] = j_edge(kPanels, i + wa, j + wb);
      out.push_back(w);
    }
  return out;
}

std::array<int, 12> corrugated_tessellation_corner_edges(int corner) {
  if (corner < 0 || corner > 3) throw InputError("corners", "corner index must be 0..3");
  const auto windows = corrugated_tessellation_windows();
  const auto& w = windows[3 * kCorners[corner][1] + kCorners[corner][0]];
  const auto local = corrugated_interior_edges(CorrugatedUnit::P);
  std::array<int, 12> out{};
  for (int c = 0; c < 12; ++c) out[c] = w.edges[local[c]];
  return out;
}

CreasePattern corrugated_tessellation(const CorrugatedParams& params,
                                      const std::array<std::vector<Assignment>, 4>& corners) {
  check_params(params);
  std::vector<Eigen::Vector2d> u, v;
  lattice_vectors(params, 0, 0, kPanels, u, v);
  ParallelogramLattice L = parallelogram_lattice(u, v);
  CreasePattern p = std::move(L.pattern);
  std::vector<int> set_by(p.edges.size(), -1);
  for (int k = 0; k < 4; ++k) {
    const std::string where = window_name(kCorners[k][0], kCorners[k][1]);
    require(corners[k].size() == 12, "corners",
            where + " needs 12 letters (unit P order AB BC CD DA a3 a4 b1 b2 c3 c4 d1 d2), got " +
                std::to_string(corners[k].size()));
    const auto edges = corrugated_tessellation_corner_edges(k);
    for (int c = 0; c < 12; ++c) {
      const Assignment a = corners[k][c];
      require(a == Assignment::Mountain || a == Assignment::Valley, "corners",
              where + " letter " + std::to_string(c) + " must be M or V");
      const int e = edges[c];
      if (set_by[e] >= 0 && p.assignments[e] != a)
        throw InputError("corners", "crease " + std::to_string(e) + " is " + std::string(1, assignment_letter(p.assignments[e])) +
                                        " in " + window_name(kCorners[set_by[e]][0], kCorners[set_by[e]][1]) + " but " +
                                        std::string(1, assignment_letter(a)) + " in " + where);
      p.assignments[e] = a;
      set_by[e] = k;
    }
  }
  std::string letters;
  for (const auto& c : corners) letters += assignment_letters(c) + " ";
  letters.pop_back();
  nlohmann::ordered_json g;
  g["kind"] = "corrugated-tessellation";
  g["alpha_deg"] = deg_rounded(params.alpha);
  g["beta_deg"] = deg_rounded(params.beta);
  g["a"] = params.a;
  g["b"] = params.b;
  g["corners"] = letters;
  g["corners_order"] = "windows (0,0) (2,0) (0,2) (2,2), each in unit P order AB BC CD DA a3 a4 b1 b2 c3 c4 d1 d2";
  char title[200];
  std::snprintf(title, sizeof title, "Double-corrugated tessellation 5x5 panels, alpha %g deg, beta %g deg",
                to_degrees(params.alpha), to_degrees(params.beta));
  return finish_pattern(std::move(p), title, "corner P windows " + letters + " (seed 003 Fig 3-9)", g);
}

CreasePattern corrugated_tessellation_window(const CorrugatedParams& params, const CreasePattern& sheet, int wa, int wb) {
  check_params(params);
  require(wa >= 0 && wa <= 2 && wb >= 0 && wb <= 2, "window", "w_a and w_b must lie in 0..2");
  const int sheet_edges = 2 * kPanels * (kPanels + 1);
  require(sheet.num_edges() == sheet_edges && sheet.num_vertices() == (kPanels + 1) * (kPanels + 1), "window",
          "the sheet is not a 5 x 5-panel corrugated tessellation");
  const auto w = corrugated_tessellation_windows()[3 * wb + wa];
  std::vector<Eigen::Vector2d> u, v;
  lattice_vectors(params, wa, wb, kWindow, u, v);
  ParallelogramLattice L = parallelogram_lattice(u, v);
  CreasePattern p = std::move(L.pattern);
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] != Assignment::Boundary) p.assignments[e] = sheet.assignments[w.edges[e]];
  std::vector<Assignment> interior;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] != Assignment::Boundary) interior.push_back(p.assignments[e]);
  nlohmann::ordered_json g;
  g["kind"] = "corrugated-tessellation-window";
  g["window"] = {wa, wb};
  g["alpha_deg"] = deg_rounded(params.alpha);
  g["beta_deg"] = deg_rounded(params.beta);
  g["a"] = params.a;
  g["b"] = params.b;
  return finish_pattern(std::move(p), window_name(wa, wb) + " of a double-corrugated tessellation",
                        "interior letters " + assignment_letters(interior), g);
}

}  // namespace rigidfold::generators
