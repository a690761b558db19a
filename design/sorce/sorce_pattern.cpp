#include "design/sorce/sorce_pattern.hpp"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/geometry/bvh/BVH_model.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <nlopt.hpp>
#include <string>

#include "design/sorce/sorce_rolling.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::sorce {

namespace {

using Eigen::Isometry3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;

std::string at(const std::string& name, int i) { return name + "[" + std::to_string(i) + "]"; }

Matrix4d translation_y(double y) {
  Matrix4d m = Matrix4d::Identity();
  m(1, 3) = y;
  return m;
}

Matrix4d rotation_z(double a) {
  Matrix4d m = Matrix4d::Identity();
  m(0, 0) = std::cos(a);
  m(0, 1) = -std::sin(a);
  m(1, 0) = std::sin(a);
  m(1, 1) = std::cos(a);
  return m;
}

// d/da of rotation_z (no identity part).
Matrix4d rotation_z_derivative(double a) {
  Matrix4d m = Matrix4d::Zero();
  m(0, 0) = -std::sin(a);
  m(0, 1) = -std::cos(a);
  m(1, 0) = std::cos(a);
  m(1, 1) = -std::sin(a);
  return m;
}

// The split offset's value (k = 0) or derivative (k = 1) as a translation column; 0 if not split.
Matrix4d split_part(const FoldMotion& m, double t, int k) {
  Matrix4d out = Matrix4d::Zero();
  if (k == 0) out.setIdentity();
  if (!m.d) return out;
  const VectorJet d = m.d(t);
  out(0, 3) = d[0][k];
  out(1, 3) = d[1][k];
  return out;
}

// The crease's planar relative motion in its frame: right panel in the left panel's coordinates
// (eq 55: q = R(gamma) (p + (0, z_r)) + d - (0, z_l)).
Matrix4d planar_relative(const FoldMotion& m, double t) {
  return translation_y(-m.z_left(t)[0]) * split_part(m, t, 0) * rotation_z(m.gamma(t)[0]) * translation_y(m.z_right(t)[0]);
}

Isometry3d offset_pose(const Isometry3d& placement, const Vector3d& normal, double z) {
  Isometry3d p = placement;
  p.translate(z * normal);
  return p;
}

// Face poses at t: face f's zero-thickness placement offset by z_f along its normal; with split
// creases, face 0's pose carried across a spanning tree of the joints instead (the split
// translations are not in the zero-thickness placement).
std::vector<Isometry3d> poses_of(const CreasePattern& pattern, const Topology& topology, const PathSpline& path,
                                 const std::vector<CreaseJoint>& creases, const std::vector<FaceOffset>& faces, double t,
                                 bool split) {
  const int ne = pattern.num_edges(), nf = pattern.num_faces();
  Eigen::VectorXd rho(ne);
  for (int e = 0; e < ne; ++e) rho(e) = path.rho[e](t)[0];
  const FoldedGeometry g = place_faces(pattern, topology, rho, Eigen::VectorXd::Zero(ne));
  std::vector<Isometry3d> p(nf);
  for (int f = 0; f < nf; ++f) p[f] = offset_pose(g.face_motions[f], topology.face_normals[f], faces[f].z(t)[0]);
  if (!split) return p;
  std::vector<char> placed(nf, 0);
  std::vector<int> queue{0};
  placed[0] = 1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const int f = queue[k];
    for (const CreaseJoint& j : creases) {
      if (j.left_face != f && j.right_face != f) continue;
      const int other = j.left_face == f ? j.right_face : j.left_face;
      if (placed[other]) continue;
      const Matrix4d frame = j.frame.matrix();
      Matrix4d rel = frame * planar_relative(j.motion, t) * frame.inverse();  // right in left
      if (f == j.right_face) rel = Matrix4d(rel.inverse());
      p[other] = Isometry3d(p[f].matrix() * rel);
      placed[other] = 1;
      queue.push_back(other);
    }
  }
  return p;
}

// Largest entry of |a - b|, translation column divided by `size`.
double relative_difference(const Matrix4d& a, const Matrix4d& b, double size) {
  Matrix4d d = (a - b).cwiseAbs();
  d.block<3, 1>(0, 3) /= size;
  return d.maxCoeff();
}


