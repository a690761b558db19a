#include "design/metamaterial/metamaterial_request.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::metamaterial {
namespace {

// The defaults of the fields not given (docs/cli/metamaterial.md).
constexpr double kSquareTwistAlphaDeg = 150.0;  // the seed's 5 pi / 6
constexpr double kElementAlphaDeg = 60.0;       // elements and stacks
constexpr double kBetaDeg = 70.0;
constexpr int kCrossCheckSteps = 40;

// The caller's name of a request field, for the place and the text of an InputError.
class FieldNamer {
 public:
  explicit FieldNamer(FieldNaming naming) : flags_(naming == FieldNaming::kCommandLineFlags) {}
  // "cross_check_steps" -> "--cross-check-steps" (flags) or "cross_check_steps" (keywords).
  std::string operator()(std::string field) const {
    if (!flags_) return field;
    std::replace(field.begin(), field.end(), '_', '-');
    return "--" + field;
  }
  // A field with a value: "--unit square-twist" (flags) or "unit=square-twist" (keywords).
  std::string with_value(const std::string& field, const std::string& value) const {
    return (*this)(field) + (flags_ ? " " : "=") + value;
  }

 private:
  bool flags_;
};

void require_finite(const FieldNamer& name, const char* field, double value) {
  if (!std::isfinite(value)) throw InputError(name(field), "must be a finite number");
}

// The stack's parameters, every field checked in the order the CLI always checked them (the
// first bad field is the one named).
generators::StackedMetamaterialParams checked_stack_params(const MetamaterialRequest& r, const FieldNamer& name,
                                                           StackedMetamaterialOptions* options) {
  if (!r.unit.empty()) throw InputError(name("unit"), "give either " + name("unit") + " or " + name("stacked") + ", not both");
  const std::pair<const char*, bool> unit_fields[] = {{"a", r.a.has_value()},
                                                      {"b", r.b.has_value()},
                                                      {"c", r.c.has_value()},
                                                      {"samples", r.samples.has_value()},
                                                      {"plot", r.plot.has_value()},
                                                      {"cross_check", r.cross_check.has_value()},
                                                      {"cross_check_steps", r.cross_check_steps.has_value()}};
  for (const auto& [field, given] : unit_fields)
    if (given) throw InputError(name(field), "does not apply to " + name("stacked"));
  const int stacked = *r.stacked;
  if (stacked < 1 || stacked > 4) throw InputError(name("stacked"), "must be 1, 2, 3 or 4, got " + std::to_string(stacked));
  options->layers = r.layers.value_or(4);
  options->steps = r.stacked_steps.value_or(24);
  if (options->layers < 2 || options->layers > 16)
    throw InputError(name("layers"), "must be between 2 and 16, got " + std::to_string(options->layers));
  if (options->steps < 8 || options->steps > 200)
    throw InputError(name("stacked_steps"), "must be between 8 and 200, got " + std::to_string(options->steps));
  const double alpha_deg = r.alpha_deg.value_or(kElementAlphaDeg);
  const double beta_deg = r.beta_deg.value_or(kBetaDeg);
  const double l = r.l.value_or(1.0);
  for (const auto& [field, v] : {std::pair<const char*, double>{"alpha_deg", alpha_deg}, {"beta_deg", beta_deg}})
    if (!(std::isfinite(v) && v > 0 && v < 180)) throw InputError(name(field), "must lie strictly between 0 and 180 degrees");
  if (!(std::isfinite(l) && l > 0)) throw InputError(name("l"), "must be a finite number > 0");
  generators::StackedMetamaterialParams params;
  params.metamaterial = stacked;
  params.alpha = to_radians(alpha_deg);
  params.beta = to_radians(beta_deg);
  params.l = l;
  if (stacked == 4 && std::fabs(std::cos((params.alpha + params.beta) / 2)) <= 1e-6)
    throw InputError(name("beta_deg"), "metamaterial 4 needs alpha + beta != 180 degrees (element 3 is locked there)");
  return params;
}

StackedMetamaterialRun run_stacked(const MetamaterialRequest& r, const FieldNamer& name) {
  StackedMetamaterialOptions options;
  const generators::StackedMetamaterialParams params = checked_stack_params(r, name, &options);
  StackedMetamaterialRun run;
  run.alpha_deg = r.alpha_deg.value_or(kElementAlphaDeg);
  run.beta_deg = r.beta_deg.value_or(kBetaDeg);
  // Checked inside: NoAnswerError before anything is returned.
  run.check = stacked_metamaterial_check(params, options);
  return run;
}

MetamaterialUnit checked_unit(const MetamaterialRequest& r, const FieldNamer& name) {
  if (r.unit.empty()) throw InputError(name("unit"), "is required (or " + name.with_value("stacked", "1..4") + ")");
  for (const auto& [field, given] : {std::pair<const char*, bool>{"layers", r.layers.has_value()},
                                     {"stacked_steps", r.stacked_steps.has_value()}})
    if (given) throw InputError(name(field), "applies only with " + name("stacked"));
  if (r.unit == "square-twist") return MetamaterialUnit::kSquareTwist;
  if (r.unit == "element1") return MetamaterialUnit::kElement1;
  if (r.unit == "element2") return MetamaterialUnit::kElement2;
  if (r.unit == "element3") return MetamaterialUnit::kElement3;
  if (r.unit == "P" || r.unit == "Q")
    throw InputError(name("unit"), r.unit + ": the seed gives dimension closed forms for the elements of the P/Q "
                                            "tessellations, not for a unit alone: use element1, element2 or element3");
  throw InputError(name("unit"), "'" + r.unit + "' is not square-twist, element1, element2 or element3");
}

// The cross-check traces a tessellation, which needs more of b and c than the unit alone.
void check_cross_check_fields(const MetamaterialRequest& r, const FieldNamer& name, const SquareTwistUnitParams& twist) {
  if (r.cross_check_steps && !r.cross_check.value_or(false))
    throw InputError(name("cross_check_steps"), "applies only with " + name("cross_check"));
  if (!r.cross_check.value_or(false)) return;
  const double least = square_twist_cross_check_min_offset(twist.alpha, twist.a);
  for (const auto& [field, v] : {std::pair<const char*, double>{"b", twist.b}, {"c", twist.c}})
    if (!(v > least * (1 + 1e-9)))
      throw InputError(name(field), name("cross_check") + " traces a tessellation whose pleat creases between twists "
                                                          "need it > -a cos(alpha) = " + std::to_string(least));
  const int steps = r.cross_check_steps.value_or(kCrossCheckSteps);
  if (steps < 10 || steps > 2000)
    throw InputError(name("cross_check_steps"), "must be between 10 and 2000, got " + std::to_string(steps));
}

SquareTwistUnitParams checked_square_twist(const MetamaterialRequest& r, const FieldNamer& name) {
  for (const auto& [field, given] : {std::pair<const char*, bool>{"beta_deg", r.beta_deg.has_value()}, {"l", r.l.has_value()}})
    if (given) throw InputError(name(field), "applies to the elements, not to " + name.with_value("unit", "square-twist"));
  const double alpha_deg = r.alpha_deg.value_or(kSquareTwistAlphaDeg);
  require_finite(name, "alpha_deg", alpha_deg);
  if (!(alpha_deg > 90 && alpha_deg < 180))
    throw InputError(name("alpha_deg"), std::to_string(alpha_deg) + " is outside (90, 180) degrees");
  SquareTwistUnitParams twist;
  twist.alpha = to_radians(alpha_deg);
  twist.a = r.a.value_or(1.0);
  twist.b = r.b.value_or(1.0);
  twist.c = r.c.value_or(1.0);
  require_finite(name, "a", twist.a);
  require_finite(name, "b", twist.b);
  require_finite(name, "c", twist.c);
  if (!(twist.a > 0)) throw InputError(name("a"), "must be > 0");
  // Lengths over the whole motion (theta, phi -> pi): 2c, 2b > a (sin alpha - cos alpha).
  const double need = twist.a * (std::sin(twist.alpha) - std::cos(twist.alpha));
  for (const auto& [field, offset, side] : {std::tuple<const char*, double, const char*>{"b", twist.b, "S"}, {"c", twist.c, "L"}})
    if (!(2 * offset > need))
      throw InputError(name(field), "must exceed a (sin alpha - cos alpha) / 2 = " + std::to_string(need / 2) + " so that " +
                                        side + " > 0 over the motion");
  check_cross_check_fields(r, name, twist);
  return twist;
}

CorrugatedElementParams checked_element(const MetamaterialRequest& r, const FieldNamer& name, MetamaterialUnit unit) {
  const std::string square_twist = name.with_value("unit", "square-twist");
  if (r.cross_check.value_or(false))
    throw InputError(name("cross_check"), "applies to " + square_twist + " (the elements have no traced tessellation here)");
  if (r.cross_check_steps) throw InputError(name("cross_check_steps"), "applies to " + square_twist + " with " + name("cross_check"));
  for (const auto& [field, given] : {std::pair<const char*, bool>{"a", r.a.has_value()}, {"b", r.b.has_value()}, {"c", r.c.has_value()}})
    if (given) throw InputError(name(field), "applies to " + square_twist + ", not to the elements");
  const double alpha_deg = r.alpha_deg.value_or(kElementAlphaDeg);
  const double beta_deg = r.beta_deg.value_or(kBetaDeg);
  const double l = r.l.value_or(1.0);
  require_finite(name, "alpha_deg", alpha_deg);
  require_finite(name, "beta_deg", beta_deg);
  require_finite(name, "l", l);
  if (!(alpha_deg > 0 && alpha_deg < 180)) throw InputError(name("alpha_deg"), std::to_string(alpha_deg) + " is outside (0, 180) degrees");
  if (!(beta_deg > 0 && beta_deg < 180)) throw InputError(name("beta_deg"), std::to_string(beta_deg) + " is outside (0, 180) degrees");
  if (!(l > 0)) throw InputError(name("l"), "must be > 0");
  CorrugatedElementParams element;
  element.alpha = to_radians(alpha_deg);
  element.beta = to_radians(beta_deg);
  element.l = l;
  if (unit == MetamaterialUnit::kElement3 && std::fabs(std::cos((element.beta + element.alpha) / 2)) < 1e-12)
    throw InputError(name("beta_deg"), "element3 with alpha + beta = 180 degrees is locked ((3-26) pins theta at 0)");
  return element;
}

MetamaterialParams checked_unit_params(const MetamaterialRequest& r, const FieldNamer& name) {
  MetamaterialParams params;
  params.unit = checked_unit(r, name);
  if (params.unit == MetamaterialUnit::kSquareTwist)
    params.square_twist = checked_square_twist(r, name);
  else
    params.element = checked_element(r, name, params.unit);
  params.samples = r.samples.value_or(181);
  if (params.samples < 3 || params.samples > 100000)
    throw InputError(name("samples"), "must be between 3 and 100000, got " + std::to_string(params.samples));
  return params;
}

MetamaterialUnitRun run_unit(const MetamaterialRequest& r, const FieldNamer& name) {
  MetamaterialUnitRun run;
  run.params = checked_unit_params(r, name);
  // The plot files are declared before any work, so that a clash or an unwritable directory
  // is refused at once; they are written only after every check below passed.
  OutputSet outputs;
  const std::string plot_directory = r.plot.value_or("");
  if (!plot_directory.empty()) {
    outputs.add_output_directory(name("plot"), plot_directory);
    const std::string dir = plot_directory.back() == '/' ? plot_directory : plot_directory + "/";
    run.plot_files = {dir + "metamaterial.csv", dir + "dimensions.svg", dir + "poisson.svg"};
    for (const std::string& path : run.plot_files) outputs.add_output(name("plot"), path);
  }
  // Every row passed its checks in metamaterial_table (else NoAnswerError).
  run.table = metamaterial_table(run.params);
  // Checked inside (every difference <= kCrossCheckTolerance, else NoAnswerError).
  if (r.cross_check.value_or(false)) {
    SquareTwistCrossCheckOptions options;
    options.steps = r.cross_check_steps.value_or(kCrossCheckSteps);
    run.cross_check = square_twist_cross_check(run.params.square_twist, options);
  }
  if (!run.plot_files.empty()) {
    outputs.stage(run.plot_files[0], metamaterial_csv(run.table));
    outputs.stage(run.plot_files[1], metamaterial_dimensions_svg(run.table));
    outputs.stage(run.plot_files[2], metamaterial_ratios_svg(run.table));
  }
  outputs.commit();
  return run;
}

}  // namespace

MetamaterialRun run_metamaterial(const MetamaterialRequest& request) {
  const FieldNamer name(request.naming);
  MetamaterialRun run;
  if (request.stacked)
    run.stacked = run_stacked(request, name);
  else
    run.unit = run_unit(request, name);
  return run;
}

}  // namespace rigidfold::metamaterial
