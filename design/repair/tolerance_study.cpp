#include "design/repair/tolerance_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include "design/repair/pattern_repair.hpp"
#include "kernel/analysis/flat_fold_constraints.hpp"
#include "kernel/geometry/flat_development.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {
namespace {

// One error of the distribution, in units of sigma.
double unit_error(SplitMix64& rng, ErrorDistribution d) {
  if (d == ErrorDistribution::kUniform) return 2 * rng.uniform() - 1;
  // Box-Muller on (0, 1) uniforms (no log of 0).
  const double u1 = rng.open_uniform(), u2 = rng.open_uniform();
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * kPi * u2);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The loops of the multiplier model in the design's modes, where the repair's model applies.
std::optional<FlatFoldConstraints> loop_constraints(const CreasePattern& pattern, const Topology& topology) {
  try {
    require_repair_scope(pattern, topology);
  } catch (const InputError&) {
    return std::nullopt;
  }
  int chosen = 0;
  std::string refusal;
  std::vector<FlatFoldMode> modes = repair_modes(pattern, topology, chosen, refusal);
  if (!refusal.empty() || modes.empty()) return std::nullopt;
  FlatFoldConstraints c(pattern, topology, std::move(modes));
  if (!c.gains_usable()) return std::nullopt;
  return c;
}

}  // namespace

const char* to_string(ErrorDistribution d) { return d == ErrorDistribution::kGaussian ? "gaussian" : "uniform"; }

bool ToleranceStudyOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& why) {
    if (error) *error = why;
    return false;
  };
  if (!(std::isfinite(sigma) && sigma > 0)) return fail("sigma must be finite and > 0");
  if (samples < 1 || samples > 100000) return fail("samples must lie in 1 .. 100000");
  return true;
}

ToleranceStudy tolerance_study(const CreasePattern& given, const Topology& given_topology, const ToleranceStudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (std::string why; !options.IsValid(&why)) throw InputError("tolerance study", why);
  // A folded form is studied on the crease pattern it folds from (InputError where none exists).
  const FlatDevelopment development = flat_development(given, "the tolerance study's pattern");
  const CreasePattern& pattern = development.pattern;
  const Topology topology = development.unfolded ? build_topology(pattern, "flat development") : given_topology;
  ToleranceStudy out;
  out.on_flat_development = development.unfolded;
  out.samples = options.samples;
  const double sigma = std::ldexp(options.sigma, -pattern.length_exponent);  // in the stored units
  FoldabilityOptions check = options.check;
  check.use_assignment = true;
  check.coordinate_tolerance = 0.0;
  const std::optional<FlatFoldConstraints> loops = loop_constraints(pattern, topology);
  out.degree4_model = loops.has_value();
  Eigen::VectorXd gain_sum = Eigen::VectorXd::Zero(loops ? loops->gain_rows() : 0);
  std::vector<double> repair_moves;
  SplitMix64 rng{options.seed};
  for (int s = 0; s < options.samples; ++s) {
    CreasePattern moved = pattern;
    moved.position_bounds = {};
    for (Eigen::Vector3d& v : moved.vertices) {
      v.x() += sigma * unit_error(rng, options.distribution);
      v.y() += sigma * unit_error(rng, options.distribution);
    }
    Topology moved_topology;
    try {
      moved_topology = build_topology(moved, "sample " + std::to_string(s));
    } catch (const InputError&) {
      ++out.verdicts["no pattern (the errors made creases cross)"];
      continue;
    }
    const FoldabilityReport r = check_foldability(moved, moved_topology, check);
    ++out.verdicts[to_string(r.verdict)];
    if (r.verdict == FoldabilityClass::kFoldable) ++out.foldable;
    if (!loops) continue;
    Eigen::VectorXd values;
    loops->evaluate(moved.vertices, values, nullptr);
    gain_sum += values.tail(loops->gain_rows()).cwiseAbs();
    if (!options.with_repair) continue;
    RepairOptions repair;
    repair.check = check;
    const RepairSummary fixed = repair_pattern(moved, moved_topology, repair);
    if (fixed.termination == RepairTermination::kRepaired) repair_moves.push_back(fixed.rms_move / options.sigma);
  }
  // The 95% Wilson score interval of the fraction.
  const double n = options.samples, p = out.foldable / n, z = 1.959963984540054;
  out.fraction = p;
  const double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n);
  out.interval_low = std::max(0.0, centre - half);
  out.interval_high = std::min(1.0, centre + half);
  if (loops) {
    for (int c = 0; c < loops->gain_rows(); ++c) out.loops.push_back({loops->cycle_vertices(c), gain_sum[c] / n});
    std::stable_sort(out.loops.begin(), out.loops.end(), [](const LoopSensitivity& a, const LoopSensitivity& b) { return a.mean_log_gain > b.mean_log_gain; });
    if (out.loops.size() > 10) out.loops.resize(10);
  }
  out.repairs = static_cast<int>(repair_moves.size());
  out.repair_move_median = median(repair_moves);
  out.repair_move_max = repair_moves.empty() ? 0.0 : *std::max_element(repair_moves.begin(), repair_moves.end());
  std::ostringstream msg;
  msg << out.foldable << " of " << out.samples << " samples fold with their letters (" << to_string(options.distribution)
      << " error, sigma " << options.sigma << "): fraction " << out.fraction << ", 95% interval [" << out.interval_low << ", "
      << out.interval_high << "]" << (out.on_flat_development ? " (on the flat pattern the folded form unfolds to)" : "");
  out.message = msg.str();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace rigidfold
