#pragma once
// Small text helpers shared by the sweep layer: numbers, durations, timestamps.
#include <string>

namespace wirepack::sweep {

// Shortest text that reads back as the same double ("0.1", "1e-05", "nan", "inf").
std::string format_number(double x);
// Wall-clock duration as H:MM:SS, e.g. 0:00:41 (seconds; negative or non-finite -> "?").
std::string format_duration(double seconds);
// Current time as ISO-8601 UTC with seconds, e.g. 2024-05-01T12:34:56Z.
std::string utc_now_iso8601();

}  // namespace wirepack::sweep
