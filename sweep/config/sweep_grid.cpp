#include "sweep/config/sweep_grid.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "sweep/config/json_file.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/format.hpp"

namespace wirepack::sweep::detail {

using json = nlohmann::json;

// Top-level keys of a sweep file, in documentation order.
const std::vector<std::string>& sweep_keys() {
  static const std::vector<std::string> keys = {"name",     "base",   "grid",       "seeds",
                                                "analysis", "points", "extra_seeds"};
  return keys;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The value as the run identity sees it: numbers as doubles, -0 as 0, recursively.
json canonical(const json& v) {
  if (v.is_number()) {
    const double x = v.get<double>();
    return json(x == 0 ? 0.0 : x);
  }
  if (v.is_object()) {
    json out = json::object();
    for (const auto& [k, c] : v.items()) out[k] = canonical(c);
    return out;
  }
  if (v.is_array()) {
    json out = json::array();
    for (const auto& c : v) out.push_back(canonical(c));
    return out;
  }
  return v;
}

// Unescaped last token of a JSON pointer ("/numerics/element_length" -> "element_length").
std::string last_token(const std::string& pointer) {
  std::string tok = pointer.substr(pointer.rfind('/') + 1);
  std::string out;
  for (std::size_t i = 0; i < tok.size(); ++i) {
    if (tok[i] == '~' && i + 1 < tok.size()) {
      out += tok[i + 1] == '1' ? '/' : '~';
      ++i;
    } else {
      out += tok[i];
    }
  }
  return out;
}

// Keeps a file name within the POSIX portable set [A-Za-z0-9._-]; '+' (exponents) is dropped.
std::string sanitize(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '+') continue;
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    out += ok ? c : '_';
  }
  return out;
}

std::string value_text(const json& v) {
  if (v.is_number()) return format_number(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// Valid grid axes: every scene key but the seed, top-level keys by name, nested ones by pointer.
std::vector<std::string> valid_axes() {
  std::vector<std::string> out;
  for (const auto& spec : scene_schema()) {
    if (spec.pointer == "/seed") continue;
    const bool nested = spec.pointer.find('/', 1) != std::string::npos;
    out.push_back(nested ? spec.pointer : spec.pointer.substr(1));
  }
  out.push_back("/numerics/preset");
  return out;
}

bool is_scene_key(const std::string& pointer) {
  if (pointer == "/numerics/preset") return true;
  for (const auto& spec : scene_schema())
    if (spec.pointer == pointer) return true;
  return false;
}

// Sets `pointer` in `scene` unless a non-object is in the way (parse_scene reports that one).
void set_at(json& scene, const std::string& pointer, const json& value) {
  json* node = &scene;
  std::size_t pos = 1;
  while (true) {
    const auto next = pointer.find('/', pos);
    const std::string tok = pointer.substr(pos, next == std::string::npos ? next : next - pos);
    if (next == std::string::npos) {
      (*node)[tok] = value;
      return;
    }
    json& child = (*node)[tok];  // creates an object level if missing
    if (child.is_null()) child = json::object();
    if (tok == "numerics" && child.is_string()) child = json{{"preset", child}};  // a preset name
    if (!child.is_object()) return;
    node = &child;
    pos = next + 1;
  }
}

void parse_seeds(const json& j, Messages& msg, std::vector<std::uint64_t>& seeds) {
  const auto it = j.find("seeds");
  if (it == j.end()) {
    for (std::uint64_t s = 1; s <= 10; ++s) seeds.push_back(s);  // the paper's 10 seeds
    return;
  }
  const json& v = *it;
  if (v.is_number_integer()) {
    const bool pos = v.is_number_unsigned() || v.get<std::int64_t>() > 0;
    if (!pos || v.get<std::uint64_t>() < 1 || v.get<std::uint64_t>() > kMaxRuns) {
      msg.fail("/seeds", "a seed count must be in [1, " + std::to_string(kMaxRuns) + "] (got " +
                             describe_value(v) + ")");
      return;
    }
    for (std::uint64_t s = 1; s <= v.get<std::uint64_t>(); ++s) seeds.push_back(s);
    return;
  }
  if (!v.is_array()) {
    msg.fail("/seeds", "must be a seed count (integer >= 1) or a list of seeds (got " +
                           describe_value(v) + ")");
    return;
  }
  if (v.empty()) {
    msg.fail("/seeds", "the list of seeds must not be empty");
    return;
  }
  std::map<std::uint64_t, std::size_t> first;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string p = "/seeds/" + std::to_string(i);
    if (!v[i].is_number_unsigned()) {
      msg.fail(p, "a seed must be an integer >= 0 (got " + describe_value(v[i]) + ")");
      continue;
    }
    const auto s = v[i].get<std::uint64_t>();
    if (const auto f = first.find(s); f != first.end()) {
      msg.fail(p, "duplicate seed (also at /seeds/" + std::to_string(f->second) + ")");
      continue;
    }
    first[s] = i;
    seeds.push_back(s);
  }
}

void parse_axes(const json& grid, Messages& msg, std::vector<GridAxis>& axes) {
  std::map<std::string, std::string> by_pointer;  // pointer -> key, to find two names of one key
  for (const auto& [key, values] : grid.items()) {
    const std::string here = pointer_child("/grid", key);
    const std::string pointer = !key.empty() && key[0] == '/' ? key : "/" + key;
    if (pointer == "/seed") {
      msg.fail(here, "the seed is not a grid axis; list the seeds in /seeds");
      continue;
    }
    if (!key.empty() && key[0] != '/' && key.find('/') != std::string::npos) {
      msg.fail(here, "unknown scene key; nested keys are JSON pointers (\"/" + key +
                         "\"); valid axes: " + join(valid_axes()));
      continue;
    }
    if (!is_scene_key(pointer)) {
      msg.fail(here, "unknown scene key; valid axes: " + join(valid_axes()));
      continue;
    }
    if (const auto other = by_pointer.find(pointer); other != by_pointer.end()) {
      msg.fail(here, "the same scene key as " + pointer_child("/grid", other->second));
      continue;
    }
    by_pointer[pointer] = key;
    if (!values.is_array()) {
      msg.fail(here, "an axis must be a list of values (got " + describe_value(values) + ")");
      continue;
    }
    if (values.empty()) {
      msg.fail(here, "an axis must list at least one value");
      continue;
    }
    GridAxis axis{key, pointer, last_token(pointer), {}};
    bool ok = true;
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (std::size_t k = 0; k < i; ++k) {
        if (canonical(values[i]) == canonical(values[k])) {
          msg.fail(here + "/" + std::to_string(i), "duplicate value " + describe_value(values[i]) +
                                                       " (also at " + here + "/" +
                                                       std::to_string(k) + ")");
          ok = false;
          break;
        }
      }
      axis.values.push_back(values[i]);
    }
    if (ok) axes.push_back(std::move(axis));
  }
  std::sort(axes.begin(), axes.end(),
            [](const GridAxis& a, const GridAxis& b) { return a.pointer < b.pointer; });
}