// Convex polygon inset: edge i (vertex i -> i + 1) moved inward by inset[i]. Empty if the face is
// not convex (counter-clockwise about +z) or the inset polygon degenerates.
std::vector<Eigen::Vector2d> inset_polygon(const std::vector<Eigen::Vector2d>& p, const std::vector<double>& inset) {
  const int n = static_cast<int>(p.size());
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  for (int i = 0; i < n; ++i)
    if (cross(p[(i + 1) % n] - p[i], p[(i + 2) % n] - p[(i + 1) % n]) <= 0.0) return {};
  std::vector<Eigen::Vector2d> q(n);
  for (int i = 0; i < n; ++i) {
    // Vertex i + 1 is where the inset lines of edges i and i + 1 meet.
    const Eigen::Vector2d d0 = (p[(i + 1) % n] - p[i]).normalized(), d1 = (p[(i + 2) % n] - p[(i + 1) % n]).normalized();
    const Eigen::Vector2d a0 = p[i] + inset[i] * Eigen::Vector2d(-d0.y(), d0.x());
    const Eigen::Vector2d a1 = p[(i + 1) % n] + inset[(i + 1) % n] * Eigen::Vector2d(-d1.y(), d1.x());
    const double s = cross(a1 - a0, d1) / cross(d0, d1);
    q[(i + 1) % n] = a0 + s * d0;
  }
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e0 = q[(i + 1) % n] - q[i], e1 = p[(i + 1) % n] - p[i];
    if (e0.dot(e1) <= 0.0 || cross(q[(i + 1) % n] - q[i], q[(i + 2) % n] - q[(i + 1) % n]) <= 0.0) return {};
  }
  return q;
}

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> slab_model(const std::vector<Eigen::Vector2d>& q, double half) {
  const int n = static_cast<int>(q.size());
  std::vector<fcl::Vector3d> v;
  for (const auto& p : q) v.emplace_back(p.x(), p.y(), -half);
  for (const auto& p : q) v.emplace_back(p.x(), p.y(), half);
  std::vector<fcl::Triangle> tris;
  for (int i = 1; i + 1 < n; ++i) {
    tris.emplace_back(0, i + 1, i);
    tris.emplace_back(n, n + i, n + i + 1);
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    tris.emplace_back(i, j, n + j);
    tris.emplace_back(i, n + j, n + i);
  }
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  model->addSubModel(v, tris);
  model->endModel();
  return model;
}

}  // namespace

