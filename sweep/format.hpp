#pragma once
// Text of numbers and values, for the sweep layer and everything above it: the one place where
// CSV cells (manifest tables, joblog, analysis tables) and number texts are made; durations,
// timestamps.
#include <string>

#include <nlohmann/json.hpp>

namespace wirepack::sweep {

// Shortest text that reads back as the same double ("0.1", "1e-05", "nan", "inf").
std::string format_number(double x);
// CSV field: quoted when it holds a comma, quote or newline (quotes doubled, newlines -> space).
std::string csv_field(const std::string& s);
// A number as CSV: shortest round-trip text, "nan" for any NaN.
std::string csv_number(double x);
// A parameter value as CSV: numbers as numbers, strings quoted where needed, null empty.
std::string csv_cell(const nlohmann::json& v);
// Wall-clock duration as H:MM:SS, e.g. 0:00:41 (seconds; negative or non-finite -> "?").
std::string format_duration(double seconds);
// Current time as ISO-8601 UTC with seconds, e.g. 2024-05-01T12:34:56Z.
std::string utc_now_iso8601();

}  // namespace wirepack::sweep
