#pragma once
// Sweep file (docs/design.md §4.4):
// {"name", "base": {scene}, "grid": {"<key or JSON pointer>": [values]},
// "points": [{"<key>": value, ...}], "seeds": 10 | [list],
// "extra_seeds": [{"<key>": value, ..., "seeds": [list]}], "analysis": {...}}. The points are
// the Cartesian product of the grid's axes, then the listed points (each sets every axis); each
// point runs with every seed, and a point named in extra_seeds with those seeds too; every
// (point, seed) is one scene validated by parse_scene, errors reported against the sweep file's
// own pointers (`sweep.json: /grid/mu_s/2: must be >= 0`).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/config/scene_config.hpp"
#include "sweep/errors.hpp"

namespace wirepack::sweep {

// One axis of the grid.
struct GridAxis {
  std::string key;      // as written in the file: "mu_s" or "/numerics/element_length"
  std::string pointer;  // the scene key it sets, e.g. "/mu_s"
  std::string label;    // short name for file names, e.g. "element_length"
  std::vector<nlohmann::json> values;  // in file order
};

// One simulation of the sweep: a grid point and a seed.
struct SweepRun {
  std::size_t index = 0;  // position in the deterministic run order (points major, seeds minor;
                          // the extra seeds' runs last)
  std::size_t point = 0;  // grid point (mixed radix over the axes, the first axis slowest;
                          // listed points follow the grid's)
  nlohmann::json point_values;  // {axis key: resolved value}, e.g. {"mu_s": 0.5, "rho": 20.0}
  std::uint64_t seed = 0;
  Scene scene;       // validated, seed set; scene.resolved is the run's identity
  std::string id;    // 16 hex digits: FNV-1a 64 of canonical_json(scene.resolved)
  std::string file;  // relative to the sweep directory: runs/<params>_s<seed>_<id 12>.h5
  double cost = 0;   // expected relative cost (expected_cost), for scheduling only
};

struct Sweep {
  std::string name;
  nlohmann::json base;         // the base scene as given (not resolved: the grid may complete it)
  std::vector<GridAxis> axes;  // sorted by pointer, so the order is independent of the file
  // Listed points ("points": [{"<axis key>": value, ...}]) after the grid's, one value per axis
  // in `axes` order; `wirepack refine` adds its grid values here.
  std::vector<std::vector<nlohmann::json>> listed_points;
  std::vector<std::uint64_t> seeds;  // every point's seeds
  // Further seeds at single points ("extra_seeds"; `wirepack refine` adds them where seeds, not
  // grid values, narrow the interval of x_c): the point's index and values (as listed_points) and
  // seeds none of which is in `seeds` or in an earlier entry for that point.
  struct ExtraSeeds {
    std::size_t point = 0;
    std::vector<nlohmann::json> values;
    std::vector<std::uint64_t> seeds;
  };
  std::vector<ExtraSeeds> extra_seeds;
  nlohmann::json analysis;      // free-form settings for the analysis stage (an object)
  nlohmann::json resolved;      // {"name", "base", "grid", ["points",] "seeds" (as a list),
                                // ["extra_seeds",] "analysis"}; the optional ones when not empty
  std::size_t grid_points = 0;  // points of /grid (the listed points follow)
  // In run order: index i < (grid_points + listed) * seeds.size() is point i / seeds.size() with
  // seed position i % seeds.size(); the extra seeds' runs follow, entry by entry.
  std::vector<SweepRun> runs;

  std::size_t points() const { return grid_points + listed_points.size(); }
};

// A parsed JSON document is a sweep (not a scene) when it is an object with a "grid" key.
bool is_sweep_json(const nlohmann::json& j);

// Validates a parsed sweep and expands it; `source` names it in messages. Throws InputError
// listing every problem found (each grid value and base key once, however many points share it).
Sweep parse_sweep(const nlohmann::json& j, const std::string& source);
// Reads (strictly, see json_file.hpp), validates and expands a sweep file.
Sweep load_sweep(const std::string& path);

// The embedded default sweep of `wirepack sweep` without a file; the same as
// scenes/default.sweep.json (a test keeps them equal).
const nlohmann::json& default_sweep_json();

// Canonical text of a JSON value: keys sorted, no whitespace, every number as a double
// (so 20 and 20.0 are the same), -0 as 0.
std::string canonical_json(const nlohmann::json& j);
// FNV-1a 64 of `bytes` (run ids, run checkpoints' checksum).
std::uint64_t fnv1a64(std::string_view bytes);
// FNV-1a 64 of canonical_json(resolved scene), as 16 lower-case hex digits.
std::string run_id(const nlohmann::json& resolved_scene);

// The grid point of a resolved scene: the scene without its seed and its output settings, so
// runs of one point differ only in the seed (docs/design.md §5.8). Not an object: null.
nlohmann::json point_scene(const nlohmann::json& resolved_scene);
// canonical_json(point_scene(...)): the key that groups runs into grid points ("" when the
// scene is not an object).
std::string point_key(const nlohmann::json& resolved_scene);
// Keys resolved only where they act whose absence has one meaning, with that value (the schema's
// `when_absent`: feeder_spin "held", friction_stiffness_ratio "mindlin", ...), for tables that
// compare points with and without them.
const std::map<std::string, nlohmann::json>& values_where_not_resolved();

// Expected relative cost of a run, for longest-first scheduling (not a time in any unit).
// With L = l_max R injected, elements of length ell and the mass scaling q, the step is bounded
// by the axial wave crossing an element, dt ~ ell q / v, so a run takes ~ L / (ell q) steps of
// O(nodes) work each: wire nodes grow to L / ell (L / (2 ell) on average) plus ~14.5 R^2 / h^2
// shell vertices for an elastic shell (mesh size h). Twist (friction) doubles the work per node.
// cost = L / (ell q) * (L / (2 ell) + shell vertices) * (2 if twist else 1).
double expected_cost(const SceneParams& p);

}  // namespace wirepack::sweep
