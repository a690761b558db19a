// rigidfold generate KIND [options] --out FILE.fold
// rigidfold generate bundle --out-dir DIR
//
// KIND: miura | miura-tube | square-twist | square-twist-tessellation | waterbomb | corrugated-p | corrugated-q | resch-triangle, or `bundle` to write
// every pattern of bundled_examples() as DIR/NAME.fold. Angles are given in degrees.
// A flag that does not apply to KIND, or a bad value, is an InputError naming the flag.
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "app/commands.hpp"
#include "app/summary_stream.hpp"
#include "data/generators/bundled_examples.hpp"
#include "data/generators/double_corrugated.hpp"
#include "data/generators/generator_common.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/miura_tube.hpp"
#include "data/generators/resch_triangle.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/square_twist_tessellation.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {
namespace {

namespace gen = rigidfold::generators;

struct GenerateOptions {
  std::string kind;
  std::string out, out_dir;
  int rows = 4, cols = 4;
  std::optional<double> alpha_deg;  // default per kind: Miura 60, corrugated 135
  double beta_deg = 60;
  double a = 1, b = 1;
  double perturb = 0;
  std::int64_t seed = 1;  // read signed so that a negative value is an error, not a wrap-around
  double fold_deg = 0;
  double twist_deg = 30;
  std::string type = "3";
  std::string assignment;
  std::string diagonal = "none";
  double side = 1, pleat = 1;
  double spacing = 2.5;
  std::string layout = "type4";
  int n = 4;
  double radius = 1;
  std::string corners = "M";
  std::string odd;
};

// Flags each kind accepts (besides --out).
const std::map<std::string, std::set<std::string>>& accepted_flags() {
  static const std::map<std::string, std::set<std::string>> m{
      {"miura", {"--rows", "--cols", "--alpha-deg", "--a", "--b", "--perturb", "--seed", "--fold-deg"}},
      {"miura-tube", {"--rows", "--alpha-deg", "--a", "--b", "--fold-deg"}},
      {"square-twist", {"--twist-deg", "--type", "--assignment", "--diagonal", "--side", "--pleat"}},
      {"square-twist-tessellation", {"--rows", "--cols", "--twist-deg", "--side", "--spacing", "--layout"}},
      {"waterbomb", {"--n", "--radius", "--corners"}},
      {"corrugated-p", {"--alpha-deg", "--beta-deg", "--a", "--b", "--assignment", "--odd"}},
      {"corrugated-q", {"--alpha-deg", "--beta-deg", "--a", "--b", "--assignment", "--odd"}},
      {"resch-triangle", {"--rows", "--cols", "--side"}},
      {"bundle", {}},
  };
  return m;
}

// Library parameter name (InputError::place) -> flag.
std::string flag_for(const std::string& place) {
  static const std::map<std::string, std::string> common{
      {"rows", "--rows"}, {"cols", "--cols"}, {"alpha", "--alpha-deg"}, {"beta", "--beta-deg"},
      {"a", "--a"}, {"b", "--b"}, {"perturbation", "--perturb"}, {"twist", "--twist-deg"},
      {"side", "--side"}, {"pleat", "--pleat"}, {"assignment", "--assignment"}, {"diagonal", "--diagonal"},
      {"sides", "--type"}, {"fold", "--fold-deg"}, {"spacing", "--spacing"}, {"layout", "--layout"}, {"n", "--n"}, {"radius", "--radius"}, {"odd_joint", "--odd"}};
  auto it = common.find(place);
  return it == common.end() ? place : it->second;
}

// Re-throws a generator's InputError with the flag as its place.
template <class F>
auto with_flags(F&& make) {
  try {
    return make();
  } catch (const InputError& e) {
    std::string what = e.what();
    const std::string prefix = e.place() + ": ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw InputError(flag_for(e.place()), what);
  }
}

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

CreasePattern make_miura_tube(const GenerateOptions& o, bool fold_given) {
  gen::MiuraTubeParams p;
  p.rows = o.rows;
  p.alpha = to_radians(o.alpha_deg.value_or(60));
  p.a = o.a;
  p.b = o.b;
  p.fold = to_radians(fold_given ? o.fold_deg : 90.0);
  return with_flags([&] { return gen::miura_tube(p); });
}

CreasePattern make_square_twist_tessellation(const GenerateOptions& o) {
  gen::SquareTwistTessellationParams p;
  p.rows = o.rows;
  p.cols = o.cols;
  p.twist = to_radians(o.twist_deg);
  p.side = o.side;
  p.spacing = o.spacing;
  return with_flags([&] {
    p.layout = gen::square_twist_tessellation_layout_from_string(o.layout);
    return gen::square_twist_tessellation(p);
  });
}

CreasePattern make_miura(const GenerateOptions& o, bool folded) {
  gen::MiuraParams p;
  p.rows = o.rows;
  p.cols = o.cols;
  p.alpha = to_radians(o.alpha_deg.value_or(60));
  p.a = o.a;
  p.b = o.b;
  p.perturbation = o.perturb;
  if (o.seed < 0) throw InputError("--seed", "must be a non-negative integer");
  p.seed = static_cast<std::uint64_t>(o.seed);
  CreasePattern pattern = with_flags([&] { return gen::miura_ori(p); });
  if (folded) {
    if (o.perturb != 0) throw InputError("--fold-deg", "the closed-form fold exists only for the unperturbed Miura-ori (--perturb 0)");
    if (!(std::fabs(o.fold_deg) <= 180)) throw InputError("--fold-deg", "must lie in [-180, 180]");
    pattern.fold_angles = gen::miura_fold_angles(pattern, p, to_radians(o.fold_deg));
    pattern.fold_angles_in_file = true;
    pattern.extra["frame_title"] = pattern.extra["frame_title"].get<std::string>() +
                                   "; edges_foldAngle: closed-form rigid fold, straight creases " +
                                   std::to_string(o.fold_deg) + " deg";
  }
  return pattern;
}

CreasePattern make_square_twist(const GenerateOptions& o, bool explicit_assignment, bool diagonal_given, bool type_given) {
  gen::SquareTwistParams p;
  p.twist = to_radians(o.twist_deg);
  p.side = o.side;
  p.pleat = o.pleat;
  const std::string d = upper(o.diagonal);
  if (d == "NONE") p.diagonal = gen::SquareTwistDiagonal::None;
  else if (d == "BD") p.diagonal = gen::SquareTwistDiagonal::BD;
  else if (d == "AC") p.diagonal = gen::SquareTwistDiagonal::AC;
  else throw InputError("--diagonal", "must be none, BD or AC, got '" + o.diagonal + "'");
  if (explicit_assignment) {
    if (type_given) throw InputError("--type", "give either --type or --assignment, not both");
    return with_flags([&] {
      return gen::square_twist(p, gen::parse_assignment_letters(o.assignment, "assignment"));
    });
  }
  if (diagonal_given) throw InputError("--diagonal", "applies only with --assignment (use --type 1M or 2M for the seed's diagonals)");
  const std::string t = upper(o.type);
  static const std::map<std::string, gen::SquareTwistType> types{{"1", gen::SquareTwistType::Type1},
                                                                 {"2", gen::SquareTwistType::Type2},
                                                                 {"3", gen::SquareTwistType::Type3},
                                                                 {"4", gen::SquareTwistType::Type4}};
  if (auto it = types.find(t); it != types.end())
    return with_flags([&] { return gen::square_twist(p, it->second); });
  if (t == "1M" || t == "2M")
    return with_flags([&] {
      return gen::square_twist_modified(p, t == "1M" ? gen::SquareTwistModifiedType::Type1M : gen::SquareTwistModifiedType::Type2M);
    });
  throw InputError("--type", "must be 1, 2, 3, 4 (seed 001 types), 1M or 2M, got '" + o.type + "'");
}

CreasePattern make_waterbomb(const GenerateOptions& o) {
  gen::WaterbombParams p;
  p.n = o.n;
  p.radius = o.radius;
  const std::string c = upper(o.corners);
  if (c != "M" && c != "V") throw InputError("--corners", "must be M or V (assignment of the corner creases), got '" + o.corners + "'");
  p.corners_mountain = c == "M";
  return with_flags([&] { return gen::waterbomb_base(p); });
}

CreasePattern make_resch_triangle(const GenerateOptions& o) {
  gen::ReschTriangleParams p;
  p.rows = o.rows;
  p.cols = o.cols;
  p.side = o.side;
  return with_flags([&] { return gen::resch_triangle(p); });
}

CreasePattern make_corrugated(const GenerateOptions& o, gen::CorrugatedUnit unit, bool assignment_given, bool odd_given) {
  gen::CorrugatedParams p;
  p.alpha = to_radians(o.alpha_deg.value_or(135));
  p.beta = to_radians(o.beta_deg);
  p.a = o.a;
  p.b = o.b;
  if (assignment_given && odd_given) throw InputError("--odd", "give either --assignment or --odd, not both");
  std::vector<Assignment> interior;
  if (assignment_given) {
    interior = with_flags([&] { return gen::parse_assignment_letters(o.assignment, "assignment"); });
  } else if (odd_given) {
    if (o.odd.size() != 4) throw InputError("--odd", "needs 4 digits (3 or 4), the odd joint of each vertex, got '" + o.odd + "'");
    std::array<int, 4> odd{};
    for (int k = 0; k < 4; ++k) {
      if (o.odd[k] != '3' && o.odd[k] != '4') throw InputError("--odd", "each digit must be 3 or 4, got '" + o.odd + "'");
      odd[k] = o.odd[k] - '0';
    }
    interior = with_flags([&] { return gen::corrugated_assignment(unit, odd); });
  } else {
    interior = gen::corrugated_rigid_assignment(unit);
  }
  return with_flags([&] { return gen::corrugated_unit(unit, p, interior); });
}

// Patterns of many cells: the size limit (input_limits.hpp) checked before generating. Each
// generator checks its own ranges of --rows and --cols; this checks their product.
void check_size(const GenerateOptions& o) {
  const bool miura = o.kind == "miura", tessellation = o.kind == "square-twist-tessellation";
  if (!(miura || tessellation) || o.rows < 1 || o.cols < 1) return;
  const std::int64_t cells = std::int64_t{o.rows} * o.cols;
  const std::int64_t limit = miura ? kMaxGeneratedMiuraCells : kMaxGeneratedTwistCells;
  if (cells > limit)
    throw InputError("--rows", "--rows x --cols = " + std::to_string(cells) + " cells, over the limit of " + std::to_string(limit) +
                                   " for " + o.kind);
}

void report(const std::string& path, const CreasePattern& p) {
  std::cout << "wrote " << path << " (" << p.num_vertices() << " vertices, " << p.num_edges() << " edges, "
            << p.num_faces() << " faces): " << p.extra.value("file_title", std::string()) << "\n";
}

void run(const GenerateOptions& o, CLI::App& sub) {
  const auto& accepted = accepted_flags();
  auto kind_it = accepted.find(o.kind);
  if (kind_it == accepted.end())
    throw InputError("KIND", "unknown pattern kind '" + o.kind +
                                 "' (expected miura, miura-tube, square-twist, square-twist-tessellation, waterbomb, corrugated-p, corrugated-q, resch-triangle or bundle)");
  auto given = [&](const std::string& flag) { return sub.get_option(flag)->count() > 0; };
  for (const auto& [other_kind, flags] : accepted)
    for (const auto& flag : flags)
      if (given(flag) && !kind_it->second.count(flag)) throw InputError(flag, "does not apply to '" + o.kind + "'");

  if (o.kind == "bundle") {
    if (given("--out")) throw InputError("--out", "bundle writes several files: use --out-dir DIR");
    if (o.out_dir.empty()) throw InputError("--out-dir", "is required for 'bundle'");
    // Every file staged, then all committed: a failure leaves the directory as it was.
    OutputSet outputs;
    outputs.add_output_directory("--out-dir", o.out_dir);
    const auto examples = gen::bundled_examples();
    for (const auto& [name, pattern] : examples) {
      const std::string path = (std::filesystem::path(o.out_dir) / (name + ".fold")).string();
      outputs.add_output("--out-dir", path);
      outputs.stage(path, write_fold_string(pattern));
    }
    outputs.commit();
    for (const auto& [name, pattern] : examples) report((std::filesystem::path(o.out_dir) / (name + ".fold")).string(), pattern);
    return;
  }
  if (given("--out-dir")) throw InputError("--out-dir", "applies only to 'bundle'; use --out FILE.fold");
  if (o.out.empty()) throw InputError("--out", "is required (the .fold file to write)");
  OutputSet outputs;
  outputs.add_output("--out", o.out);
  const SummaryToStderrIfStdoutIsAnOutput summary(outputs);

  check_size(o);
  CreasePattern pattern;
  if (o.kind == "miura") pattern = make_miura(o, given("--fold-deg"));
  else if (o.kind == "miura-tube") pattern = make_miura_tube(o, given("--fold-deg"));
  else if (o.kind == "square-twist") pattern = make_square_twist(o, given("--assignment"), given("--diagonal"), given("--type"));
  else if (o.kind == "square-twist-tessellation") pattern = make_square_twist_tessellation(o);
  else if (o.kind == "waterbomb") pattern = make_waterbomb(o);
  else if (o.kind == "resch-triangle") pattern = make_resch_triangle(o);
  else if (o.kind == "corrugated-p") pattern = make_corrugated(o, gen::CorrugatedUnit::P, given("--assignment"), given("--odd"));
  else pattern = make_corrugated(o, gen::CorrugatedUnit::Q, given("--assignment"), given("--odd"));
  outputs.stage(o.out, write_fold_string(pattern));
  outputs.commit();
  report(o.out, pattern);
}

}  // namespace