std::vector<double> stacking_end_offsets(const CreasePattern& pattern, const Topology& topology,
                                         const std::vector<int>& fold_sign, const std::vector<double>& thickness) {
  const int nf = pattern.num_faces();
  // Rows a z >= b (inequalities) and a z = 0 (flat hinges).
  std::vector<std::pair<Eigen::VectorXd, double>> ineq, eq;
  for (int e = 0; e < pattern.num_edges(); ++e) {
    if (!topology.edge_is_hinge[e]) continue;
    const int r = topology.edge_faces[e][0], l = topology.edge_faces[e][1];
    Eigen::VectorXd a = Eigen::VectorXd::Zero(nf);
    if (fold_sign[e] == 0) {
      a(l) += 1.0;
      a(r) -= 1.0;
      eq.emplace_back(a, 0.0);
    } else {
      a(l) -= fold_sign[e];
      a(r) -= fold_sign[e];
      ineq.emplace_back(a, 0.5 * (thickness[l] + thickness[r]));
    }
  }
  const double scale = *std::max_element(thickness.begin(), thickness.end());
  std::vector<double> z(nf, 0.0);
  {
    nlopt::opt opt(nlopt::LD_SLSQP, nf);
    opt.set_min_objective(
        [](const std::vector<double>& x, std::vector<double>& g, void*) {
          double s = 0.0;
          for (std::size_t i = 0; i < x.size(); ++i) {
            s += x[i] * x[i];
            if (!g.empty()) g[i] = 2.0 * x[i];
          }
          return s;
        },
        nullptr);
    // NLopt wants c(z) <= 0: b - a z <= 0 and a z = 0. The rows outlive the optimizer.
    auto linear = [](const std::vector<double>& x, std::vector<double>& g, void* data) {
      const auto* row = static_cast<const std::pair<Eigen::VectorXd, double>*>(data);
      double s = -row->second;
      for (std::size_t i = 0; i < x.size(); ++i) {
        s += row->first(i) * x[i];
        if (!g.empty()) g[i] = row->first(i);
      }
      return s;
    };
    std::vector<std::pair<Eigen::VectorXd, double>> neg;
    neg.reserve(ineq.size());
    for (const auto& [a, b] : ineq) neg.emplace_back(-a, -b);
    for (auto& row : neg) opt.add_inequality_constraint(linear, &row, 1e-12 * scale);
    for (auto& row : eq) opt.add_equality_constraint(linear, &row, 1e-12 * scale);
    opt.set_xtol_abs(1e-14 * scale);
    opt.set_maxeval(2000);
    double value = 0.0;
    try {
      opt.optimize(z, value);
    } catch (const std::exception& ex) {
      throw InputError("end_offsets", std::string("stacking offsets: the optimizer failed: ") + ex.what());
    }
  }
  // Polish: the active rows (and the equalities) as equations, minimum-norm solution, so that
  // the binding stacking conditions hold to round-off rather than to the optimizer's tolerance.
  std::vector<std::pair<Eigen::VectorXd, double>> active = eq;
  const Eigen::Map<Eigen::VectorXd> zv(z.data(), nf);
  for (const auto& [a, b] : ineq)
    if (a.dot(zv) - b <= 1e-6 * scale) active.emplace_back(a, b);
  if (!active.empty()) {
    Eigen::MatrixXd a(active.size(), nf);
    Eigen::VectorXd b(active.size());
    for (std::size_t i = 0; i < active.size(); ++i) {
      a.row(i) = active[i].first.transpose();
      b(i) = active[i].second;
    }
    const Eigen::VectorXd polished = a.completeOrthogonalDecomposition().solve(b);
    bool ok = (a * polished - b).cwiseAbs().maxCoeff() <= 1e-12 * scale;
    for (const auto& [r, c] : ineq) ok = ok && r.dot(polished) - c >= -1e-12 * scale;
    if (ok) std::copy(polished.data(), polished.data() + nf, z.begin());
  }
  for (const auto& [a, b] : ineq)
    if (a.dot(Eigen::Map<Eigen::VectorXd>(z.data(), nf)) - b < -1e-9 * scale)
      throw InputError("end_offsets", "no offsets satisfy every crease's stacking condition");
  return z;
}

