#pragma once
// The pieces of sweep-file parsing (sweep_config.cpp): the identity's canonical JSON, file-name
// parts, collected messages, and the parsers of "seeds", "grid", "points" and "extra_seeds".
// Internal to the sweep layer (docs/design.md §4.4).
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/config/sweep_config.hpp"

namespace wirepack::sweep::detail {

// Most runs one sweep may expand to (each is validated and kept in memory).
inline constexpr std::size_t kMaxRuns = 100000;
// Longest readable-parameter prefix of a run file name (the id keeps names unique anyway).
inline constexpr std::size_t kMaxReadable = 120;

// Top-level keys of a sweep file, in documentation order.
const std::vector<std::string>& sweep_keys();
std::string join(const std::vector<std::string>& names);
// The value as the run identity sees it: numbers as doubles, -0 as 0, recursively.
nlohmann::json canonical(const nlohmann::json& v);
// Unescaped last token of a JSON pointer ("/numerics/element_length" -> "element_length").
std::string last_token(const std::string& pointer);
// Keeps a file name within the POSIX portable set [A-Za-z0-9._-]; '+' (exponents) is dropped.
std::string sanitize(const std::string& s);
std::string value_text(const nlohmann::json& v);

// Collects messages in first-seen order without repeats.
class Messages {
 public:
  explicit Messages(std::string source) : source_(std::move(source)) {}
  void fail(const std::string& pointer, const std::string& rule) {
    add(source_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + rule);
  }
  void add(const std::string& message) {
    if (seen_.insert(message).second) list_.push_back(message);
  }
  bool empty() const { return list_.empty(); }
  const std::vector<std::string>& list() const { return list_; }
  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> list_;
  std::set<std::string> seen_;
};

// Valid grid axes: every scene key but the seed, top-level keys by name, nested ones by pointer.
std::vector<std::string> valid_axes();
bool is_scene_key(const std::string& pointer);
// Sets `pointer` in `scene` unless a non-object is in the way (parse_scene reports that one).
void set_at(nlohmann::json& scene, const std::string& pointer, const nlohmann::json& value);
void parse_seeds(const nlohmann::json& j, Messages& msg, std::vector<std::uint64_t>& seeds);
void parse_axes(const nlohmann::json& grid, Messages& msg, std::vector<GridAxis>& axes);
// The listed points (/points): objects giving a value for every grid axis, none repeating a
// grid point or an earlier listed one. Appends to values and where (see parse_sweep).
void parse_points(const nlohmann::json& list, const std::vector<GridAxis>& axes, Messages& msg,
                  std::vector<std::vector<nlohmann::json>>& values,
                  std::vector<std::vector<std::string>>& where);
// The further seeds at single points (/extra_seeds): objects giving a value for every grid axis
// (naming a point of `values`, the grid's or a listed one) and "seeds", a non-empty list of
// integers >= 0 none of which the point already has (from /seeds or an earlier entry).
void parse_extra_seeds(const nlohmann::json& list, const std::vector<GridAxis>& axes,
                       const std::vector<std::vector<nlohmann::json>>& values,
                       const std::vector<std::uint64_t>& seeds, Messages& msg,
                       std::vector<Sweep::ExtraSeeds>& out);
// File name of a run: the grid values, the seed and the id, e.g.
// runs/mu_s-0.5_rho-20_s3_0123456789ab.h5.
std::string run_file_name(const std::vector<GridAxis>& axes,
                          const std::vector<nlohmann::json>& values, std::uint64_t seed,
                          const std::string& id);

}  // namespace wirepack::sweep::detail
