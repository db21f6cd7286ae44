#include "sweep/config/scene_config.hpp"

#include <cmath>
#include <map>
#include <set>

#include "engine/scene.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/format.hpp"

namespace wirepack::sweep {

using json = nlohmann::json;
using Type = KeySpec::Type;
using Need = KeySpec::Need;

namespace {

std::vector<std::string> split_pointer(const std::string& pointer) {
  std::vector<std::string> tokens;
  std::size_t pos = 1;
  while (pos <= pointer.size()) {
    const auto next = pointer.find('/', pos);
    const auto end = next == std::string::npos ? pointer.size() : next;
    tokens.push_back(pointer.substr(pos, end - pos));
    pos = end + 1;
  }
  return tokens;
}

std::string join(const std::set<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Valid child keys per object level ("" is the root) and the levels that are groups.
struct Levels {
  std::map<std::string, std::set<std::string>> children;
  std::set<std::string> groups;
};

const Levels& levels() {
  static const Levels lv = [] {
    Levels out;
    for (const auto& spec : scene_schema()) {
      const auto tokens = split_pointer(spec.pointer);
      std::string level;
      for (std::size_t i = 0; i < tokens.size(); ++i) {
        out.children[level].insert(tokens[i]);
        level += "/" + tokens[i];
        if (i + 1 < tokens.size()) out.groups.insert(level);
      }
    }
    out.children["/numerics"].insert("preset");  // handled beside the table (numerics_presets)
    return out;
  }();
  return lv;
}

class Validator {
 public:
  explicit Validator(std::string source) : source_(std::move(source)) {}

  void fail(const std::string& pointer, const std::string& rule) {
    errors_.push_back(source_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + rule);
  }
  const std::vector<std::string>& errors() const { return errors_; }

  // Unknown keys and groups that are not objects, recursively.
  void check_keys(const json& obj, const std::string& level) {
    const auto& lv = levels();
    const auto& valid = lv.children.at(level);
    for (const auto& [key, value] : obj.items()) {
      const std::string child = pointer_child(level, key);
      if (!valid.contains(key)) {
        fail(child, "unknown key; valid keys here: " + join(valid));
      } else if (lv.groups.contains(child)) {
        if (value.is_object())
          check_keys(value, child);
        else
          fail(child, "must be an object with keys " + join(lv.children.at(child)) + " (got " +
                          describe_value(value) + ")");
      }
    }
  }

  // Checks one present value against its spec; returns the canonical value (numbers as
  // double, integers as int) or nothing after recording the error.
  std::optional<json> check_value(const KeySpec& spec, const json& v) {
    double x = 0;
    json canonical;
    switch (spec.type) {
      case Type::Choice:
        for (const auto& c : spec.choices)
          if (v.is_string() && v.get<std::string>() == c) return json(c);
        fail(spec.pointer,
             "must be one of " + spec.range_text() + " (got " + describe_value(v) + ")");
        return std::nullopt;
      case Type::Number:
        if (!v.is_number()) {
          fail(spec.pointer, "must be a number (got " + describe_value(v) + ")");
          return std::nullopt;
        }
        x = v.get<double>();
        if (!std::isfinite(x)) {
          fail(spec.pointer, "must be a finite number (got " + describe_value(v) + ")");
          return std::nullopt;
        }
        canonical = x;
        break;
      case Type::Integer:
        if (!v.is_number_integer()) {
          fail(spec.pointer, "must be an integer (got " + describe_value(v) + ")");
          return std::nullopt;
        }
        if (v.is_number_unsigned()) {
          canonical = v.get<std::uint64_t>();
          x = static_cast<double>(v.get<std::uint64_t>());
        } else {
          canonical = v.get<std::int64_t>();
          x = static_cast<double>(v.get<std::int64_t>());
        }
        break;
    }
    const bool below =
        spec.min && (spec.min->inclusive ? x < spec.min->value : x <= spec.min->value);
    const bool above =
        spec.max && (spec.max->inclusive ? x > spec.max->value : x >= spec.max->value);
    if (below || above) {
      std::string range = spec.range_text();
      if (!spec.extra_rule.empty())
        range = range.substr(0, range.size() - spec.extra_rule.size() - 2);
      fail(spec.pointer, std::string("must be ") + (spec.min && spec.max ? "in " : "") + range +
                             " (got " + describe_value(v) + ")");
      return std::nullopt;
    }
    return canonical;
  }

 private:
  std::string source_;
  std::vector<std::string> errors_;
};

enum class Lookup { Found, Missing, ParentInvalid };

// Finds `pointer` in `j`; a non-object on the way is ParentInvalid (reported by check_keys).
Lookup lookup(const json& j, const std::string& pointer, const json** out) {
  const json* node = &j;
  const auto tokens = split_pointer(pointer);
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!node->is_object()) return Lookup::ParentInvalid;
    const auto it = node->find(tokens[i]);
    if (it == node->end()) return Lookup::Missing;
    node = &*it;
  }
  *out = node;
  return Lookup::Found;
}

}  // namespace

