#pragma once
// Strict scene config (docs/design.md §4.1): one table of (JSON pointer, type, default,
// range, doc) drives validation, default filling, `wirepack validate` and the schema in
// docs/reference.md. Errors are collected and thrown together as one InputError.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/params.hpp"
#include "sweep/errors.hpp"

namespace wirepack::sweep {

// What the run loop records, in units of l = L / R.
struct OutputParams {
  double every_l = 0.1;            // series sampling interval [-]
  double snapshots_every_l = 5.0;  // snapshot interval [-]
};

struct Scene {
  SceneParams engine;       // what the engine sees
  OutputParams output;      // what the run loop records
  nlohmann::json resolved;  // the validated input with every default filled (sorted keys)
  std::string numerics_preset = "default";  // the preset the numerics defaults came from
};

// A numerics preset (docs/reference.md "Scene file"; measured in docs/measurements.md "Presets"):
// `"numerics": "NAME"` or `{"preset": "NAME", ...}` sets these four defaults; keys given beside
// "preset" override them. Not part of the resolved scene (a run's identity is its resolved values,
// so "default" and no preset are one run).
struct NumericsPreset {
  std::string name;                        // "fast" | "default" | "accurate" | "inertial"
  double element_per_r;                    // element_length / wire radius [-]
  double mesh_per_r;                       // shell_mesh_size / wire radius [-]
  double quasistatic_ratio;                // [-]
  double tolerance;                        // [r]
  std::string summary;                     // what it buys, from the accuracy-vs-time study
  std::string mass_scaling = "selective";  // numerics/mass_scaling unless given
};
const std::vector<NumericsPreset>& numerics_presets();
// The preset called `name`, or nullptr.
const NumericsPreset* find_numerics_preset(const std::string& name);
// The presets' names, quoted and comma-separated, for messages.
std::string preset_names();

// One row of the schema table.
struct KeySpec {
  enum class Type { Number, Integer, Choice };
  enum class Need { Optional, Required, RequiredIfElastic };
  struct Bound {
    double value;
    bool inclusive;
  };
  std::string pointer;  // JSON pointer, e.g. "/wire/radius"
  Type type;
  Need need;
  nlohmann::json fallback = nullptr;  // default when optional; null: derived (default_text)
  std::string default_text = {};      // the default as the schema shows it, e.g. "0.9 mu_s"
  std::optional<Bound> min = {};      // numeric range (Number, Integer)
  std::optional<Bound> max = {};
  std::vector<std::string> choices = {};  // allowed strings (Choice)
  std::string extra_rule = {};            // cross-key rule, checked after the table, e.g. "<= mu_s"
  // The key's parts in the analysis (report/), so that no list of names lives elsewhere.
  struct Roles {
    bool column = false;        // a column of every per-point table; also `physical`
    bool physical = false;      // a physical parameter: taken as a swept axis before numerics keys
    bool transition = false;    // a control parameter of the transition: critical points, refine
    bool log_scale = false;     // spans decades: its critical points are fitted in log10
    bool refine_first = false;  // refine's axis where several transition parameters are swept
    bool label = false;         // names a scene in words where nothing else varies (accuracy study)
  };
  Roles roles = {};
  // Keys added after runs existed enter the resolved scene (so a run's id) only where this holds
  // for the parsed scene (null: always; `given`: the scene file names the key), so that runs
  // they leave bitwise unchanged keep their ids.
  bool (*resolved_where)(const Scene&, bool given) = nullptr;
  // What a key's absence from a resolved scene means, for tables that compare points with and
  // without it (null: no one meaning).
  nlohmann::json when_absent = nullptr;
  std::string doc = {};
  // Copies a validated value into the Scene.
  void (*apply)(Scene&, const nlohmann::json&);

  std::string type_name() const;   // "number", "integer", "string"
  std::string range_text() const;  // e.g. "(0, 0.5]", "> 2", "\"auto\" | \"on\" | \"off\""
};

// The scene schema, in documentation order.
const std::vector<KeySpec>& scene_schema();
// The row of `pointer`, or nullptr.
const KeySpec* find_key(const std::string& pointer);
// The pointers whose row has the role (e.g. &KeySpec::Roles::transition), in schema order.
std::vector<std::string> keys_with(bool KeySpec::Roles::*role);
// The same as names without the leading '/', comma-separated, for messages: "rho, xi, eps".
std::string key_names_with(bool KeySpec::Roles::*role);

// Validates a parsed scene; `source` names it in messages (`SOURCE: /pointer: rule`).
// Throws InputError listing every problem found.
Scene parse_scene(const nlohmann::json& j, const std::string& source);
// Reads, parses (strictly, see json_file.hpp) and validates a scene file.
Scene load_scene(const std::string& path);

// The embedded default scene of `wirepack run` without a scene file (the same as
// scenes/rigid_default.json): a rigid sphere, rho = 20, mu_s = 0, to l = 20.
const nlohmann::json& default_scene_json();

// The schema as a Markdown table: pointer | type | default | range | doc.
std::string schema_markdown();

}  // namespace wirepack::sweep
