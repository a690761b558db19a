// `rigidfold trace`: the Miura fold family against its closed form (CSV and multi-frame FOLD),
// the square twist Type 3 without M/V switch, the general solver against the multiplier model,
// and exit 2 with no output file for bad flags.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "data/generators/miura.hpp"
#include "data/generators/miura_tube.hpp"
#include "data/generators/square_twist.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


class TempDir {
 public:
  TempDir() : path_(std::filesystem::temp_directory_path() / ("rigidfold_trace_" + std::to_string(::getpid()) + "_" +
                                                             std::to_string(counter_++))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  static inline int counter_ = 0;
  std::filesystem::path path_;
};

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return static_cast<int>(i);
    return -1;
  }
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::stringstream ss(line);
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

Csv read_csv(const std::string& path) {
  Csv c;
  std::ifstream in(path);
  std::string line;
  if (std::getline(in, line)) c.header = split(line);
  while (std::getline(in, line))
    if (!line.empty()) c.rows.push_back(split(line));
  return c;
}

nlohmann::json run_json(const std::string& args, int expected_status = 0) {
  const auto r = test::run_command(test::cli() + " trace " + args + " --json");
  EXPECT_EQ(r.status, expected_status) << r.err;
  if (r.status != 0) return nullptr;
  return nlohmann::json::parse(r.out);
}

TEST(TraceCli, MiuraFollowsTheClosedForm) {
  TempDir dir;
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  const CreasePattern p = generators::miura_ori(m);
  const std::string in = dir.file("miura.fold"), csv = dir.file("angles.csv"), out = dir.file("frames.fold");
  write_fold(p, in);
  const int steps = 20;
  const auto j = run_json(in + " --steps " + std::to_string(steps) + " --csv " + csv + " --out " + out);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["model"], "multiplier-propagation");
  EXPECT_EQ(j["traced"], true);
  EXPECT_EQ(j["branch"], 0);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-12);
  const int drive = j["driving_crease"];
  const auto kinds = generators::miura_crease_kinds(m);
  // The largest multiplier is a zig-zag crease's (the straight ones lag).
  EXPECT_EQ(kinds[drive], generators::MiuraCrease::ZigZag);
  EXPECT_NEAR(j["reached_deg"].get<double>(), p.assignments[drive] == Assignment::Mountain ? -170.0 : 170.0, 1e-12);
  for (const auto& e : j["events"]) EXPECT_NE(e["kind"].get<std::string>(), "mv_switch");

  const Csv c = read_csv(csv);
  ASSERT_EQ(static_cast<int>(c.header.size()), 5 + p.num_edges());
  EXPECT_EQ(c.header[0], "step");
  EXPECT_EQ(c.header[1], "drive_deg");
  EXPECT_EQ(c.header[2], "max_residual_rad");
  EXPECT_EQ(c.header[3], "mismatch");
  EXPECT_EQ(c.header[4], "events");
  EXPECT_EQ(c.header[5], "e0_deg");
  ASSERT_EQ(static_cast<int>(c.rows.size()), steps);
  const double drive_sign = p.assignments[drive] == Assignment::Mountain ? -1.0 : 1.0;
  double worst_angle = 0, worst_residual = 0;
  for (const auto& row : c.rows) {
    ASSERT_EQ(row.size(), c.header.size());
    const double drive_rad = std::stod(row[1]) / kDegreesPerRadian;
    worst_residual = std::max(worst_residual, std::stod(row[2]));
    EXPECT_NEAR(std::stod(row[5 + drive]) / kDegreesPerRadian, drive_rad, 1e-15);
    // Straight-crease fold from the zig-zag one: tan(|rs|/2) = cos(alpha) tan(|rz|/2);
    // positive when the creases fold as assigned.
    const double rs = 2 * std::atan(std::cos(m.alpha) * std::tan(std::fabs(drive_rad) / 2)) *
                      (drive_rad * drive_sign > 0 ? 1.0 : -1.0);
    const auto expected = generators::miura_fold_angles(p, m, rs);
    for (int e = 0; e < p.num_edges(); ++e)
      worst_angle = std::max(worst_angle, std::fabs(std::stod(row[5 + e]) / kDegreesPerRadian - expected[e].value_or(0.0)));
  }
  EXPECT_LE(worst_residual, 1e-12);
  EXPECT_LE(worst_angle, 1e-10);
  std::cout << "[measured] miura 4x5 trace: max residual " << worst_residual << " rad, max |angle - closed form| "
            << worst_angle << " rad\n";

  // The multi-frame FOLD: key frame + one foldedForm frame per step; rigid panels.
  std::ifstream fin(out);
  const auto fold = nlohmann::json::parse(fin);
  ASSERT_TRUE(fold.contains("file_frames"));
  ASSERT_EQ(static_cast<int>(fold["file_frames"].size()), steps);
  for (const auto& f : fold["file_frames"]) {
    EXPECT_EQ(f["frame_classes"][0], "foldedForm");
    EXPECT_EQ(f["frame_parent"], 0);
    EXPECT_EQ(f["frame_inherit"], true);
    ASSERT_TRUE(f.contains("edges_foldAngle"));
    EXPECT_EQ(static_cast<int>(f["edges_foldAngle"].size()), p.num_edges());
  }
  const auto& last = fold["file_frames"].back()["vertices_coords"];
  ASSERT_EQ(static_cast<int>(last.size()), p.num_vertices());
  double worst_length = 0;
  for (const auto& e : p.edges) {
    const Eigen::Vector3d a(last[e[0]][0].get<double>(), last[e[0]][1].get<double>(), last[e[0]][2].get<double>());
    const Eigen::Vector3d b(last[e[1]][0].get<double>(), last[e[1]][1].get<double>(), last[e[1]][2].get<double>());
    worst_length = std::max(worst_length, std::fabs((a - b).norm() - (p.vertices[e[0]] - p.vertices[e[1]]).norm()));
  }
  EXPECT_LE(worst_length, 1e-12);
  // The last frame is really folded (not flat).
  double zmax = 0;
  for (const auto& v : last) zmax = std::max(zmax, std::fabs(v[2].get<double>()));
  EXPECT_GT(zmax, 0.1);
}

