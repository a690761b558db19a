#pragma once
// The thick-panel vertices of seed 003 ch. 4 (docs/REFERENCES.md (seed 003); its corrections
// in docs/errata.md): a zero-thickness vertex and the overconstrained spatial linkage whose
// panel thicknesses make it fold with the same fold angles.
//
//   Bennett (4 creases, flat-foldable: alpha_34 = pi - alpha_12, alpha_41 = pi - alpha_23)
//       twists (a12, a23, a12, a23), lengths t (sin a12, sin a23, sin a12, sin a23)  (4-3, 4-4)
//   Myard (5 creases: a, pi/2, pi - 2a, pi/2, a)
//       twists (pi - a, pi/2, pi + 2a, pi/2, a), lengths t (1, 1/sin a, 0, 1/sin a, 1)  (4-24, 4-25 corrected)
//   Diamond, plane-symmetric Bricard (6 creases: a, pi - 2a, a, a, pi - 2a, a; 0 < a <= pi/4)
//       twists (2pi - a, pi - 2a, a, 2pi - a, pi + 2a, a), lengths (t1, t2, t1+t2, t1+t2, t2, t1)  (4-40, 4-41)
//   Waterbomb, plane-symmetric Bricard (6 creases: pi/2, pi/4, pi/4, pi/4, pi/4, pi/2)
//       twists (pi/2, pi/4, 7pi/4, pi/4, 7pi/4, 3pi/2), lengths t (1+mu, 1, mu, mu, 1, 1+mu)  (4-55, 4-57);
//       mu = 1 (4-60, 4-61) keeps the zero-thickness motion.
// Every offset d_i (seed R_i) is 0. Twist and length k belong to the link after joint k
// (creases numbered from 0 here; the seed's joint k+1).
//
// Fold angles: kernel convention (radians, > 0 valley, < 0 mountain). Each model fixes the
// mountain-valley assignment of the branch it models (mountain_valley: +1 valley, -1
// mountain), and the seed's per-joint maps theta = offset + s * phi with the dihedral
// phi = pi - |rho| (4-8, 4-27, 4-49, 4-59) become theta = offset + s*pi - s*m*rho.
//
// Units: angles in radians; thicknesses and link lengths in pattern units.
#include <string>
#include <vector>

#include "kernel/thick/thick_pattern.hpp"

namespace rigidfold {

struct ThickVertexModel {
  std::string name;
  std::vector<double> sectors;        // zero-thickness sector angles, sector i between crease i and i+1 (radians)
  std::vector<int> mountain_valley;   // per crease: +1 valley, -1 mountain, on the modelled branch
  ThickPattern thick;                 // one loop, joint i on crease i
};

// Bennett model of the flat-foldable degree-4 vertex with sectors (alpha12, alpha23,
// pi - alpha12, pi - alpha23). Needs 0 < alpha12 < alpha23 < pi and alpha12 + alpha23 != pi
// (crease 0 is then the valley, creases 1..3 mountains: branch S of eq. 3-3a);
// thickness > 0 scales the link lengths (a12 = thickness * sin alpha12).
ThickVertexModel bennett_vertex(double alpha12, double alpha23, double thickness);

// Myard model of the symmetric degree-5 vertex with sectors (a, pi/2, pi - 2a, pi/2, a),
// 0 < a < pi/2 (crease 0 valley, creases 1..4 mountains); a12 = a51 = thickness.
ThickVertexModel myard_vertex(double a, double thickness);

// Plane-symmetric Bricard model of the diamond vertex (a, pi - 2a, a, a, pi - 2a, a),
// 0 < a <= pi/4 (creases 0 and 3 valleys, the others mountains); a12 = a61 = t1,
// a23 = a56 = t2 (> 0), a34 = a45 = t1 + t2 (4-41c).
ThickVertexModel diamond_vertex(double a, double t1, double t2);

// Plane-symmetric Bricard model of the waterbomb vertex (pi/2, pi/4, pi/4, pi/4, pi/4, pi/2)
// (creases 2 and 4 valleys, the others mountains), link lengths thickness * (1+mu, 1, mu,
// mu, 1, 1+mu), mu > 0. Only mu = 1 keeps the zero-thickness motion (4-60).
ThickVertexModel waterbomb_vertex(double mu, double thickness);

// Zero-thickness fold angles (kernel convention) of each modelled branch from the fold
// angle rho0 of crease 0 (radians, with the sign of mountain_valley[0], |rho0| <= pi).
// These are the digest's relations, in dihedral form phi = pi - |rho|:
//   Bennett (4-7):   phi3 = phi1, phi4 = phi2, tan(phi2/2) = tan(phi1/2) sin((a23-a12)/2)/sin((a12+a23)/2)
//   Myard (4-23, corrected; digest [D]): phi3 = phi4 = (pi + phi1)/2, tan(phi2/2) = tan(phi3/2)(1 - sin a)/cos a, phi5 = phi2
//   Diamond (4-39):  phi4 = phi1, tan(phi2/2) = cos a tan(phi1/2), phi3 = phi5 = phi6 = phi2
//   Waterbomb (4-54): T = tan(phi1/2): tan(phi2/2) = T/2, tan(phi3/2) = T/sqrt(2),
//                     tan(phi4/2) = T^3/(4 + 3T^2), phi5 = phi3, phi6 = phi2
std::vector<double> bennett_zero_thickness(double alpha12, double alpha23, double rho0);
std::vector<double> myard_zero_thickness(double a, double rho0);
std::vector<double> diamond_zero_thickness(double a, double rho0);
std::vector<double> waterbomb_zero_thickness(double rho0);

// Fold angles from dihedral angles: rho_i = m_i (pi - phi_i), m = mountain_valley.
std::vector<double> fold_angles_from_dihedrals(const std::vector<int>& mountain_valley, const std::vector<double>& phi);

}  // namespace rigidfold
