#include "data/generators/bundled_examples.hpp"

#include "data/generators/double_corrugated.hpp"
#include "data/generators/generator_common.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/miura_tube.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::generators {

std::vector<std::pair<std::string, CreasePattern>> bundled_examples() {
  std::vector<std::pair<std::string, CreasePattern>> out;
  MiuraParams miura;
  miura.rows = miura.cols = 4;
  miura.alpha = to_radians(60);
  out.emplace_back("miura_4x4_alpha60", miura_ori(miura));
  // A larger Miura-ori carrying its closed-form folded state (straight creases at 100 deg),
  // so the report shows a folded sheet and the closure mismatch of the closed form.
  MiuraParams folded = miura;
  folded.rows = folded.cols = 12;
  CreasePattern folded_miura = miura_ori(folded);
  folded_miura.fold_angles = miura_fold_angles(folded_miura, folded, to_radians(100));
  folded_miura.extra["file_title"] = "Miura-ori 12x12, alpha 60 deg, folded (straight creases 100 deg)";
  out.emplace_back("miura_12x12_folded", std::move(folded_miura));
  MiuraParams perturbed;
  perturbed.rows = perturbed.cols = 3;
  perturbed.alpha = to_radians(60);
  perturbed.perturbation = 0.05;
  perturbed.seed = 7;
  out.emplace_back("miura_3x3_perturbed", miura_ori(perturbed));

  // A sheet with a hole: two mirrored Miura strips bonded into a tube, given folded in 3D
  // (straight creases at 90 deg); checked from that state with the SE(3) hole closure.
  MiuraTubeParams tube;
  tube.rows = 6;
  tube.alpha = to_radians(60);
  out.emplace_back("miura_tube_6_alpha60", miura_tube(tube));

  SquareTwistParams twist;
  twist.twist = to_radians(30);
  for (auto type : {SquareTwistType::Type1, SquareTwistType::Type2, SquareTwistType::Type3, SquareTwistType::Type4})
    out.emplace_back(std::string("square_twist_30_") + to_string(type), square_twist(twist, type));
  for (auto type : {SquareTwistModifiedType::Type1M, SquareTwistModifiedType::Type2M})
    out.emplace_back(std::string("square_twist_30_") + to_string(type), square_twist_modified(twist, type));

  out.emplace_back("waterbomb_base", waterbomb_base(WaterbombParams{}));

  const CorrugatedParams corrugated;  // seed 003's alpha = 135, beta = 60 deg
  out.emplace_back("corrugated_p_rigid",
                   corrugated_unit(CorrugatedUnit::P, corrugated, corrugated_rigid_assignment(CorrugatedUnit::P)));
  out.emplace_back("corrugated_q_rigid",
                   corrugated_unit(CorrugatedUnit::Q, corrugated, corrugated_rigid_assignment(CorrugatedUnit::Q)));
  return out;
}

}  // namespace rigidfold::generators
