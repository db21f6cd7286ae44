// Text helpers: round-trip numbers, durations, UTC timestamps.
#include "sweep/format.hpp"

#include <cmath>
#include <regex>
#include <string>

#include <gtest/gtest.h>

namespace wirepack::sweep {
namespace {

TEST(Format, NumbersRoundTrip) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(20), "20");
  EXPECT_EQ(format_number(std::nan("")), "nan");
  for (double x : {1.0 / 3.0, 6.02214076e23, -1e-300, 0.30000000000000004})
    EXPECT_EQ(std::stod(format_number(x)), x);
}

// CSV cells (the one place they are made): fields quoted where needed, numbers round-trip with
// "nan" for any NaN, parameter values by type.
TEST(Format, CsvCells) {
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(csv_field("a\nb"), "\"a b\"");
  EXPECT_EQ(csv_number(0.1), "0.1");
  EXPECT_EQ(csv_number(-std::nan("")), "nan");
  EXPECT_EQ(csv_cell(nlohmann::json()), "");
  EXPECT_EQ(csv_cell(nlohmann::json(1e-05)), "1e-05");
  EXPECT_EQ(csv_cell(nlohmann::json("rigid")), "rigid");
  EXPECT_EQ(csv_cell(nlohmann::json(true)), "true");
  EXPECT_EQ(csv_cell(nlohmann::json::array({1, 2})), "\"[1,2]\"");
}

TEST(Format, Durations) {
  EXPECT_EQ(format_duration(41), "0:00:41");
  EXPECT_EQ(format_duration(3 * 3600 + 61.4), "3:01:01");
  EXPECT_EQ(format_duration(-1), "?");
  EXPECT_EQ(format_duration(INFINITY), "?");
}

TEST(Format, Iso8601) {
  EXPECT_TRUE(
      std::regex_match(utc_now_iso8601(), std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)")));
}

}  // namespace
}  // namespace wirepack::sweep
