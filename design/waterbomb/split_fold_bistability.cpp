#include "design/waterbomb/split_fold_bistability.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "design/waterbomb/flat_branch_continuation.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::waterbomb {

CreasePattern split_fold_base(int n, double b) {
  split_fold_angles_printed(n, b, kPi / 2 - 0.1);  // checks n and b
  const double a = kPi / n - b;
  CreasePattern p;
  p.vertices.push_back(Eigen::Vector3d::Zero());
  for (int k = 0; k < n; ++k) {
    const double s = k * 2 * kPi / n;
    for (double t : {s, s + b, s + b + a, s + 2 * b + a}) p.vertices.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  const int m = 4 * n;
  for (int i = 0; i < m; ++i) {
    p.edges.push_back({0, i + 1});
    p.assignments.push_back(i % 4 < 2 ? Assignment::Valley : Assignment::Mountain);
  }
  for (int i = 0; i < m; ++i) {
    p.edges.push_back({i + 1, (i + 1) % m + 1});
    p.assignments.push_back(Assignment::Boundary);
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  for (int i = 0; i < m; ++i) p.faces.push_back({0, i + 1, (i + 1) % m + 1});
  return p;
}

SplitFoldSprings split_fold_springs(int n, double b, double theta0, double k_m, double k_v) {
  SplitFoldSprings s;
  s.n = n;
  s.b = b;
  s.range = split_fold_range(n, b);  // checks n and b
  if (!std::isfinite(theta0) || theta0 < s.range.theta_min || theta0 > s.range.theta_max)
    throw InputError("theta0", "the rest angle of a split fold must lie in its contact limits [" +
                                   round_trip_text(to_degrees(s.range.theta_min)) + ", " +
                                   round_trip_text(to_degrees(s.range.theta_max)) + "] deg, got " +
                                   round_trip_text(to_degrees(theta0)) + " deg");
  if (!std::isfinite(k_m) || k_m < 0.0) throw InputError("k_m", "stiffness must be finite and >= 0");
  if (!std::isfinite(k_v) || k_v < 0.0) throw InputError("k_v", "stiffness must be finite and >= 0");
  if (k_m == 0.0 && k_v == 0.0) throw InputError("k_m", "at least one stiffness must be > 0");
  s.k_m = k_m;
  s.k_v = k_v;
  s.rest = split_fold_angles_printed(n, b, theta0);
  return s;
}

namespace {

double energy_of(const SplitFoldSprings& s, FoldPair g) {
  const double dm = g.gamma_m - s.rest.gamma_m, dv = g.gamma_v - s.rest.gamma_v;
  return s.n * (s.k_m * dm * dm + s.k_v * dv * dv);
}

// The general 4n-crease model of one split-fold base with its springs and supports.
struct GeneralModel {
  const SplitFoldSprings& s;
  CreasePattern pattern;
  Topology topology;
  ClosureSystem system;
  CreaseSprings springs;
  VertexHeightLoad load;
  double r;

  explicit GeneralModel(const SplitFoldSprings& sp)
      : s(sp), pattern(split_fold_base(sp.n, sp.b)), topology(build_topology(pattern)), system(pattern, topology),
        r(std::cos(sp.b / 2)) {
    Eigen::VectorXd k = Eigen::VectorXd::Zero(pattern.num_edges());
    for (int i = 0; i < 4 * s.n; ++i) k[i] = (i % 4 < 2) ? s.k_v : s.k_m;
    springs = make_crease_springs(pattern, k, per_edge(s.rest));
    load.vertex = 0;
    for (int i = 0; i < 4 * s.n; ++i)
      if (i % 4 < 2) load.support_edges.push_back(i);
  }
  Eigen::VectorXd per_edge(FoldPair g) const {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(pattern.num_edges());
    for (int i = 0; i < 4 * s.n; ++i) rho[i] = (i % 4 < 2) ? g.gamma_v : g.gamma_m;
    return rho;
  }
  // The loaded equilibrium at the vertex height r cos(theta), started on the printed path.
  HeightControlledEquilibrium loaded(double theta) {
    return loaded_from(r * std::cos(theta), system.unknowns_from_edges(per_edge(split_fold_angles_printed(s.n, s.b, theta))));
  }
  // The loaded equilibrium at vertex height h from the start x0 (free fold angles).
  HeightControlledEquilibrium loaded_from(double h, const Eigen::VectorXd& x0, bool stability = true) {
    load.height = h;
    HeightControlOptions ho;
    ho.compute_stability = stability;
    return vertex_height_equilibrium(pattern, system, topology, springs, load, x0, ho);
  }
  // Largest spread among the half-valleys and among the half-mountains (radians).
  double asymmetry(const Eigen::VectorXd& rho) const {
    double out = 0.0;
    for (int i = 0; i < 4 * s.n; ++i) out = std::max(out, std::fabs(rho[i] - rho[i % 4 < 2 ? 0 : 2]));
    return out;
  }
  // The theta on the side of `side_theta` whose printed gamma_m is `gamma_m` (bisection:
  // gamma_m rises monotonically toward 0 at flat on either side), and the gap of the printed
  // gamma_v there to `gamma_v` (radians).
  double theta_on_path(double gamma_m, double gamma_v, double side_theta, double* gap) const {
    const bool below = side_theta < kPi / 2;
    double lo = below ? s.range.theta_min : kPi / 2, hi = below ? kPi / 2 : s.range.theta_max;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const bool rising_side = split_fold_angles_printed(s.n, s.b, mid).gamma_m < gamma_m;
      // Below flat gamma_m rises with theta; above flat it falls.
      ((rising_side == below) ? lo : hi) = mid;
    }
    const double th = 0.5 * (lo + hi);
    *gap = std::fabs(split_fold_angles_printed(s.n, s.b, th).gamma_v - gamma_v);
    return th;
  }
};

std::vector<double> side_grid(double a, double b, int intervals) {
  std::vector<double> t;
  for (int i = 0; i <= intervals; ++i) t.push_back(i == intervals ? b : a + (b - a) * i / intervals);
  return t;
}

std::string deg_text(double theta) { return round_trip_text(to_degrees(theta)); }

}  // namespace

static FoldPair ranged_angles(const SplitFoldSprings& s, double theta) {
  if (!std::isfinite(theta) || theta < s.range.theta_min || theta > s.range.theta_max)
    throw InputError("theta", "outside the split-fold model's range [" + deg_text(s.range.theta_min) + ", " +
                                  deg_text(s.range.theta_max) + "] deg");
  return split_fold_angles_printed(s.n, s.b, theta);
}

double split_fold_energy(const SplitFoldSprings& s, double theta) {
  if (theta == kPi / 2) return energy_of(s, FoldPair{0.0, 0.0});
  return energy_of(s, ranged_angles(s, theta));
}

std::vector<CheckedEquilibrium> SplitFoldBistability::stable_states() const {
  std::vector<CheckedEquilibrium> out;
  for (const CheckedEquilibrium& e : equilibria)
    if (e.path.kind == EquilibriumKind::kMinimum && !e.path.at_validity_limit && e.stable_unrestricted) out.push_back(e);
  return out;
}

std::vector<WaterbombBistability::Barrier> SplitFoldBistability::symmetric_path_barriers() const {
  std::vector<WaterbombBistability::Barrier> out;
  for (const CheckedEquilibrium& cusp : equilibria)
    if (cusp.path.kind == EquilibriumKind::kCuspMaximum)
      for (const CheckedEquilibrium& st : stable_states()) out.push_back({st.path.theta, cusp.path.energy - st.path.energy});
  return out;
}

SplitFoldBistability split_fold_bistability(int n, double b, double theta0, double k_m, double k_v) {
  SplitFoldBistability out;
  out.springs = split_fold_springs(n, b, theta0, k_m, k_v);
  out.theta0 = theta0;
  const SplitFoldSprings& s = out.springs;
  GeneralModel model(s);
  out.support_distance = model.r;
  const double scale = std::max(k_m, k_v);
  constexpr double kFlatOffset = 1e-4;  // the cusp's sides are probed this far from flat (rad)
  constexpr int kIntervals = 256;

  auto boundary_minimum = [&](double theta) {
    CheckedEquilibrium c;
    c.path.kind = EquilibriumKind::kMinimum;
    c.path.theta = theta;
    c.path.angles = ranged_angles(s, theta);
    c.path.energy = split_fold_energy(s, theta);
    c.path.at_validity_limit = true;
    c.min_reduced_eigenvalue = std::nan("");
    out.equilibria.push_back(c);
  };

  // A free equilibrium between grid nodes lo and hi: the root of the general model's force.
  auto refine = [&](double lo, double hi, EquilibriumKind kind) {
    auto force = [&](double th) {
      const HeightControlledEquilibrium eq = model.loaded(th);
      if (!eq.converged)
        throw NoAnswerError("split-fold waterbomb: the general model's loaded equilibrium at theta = " + deg_text(th) +
                                " deg does not converge (" + eq.message + "; constraint residual)",
                            eq.constraint_residual);
      return eq.force;
    };
    const double flo = force(lo), fhi = force(hi);
    double root;
    if (flo == 0.0) {
      root = lo;
    } else if (fhi == 0.0) {
      root = hi;
    } else {
      if ((flo < 0.0) == (fhi < 0.0))
        throw NoAnswerError("split-fold waterbomb: the energy has an extremum between theta = " + deg_text(lo) + " and " +
                                deg_text(hi) + " deg but the general model's force does not change sign there (force at " +
                                deg_text(lo) + " deg)",
                            flo);
      std::uintmax_t iterations = 200;
      const auto bracket = boost::math::tools::toms748_solve(
          force, lo, hi, flo, fhi, [](double x, double y) { return std::fabs(x - y) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(x); },
          iterations);
      root = 0.5 * (bracket.first + bracket.second);
    }
    const HeightControlledEquilibrium loaded = model.loaded(root);
    const Equilibrium free = analyse_equilibrium(model.system, model.topology, model.springs, loaded.x);
    CheckedEquilibrium c;
    c.path.kind = kind;
    c.path.theta = root;
    c.path.angles = {loaded.edge_angles[2], loaded.edge_angles[0]};
    c.path.energy = free.energy;
    c.path.slope_residual = std::fabs(loaded.force) * model.r * std::sin(root);
    c.closure_residual = free.closure_residual;
    c.stationarity_residual = free.stationarity_residual;
    c.min_reduced_eigenvalue = free.min_eigenvalue;
    c.stable_unrestricted = free.stable;
    const std::string where = "split-fold waterbomb state at theta = " + deg_text(root) + " deg";
    if (!(free.closure_residual <= 1e-12))
      throw NoAnswerError(where + " does not close its vertex loop (closure residual, rad)", free.closure_residual);
    if (!(free.stationarity_residual <= 1e-10 * scale))
      throw NoAnswerError(where + " is not an equilibrium of the unsymmetric problem (stationarity, energy/rad)",
                          free.stationarity_residual);
    const double asym = model.asymmetry(loaded.edge_angles);
    if (!(asym <= SplitFoldBistability::kSymmetryTolerance))
      throw NoAnswerError(where + " is not symmetric (spread of the half-fold angles, rad)", asym);
    double gap = 0.0;
    model.theta_on_path(c.path.angles.gamma_m, c.path.angles.gamma_v, root, &gap);
    if (!(gap <= SplitFoldBistability::kPathAgreement))
      throw NoAnswerError(where + " is not on the printed split-fold path (seed eqs 3.13-3.30; gamma_v gap, rad)", gap);
    out.equilibria.push_back(c);
  };

  auto scan = [&](double a, double z) {
    const std::vector<double> t = side_grid(a, z, kIntervals);
    std::vector<double> v;
    for (double th : t) v.push_back(split_fold_energy(s, th));
    if (a == s.range.theta_min && v[0] < v[1]) boundary_minimum(a);
    for (int i = 1; i < kIntervals; ++i) {
      EquilibriumKind kind;
      if (v[i] < v[i - 1] && v[i] <= v[i + 1]) kind = EquilibriumKind::kMinimum;
      else if (v[i] > v[i - 1] && v[i] >= v[i + 1]) kind = EquilibriumKind::kMaximum;
      else continue;
      const bool at_contact = (i == 1 && a == s.range.theta_min) || (i + 1 == kIntervals && z == s.range.theta_max);
      if (!at_contact) {
        refine(t[i - 1], t[i + 1], kind);
        continue;
      }
      // Next to a contact limit gamma_v has a square-root onset and the height control is
      // nearly singular: an extremum there that the general model cannot confirm is listed
      // apart, never as an equilibrium.
      try {
        refine(t[i - 1], t[i + 1], kind);
      } catch (const NoAnswerError& e) {
        out.unconfirmed_near_contact.push_back({t[i - 1], t[i + 1], kind, e.what()});
      }
    }
    if (z == s.range.theta_max && v[kIntervals] < v[kIntervals - 1]) boundary_minimum(z);
  };

  const double flat = kPi / 2;
  scan(s.range.theta_min, flat - kFlatOffset);
  {
    // The flat cusp: every fold at 0; its sides from the general model's force 1e-4 rad away
    // (1e-3, then 1e-2 rad where the height control does not converge that close to flat).
    double offset = kFlatOffset;
    HeightControlledEquilibrium below = model.loaded(flat - offset), above = model.loaded(flat + offset);
    for (double wider : {1e-3, 1e-2}) {
      if (below.converged && above.converged) break;
      offset = wider;
      below = model.loaded(flat - offset);
      above = model.loaded(flat + offset);
    }
    if (!below.converged || !above.converged)
      throw NoAnswerError("split-fold waterbomb: the general model does not converge next to the flat state (constraint residual)",
                          std::max(below.constraint_residual, above.constraint_residual));
    CheckedEquilibrium c;
    c.path.theta = flat;
    c.path.energy = energy_of(s, FoldPair{0.0, 0.0});
    c.path.slope_below = below.force * model.r * std::sin(flat - offset);
    c.path.slope_above = above.force * model.r * std::sin(flat + offset);
    c.min_reduced_eigenvalue = std::nan("");
    if (c.path.slope_below > 0.0 && c.path.slope_above < 0.0) {
      c.path.kind = EquilibriumKind::kCuspMaximum;
      out.equilibria.push_back(c);
    } else if (c.path.slope_below < 0.0 && c.path.slope_above > 0.0) {
      c.path.kind = EquilibriumKind::kCuspMinimum;
      out.equilibria.push_back(c);
    }
  }
  scan(flat + kFlatOffset, s.range.theta_max);
  return out;
}

namespace {
// dV/dtheta of the printed energy at th by central differences with two Richardson levels.
double printed_slope(const SplitFoldSprings& s, double th) {
  const double room = std::min({th - s.range.theta_min, s.range.theta_max - th, std::fabs(th - kPi / 2)});
  const double h = std::min(1e-3, 0.5 * room);
  auto central = [&](double step) { return (split_fold_energy(s, th + step) - split_fold_energy(s, th - step)) / (2 * step); };
  const double d1 = central(h), d2 = central(h / 2), d4 = central(h / 4);
  const double r1 = (4 * d2 - d1) / 3, r2 = (4 * d4 - d2) / 3;
  return (16 * r2 - r1) / 15;
}
}  // namespace

SplitFoldSwitching split_fold_switching_force(int n, double b, double theta0, double k_m, double k_v) {
  const SplitFoldSprings s = split_fold_springs(n, b, theta0, k_m, k_v);
  if (!(theta0 < kPi / 2 - 2e-4))
    throw InputError("theta0", "the switching force needs a rest state before flat (theta0 < 90 deg)");
  GeneralModel model(s);
  // How close to flat the height control converges: 1e-4 rad, else 1e-3 or 1e-2 (as the cusp).
  double kNearFlat = 1e-4;
  for (double wider : {1e-3, 1e-2}) {
    if (model.loaded(kPi / 2 - kNearFlat).converged && model.loaded(kPi / 2 - 2 * kNearFlat).converged) break;
    if (!(theta0 < kPi / 2 - 2 * wider)) break;
    kNearFlat = wider;
  }
  auto force = [&](double th) {
    const HeightControlledEquilibrium eq = model.loaded(th);
    if (!eq.converged)
      throw NoAnswerError("split-fold switching force: the general model's loaded equilibrium at theta = " + deg_text(th) +
                              " deg does not converge (constraint residual)",
                          eq.constraint_residual);
    return eq.force;
  };
  constexpr int kSamples = 64;
  const double a = theta0, z = kPi / 2 - kNearFlat;
  int best = 0;
  double best_force = -INFINITY;
  std::vector<double> t(kSamples + 1), f(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) {
    t[i] = i == kSamples ? z : a + (z - a) * i / kSamples;
    f[i] = force(t[i]);
    if (f[i] > best_force) {
      best_force = f[i];
      best = i;
    }
  }
  SplitFoldSwitching out;
  if (best == kSamples) {
    out.at_flat = true;
    out.theta = kPi / 2;
    out.force = 2 * f[kSamples] - force(kPi / 2 - 2 * kNearFlat);
  } else {
    double lo = t[std::max(0, best - 1)], hi = t[best + 1];
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = force(x1), f2 = force(x2);
    while (hi - lo > 1e-9) {
      if (f1 > f2) {
        hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = force(x1);
      } else {
        lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = force(x2);
      }
    }
    out.theta = 0.5 * (lo + hi);
    out.force = force(out.theta);
  }
  // The check: general force against dV/dh of the printed energy where the maximum is, or
  // 1e-2 rad before flat when it is closer (the printed forms lose digits next to flat, where a
  // difference quotient is noise).
  const double check = std::min(out.theta, kPi / 2 - 1e-2);
  if (check > theta0) {
    const double f_check = check == out.theta ? out.force : force(check);
    out.closed_form_gap = std::fabs(f_check - printed_slope(s, check) / (model.r * std::sin(check)));
  }
  if (!(out.closed_form_gap <= SplitFoldCurve::kForceAgreement * std::max(1.0, std::fabs(out.force))))
    throw NoAnswerError("split-fold switching force: the general model's force differs from dV/dh of the printed energy "
                        "(seed eqs 3.13-3.31) where the maximum is",
                        out.closed_form_gap);
  return out;
}

double split_fold_mountain_stiffness_for_switching_force(int n, double b, double theta0, double k_v, double target) {
  return mountain_stiffness_for_force(
      [&](double k_m) { return split_fold_switching_force(n, b, theta0, k_m, k_v).force; }, k_v, target);
}

std::vector<std::vector<int>> split_fold_motion_classes(int n) {
  std::vector<std::vector<int>> classes(2);
  for (int i = 0; i < 4 * n; ++i) classes[i % 4 < 2 ? 0 : 1].push_back(i);
  return classes;
}

SplitFoldCurve split_fold_curve(int n, double b, double theta0, double k_m, double k_v, int samples,
                                const SplitFoldCurveOptions& options) {
  if (samples < 3 || samples > 2001)
    throw InputError("samples", "must be between 3 and 2001, got " + std::to_string(samples));
  const SplitFoldSprings s = split_fold_springs(n, b, theta0, k_m, k_v);
  for (int e : options.flipped_letters)
    if (e < 0 || e >= 4 * n) throw InputError("flipped_letters", "crease " + std::to_string(e) + " is not one of the 4n creases");
  GeneralModel model(s);
  const double lo = s.range.theta_min, hi = s.range.theta_max;
  const double margin = 1e-2 * (hi - lo);  // the printed forms turn singular at both ends (sqrt onset)
  std::vector<double> thetas;
  for (int i = 0; i < samples; ++i) {
    double th = lo + margin + (hi - lo - 2 * margin) * i / (samples - 1);
    if (std::fabs(th - kPi / 2) < margin) th = th < kPi / 2 ? kPi / 2 - margin : kPi / 2 + margin;
    thetas.push_back(th);
  }
  thetas.erase(std::unique(thetas.begin(), thetas.end()), thetas.end());
  const double r = model.r;
  SplitFoldCurve out;

  // Far side: the branch through flat from the tangent cone of the symmetric closure system,
  // continued from the flat state along it (flat_branch_continuation.hpp).
  Eigen::VectorXd ray_x;
  double ray_rate = 0.0;
  if (thetas.back() > kPi / 2) {
    out.crosses_flat = true;
    CreasePattern lettered = model.pattern;
    for (int e : options.flipped_letters)
      lettered.assignments[e] = lettered.assignments[e] == Assignment::Mountain ? Assignment::Valley : Assignment::Mountain;
    out.flat_crossing = waterbomb_flat_crossing(lettered, model.load.support_edges, split_fold_motion_classes(n));
    if (out.flat_crossing.continues) {
      const FlatBranch& ray = out.flat_crossing.branches[out.flat_crossing.taken];
      ray_x = model.system.unknowns_from_edges(ray.direction);
      ray_rate = ray.height_rate;
    } else {
      out.stopped_at_flat = true;
      out.stop_message = out.flat_crossing.message;
    }
  }
  HeightControlledEquilibrium sampled;
  FlatBranchContinuation continuation(ray_x, ray_rate, r, SplitFoldCurveOptions::kMaxHeightStep,
                                      SplitFoldCurveOptions::kMaxAngleStep,
                                      [&](double th, const Eigen::VectorXd& start, bool sample) {
                                        sampled = model.loaded_from(r * std::cos(th), start, sample);
                                        return FlatBranchSolve{sampled.converged, sampled.x};
                                      });

  for (double th : thetas) {
    CurveSample c;
    c.theta = th;
    HeightControlledEquilibrium eq;
    if (th > kPi / 2) {
      if (!out.stopped_at_flat && !continuation.failed() && continuation.advance_to(th).converged) eq = sampled;
      if (continuation.failed() && out.stop_message.empty())
        out.stop_message = "the continuation from the flat state did not converge before theta = " +
                           round_trip_text(to_degrees(th)) + " deg";
      if (!eq.converged) {  // no solution on the chosen branch: nothing to check or show
        ++out.unchecked;
        out.samples.push_back(c);
        continue;
      }
    } else {
      eq = model.loaded(th);
    }
    const FoldPair printed = ranged_angles(s, th);
    // dV/dtheta of the printed energy: two Richardson levels on central differences (steps h,
    // h/2, h/4; error O(h^6)), h kept inside the range and on this side of flat.
    const double room = std::min({th - lo, hi - th, std::fabs(th - kPi / 2)});
    const double h = std::min(1e-3, 0.5 * room);
    auto central = [&](double step) {
      return (split_fold_energy(s, th + step) - split_fold_energy(s, th - step)) / (2 * step);
    };
    const double d1 = central(h), d2 = central(h / 2), d4 = central(h / 4);
    const double r1 = (4 * d2 - d1) / 3, r2 = (4 * d4 - d2) / 3;
    const double slope = (16 * r2 - r1) / 15;
    c.force_closed_form = slope / (r * std::sin(th));
    const double gap = eq.converged ? (eq.edge_angles - model.per_edge(printed)).lpNorm<Eigen::Infinity>() : INFINITY;
    c.checked = eq.converged && model.asymmetry(eq.edge_angles) <= SplitFoldBistability::kSymmetryTolerance &&
                gap <= SplitFoldBistability::kPathAgreement &&
                std::fabs(eq.force - c.force_closed_form) <= SplitFoldCurve::kForceAgreement * std::max(1.0, std::fabs(eq.force));
    if (c.checked) {
      c.angles = printed;
      c.energy = eq.energy;
      c.height = r * std::cos(th);
      c.deflection = r * (std::cos(theta0) - std::cos(th));
      c.force = eq.force;
      c.min_eigenvalue = eq.min_eigenvalue;
      c.stable = eq.stable;
    } else {
      c.force = eq.force;  // kept for diagnosis only (tests); not shown by the command
      ++out.unchecked;
    }
    out.samples.push_back(c);
  }
  return out;
}

}  // namespace rigidfold::waterbomb