namespace {

// The grid-axis values of the entry `obj` at `here` (of /points or /extra_seeds), in axes order,
// with their pointers; `also` is one further key the entry may have ("" for none) and `what`
// names an entry in messages. False, with the messages added, when a key is not a grid axis or
// an axis is missing.
bool entry_values(const json& obj, const std::vector<GridAxis>& axes, const std::string& here,
                  const std::string& also, const std::string& what, Messages& msg,
                  std::vector<json>& v, std::vector<std::string>& w) {
  bool ok = true;
  std::string keys;
  for (const auto& axis : axes) keys += (keys.empty() ? "" : ", ") + axis.key;
  for (const auto& item : obj.items()) {
    // A plain variable, not a structured binding: clang 14 (the fuzz build) cannot capture one.
    const std::string key = item.key();
    if (key != also &&
        std::none_of(axes.begin(), axes.end(), [&](const GridAxis& a) { return a.key == key; })) {
      msg.fail(pointer_child(here, key), "not a grid axis; " + what + " sets exactly: " + keys +
                                             (also.empty() ? "" : " and " + also));
      ok = false;
    }
  }
  for (const auto& axis : axes) {
    const auto it = obj.find(axis.key);
    if (it == obj.end()) {
      msg.fail(pointer_child(here, axis.key),
               "required key is missing (" + what + " sets every grid axis: " + keys + ")");
      ok = false;
      continue;
    }
    v.push_back(*it);
    w.push_back(pointer_child(here, axis.key));
  }
  return ok;
}

}  // namespace

