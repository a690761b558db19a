#pragma once
// The crease patterns the main job ships in data/bundled/ (written by
// `rigidfold generate bundle --out-dir data/bundled`): name (file stem) and validated pattern.
//   miura_4x4_alpha60          Miura-ori 4x4 panels, alpha 60 deg, a = b = 1
//   miura_3x3_perturbed        Miura-ori 3x3, alpha 60 deg, interior vertices perturbed by
//                              up to 0.05 (seed 7): violates Kawasaki, not flat-foldable
//   miura_tube_6_alpha60       Miura tube, 6 cells, alpha 60 deg, given folded in 3D
//                              (straight creases 90 deg): a sheet with a hole, 1 DOF
//   square_twist_30_type1..4   square twist, twist 30 deg, seed 001 Types 1-4
//                              (Types 3, 4 = seed 003 T1, T2 rigid; Types 1, 2 not)
//   square_twist_30_type1m/2m  seed 001 Types 1M and 2M (diagonal BD added), twist 30 deg
//   waterbomb_base             traditional waterbomb base (n = 4, corner creases M)
//   corrugated_p_rigid         double-corrugated unit P, seed 003's angles, rigid assignment
//   corrugated_q_rigid         double-corrugated unit Q, seed 003's angles, rigid assignment
#include <string>
#include <utility>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

std::vector<std::pair<std::string, CreasePattern>> bundled_examples();

}  // namespace rigidfold::generators
