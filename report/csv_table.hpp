#pragma once
// Small helpers of the report layer's CSV tables and plot titles: cells, tables, JSON leaves,
// the order of parameter values.
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/format.hpp"

namespace wirepack::report {

// CSV cells are sweep/format.hpp's csv_number and csv_cell (one place for CSV text).
// A value as text for plot titles ("0.5", "rigid").
std::string text_of(const nlohmann::json& v);

// A CSV table: one header row, then rows of exactly as many cells.
class Table {
 public:
  explicit Table(const std::vector<std::string>& header) : width_(header.size()) {
    if (std::set<std::string>(header.begin(), header.end()).size() != header.size())
      throw std::logic_error("analyze: a CSV header repeats a column name");
    add(header);
  }
  void add(const std::vector<std::string>& row) {
    if (row.size() != width_)
      throw std::logic_error("analyze: a CSV row has " + std::to_string(row.size()) +
                             " cells, the header " + std::to_string(width_));
    for (std::size_t i = 0; i < row.size(); ++i) text_ += (i ? "," : "") + row[i];
    text_ += '\n';
  }
  const std::string& text() const { return text_; }

 private:
  std::size_t width_;
  std::string text_;
};

// The concatenation of string lists.
template <class... Parts>
std::vector<std::string> cat(Parts&&... parts) {
  std::vector<std::string> out;
  (out.insert(out.end(), parts.begin(), parts.end()), ...);
  return out;
}

// Leaves of a JSON object: pointer -> value (arrays count as leaves).
void flatten(const nlohmann::json& j, const std::string& pointer,
             std::map<std::string, nlohmann::json>& out);

// Total order on parameter values: absent, numbers (by value), strings, anything else.
int compare_values(const nlohmann::json& a, const nlohmann::json& b);

// CSV column of a scene pointer: "/mu_s" -> "mu_s", "/numerics/element_length" ->
// "numerics.element_length".
std::string column_name(const std::string& pointer);

}  // namespace wirepack::report