PatternSorce pattern_sorce(const CreasePattern& pattern, const PatternSorceRequest& request) {
  const Topology topology = build_topology(pattern, "pattern");
  const int nf = pattern.num_faces(), ne = pattern.num_edges();
  // A flat reference: every face normal +z (the offsets' direction at t = 0).
  for (int f = 0; f < nf; ++f)
    if ((topology.face_normals[f] - Vector3d::UnitZ()).norm() > 1e-9)
      throw InputError("pattern", "face " + std::to_string(f) + " is not flat with normal +z (reference state must be unfolded)");
  // Thicknesses.
  std::vector<double> thickness(nf, request.thickness);
  if (!request.face_thickness.empty()) {
    if (static_cast<int>(request.face_thickness.size()) != nf)
      throw InputError("face_thickness", "one per face expected (" + std::to_string(nf) + ")");
    thickness = request.face_thickness;
    for (int f = 0; f < nf; ++f)
      if (!(thickness[f] > 0.0) || !std::isfinite(thickness[f])) throw InputError(at("face_thickness", f), "must be > 0");
  } else if (!(request.thickness > 0.0) || !std::isfinite(request.thickness)) {
    throw InputError("thickness", "must be > 0");
  }
  if (request.check_samples < 2) throw InputError("check_samples", "must be >= 2");
  if (!request.offset_coefficients.empty() && static_cast<int>(request.offset_coefficients.size()) != nf)
    throw InputError("offset_coefficients", "one list per face expected");
  if (!request.end_offsets.empty() && static_cast<int>(request.end_offsets.size()) != nf)
    throw InputError("end_offsets", "one per face expected (" + std::to_string(nf) + ")");
  for (std::size_t f = 0; f < request.end_offsets.size(); ++f)
    if (!std::isfinite(request.end_offsets[f])) throw InputError(at("end_offsets", static_cast<int>(f)), "not finite");
  for (std::size_t i = 0; i < request.pose_times.size(); ++i)
    if (!(request.pose_times[i] >= 0.0 && request.pose_times[i] <= 1.0))
      throw InputError(at("pose_times", static_cast<int>(i)), "must lie in [0, 1]");

  PatternSorce out;
  // The path.
  if (request.branch) {
    out.path = path_spline(*request.branch, ne, request.path_parameter);
  } else {
    TraceRequest trace = request.trace;
    trace.force_general = true;
    const MotionTrace m = trace_motion(pattern, topology, trace);
    if (m.branches.empty()) throw InputError("branch", "nothing traced: " + m.note);
    out.path = path_spline(m.branches[0], ne, request.path_parameter);
  }
  const PathSpline& path = out.path;
  const int knots = static_cast<int>(path.knots.size());

  // Fold signs at t = 1 and the offsets.
  std::vector<int> sign(ne, 0);
  for (int e = 0; e < ne; ++e) {
    if (!topology.edge_is_hinge[e]) continue;
    if (path.samples.row(e).cwiseAbs().maxCoeff() <= 1e-9) continue;  // stays flat
    const double end = path.samples(e, knots - 1);
    sign[e] = end > 0.0 ? 1 : (end < 0.0 ? -1 : 0);
  }
  const std::vector<double> end_offsets =
      request.end_offsets.empty() ? stacking_end_offsets(pattern, topology, sign, thickness) : request.end_offsets;
  out.faces.resize(nf);
  for (int f = 0; f < nf; ++f) {
    FaceOffset& face = out.faces[f];
    face.end_value = end_offsets[f];
    face.thickness = thickness[f];
    if (request.offset_coefficients.empty() || request.offset_coefficients[f].empty()) {
      face.z = power_function(end_offsets[f], 1);
    } else {
      try {
        face.z = basis_offset(end_offsets[f], request.offset_coefficients[f], seed_offset_bases());
      } catch (const InputError& ex) {
        throw InputError(at("offset_coefficients", f), ex.message());
      }
    }
  }
  // Circular CORE joints: each listed crease's two faces follow its fold angle.
  std::vector<int> circular_edge_of_face(nf, -1);
  for (std::size_t k = 0; k < request.circular_edges.size(); ++k) {
    const int e = request.circular_edges[k];
    const std::string place = at("circular_edges", static_cast<int>(k));
    if (e < 0 || e >= ne || !topology.edge_is_hinge[e]) throw InputError(place, "is not a hinge crease of the pattern");
    const int l = topology.edge_faces[e][0], r = topology.edge_faces[e][1];
    if (thickness[l] != thickness[r]) throw InputError(place, "its two faces differ in thickness");
    for (int f : {l, r}) {
      const int other = circular_edge_of_face[f];
      if (other >= 0 && other != e)
        for (int i = 0; i < request.check_samples; ++i) {
          const double t = static_cast<double>(i) / (request.check_samples - 1);
          if (!(std::abs(path.rho[e](t)[0] - path.rho[other](t)[0]) <= 1e-9))
            throw InputError(place, "face " + std::to_string(f) + " is also on circular crease " + std::to_string(other) +
                                        ", whose fold angle differs from this one's along the path");
        }
      circular_edge_of_face[f] = e;
      out.faces[f].z = circular_offset(thickness[f] / 2, path.rho[e]);
      out.faces[f].end_value = out.faces[f].z(1.0)[0];
    }
  }

  // Split creases.
  std::vector<ScalarFunction> split_of_edge(ne);
  for (std::size_t k = 0; k < request.splits.size(); ++k) {
    const int e = request.splits[k].edge;
    const std::string place = at("splits", static_cast<int>(k));
    if (e < 0 || e >= ne || !topology.edge_is_hinge[e]) throw InputError(place, "is not a hinge crease of the pattern");
    if (split_of_edge[e]) throw InputError(place, "crease " + std::to_string(e) + " is split twice");
    if (!request.splits[k].d) throw InputError(place, "no offset function d(t)");
    const double d0 = request.splits[k].d(0.0)[0];
    if (!(std::abs(d0) <= 1e-12)) throw InputError(place, "d(0) must be 0 (the panels are coplanar when flat)");
    split_of_edge[e] = request.splits[k].d;
  }
  const bool split = !request.splits.empty();

  // Size for relative figures.
  Vector3d lo = pattern.vertices[0], hi = pattern.vertices[0];
  for (const auto& v : pattern.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double size = std::max((hi - lo).norm(), 1e-300);

  // The joints.
  ReportOptions report = request.report;
  std::vector<int> joint_of_edge(ne, -1);
  for (int e = 0; e < ne; ++e) {
    if (!topology.edge_is_hinge[e]) continue;
    CreaseJoint j;
    j.edge = e;
    j.right_face = topology.edge_faces[e][0];
    j.left_face = topology.edge_faces[e][1];
    const Vector3d a = pattern.vertices[pattern.edges[e][0]], b = pattern.vertices[pattern.edges[e][1]];
    const Vector3d z = (b - a).normalized(), y = Vector3d::UnitZ(), x = y.cross(z);
    j.frame.linear().col(0) = x;
    j.frame.linear().col(1) = y;
    j.frame.linear().col(2) = z;
    j.frame.translation() = a;
    j.motion.gamma = path.rho[e];
    j.motion.z_left = out.faces[j.left_face].z;
    j.motion.z_right = out.faces[j.right_face].z;
    j.motion.thickness_left = thickness[j.left_face];
    j.motion.thickness_right = thickness[j.right_face];
    if (split_of_edge[e]) j.motion.d = split_offset_along_half_angle(split_of_edge[e], path.rho[e]);  // eqs 58, 59
    j.folds = sign[e] != 0 || path.samples.row(e).cwiseAbs().maxCoeff() > 1e-9;
    if (j.folds) {
      j.report = fold_report(j.motion, report);
      if (j.report.cusps.empty() && j.report.ill_behaved.empty() && j.report.stationary.empty()) {
        // At a pivot at t = 1 the contact is one point whose tangent is a limit (-s''), while
        // the spline's path leaves |s'| ~ 1e-13 there, turning the tangent within t ~ 1e-12 of
        // the end: the roll is ill-conditioned at that point alone, so it is left out.
        // (The roll starts at t = 0 whatever it is: its first sample is the initial contact.)
        std::vector<double> ts;
        for (int i = 0; i < request.check_samples; ++i)
          if (!(i == request.check_samples - 1 && j.report.pivot_at_end)) ts.push_back(static_cast<double>(i) / (request.check_samples - 1));
        const RollingRecovery rolled = rolling_recovery(j.motion, right_profile_curve(j.motion), ts);
        j.rolled_gamma = rolled.gamma;
        j.rolled_translation = rolled.translation;
      } else {
        j.rolled_gamma = j.rolled_translation = std::numeric_limits<double>::quiet_NaN();
      }
    }
    joint_of_edge[e] = static_cast<int>(out.creases.size());
    out.creases.push_back(std::move(j));
  }
  if (out.creases.empty()) throw InputError("pattern", "has no hinge creases");

  PatternChecks& checks = out.checks;
  checks.flat_folded_end = true;
  checks.all_stack = true;
  for (const CreaseJoint& j : out.creases) {
    if (!j.folds) continue;
    checks.rolling = std::max(checks.rolling, j.report.max_rolling_residual);
    checks.contact_planar = std::max(checks.contact_planar, j.report.max_contact_residual);
    if (std::isnan(j.rolled_gamma)) {
      checks.not_rolled.push_back(j.edge);
    } else {
      checks.rolled_gamma = std::max(checks.rolled_gamma, j.rolled_gamma);
      checks.rolled_translation = std::max(checks.rolled_translation, j.rolled_translation);
    }
    checks.flat_folded_end = checks.flat_folded_end && j.report.ends.flat_folded_end;
    checks.all_stack = checks.all_stack && j.report.stacks;
  }
  if (!checks.flat_folded_end) checks.all_stack = false;
  checks.stacking_margin = std::numeric_limits<double>::infinity();
  for (const CreaseJoint& j : out.creases) {
    if (!j.folds) continue;
    const double end = j.motion.gamma(1.0)[0];
    checks.end_gap = std::max(checks.end_gap, M_PI - std::abs(end));
    const double separation = -(out.faces[j.left_face].end_value + out.faces[j.right_face].end_value);
    checks.stacking_margin = std::min(checks.stacking_margin, (end >= 0.0 ? separation : -separation) -
                                                                  0.5 * (thickness[j.left_face] + thickness[j.right_face]));
  }

  auto angles_at = [&](double t) {
    Eigen::VectorXd rho(ne);
    for (int e = 0; e < ne; ++e) rho(e) = path.rho[e](t)[0];
    return rho;
  };
  auto poses_at = [&](double t, const Eigen::VectorXd&) { return poses_of(pattern, topology, path, out.creases, out.faces, t, split); };
  // Relative transform of face `to` in face `from`'s coordinates across crease joint j.
  auto crossing = [&](const CreaseJoint& j, int from, double t) -> Matrix4d {
    const Matrix4d f = j.frame.matrix();
    const Matrix4d rel = f * planar_relative(j.motion, t) * f.inverse();
    return from == j.left_face ? rel : Matrix4d(rel.inverse());
  };
  auto vertex_closure = [&](double t) {
    double worst = 0.0;
    for (int v : topology.interior_vertices) {
      const Fan& fan = topology.stars[v].fans[0];
      const int n = static_cast<int>(fan.edges.size());
      Matrix4d prod = Matrix4d::Identity();
      for (int i = 0; i < n; ++i) {
        const int from = fan.faces[(i + n - 1) % n];
        const CreaseJoint& j = out.creases[joint_of_edge[fan.edges[i]]];
        prod = prod * crossing(j, from, t);
      }
      worst = std::max(worst, relative_difference(prod, Matrix4d::Identity(), size));
    }
    return worst;
  };

  // (a), (b), (c) at the knots.
  for (int k = 0; k < knots; ++k) {
    const double t = path.knots[k];
    const std::vector<Isometry3d> p = poses_at(t, angles_at(t));
    for (CreaseJoint& j : out.creases) {
      const Matrix4d f = j.frame.matrix();
      const Matrix4d actual = (p[j.left_face].inverse() * p[j.right_face]).matrix();
      const Matrix4d expected = f * planar_relative(j.motion, t) * f.inverse();
      j.consistency = std::max(j.consistency, relative_difference(actual, expected, size));
      if (j.folds && std::abs(j.motion.gamma(t)[1]) > 0.0) {
        const ProfilePoint pp = profile_point(j.motion, t);
        const double along = 0.5 * (pattern.vertices[pattern.edges[j.edge][1]] - pattern.vertices[pattern.edges[j.edge][0]]).norm();
        const Vector3d sl = j.frame * Vector3d(pp.s_left.x(), pp.s_left.y(), along);
        const Vector3d sr = j.frame * Vector3d(pp.s_right.x(), pp.s_right.y(), along);
        j.contact = std::max(j.contact, (p[j.left_face] * sl - p[j.right_face] * sr).norm());
      }
    }
    checks.closure_knots = std::max(checks.closure_knots, vertex_closure(t));
  }

  // The spline's closure gap midway between knots, where it is largest (check samples could
  // coincide with knots, which close as the solver left them).
  for (std::size_t k = 0; k + 1 < path.knots.size(); ++k)
    checks.closure_samples = std::max(checks.closure_samples, vertex_closure(0.5 * (path.knots[k] + path.knots[k + 1])));
  // Pitch at the check samples.
  const int ns = request.check_samples;
  std::vector<double> samples(ns);
  for (int i = 0; i < ns; ++i) samples[i] = static_cast<double>(i) / (ns - 1);
  for (double t : samples) {
    for (CreaseJoint& j : out.creases) {
      if (!j.folds) continue;
      const Jet g = j.motion.gamma(t), zl = j.motion.z_left(t), zr = j.motion.z_right(t);
      if (g[1] == 0.0) continue;
      const Matrix4d a = translation_y(-zl[0]), b = rotation_z(g[0]), c = translation_y(zr[0]);
      const Matrix4d s = split_part(j.motion, t, 0), ds = split_part(j.motion, t, 1);
      Matrix4d da = Matrix4d::Zero(), dc = Matrix4d::Zero();
      da(1, 3) = -zl[1];
      dc(1, 3) = zr[1];
      const Matrix4d f = j.frame.matrix(), finv = f.inverse();
      const Matrix4d rel = f * a * s * b * c * finv;
      const Matrix4d drel =
          f * (da * s * b * c + a * ds * b * c + a * s * (g[1] * rotation_z_derivative(g[0])) * c + a * s * b * dc) * finv;
      const Matrix4d twist = rel.inverse() * drel;  // body twist in the left face's reference coordinates
      const Vector3d omega(twist(2, 1), twist(0, 2), twist(1, 0)), v = twist.block<3, 1>(0, 3);
      j.pitch = std::max(j.pitch, std::abs(omega.dot(v)) / omega.squaredNorm() / size);
    }
  }
  for (const CreaseJoint& j : out.creases) {
    checks.consistency = std::max(checks.consistency, j.consistency);
    checks.pitch = std::max(checks.pitch, j.pitch);
    checks.contact = std::max(checks.contact, j.contact);
  }

  // Pose table.
  out.pose_times = request.pose_times;
  if (out.pose_times.empty())
    for (int i = 0; i <= 10; ++i) out.pose_times.push_back(i / 10.0);
  for (double t : out.pose_times) out.poses.push_back(poses_at(t, angles_at(t)));

  // (e) Slab interference.
  if (request.check_interference) {
    // Cut-back per hinge edge: the cam's lateral extent plus half the two thicknesses.
    std::vector<double> cut(ne, 0.0);
    for (const CreaseJoint& j : out.creases) {
      double lateral = 0.0;
      if (j.folds)
        for (double t : samples) {
          if (j.motion.gamma(t)[1] == 0.0) continue;
          const ProfilePoint pp = profile_point(j.motion, t);
          lateral = std::max({lateral, std::abs(pp.s_left.x()), std::abs(pp.s_right.x())});
        }
      cut[j.edge] = lateral + 0.5 * (thickness[j.left_face] + thickness[j.right_face]);
    }
    std::vector<std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>>> models(nf);
    for (int f = 0; f < nf; ++f) {
      const std::vector<int>& fv = pattern.faces[f];
      const int n = static_cast<int>(fv.size());
      std::vector<Eigen::Vector2d> poly(n);
      std::vector<double> inset(n, 0.0);
      for (int i = 0; i < n; ++i) {
        poly[i] = pattern.vertices[fv[i]].head<2>();
        const int u = fv[i], w = fv[(i + 1) % n];
        for (int e = 0; e < ne; ++e)
          if ((pattern.edges[e][0] == u && pattern.edges[e][1] == w) || (pattern.edges[e][0] == w && pattern.edges[e][1] == u))
            inset[i] = cut[e];
      }
      const std::vector<Eigen::Vector2d> q = inset_polygon(poly, inset);
      if (q.empty()) {
        checks.skipped_faces.push_back(f);
        continue;
      }
      models[f] = slab_model(q, 0.5 * thickness[f] * (1.0 - 1e-9));
    }
    for (double t : samples) {
      const std::vector<Isometry3d> p = poses_at(t, angles_at(t));
      SlabInterference hit;
      hit.t = t;
      for (int f = 0; f < nf; ++f) {
        if (!models[f]) continue;
        for (int g = f + 1; g < nf; ++g) {
          if (!models[g]) continue;
          fcl::CollisionObjectd a(models[f], fcl::Transform3d(p[f].matrix()));
          fcl::CollisionObjectd b(models[g], fcl::Transform3d(p[g].matrix()));
          fcl::CollisionRequestd rq;
          fcl::CollisionResultd rs;
          if (fcl::collide(&a, &b, rq, rs) > 0) hit.face_pairs.emplace_back(f, g);
        }
      }
      checks.interference.push_back(std::move(hit));
    }
  }
  return out;
}

std::vector<Isometry3d> panel_poses(const CreasePattern& pattern, const Topology& topology, const PatternSorce& sorce,
                                    double t) {
  bool split = false;
  for (const CreaseJoint& j : sorce.creases) split = split || static_cast<bool>(j.motion.d);
  return poses_of(pattern, topology, sorce.path, sorce.creases, sorce.faces, t, split);
}

}  // namespace rigidfold::sorce
