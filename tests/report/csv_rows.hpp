#pragma once
// Test helper of the report tests: a CSV text (one header row, fields quoted where they hold a
// comma) as rows of column name -> cell text; a row with another number of cells than the
// header fails the calling test.
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace wirepack::testing {

inline std::vector<std::map<std::string, std::string>> csv_rows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream hs(line);
  for (std::string c; std::getline(hs, c, ',');) names.push_back(c);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    std::map<std::string, std::string> row;
    std::size_t i = 0;
    bool quoted = false;
    std::string c;
    for (char ch : line + ",") {
      if (ch == '"') {
        quoted = !quoted;
      } else if (ch == ',' && !quoted) {
        if (i < names.size()) row[names[i]] = c;
        ++i;
        c.clear();
      } else {
        c += ch;
      }
    }
    EXPECT_EQ(i, names.size()) << line;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace wirepack::testing