TEST(TraceCli, MiuraGeneralSolverAgreesWithMultipliers) {
  TempDir dir;
  generators::MiuraParams m;
  m.rows = 3;
  m.cols = 4;
  const CreasePattern p = generators::miura_ori(m);
  const std::string in = dir.file("miura.fold"), a = dir.file("a.csv"), b = dir.file("b.csv");
  write_fold(p, in);
  const auto jm = run_json(in + " --steps 10 --to 120 --csv " + a);
  ASSERT_FALSE(jm.is_null());
  const int drive = jm["driving_crease"];
  const auto jg = run_json(in + " --steps 10 --to 120 --general --drive " + std::to_string(drive) + " --csv " + b);
  ASSERT_FALSE(jg.is_null());
  EXPECT_EQ(jg["model"], "general loop-closure solver");
  ASSERT_EQ(jg["traced"], true) << jg.dump(2);
  EXPECT_EQ(jg["branches"][0]["dof_at_start"], 1);
  EXPECT_LE(jg["max_residual"].get<double>(), 1e-12);
  const Csv ca = read_csv(a), cb = read_csv(b);
  ASSERT_EQ(ca.rows.size(), 10u);
  ASSERT_EQ(cb.rows.size(), 10u);
  double worst = 0;
  for (std::size_t k = 0; k < ca.rows.size(); ++k)
    for (int e = 0; e < p.num_edges(); ++e)
      worst = std::max(worst, std::fabs(std::stod(ca.rows[k][5 + e]) - std::stod(cb.rows[k][5 + e])) / kDegreesPerRadian);
  EXPECT_LE(worst, 1e-10);
  std::cout << "[measured] miura 3x4 general vs multiplier: max |delta rho| " << worst << " rad, general residual "
            << jg["max_residual"].get<double>() << " rad\n";
}

