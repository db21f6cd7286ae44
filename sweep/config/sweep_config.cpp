#include "sweep/config/sweep_config.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <utility>

#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_grid.hpp"
#include "sweep/format.hpp"

namespace wirepack::sweep {

using json = nlohmann::json;

using namespace detail;

bool is_sweep_json(const json& j) {
  return j.is_object() && j.contains("grid");
}

std::string canonical_json(const json& j) {
  return canonical(j).dump();
}

json point_scene(const json& resolved_scene) {
  if (!resolved_scene.is_object()) return nullptr;
  json point = resolved_scene;
  point.erase("seed");
  point.erase("output");
  return point;
}

const std::map<std::string, json>& values_where_not_resolved() {
  static const std::map<std::string, json> table = [] {
    std::map<std::string, json> t;
    for (const auto& spec : scene_schema())
      if (spec.resolved_where && !spec.when_absent.is_null())
        t.emplace(spec.pointer, spec.when_absent);
    return t;
  }();
  return table;
}

std::string point_key(const json& resolved_scene) {
  return resolved_scene.is_object() ? canonical_json(point_scene(resolved_scene)) : "";
}

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a 64 offset basis
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;  // FNV prime
  }
  return h;
}

std::string run_id(const json& resolved_scene) {
  const std::uint64_t h = fnv1a64(canonical_json(resolved_scene));
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

double expected_cost(const SceneParams& p) {
  const double R = p.R();
  const double L = p.l_max * R;                  // injected length [m]
  const double ell = p.numerics.element_length;  // [m]
  const double steps = L / (ell * p.numerics.quasistatic_ratio);
  double nodes = L / (2 * ell);
  if (p.shell == ShellKind::Elastic) {
    const double h = p.numerics.shell_mesh_size;
    nodes +=
        8 * std::numbers::pi / std::sqrt(3.0) * R * R / (h * h);  // sphere area / area per vertex
  }
  return steps * nodes * (p.twist_enabled() ? 2.0 : 1.0);
}

Sweep parse_sweep(const json& j, const std::string& source) {
  Messages msg(source);
  if (!j.is_object()) {
    msg.fail("", "a sweep must be a JSON object (got " + describe_value(j) + ")");
    throw InputError(msg.list());
  }
  const auto& keys = sweep_keys();
  for (const auto& [key, value] : j.items())
    if (std::find(keys.begin(), keys.end(), key) == keys.end())
      msg.fail(pointer_child("", key), "unknown key; valid keys here: " + join(keys));

  Sweep sw;
  // name: used for the default output directory sweeps/<name>, so a plain file name.
  if (const auto it = j.find("name"); it == j.end()) {
    msg.fail("/name", "required key is missing");
  } else if (!it->is_string() || it->get<std::string>().empty() ||
             sanitize(it->get<std::string>()) != it->get<std::string>() ||
             it->get<std::string>()[0] == '.') {
    msg.fail("/name",
             "must be a non-empty string of letters, digits, '.', '_', '-' not starting "
             "with '.' (got " +
                 describe_value(*it) + ")");
  } else {
    sw.name = it->get<std::string>();
  }

  bool base_ok = false;
  if (const auto it = j.find("base"); it == j.end()) {
    msg.fail("/base", "required key is missing (the scene every grid point starts from)");
  } else if (!it->is_object()) {
    msg.fail("/base", "must be a scene object (got " + describe_value(*it) + ")");
  } else {
    sw.base = *it;
    base_ok = true;
    if (sw.base.contains("seed")) {
      msg.fail("/base/seed", "the seeds of a sweep are set by /seeds, not in the base scene");
      base_ok = false;
    }
  }

  if (const auto it = j.find("grid"); it == j.end()) {
    msg.fail("/grid", "required key is missing");
  } else if (!it->is_object()) {
    msg.fail("/grid",
             "must be an object of axes {\"key\": [values...]} (got " + describe_value(*it) + ")");
  } else {
    parse_axes(*it, msg, sw.axes);
  }

  parse_seeds(j, msg, sw.seeds);

  sw.analysis = json::object();
  if (const auto it = j.find("analysis"); it != j.end()) {
    if (it->is_object())
      sw.analysis = *it;
    else
      msg.fail("/analysis", "must be an object (got " + describe_value(*it) + ")");
  }

  // Count before expanding, so a typo like 1e6 values fails fast.
  std::size_t grid_points = 1;
  bool too_many = false;
  for (const auto& a : sw.axes) {
    if (grid_points > kMaxRuns / a.values.size()) too_many = true;
    grid_points *= a.values.size();
  }
  if (too_many || (!sw.seeds.empty() && grid_points > kMaxRuns / sw.seeds.size()))
    msg.fail("/grid", "the grid times the seeds has more than " + std::to_string(kMaxRuns) +
                          " runs; split the sweep");
  if (!msg.empty() || !base_ok) throw InputError(msg.list());

  // The points: the grid's in mixed radix over the sorted axes (the first axis slowest), then
  // the listed ones (/points) in their order. where[p][a] is the pointer of the value in the
  // sweep file, for messages.
  std::vector<std::vector<json>> point_values;
  std::vector<std::vector<std::string>> where;
  for (std::size_t p = 0; p < grid_points; ++p) {
    std::size_t rest = p;
    std::vector<json> v(sw.axes.size());
    std::vector<std::string> w(sw.axes.size());
    for (std::size_t a = sw.axes.size(); a-- > 0;) {
      const std::size_t i = rest % sw.axes[a].values.size();
      rest /= sw.axes[a].values.size();
      v[a] = sw.axes[a].values[i];
      w[a] = pointer_child("/grid", sw.axes[a].key) + "/" + std::to_string(i);
    }
    point_values.push_back(std::move(v));
    where.push_back(std::move(w));
  }
  if (const auto it = j.find("points"); it != j.end()) {
    parse_points(*it, sw.axes, msg, point_values, where);
    if (!sw.seeds.empty() && point_values.size() > kMaxRuns / sw.seeds.size())
      msg.fail("/points", "the points times the seeds are more than " + std::to_string(kMaxRuns) +
                              " runs; split the sweep");
    if (!msg.empty()) throw InputError(msg.list());
    for (std::size_t p = grid_points; p < point_values.size(); ++p)
      sw.listed_points.push_back(point_values[p]);
  }
  const std::size_t points = point_values.size();
  sw.grid_points = grid_points;
  std::size_t extra_runs = 0;
  if (const auto it = j.find("extra_seeds"); it != j.end()) {
    parse_extra_seeds(*it, sw.axes, point_values, sw.seeds, msg, sw.extra_seeds);
    for (const auto& e : sw.extra_seeds) extra_runs += e.seeds.size();
    if (!sw.seeds.empty() && points > (kMaxRuns - std::min(kMaxRuns, extra_runs)) / sw.seeds.size())
      msg.fail("/extra_seeds", "the runs of the sweep are more than " + std::to_string(kMaxRuns) +
                                   "; split the sweep");
    if (!msg.empty()) throw InputError(msg.list());
  }

  // Expand: every point, the seeds innermost. Every (point, seed) goes through parse_scene; its
  // messages are mapped onto the sweep file: a point value's pointer -> /grid/<key>/<i> or
  // /points/<k>/<key>, anything else -> /base/... (with the point named when not every point
  // has the problem).
  const std::string marker = "\x01";   // parse_scene's source; messages start with "\x01: "
  std::vector<std::string> base_msgs;  // base problems in first-seen order ...
  std::map<std::string, std::pair<std::size_t, std::size_t>> base_seen;  // ... -> (count, first)
  // One (point, seed): its run, or its messages (each point's counted once, in point_msgs).
  const auto expand = [&](std::size_t p, json& scene, std::uint64_t seed,
                          std::set<std::string>& point_msgs) {
    scene["seed"] = seed;
    try {
      Scene s = parse_scene(scene, marker);
      if (!msg.empty() || !base_msgs.empty()) return;  // only errors matter from now on
      SweepRun run;
      run.index = sw.runs.size();
      run.point = p;
      run.point_values = json::object();
      // The preset is not in the resolved scene, nor are keys resolved only where they act
      // (the schema's resolved_where): those take the value the grid gave.
      for (std::size_t a = 0; a < sw.axes.size(); ++a) {
        const auto& axis = sw.axes[a];
        const json::json_pointer ptr(axis.pointer);
        run.point_values[axis.key] = axis.pointer == "/numerics/preset" ? json(s.numerics_preset)
                                     : s.resolved.contains(ptr) ? std::as_const(s.resolved).at(ptr)
                                                                : point_values[p][a];
      }
      run.seed = seed;
      run.id = run_id(s.resolved);
      run.file = run_file_name(sw.axes, point_values[p], seed, run.id);
      run.cost = expected_cost(s.engine);
      run.scene = std::move(s);
      sw.runs.push_back(std::move(run));
    } catch (const InputError& e) {
      for (const auto& m : e.messages()) {
        const std::string rest = m.substr(marker.size() + 2);  // "/pointer: rule"
        bool on_axis = false;
        for (std::size_t a = 0; a < sw.axes.size() && !on_axis; ++a) {
          const std::string& ptr = sw.axes[a].pointer;
          if (rest.compare(0, ptr.size() + 2, ptr + ": ") == 0) {
            msg.add(source + ": " + where[p][a] + rest.substr(ptr.size()));
            on_axis = true;
          }
        }
        if (on_axis) continue;
        std::string text = source + ": /base" + rest;
        if (rest.find(": required key is missing") != std::string::npos ||
            rest.find(": required when shell") != std::string::npos)
          text += " (set it in /base or as a /grid axis)";
        if (!point_msgs.insert(text).second) continue;  // counted once per point
        auto [it, fresh] = base_seen.try_emplace(text, 0, p);
        if (fresh) base_msgs.push_back(text);
        ++it->second.first;
      }
    }
  };
  const auto point_scene_of = [&](std::size_t p) {
    json scene = sw.base;
    for (std::size_t a = 0; a < sw.axes.size(); ++a)
      set_at(scene, sw.axes[a].pointer, point_values[p][a]);
    return scene;
  };
  for (std::size_t p = 0; p < points; ++p) {
    json scene = point_scene_of(p);
    std::set<std::string> point_msgs;
    for (const std::uint64_t seed : sw.seeds) expand(p, scene, seed, point_msgs);
  }
  // The extra seeds' runs after every point's (a seed changes no rule, so a point's problems
  // are reported above already).
  for (const auto& e :
       msg.empty() && base_msgs.empty() ? sw.extra_seeds : std::vector<Sweep::ExtraSeeds>{}) {
    json scene = point_scene_of(e.point);
    std::set<std::string> point_msgs;
    for (const std::uint64_t seed : e.seeds) expand(e.point, scene, seed, point_msgs);
  }
  for (const auto& text : base_msgs) {
    const auto [count, first] = base_seen.at(text);
    if (count == points || sw.axes.empty()) {
      msg.add(text);
      continue;
    }
    // Name the first grid point that has the problem.
    std::string at;
    for (std::size_t a = 0; a < sw.axes.size(); ++a)
      at += (at.empty() ? "" : ", ") + sw.axes[a].key + " = " + value_text(point_values[first][a]);
    msg.add(text + " (at grid point " + at +
            (count > 1 ? " and " + std::to_string(count - 1) + " more" : "") + ")");
  }
  if (!msg.empty()) throw InputError(msg.list());

  json grid = json::object();
  for (const auto& axis : sw.axes) grid[axis.key] = axis.values;
  sw.resolved = {{"name", sw.name},
                 {"base", sw.base},
                 {"grid", grid},
                 {"seeds", sw.seeds},
                 {"analysis", sw.analysis}};
  if (!sw.listed_points.empty()) {
    json list = json::array();
    for (const auto& v : sw.listed_points) {
      json point = json::object();
      for (std::size_t a = 0; a < sw.axes.size(); ++a) point[sw.axes[a].key] = v[a];
      list.push_back(point);
    }
    sw.resolved["points"] = list;
  }
  if (!sw.extra_seeds.empty()) {
    json list = json::array();
    for (const auto& e : sw.extra_seeds) {
      json entry = json::object();
      for (std::size_t a = 0; a < sw.axes.size(); ++a) entry[sw.axes[a].key] = e.values[a];
      entry["seeds"] = e.seeds;
      list.push_back(entry);
    }
    sw.resolved["extra_seeds"] = list;
  }
  return sw;
}

Sweep load_sweep(const std::string& path) {
  return load_and_parse(path,
                        [](const json& j, const std::string& src) { return parse_sweep(j, src); });
}

const json& default_sweep_json() {
  // The paper's elastic D(mu_s) at rho = 20, xi = 10, eps = 1e3 across the transition: the
  // coil at mu_s = 0 and 0.1, the crumpled packing at 0.25 and 0.5 (README, first command).
  // The default preset with a shell mesh of 3 r (not 2 r) and l up to 14 keep it within a few
  // minutes on 2 cores; D is maximised over l in [8, 14], after the bifurcation at l ~ 6.5
  // (below l ~ 8 the wire's entry chord gives a coil D ~ 1 / l, docs/reference.md "Analysis").
  static const json j = {{"name", "default"},
                         {"base",
                          {{"rho", 20},
                           {"xi", 10},
                           {"eps", 1000},
                           {"shell", "elastic"},
                           {"l_max", 14},
                           {"numerics", {{"preset", "default"}, {"shell_mesh_size", 0.0015}}},
                           {"output", {{"snapshots_every_l", 2}}}}},
                         {"grid", {{"mu_s", {0, 0.1, 0.25, 0.5}}}},
                         {"seeds", 2},
                         {"analysis", {{"D_window", {8, 14}}}}};
  return j;
}

}  // namespace wirepack::sweep