void add_generate_command(CLI::App& app) {
  auto opts = std::make_shared<GenerateOptions>();
  CLI::App* sub = app.add_subcommand("generate", "Write a generated crease pattern (FOLD)");
  sub->footer(
      "KIND: miura | miura-tube | square-twist | square-twist-tessellation | waterbomb | corrugated-p | corrugated-q | resch-triangle | bundle\n"
      "  miura          --rows --cols (panels) --alpha-deg (acute angle, default 60) --a (zig-zag length)\n"
      "                 --b (straight length) [--perturb AMP --seed S] [--fold-deg RHO: closed-form fold]\n"
      "  miura-tube     --rows (cells along the tube) --alpha-deg --a --b --fold-deg (straight creases of\n"
      "                 the given 3D state, default 90): two mirrored Miura strips bonded along zig-zags\n"
      "  square-twist   --twist-deg (default 30) --type 1|2|3|4|1M|2M (seed 001; default 3)\n"
      "                 or --assignment LETTERS (12: AB BC CD DA, o_a o_b of A B C D; 13 with --diagonal BD|AC)\n"
      "                 --side --pleat\n"
      "  square-twist-tessellation  --rows --cols (twists) --twist-deg --side --spacing (centre to centre,\n"
      "                 default 2.5) --layout type4|type3-rows (rigid, 1 DOF) | type1|type2 (not foldable)\n"
      "  waterbomb      --n (mountain folds, default 4) --radius --corners M|V\n"
      "  corrugated-p/q --alpha-deg (default 135) --beta-deg (default 60) --a --b\n"
      "                 --assignment LETTERS (12) or --odd DDDD (odd joint 3|4 per vertex); default rigid\n"
      "  resch-triangle --rows (grid rows) --cols (grid edges along x) --side (grid triangle side):\n"
      "                 Resch's triangle tessellation, the faces whose centroids lie in the rectangle\n"
      "  bundle         --out-dir DIR: every bundled example as DIR/NAME.fold");
  sub->add_option("kind", opts->kind, "Pattern kind")->required();
  sub->add_option("--out", opts->out, "Output .fold file");
  sub->add_option("--out-dir", opts->out_dir, "Output directory (bundle)");
  sub->add_option("--rows", opts->rows, "Miura: panels along y; Resch triangle: grid rows");
  sub->add_option("--cols", opts->cols, "Miura: panels along x; Resch triangle: grid edges along x");
  sub->add_option("--alpha-deg", opts->alpha_deg, "Miura: acute panel angle; corrugated: sector alpha (deg)");
  sub->add_option("--beta-deg", opts->beta_deg, "Corrugated: sector beta (deg)");
  sub->add_option("--a", opts->a, "Miura: zig-zag length; corrugated: i-edge length");
  sub->add_option("--b", opts->b, "Miura: straight length; corrugated: j-edge length");
  sub->add_option("--perturb", opts->perturb, "Miura: amplitude of the random interior-vertex perturbation");
  sub->add_option("--seed", opts->seed, "Miura: random seed of the perturbation");
  sub->add_option("--fold-deg", opts->fold_deg, "Miura: write the closed-form fold with straight creases at this angle");
  sub->add_option("--twist-deg", opts->twist_deg, "Square twist: twist angle (deg, 0..90)");
  sub->add_option("--type", opts->type, "Square twist: 1, 2, 3, 4, 1M or 2M");
  sub->add_option("--assignment", opts->assignment, "Interior crease letters (M/V/F/U)");
  sub->add_option("--diagonal", opts->diagonal, "Square twist with --assignment: none, BD or AC");
  sub->add_option("--side", opts->side, "Square twist: central square side; Resch triangle: grid triangle side");
  sub->add_option("--pleat", opts->pleat, "Square twist: outer crease length");
  sub->add_option("--spacing", opts->spacing, "Square-twist tessellation: twist centre to centre");
  sub->add_option("--layout", opts->layout, "Square-twist tessellation: type4, type3-rows, type1 or type2");
  sub->add_option("--n", opts->n, "Waterbomb: number of mountain (= valley) folds");
  sub->add_option("--radius", opts->radius, "Waterbomb: sheet circumradius");
  sub->add_option("--corners", opts->corners, "Waterbomb: assignment of the corner creases (M or V)");
  sub->add_option("--odd", opts->odd, "Corrugated: odd joint (3 or 4) of each vertex, e.g. 4343");
  sub->callback([opts, sub] { run(*opts, *sub); });
}

}  // namespace rigidfold::cli