TEST(TraceCli, SquareTwistType3HasNoMvSwitch) {
  TempDir dir;
  for (double twist_deg : {20.0, 30.0, 60.0}) {
    generators::SquareTwistParams params;
    params.twist = twist_deg / kDegreesPerRadian;
    const std::string in = dir.file("twist.fold");
    write_fold(generators::square_twist(params, generators::SquareTwistType::Type3), in);
    const auto j = run_json(in + " --steps 40 --branch all");
    ASSERT_FALSE(j.is_null());
    EXPECT_EQ(j["model"], "multiplier-propagation");
    EXPECT_EQ(j["traced"], true);
    ASSERT_GE(j["branches"].size(), 1u);
    for (const auto& b : j["branches"]) {
      EXPECT_EQ(b["steps"], 40);
      EXPECT_LE(b["max_residual"].get<double>(), 1e-12);
      for (const auto& e : b["events"]) EXPECT_NE(e["kind"].get<std::string>(), "mv_switch") << twist_deg << ": " << e.dump();
    }
  }
}

TEST(TraceCli, SquareTwistModifiedUsesTheGeneralSolver) {
  TempDir dir;
  const std::string in = dir.file("type1m.fold"), csv = dir.file("type1m.csv");
  write_fold(generators::square_twist_modified({}, generators::SquareTwistModifiedType::Type1M), in);
  const auto j = run_json(in + " --steps 20 --csv " + csv);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["model"], "general loop-closure solver");
  ASSERT_EQ(j["traced"], true) << j.dump(2);
  EXPECT_EQ(j["branches"][0]["dof_at_start"], 1);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-12);
  EXPECT_EQ(read_csv(csv).rows.size(), 20u);
  std::cout << "[measured] square twist 1M (30 deg): max residual " << j["max_residual"] << " rad, max mismatch "
            << j["max_mismatch"] << "\n";

  // Driven to 180 deg: the trace ends where a crease reaches 180 deg, marked as interference,
  // and no crease passes it.
  const std::string in2 = dir.file("type2m.fold"), csv2 = dir.file("type2m.csv");
  write_fold(generators::square_twist_modified({}, generators::SquareTwistModifiedType::Type2M), in2);
  const auto k = run_json(in2 + " --steps 15 --to 180 --csv " + csv2);
  ASSERT_FALSE(k.is_null());
  ASSERT_EQ(k["traced"], true) << k.dump(2);
  EXPECT_LE(k["max_residual"].get<double>(), 1e-12);
  bool interference = false;
  for (const auto& e : k["events"]) interference |= e["kind"] == "interference" && e["step"] == 15;
  EXPECT_TRUE(interference) << k.dump(2);
  const Csv c = read_csv(csv2);
  ASSERT_EQ(c.rows.size(), 15u);
  double largest = 0;
  for (const auto& row : c.rows)
    for (std::size_t i = 5; i < row.size(); ++i) largest = std::max(largest, std::fabs(std::stod(row[i])));
  EXPECT_LE(largest, 180.0);
  EXPECT_GE(largest, 180.0 - 1e-9 * kDegreesPerRadian);
  std::cout << "[measured] square twist 2M to 180: reached " << k["reached_deg"] << " deg (" << k["stopped_by"]
            << "), max residual " << k["max_residual"] << " rad\n";
}

// --branch all with the general solver: every branch of the explorer, one CSV per branch.
TEST(TraceCli, Type2MEveryBranchThroughTheBifurcation) {
  TempDir dir;
  const std::string in = dir.file("type2m.fold"), csv = dir.file("b.csv");
  write_fold(generators::square_twist_modified({}, generators::SquareTwistModifiedType::Type2M), in);
  const auto j = run_json(in + " --branch all --csv " + csv);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["model"], "general loop-closure solver, branch exploration");
  int traced = 0, from_bifurcation = 0;
  for (const auto& b : j["branches"]) {
    if (b["traced"] != true) continue;
    ++traced;
    EXPECT_TRUE(std::filesystem::exists(dir.file("b.b" + std::to_string(b["branch"].get<int>()) + ".csv")));
    from_bifurcation += b["stopped_by"].get<std::string>().find("from bifurcation") != std::string::npos;
  }
  EXPECT_GE(traced, 20);
  EXPECT_GE(from_bifurcation, 2);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-12);
  // An unknown branch id is bad input.
  EXPECT_TRUE(run_json(in + " --branch 999", 2).is_null());
}