// The listed points (/points): objects giving a value for every grid axis, none repeating a
// grid point or an earlier listed one. Appends to values and where (see parse_sweep).
void parse_points(const json& list, const std::vector<GridAxis>& axes, Messages& msg,
                  std::vector<std::vector<json>>& values,
                  std::vector<std::vector<std::string>>& where) {
  if (!list.is_array()) {
    msg.fail("/points", "must be a list of points {\"<grid axis>\": value, ...} (got " +
                            describe_value(list) + ")");
    return;
  }
  if (axes.empty() && !list.empty()) {
    msg.fail("/points", "listed points need grid axes (/grid names the keys they set)");
    return;
  }
  std::map<std::string, std::size_t> seen;  // canonical point -> index in values
  for (std::size_t p = 0; p < values.size(); ++p) seen.emplace(canonical_json(values[p]), p);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string here = "/points/" + std::to_string(k);
    const json& obj = list[k];
    if (!obj.is_object()) {
      msg.fail(here, "a point must be an object {\"<grid axis>\": value, ...} (got " +
                         describe_value(obj) + ")");
      continue;
    }
    std::vector<json> v;
    std::vector<std::string> w;
    if (!entry_values(obj, axes, here, "", "a point", msg, v, w)) continue;
    const auto [it, fresh] = seen.emplace(canonical_json(v), values.size());
    if (!fresh) {
      const std::size_t other = it->second;
      msg.fail(here, "repeats " + (other < values.size() && !where[other].empty() &&
                                           where[other][0].rfind("/points/", 0) == 0
                                       ? "/points/" + where[other][0].substr(
                                                          8, where[other][0].find('/', 8) - 8)
                                       : std::string("a point of /grid")));
      continue;
    }
    values.push_back(std::move(v));
    where.push_back(std::move(w));
  }
}

// File name of a run: the grid values, the seed and the id, e.g.
// runs/mu_s-0.5_rho-20_s3_0123456789ab.h5.
void parse_extra_seeds(const json& list, const std::vector<GridAxis>& axes,
                       const std::vector<std::vector<json>>& values,
                       const std::vector<std::uint64_t>& seeds, Messages& msg,
                       std::vector<Sweep::ExtraSeeds>& out) {
  if (!list.is_array()) {
    msg.fail("/extra_seeds",
             "must be a list of {\"<grid axis>\": value, ..., \"seeds\": [...]} (got " +
                 describe_value(list) + ")");
    return;
  }
  if (axes.empty() && !list.empty()) {
    msg.fail("/extra_seeds", "extra seeds need grid axes (/grid names the keys of a point)");
    return;
  }
  std::map<std::string, std::size_t> index;  // canonical point -> index in values
  for (std::size_t p = 0; p < values.size(); ++p) index.emplace(canonical_json(values[p]), p);
  // point -> seed -> where it was given, to name the first place in a message
  std::map<std::size_t, std::map<std::uint64_t, std::string>> has;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string here = "/extra_seeds/" + std::to_string(k);
    const json& obj = list[k];
    if (!obj.is_object()) {
      msg.fail(here,
               "an entry must be an object {\"<grid axis>\": value, ..., \"seeds\": [...]} (got " +
                   describe_value(obj) + ")");
      continue;
    }
    std::vector<json> v;
    std::vector<std::string> w;
    bool ok = entry_values(obj, axes, here, "seeds", "an entry", msg, v, w);
    const auto s = obj.find("seeds");
    if (s == obj.end()) {
      msg.fail(here + "/seeds", "required key is missing (the seeds to add at this point)");
      ok = false;
    } else if (!s->is_array() || s->empty()) {
      msg.fail(here + "/seeds",
               "must be a non-empty list of seeds (integers >= 0; got " + describe_value(*s) + ")");
      ok = false;
    }
    if (!ok) continue;
    const auto found = index.find(canonical_json(v));
    if (found == index.end()) {
      msg.fail(here,
               "names no point of the sweep (of /grid or /points); add the point to "
               "/points to run it with every seed");
      continue;
    }
    auto& given = has[found->second];
    if (given.empty())
      for (const std::uint64_t seed : seeds) given.emplace(seed, "/seeds");
    Sweep::ExtraSeeds e;
    e.point = found->second;
    e.values = std::move(v);
    for (std::size_t i = 0; i < s->size(); ++i) {
      const std::string p = here + "/seeds/" + std::to_string(i);
      const json& x = (*s)[i];
      if (!x.is_number_unsigned()) {
        msg.fail(p, "a seed must be an integer >= 0 (got " + describe_value(x) + ")");
        continue;
      }
      const auto seed = x.get<std::uint64_t>();
      if (const auto f = given.find(seed); f != given.end()) {
        msg.fail(
            p, "the point already has seed " + std::to_string(seed) + " (from " + f->second + ")");
        continue;
      }
      given.emplace(seed, p);
      e.seeds.push_back(seed);
    }
    out.push_back(std::move(e));
  }
}

std::string run_file_name(const std::vector<GridAxis>& axes, const std::vector<json>& values,
                          std::uint64_t seed, const std::string& id) {
  std::string readable;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    if (!readable.empty()) readable += '_';
    readable += sanitize(axes[a].label) + "-" + sanitize(value_text(values[a]));
  }
  if (readable.size() > kMaxReadable) readable.resize(kMaxReadable);
  if (!readable.empty()) readable += '_';
  return "runs/" + readable + "s" + std::to_string(seed) + "_" + id.substr(0, 12) + ".h5";
}

}  // namespace wirepack::sweep::detail
