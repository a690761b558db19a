// The square-twist CSV writer: header, row count, sample spacing, and every number read back
// equal (to the last bit, %.17g) to square_twist_unit at the row's theta; file round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "design/metamaterial/square_twist_csv.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<std::vector<double>> parse(std::istream& in, std::string& header) {
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

void check_rows(const std::vector<std::vector<double>>& rows, const SquareTwistUnitParams& p, int samples) {
  ASSERT_EQ(static_cast<int>(rows.size()), samples);
  for (int k = 0; k < samples; ++k) {
    ASSERT_EQ(rows[k].size(), 7u);
    const double theta = rows[k][0];
    EXPECT_NEAR(theta, std::numbers::pi * (k + 1) / (samples + 1), 1e-15);
    const SquareTwistUnitState u = square_twist_unit(p, theta);
    EXPECT_EQ(rows[k][1], u.phi);
    EXPECT_EQ(rows[k][2], u.L);
    EXPECT_EQ(rows[k][3], u.S);
    EXPECT_EQ(rows[k][4], u.H);
    EXPECT_EQ(rows[k][5], u.nu_SL);
    EXPECT_EQ(rows[k][6], u.nu_HL);
    EXPECT_LT(u.nu_SL, 0.0);
  }
}

TEST(MetamaterialSquareTwistCsv, StreamRoundTrip) {
  SquareTwistUnitParams p;
  p.alpha = 5 * std::numbers::pi / 6;
  std::stringstream ss;
  write_square_twist_csv(ss, p, 37);
  std::string header;
  const auto rows = parse(ss, header);
  EXPECT_EQ(header, kSquareTwistCsvHeader);
  check_rows(rows, p, 37);
}

TEST(MetamaterialSquareTwistCsv, FileRoundTripAndErrors) {
  SquareTwistUnitParams p;
  p.alpha = 2.0;
  p.a = 1.3;
  p.b = 0.9;
  p.c = 1.4;
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("rigidfold_square_twist_" + std::to_string(::getpid()) + ".csv");
  write_square_twist_csv(path.string(), p, 10);
  std::ifstream in(path);
  ASSERT_TRUE(in.good());
  std::string header;
  const auto rows = parse(in, header);
  EXPECT_EQ(header, kSquareTwistCsvHeader);
  check_rows(rows, p, 10);
  std::filesystem::remove(path);
  std::stringstream ss;
  EXPECT_THROW(write_square_twist_csv(ss, p, 0), std::invalid_argument);
  EXPECT_THROW(write_square_twist_csv("/nonexistent-dir/x.csv", p, 3), std::runtime_error);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
