#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/math/angle_units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rigidfold {
namespace {


// One joint per crease; the seed's per-joint map theta = offset + s * phi in terms of rho.
ThickPattern single_loop(const std::string& name, const std::vector<int>& mountain_valley,
                         const std::vector<double>& seed_offset, const std::vector<double>& seed_sign,
                         const std::vector<double>& twists, const std::vector<double>& lengths) {
  ThickPattern p;
  p.num_creases = static_cast<int>(twists.size());
  ThickLoop loop;
  loop.name = name;
  for (int i = 0; i < p.num_creases; ++i) {
    ThickJoint j;
    j.crease = i;
    j.angle_offset = seed_offset[i] + seed_sign[i] * kPi;  // phi = pi - m rho
    j.angle_sign = -seed_sign[i] * mountain_valley[i];
    j.link.length = lengths[i];
    j.link.twist = twists[i];
    loop.joints.push_back(j);
  }
  p.loops.push_back(loop);
  return p;
}

double half_tan(double phi) { return std::tan(0.5 * phi); }
double from_half_tan(double t) { return 2.0 * std::atan(t); }  // phi in (-pi, pi) for finite t; [0, pi) here
double dihedral(double rho) { return kPi - std::abs(rho); }

}  // namespace

std::vector<double> fold_angles_from_dihedrals(const std::vector<int>& mv, const std::vector<double>& phi) {
  if (mv.size() != phi.size()) throw std::invalid_argument("fold_angles_from_dihedrals: sizes differ");
  std::vector<double> rho(phi.size());
  for (std::size_t i = 0; i < phi.size(); ++i) rho[i] = mv[i] * (kPi - phi[i]);
  return rho;
}

ThickVertexModel bennett_vertex(double alpha12, double alpha23, double thickness) {
  if (!(alpha12 > 0 && alpha12 < alpha23 && alpha23 < kPi && std::abs(alpha12 + alpha23 - kPi) > 1e-12))
    throw std::invalid_argument("bennett_vertex: needs 0 < alpha12 < alpha23 < pi, alpha12 + alpha23 != pi");
  if (!(thickness > 0)) throw std::invalid_argument("bennett_vertex: thickness must be > 0");
  ThickVertexModel m;
  m.name = "Bennett";
  m.sectors = {alpha12, alpha23, kPi - alpha12, kPi - alpha23};
  m.mountain_valley = {+1, -1, -1, -1};
  const double a12 = thickness * std::sin(alpha12), a23 = thickness * std::sin(alpha23);
  // (4-8): theta1 = phi1, theta2 = pi - phi2, theta3 = 2pi - phi3, theta4 = pi + phi4.
  m.thick = single_loop(m.name, m.mountain_valley, {0, kPi, 2 * kPi, kPi}, {1, -1, -1, 1},
                        {alpha12, alpha23, alpha12, alpha23}, {a12, a23, a12, a23});
  return m;
}

ThickVertexModel myard_vertex(double a, double thickness) {
  if (!(a > 0 && a < 0.5 * kPi)) throw std::invalid_argument("myard_vertex: needs 0 < a < pi/2");
  if (!(thickness > 0)) throw std::invalid_argument("myard_vertex: thickness must be > 0");
  ThickVertexModel m;
  m.name = "Myard";
  m.sectors = {a, 0.5 * kPi, kPi - 2 * a, 0.5 * kPi, a};
  m.mountain_valley = {+1, -1, -1, -1, -1};
  // Twists (4-24) with alpha34 = pi - 2 alpha12^My = pi + 2a (mod 2pi) - the printed (4-25a)
  // "2 alpha12^My - pi" has the wrong sign (digest erratum 6); lengths a23 = a12 / sin(alpha12^My).
  const double side = thickness / std::sin(kPi - a);
  // (4-27): theta1 = 2pi - phi1, theta2 = pi - phi2, theta3 = pi + phi3, theta4 = phi4, theta5 = pi + phi5.
  m.thick = single_loop(m.name, m.mountain_valley, {2 * kPi, kPi, kPi, 0, kPi}, {-1, -1, 1, 1, 1},
                        {kPi - a, 0.5 * kPi, kPi + 2 * a, 0.5 * kPi, a}, {thickness, side, 0.0, side, thickness});
  return m;
}

