// design/metamaterial/metamaterial_request: the front door that `rigidfold metamaterial` and
// rigidfold.metamaterial share. The same request is refused with the same reason under either
// naming (flags for the CLI, keywords for Python); a field left empty takes the CLI's default.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "design/metamaterial/metamaterial_request.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The InputError of the request, as "place|message" ("" when it is accepted).
std::string refusal(MetamaterialRequest request, FieldNaming naming) {
  request.naming = naming;
  try {
    run_metamaterial(request);
  } catch (const InputError& e) {
    return e.place() + "|" + e.message();
  }
  return "";
}

TEST(MetamaterialRequest, RefusesAlikeUnderFlagAndKeywordNames) {
  MetamaterialRequest twist_alpha;
  twist_alpha.unit = "square-twist";
  twist_alpha.alpha_deg = 80;
  EXPECT_EQ(refusal(twist_alpha, FieldNaming::kCommandLineFlags), "--alpha-deg|80.000000 is outside (90, 180) degrees");
  EXPECT_EQ(refusal(twist_alpha, FieldNaming::kKeywordArguments), "alpha_deg|80.000000 is outside (90, 180) degrees");

  MetamaterialRequest stack_samples;
  stack_samples.stacked = 1;
  stack_samples.samples = 5;
  EXPECT_EQ(refusal(stack_samples, FieldNaming::kCommandLineFlags), "--samples|does not apply to --stacked");
  EXPECT_EQ(refusal(stack_samples, FieldNaming::kKeywordArguments), "samples|does not apply to stacked");

  MetamaterialRequest element_steps;
  element_steps.unit = "element2";
  element_steps.cross_check_steps = 20;
  EXPECT_EQ(refusal(element_steps, FieldNaming::kCommandLineFlags),
            "--cross-check-steps|applies to --unit square-twist with --cross-check");
  EXPECT_EQ(refusal(element_steps, FieldNaming::kKeywordArguments),
            "cross_check_steps|applies to unit=square-twist with cross_check");

  EXPECT_EQ(refusal(MetamaterialRequest{}, FieldNaming::kKeywordArguments), "unit|is required (or stacked=1..4)");
}

// A flag given as false still counts as given (the CLI's --cross-check=false): a stack refuses it.
TEST(MetamaterialRequest, CrossCheckGivenAsFalseIsGiven) {
  MetamaterialRequest r;
  r.stacked = 1;
  r.cross_check = false;
  EXPECT_EQ(refusal(r, FieldNaming::kCommandLineFlags), "--cross-check|does not apply to --stacked");
}

TEST(MetamaterialRequest, EmptyFieldsTakeTheDocumentedDefaults) {
  MetamaterialRequest r;
  r.unit = "element3";
  r.samples = 9;
  const MetamaterialRun run = run_metamaterial(r);
  ASSERT_TRUE(run.unit.has_value());
  EXPECT_FALSE(run.stacked.has_value());
  EXPECT_DOUBLE_EQ(run.unit->params.element.alpha, to_radians(60.0));
  EXPECT_DOUBLE_EQ(run.unit->params.element.beta, to_radians(70.0));
  EXPECT_EQ(run.unit->params.element.l, 1.0);
  EXPECT_EQ(run.unit->table.rows.size(), 9u);
  EXPECT_FALSE(run.unit->cross_check.has_value());
  EXPECT_TRUE(run.unit->plot_files.empty());

  MetamaterialRequest twist;
  twist.unit = "square-twist";
  twist.samples = 9;
  EXPECT_DOUBLE_EQ(run_metamaterial(twist).unit->params.square_twist.alpha, to_radians(150.0));
}

TEST(MetamaterialRequest, PlotFilesWrittenIntoTheDirectory) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("rigidfold_metamaterial_request_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  MetamaterialRequest r;
  r.unit = "element1";
  r.samples = 7;
  r.plot = dir.string();
  const MetamaterialRun run = run_metamaterial(r);
  ASSERT_EQ(run.unit->plot_files.size(), 3u);
  for (const std::string& f : run.unit->plot_files) EXPECT_TRUE(std::filesystem::is_regular_file(f)) << f;
  EXPECT_EQ(run.unit->plot_files[0], (dir / "metamaterial.csv").string());
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