TEST(TraceCli, NotOneDofSaysSo) {
  TempDir dir;
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  m.perturbation = 0.05;
  const std::string in = dir.file("perturbed.fold"), out = dir.file("frames.fold");
  write_fold(generators::miura_ori(m), in);
  const auto j = run_json(in);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j["model"], "general loop-closure solver");
  EXPECT_EQ(j["traced"], false);
  EXPECT_FALSE(j["message"].get<std::string>().empty());
  // With --out asked for, nothing traced is no answer (exit 3), the reason on stderr, no file.
  const auto r = test::run_command(test::cli() + " trace " + in + " --out " + out);
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("no answer within tolerance: nothing traced"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(j["message"].get<std::string>()), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(TraceCli, BadFlagsExitTwoWithoutOutput) {
  TempDir dir;
  generators::MiuraParams m;
  const CreasePattern p = generators::miura_ori(m);
  const std::string in = dir.file("miura.fold"), out = dir.file("frames.fold"), csv = dir.file("a.csv");
  write_fold(p, in);
  int boundary = -1;
  for (int e = 0; e < p.num_edges() && boundary < 0; ++e)
    if (p.assignments[e] == Assignment::Boundary) boundary = e;
  ASSERT_GE(boundary, 0);
  for (const std::string& flags : {"--drive " + std::to_string(p.num_edges()), std::string("--drive -1"),
                                  "--drive " + std::to_string(boundary), std::string("--to 200"),
                                  std::string("--to -180.5"), std::string("--to 0"), std::string("--steps 0"),
                                  std::string("--branch 7"), std::string("--branch x"), std::string("--tolerance -1"),
                                  std::string("--tolerance nan"), std::string("--tolerance loose")}) {
    const auto r = test::run_command(test::cli() + " trace " + in + " " + flags + " --out " + out + " --csv " + csv);
    EXPECT_EQ(r.status, 2) << flags << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << flags;
    EXPECT_FALSE(std::filesystem::exists(out)) << flags;
    EXPECT_FALSE(std::filesystem::exists(csv)) << flags;
  }
  EXPECT_NE(test::run_command(test::cli() + " trace " + in + " --drive " + std::to_string(boundary)).err.find("--drive"),
            std::string::npos);
  EXPECT_EQ(test::run_command(test::cli() + " trace /nonexistent.fold").status, 2);
}

// trace --tolerance: a Miura written with 3 decimals (turned, so that the rounding breaks
// Kawasaki) is traced on its flat-foldable witness when its digits are trusted (auto) or a
// bound is stated, and by the general solver on the numbers as they are with exact; the
// precision assumed is stated either way.
TEST(TraceCli, ToleranceChoosesWhatTheCoordinatesAreTakenToBe) {
  TempDir dir;
  generators::MiuraParams m;
  m.rows = 2;
  m.cols = 5;
  m.a = 100.0;
  m.b = 131.371;
  CreasePattern p = generators::miura_ori(m);
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (Eigen::Vector3d& v : p.vertices) {
    const Eigen::Vector3d turned(c * v.x() - s * v.y(), s * v.x() + c * v.y(), 0.0);
    for (int k = 0; k < 2; ++k) v[k] = std::round(turned[k] * 1e3) / 1e3;
  }
  const std::string in = dir.file("rounded.fold");
  write_fold(p, in);
  const auto read = run_json(in + " --steps 3");
  ASSERT_FALSE(read.is_null());
  EXPECT_NE(read["model"].get<std::string>().find("witness"), std::string::npos) << read["model"];
  EXPECT_NE(read["coordinate_precision"].get<std::string>().find("3 decimals"), std::string::npos) << read["coordinate_precision"];
  const auto stated = run_json(in + " --steps 3 --tolerance 0.01");
  ASSERT_FALSE(stated.is_null());
  EXPECT_NE(stated["model"].get<std::string>().find("witness"), std::string::npos) << stated["model"];
  EXPECT_EQ(stated["coordinate_precision"], "coordinates within 0.01 of the true ones (stated with --tolerance)");
  const auto exact = run_json(in + " --steps 3 --tolerance exact");
  ASSERT_FALSE(exact.is_null());
  EXPECT_EQ(exact["model"].get<std::string>().find("witness"), std::string::npos) << exact["model"];
  EXPECT_EQ(exact["coordinate_precision"], "coordinates taken as exact (--tolerance exact)");
}

TEST(TraceCli, FullyFoldedMarksInterference) {
  TempDir dir;
  generators::MiuraParams m;
  const std::string in = dir.file("miura.fold");
  write_fold(generators::miura_ori(m), in);
  const auto j = run_json(in + " --steps 5 --to -180 --ignore-assignment");
  ASSERT_FALSE(j.is_null());
  bool interference = false;
  for (const auto& e : j["events"]) interference |= e["kind"] == "interference" && e["step"] == 5;
  EXPECT_TRUE(interference);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-12);
  // Driven against its letter, every crease of the family folds against its letter.
  const int drive = j["driving_crease"];
  const auto k = run_json(in + " --steps 5 --drive " + std::to_string(drive) + " --to " +
                          (j["branches"][0]["drive_assignment"] == "M" ? "90" : "-90"));
  ASSERT_FALSE(k.is_null());
  int switches = 0;
  for (const auto& e : k["events"]) switches += e["kind"] == "mv_switch" && e["step"] == 1;
  EXPECT_GT(switches, 0);
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// A sheet with a hole: both branches through the Miura tube's given state, the flat-folded
// end solved exactly at 180 deg, the given state as the first CSV row.
TEST(TraceCli, MiuraTubeBothWaysFromItsGivenState) {
  TempDir dir;
  const std::string in = dir.file("tube.fold"), csv = dir.file("t.csv");
  generators::MiuraTubeParams tp;
  tp.rows = 3;
  write_fold(generators::miura_tube(tp), in);
  const auto j = run_json(in + " --branch all --csv " + csv);
  ASSERT_FALSE(j.is_null());
  EXPECT_NE(j["model"].get<std::string>().find("SE(3) hole closures"), std::string::npos);
  ASSERT_EQ(j["branches"].size(), 2u);
  EXPECT_LE(j["max_residual"].get<double>(), 1e-11);
  double largest_end = 0;
  for (const auto& b : j["branches"]) {
    EXPECT_EQ(b["traced"], true);
    EXPECT_EQ(b["stopped_by"], "fold limit");
    largest_end = std::max(largest_end, std::abs(b["reached_deg"].get<double>()));
  }
  // The flat-folded end is solved with the first crease to reach the limit held at 180 deg;
  // the end is a singular point, so the other creases are there only to ~1e-6 rad.
  EXPECT_NEAR(largest_end, 180.0, 1e-3);
  const Csv c = read_csv(dir.file("t.b0.csv"));
  ASSERT_GE(c.rows.size(), 10u);
  double last_max = 0;
  for (std::size_t i = 0; i < c.header.size(); ++i)
    if (c.header[i].size() > 5 && c.header[i][0] == 'e' && std::isdigit(static_cast<unsigned char>(c.header[i][1])))
      last_max = std::max(last_max, std::abs(std::stod(c.rows.back()[i])));
  EXPECT_NEAR(last_max, 180.0, 1e-9);
  const int drive = j["branches"][0]["driving_crease"].get<int>();
  const int col = c.column("e" + std::to_string(drive) + "_deg");
  ASSERT_GE(col, 0);
  // The first row is the given (folded) state, not the flat sheet.
  EXPECT_GT(std::abs(std::stod(c.rows[0][col])), 10.0);
  EXPECT_LT(std::abs(std::stod(c.rows[0][col])), 170.0);
}

}}  // namespace
}  // namespace rigidfold