ThickVertexModel diamond_vertex(double a, double t1, double t2) {
  if (!(a > 0 && a <= 0.25 * kPi)) throw std::invalid_argument("diamond_vertex: needs 0 < a <= pi/4");
  if (!(t1 > 0 && t2 > 0)) throw std::invalid_argument("diamond_vertex: t1 and t2 must be > 0");
  ThickVertexModel m;
  m.name = "Bricard diamond";
  m.sectors = {a, kPi - 2 * a, a, a, kPi - 2 * a, a};
  m.mountain_valley = {+1, -1, -1, +1, -1, -1};
  // (4-49): theta1 = 2pi - phi1, theta2 = phi2, theta3 = pi + phi3, theta4 = 2pi - phi4,
  // theta5 = pi + phi5, theta6 = phi6.
  m.thick = single_loop(m.name, m.mountain_valley, {2 * kPi, 0, kPi, 2 * kPi, kPi, 0}, {-1, 1, 1, -1, 1, 1},
                        {2 * kPi - a, kPi - 2 * a, a, 2 * kPi - a, kPi + 2 * a, a}, {t1, t2, t1 + t2, t1 + t2, t2, t1});
  return m;
}

ThickVertexModel waterbomb_vertex(double mu, double thickness) {
  if (!(mu > 0)) throw std::invalid_argument("waterbomb_vertex: mu must be > 0");
  if (!(thickness > 0)) throw std::invalid_argument("waterbomb_vertex: thickness must be > 0");
  ThickVertexModel m;
  m.name = "Bricard waterbomb";
  const double q = 0.25 * kPi;
  m.sectors = {2 * q, q, q, q, q, 2 * q};
  m.mountain_valley = {-1, -1, +1, -1, +1, -1};
  const double t = thickness;
  // (4-59): theta1 = phi1, theta2 = pi + phi2, theta3 = 2pi - phi3, theta4 = phi4,
  // theta5 = 2pi - phi5, theta6 = pi + phi6.
  m.thick = single_loop(m.name, m.mountain_valley, {0, kPi, 2 * kPi, 0, 2 * kPi, kPi}, {1, 1, -1, 1, -1, 1},
                        {2 * q, q, 2 * kPi - q, q, 2 * kPi - q, 2 * kPi - 2 * q},
                        {t * (1 + mu), t, t * mu, t * mu, t, t * (1 + mu)});
  return m;
}

std::vector<double> bennett_zero_thickness(double alpha12, double alpha23, double rho0) {
  const double phi1 = dihedral(rho0);
  const double phi2 = from_half_tan(half_tan(phi1) * std::sin(0.5 * (alpha23 - alpha12)) / std::sin(0.5 * (alpha12 + alpha23)));
  return fold_angles_from_dihedrals({+1, -1, -1, -1}, {phi1, phi2, phi1, phi2});
}

std::vector<double> myard_zero_thickness(double a, double rho0) {
  const double phi1 = dihedral(rho0);
  const double phi3 = 0.5 * (kPi + phi1);
  const double phi2 = from_half_tan(half_tan(phi3) * (1 - std::sin(a)) / std::cos(a));
  return fold_angles_from_dihedrals({+1, -1, -1, -1, -1}, {phi1, phi2, phi3, phi3, phi2});
}

std::vector<double> diamond_zero_thickness(double a, double rho0) {
  const double phi1 = dihedral(rho0);
  const double phi2 = from_half_tan(std::cos(a) * half_tan(phi1));
  return fold_angles_from_dihedrals({+1, -1, -1, +1, -1, -1}, {phi1, phi2, phi2, phi1, phi2, phi2});
}

std::vector<double> waterbomb_zero_thickness(double rho0) {
  const double phi1 = dihedral(rho0);
  const double T = half_tan(phi1);
  const double phi2 = from_half_tan(0.5 * T), phi3 = from_half_tan(T / std::sqrt(2.0));
  const double phi4 = from_half_tan(T * T * T / (4 + 3 * T * T));
  return fold_angles_from_dihedrals({-1, -1, +1, -1, +1, -1}, {phi1, phi2, phi3, phi4, phi3, phi2});
}

}  // namespace rigidfold
