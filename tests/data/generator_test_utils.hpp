#pragma once
// Helpers for the generator tests: a tiny 3x3 loop-closure product, Kawasaki/Maekawa per
// interior vertex, propagation of the flat-foldable tan-half multipliers over a pattern of
// degree-4 vertices, and a face placement to inspect folded shapes. Independent of the
// kernel's solvers on purpose (the generators are tested against first principles).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <queue>
#include <unistd.h>
#include <string>
#include <vector>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::test {


inline Eigen::Matrix3d rx(double a) {
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return m;
}
inline Eigen::Matrix3d rz(double a) {
  Eigen::Matrix3d m;
  m << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return m;
}

// max |R - I| of R = prod_i Rx(rho_i) Rz(alpha_i) around interior vertex v (creases CCW as
// build_topology orders them).
inline double loop_residual(const Topology& t, int v, const std::vector<double>& rho) {
  const Fan& fan = t.stars[v].fans.at(0);
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < fan.edges.size(); ++i) R = R * rx(rho[fan.edges[i]]) * rz(fan.sectors[i]);
  return (R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

// Alternating sector sum around interior vertex v (0 for Kawasaki-flat vertices).
inline double kawasaki_residual(const Topology& t, int v) {
  const Fan& fan = t.stars[v].fans.at(0);
  double s = 0;
  for (std::size_t i = 0; i < fan.sectors.size(); ++i) s += (i % 2 == 0 ? 1 : -1) * fan.sectors[i];
  return s;
}

inline std::pair<int, int> mountains_valleys(const CreasePattern& p, const Topology& t, int v) {
  int m = 0, vv = 0;
  for (int e : t.stars[v].fans.at(0).edges) {
    m += p.assignments[e] == Assignment::Mountain;
    vv += p.assignments[e] == Assignment::Valley;
  }
  return {m, vv};
}

inline double sign_of(Assignment a) { return a == Assignment::Valley ? 1.0 : a == Assignment::Mountain ? -1.0 : 0.0; }

// Flat-foldable multiplier propagation. Every interior vertex must have degree 4 with a
// 3:1 M/V assignment. At a vertex with odd crease k the creases k+1, k+3 fold by |t| = T
// and k, k+2 by |t| = mu*T, mu = |sin((b-a)/2)| / sin((a+b)/2) with a, b the sectors
// beside crease k+1; signs are the assignment's. Returns w (tan(rho_e/2) = w_e * tau) for
// every edge (0 off the creases), or nullopt if two vertices disagree (not rigid).
inline std::optional<std::vector<double>> propagate_multipliers(const CreasePattern& p, const Topology& t) {
  std::vector<double> mag(p.num_edges(), -1.0);
  std::vector<char> done(p.num_vertices(), 0);
  std::vector<std::vector<int>> vertex_edges(p.num_vertices());
  for (int v : t.interior_vertices)
    for (int e : t.stars[v].fans.at(0).edges) vertex_edges[v].push_back(e);
  auto edge_vertices = [&](int e) { return p.edges[e]; };
  bool first = true;
  for (int root : t.interior_vertices) {
    if (done[root]) continue;
    std::queue<int> q;
    q.push(root);
    done[root] = 1;
    while (!q.empty()) {
      const int v = q.front();
      q.pop();
      const Fan& fan = t.stars[v].fans.at(0);
      if (fan.edges.size() != 4) return std::nullopt;
      int odd = -1;
      for (int k = 0; k < 4; ++k) {
        int same = 0;
        for (int j = 0; j < 4; ++j) same += p.assignments[fan.edges[j]] == p.assignments[fan.edges[k]];
        if (same == 1) odd = k;
      }
      if (odd < 0) return std::nullopt;
      const double a = fan.sectors[(odd) % 4], b = fan.sectors[(odd + 1) % 4];
      const double mu = std::fabs(std::sin((b - a) / 2)) / std::sin((a + b) / 2);
      std::array<double, 4> rel{};
      for (int j = 0; j < 4; ++j) rel[j] = ((j - odd) % 2 == 0) ? mu : 1.0;
      // Scale from any crease already known.
      double scale = -1;
      for (int j = 0; j < 4; ++j)
        if (mag[fan.edges[j]] >= 0) {
          scale = mag[fan.edges[j]] / rel[j];
          break;
        }
      if (scale < 0) {
        if (!first) return std::nullopt;  // disconnected pieces are not expected here
        scale = 1.0;
        first = false;
      }
      for (int j = 0; j < 4; ++j) {
        const int e = fan.edges[j];
        const double m = rel[j] * scale;
        if (mag[e] >= 0) {
          if (std::fabs(mag[e] - m) > 1e-12 * std::max(1.0, m)) return std::nullopt;
        } else {
          mag[e] = m;
        }
        for (int w : edge_vertices(e))
          if (w != v && !vertex_edges[w].empty() && !done[w]) {
            done[w] = 1;
            q.push(w);
          }
      }
    }
  }
  std::vector<double> w(p.num_edges(), 0.0);
  for (int e = 0; e < p.num_edges(); ++e)
    if (mag[e] >= 0) w[e] = sign_of(p.assignments[e]) * mag[e];
  return w;
}

inline std::vector<double> folds_from_multipliers(const std::vector<double>& w, double tau) {
  std::vector<double> rho(w.size());
  for (std::size_t e = 0; e < w.size(); ++e) rho[e] = 2 * std::atan(w[e] * tau);
  return rho;
}

// Rotation of every face (face 0 fixed) by a breadth-first walk across hinges: the right
// face of edge v0->v1 turns by -rho about the axis v0->v1 relative to the left face (any
// consistent choice gives the folded shape or its mirror image). Also returns the largest
// disagreement over hinges not on the walk (0 when the folds close).
struct Placement {
  std::vector<Eigen::Matrix3d> rotation;
  std::vector<Eigen::Vector3d> translation;
  double mismatch = 0;
};
inline Placement place(const CreasePattern& p, const Topology& t, const std::vector<double>& rho) {
  Placement out;
  const int nf = p.num_faces();
  out.rotation.assign(nf, Eigen::Matrix3d::Identity());
  out.translation.assign(nf, Eigen::Vector3d::Zero());
  std::vector<char> placed(nf, 0);
  std::vector<std::vector<int>> face_edges(nf);
  for (int e = 0; e < p.num_edges(); ++e)
    if (t.edge_is_hinge[e]) {
      face_edges[t.edge_faces[e][0]].push_back(e);
      face_edges[t.edge_faces[e][1]].push_back(e);
    }
  auto child_motion = [&](int e, int parent, Eigen::Matrix3d& R, Eigen::Vector3d& x) {
    const Eigen::Vector3d a = p.vertices[p.edges[e][0]], b = p.vertices[p.edges[e][1]];
    const Eigen::Vector3d axis = (b - a).normalized();
    const double angle = parent == t.edge_faces[e][0] ? -rho[e] : rho[e];
    const Eigen::Matrix3d H = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    // child = parent o (rotate about the line through a)
    R = out.rotation[parent] * H;
    x = out.rotation[parent] * (a - H * a) + out.translation[parent];
  };
  std::queue<int> q;
  q.push(0);
  placed[0] = 1;
  while (!q.empty()) {
    const int f = q.front();
    q.pop();
    for (int e : face_edges[f]) {
      const int g = t.edge_faces[e][0] == f ? t.edge_faces[e][1] : t.edge_faces[e][0];
      Eigen::Matrix3d R;
      Eigen::Vector3d x;
      child_motion(e, f, R, x);
      if (!placed[g]) {
        placed[g] = 1;
        out.rotation[g] = R;
        out.translation[g] = x;
        q.push(g);
      } else {
        for (int v : p.faces[g]) {
          const Eigen::Vector3d y1 = R * p.vertices[v] + x, y2 = out.rotation[g] * p.vertices[v] + out.translation[g];
          out.mismatch = std::max(out.mismatch, (y1 - y2).norm());
        }
      }
    }
  }
  return out;
}

// Gauss-Newton on the closure of every interior vertex (9 entries of R - I each), moving
// only the creases flagged in `free_edge`; finite-difference Jacobian. Returns the final
// residual norm. Meant for small patterns.
inline double solve_closure(const Topology& t, std::vector<double>& rho, const std::vector<bool>& free_edge) {
  auto residual = [&](const std::vector<double>& x) {
    Eigen::VectorXd r(9 * t.interior_vertices.size());
    int k = 0;
    for (int v : t.interior_vertices) {
      const Fan& fan = t.stars[v].fans.at(0);
      Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
      for (std::size_t i = 0; i < fan.edges.size(); ++i) R = R * rx(x[fan.edges[i]]) * rz(fan.sectors[i]);
      R -= Eigen::Matrix3d::Identity();
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) r[k++] = R(a, b);
    }
    return r;
  };
  std::vector<int> unknowns;
  for (std::size_t e = 0; e < rho.size(); ++e)
    if (free_edge[e]) unknowns.push_back(static_cast<int>(e));
  Eigen::VectorXd r = residual(rho);
  for (int it = 0; it < 50 && r.norm() > 1e-15; ++it) {
    Eigen::MatrixXd J(r.size(), unknowns.size());
    for (std::size_t j = 0; j < unknowns.size(); ++j) {
      std::vector<double> plus = rho, minus = rho;
      plus[unknowns[j]] += 1e-7;
      minus[unknowns[j]] -= 1e-7;
      J.col(j) = (residual(plus) - residual(minus)) / 2e-7;
    }
    const Eigen::VectorXd step = J.completeOrthogonalDecomposition().solve(-r);
    for (std::size_t j = 0; j < unknowns.size(); ++j) rho[unknowns[j]] += step[j];
    r = residual(rho);
  }
  return r.norm();
}

// Face with exactly these vertices (any order), or -1.
inline int find_face(const CreasePattern& p, std::vector<int> vertices) {
  std::sort(vertices.begin(), vertices.end());
  for (int f = 0; f < p.num_faces(); ++f) {
    auto face = p.faces[f];
    std::sort(face.begin(), face.end());
    if (face == vertices) return f;
  }
  return -1;
}

// Writes the pattern to a temporary file and reads it back.
inline CreasePattern round_trip(const CreasePattern& p, const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("rigidfold_gen_" + std::to_string(::getpid()) + "_" + name + ".fold");
  write_fold(p, path.string());
  CreasePattern q = read_fold(path.string());
  std::filesystem::remove(path);
  return q;
}

}  // namespace rigidfold::test