Scene parse_scene(const json& j, const std::string& source) {
  Validator val(source);
  if (!j.is_object()) {
    val.fail("", "a scene must be a JSON object (got " + describe_value(j) + ")");
    throw InputError(val.errors());
  }
  // Numerics preset: "numerics": "NAME" is read as {"preset": "NAME"}; the preset fills the
  // defaults of the four resolution knobs below (keys given beside it win).
  json in = j;
  std::string preset = "default";
  if (const auto it = j.find("numerics"); it != j.end()) {
    const bool as_string = it->is_string();
    const bool in_object = it->is_object() && it->contains("preset");
    if (as_string || in_object) {
      const json& name = as_string ? *it : it->at("preset");
      if (name.is_string() && find_numerics_preset(name.get<std::string>()))
        preset = name.get<std::string>();
      else
        val.fail(as_string ? "/numerics" : "/numerics/preset",
                 "must be a preset: one of " + preset_names() + ", or an object of numerics " +
                     "keys (got " + describe_value(name) + ")");
    }
    if (as_string) in["numerics"] = json::object();
  }
  val.check_keys(in, "");
  const auto& schema = scene_schema();

  // The shell kind decides whether xi and eps are required; unknown if /shell is invalid.
  bool shell_known = true, elastic = true;
  {
    const json* v = nullptr;
    if (lookup(j, "/shell", &v) == Lookup::Found) {
      shell_known = v->is_string() && (*v == "elastic" || *v == "rigid");
      elastic = shell_known && *v == "elastic";
    }
  }

  // Table pass: type, finiteness and range of every key; defaults for missing ones.
  std::map<std::string, json> values;  // pointer -> canonical valid value
  std::set<std::string> given;         // pointers present in the input
  for (const auto& spec : schema) {
    const json* v = nullptr;
    const Lookup found = lookup(in, spec.pointer, &v);
    if (found == Lookup::Found) given.insert(spec.pointer);
    if (found == Lookup::ParentInvalid) continue;
    if (found == Lookup::Found) {
      if (auto c = val.check_value(spec, *v)) values[spec.pointer] = *c;
      continue;
    }
    switch (spec.need) {
      case Need::Required:
        val.fail(spec.pointer, "required key is missing");
        break;
      case Need::RequiredIfElastic:
        if (shell_known && elastic)
          val.fail(spec.pointer,
                   "required when shell is \"elastic\" (may be omitted for \"rigid\")");
        break;
      case Need::Optional:
        if (!spec.fallback.is_null()) values[spec.pointer] = spec.fallback;
        break;
    }
  }

  // Cross-key rules (the table's extra_rule column) and derived defaults.
  const auto has = [&](const char* p) { return values.contains(p); };
  const auto get = [&](const char* p) { return values.at(p).get<double>(); };
  bool mu_d_given = false;
  {
    const json* v = nullptr;
    mu_d_given = lookup(in, "/mu_d", &v) == Lookup::Found;
  }
  if (has("/mu_s") && !mu_d_given) values["/mu_d"] = 0.9 * get("/mu_s");
  const NumericsPreset& ps = *find_numerics_preset(preset);
  const auto fill = [&](const char* p, double x) {
    if (!given.contains(p)) values[p] = x;
  };
  if (has("/wire/radius")) {
    fill("/numerics/element_length", ps.element_per_r * get("/wire/radius"));
    fill("/numerics/shell_mesh_size", ps.mesh_per_r * get("/wire/radius"));
  }
  fill("/numerics/quasistatic_ratio", ps.quasistatic_ratio);
  fill("/numerics/tolerance", ps.tolerance);
  if (!given.contains("/numerics/mass_scaling")) values["/numerics/mass_scaling"] = ps.mass_scaling;
  if (has("/mu_s") && has("/mu_d") && get("/mu_d") > get("/mu_s"))
    val.fail("/mu_d", "must be <= mu_s = " + format_number(get("/mu_s")) + " (got " +
                          format_number(get("/mu_d")) + ")");
  if (has("/rho") && has("/wire/radius") && has("/numerics/element_length")) {
    const double R = get("/rho") * get("/wire/radius");
    const double ell = get("/numerics/element_length");
    if (ell > R / 4)
      val.fail("/numerics/element_length",
               "must be <= R/4 = " + format_number(R / 4) + " m with R = rho * wire/radius = " +
                   format_number(R) + " m (got " + format_number(ell) + ")");
  }

  if (!val.errors().empty()) throw InputError(val.errors());

  Scene scene;
  scene.resolved = json::object();
  for (const auto& spec : schema) {
    const auto it = values.find(spec.pointer);
    if (it == values.end()) continue;  // xi, eps omitted for a rigid shell
    spec.apply(scene, it->second);
    scene.resolved[json::json_pointer(spec.pointer)] = it->second;
  }
  // Keys added after runs existed are resolved only where their rows' rule says (where they act
  // or differ from their defaults), so the runs they leave unchanged, bitwise, keep their ids.
  for (const auto& spec : schema) {
    if (!spec.resolved_where || spec.resolved_where(scene, given.contains(spec.pointer))) continue;
    json::json_pointer at(spec.pointer);
    if (!scene.resolved.contains(at)) continue;
    while (!at.empty()) {  // the key, then each object it leaves empty
      json& parent = scene.resolved[at.parent_pointer()];
      parent.erase(at.back());
      if (!parent.empty()) break;
      at = at.parent_pointer();
    }
  }
  scene.numerics_preset = preset;
  return scene;
}

Scene load_scene(const std::string& path) {
  return load_and_parse(path,
                        [](const json& j, const std::string& src) { return parse_scene(j, src); });
}

const nlohmann::json& default_scene_json() {
  static const nlohmann::json j = {{"rho", 20}, {"mu_s", 0}, {"shell", "rigid"}, {"l_max", 20}};
  return j;
}

}  // namespace wirepack::sweep
