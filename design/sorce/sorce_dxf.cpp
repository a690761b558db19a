#include "design/sorce/sorce_dxf.hpp"

#include <algorithm>
#include <cctype>

#include "kernel/pattern/dxf_document.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

std::string fold_profiles_dxf(const std::vector<NamedFold>& folds, int samples) {
  if (samples < 2) throw InputError("samples", "need at least 2 points per profile");
  DxfDocument doc;
  for (std::size_t k = 0; k < folds.size(); ++k) {
    const std::string& name = folds[k].name;
    const bool legal = !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
      return std::isalnum(c) || c == '_' || c == '-';
    });
    if (!legal)
      throw InputError("folds[" + std::to_string(k) + "].name", "a layer prefix needs letters, digits, '_' or '-' only");
    doc.add_layer(name + "_LEFT", 5);
    doc.add_layer(name + "_RIGHT", 1);
    doc.add_layer(name + "_SLAB", 8);
  }
  for (const NamedFold& f : folds) {
    const SampledProfiles p = sample_profiles(f.motion, samples);
    doc.polyline(f.name + "_LEFT", p.left);
    doc.polyline(f.name + "_RIGHT", p.right);
    // Slab faces: each panel's from its far profile extent back to the fold line.
    double x_min = 0.0, x_max = 0.0;
    for (const Vec2& q : p.left) x_min = std::min(x_min, q.x());
    for (const Vec2& q : p.right) x_max = std::max(x_max, q.x());
    const double reach = std::max({x_max - x_min, f.motion.thickness_left, f.motion.thickness_right});
    for (double sgn : {1.0, -1.0}) {
      if (f.motion.thickness_left > 0.0)
        doc.line(f.name + "_SLAB", Vec2(x_min - reach, sgn * f.motion.thickness_left / 2), Vec2(0.0, sgn * f.motion.thickness_left / 2));
      if (f.motion.thickness_right > 0.0)
        doc.line(f.name + "_SLAB", Vec2(0.0, sgn * f.motion.thickness_right / 2), Vec2(x_max + reach, sgn * f.motion.thickness_right / 2));
    }
  }
  return doc.text();
}

}  // namespace rigidfold::sorce
