// Strict scene config (docs/design.md §4.1): defaults, every kind of malformed input, error
// collection.
#include "sweep/config/scene_config.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "sweep/config/sweep_config.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::sweep {
namespace {

using json = nlohmann::json;
using wirepack::testing::TempDir;

json minimal_elastic() {
  return {{"rho", 20}, {"xi", 10}, {"eps", 1000}, {"mu_s", 0.5}};
}
json minimal_rigid() {
  return {{"rho", 20}, {"mu_s", 0}, {"shell", "rigid"}};
}

// The InputError messages for `j`, or a test failure if it is accepted.
std::vector<std::string> errors_of(const json& j) {
  try {
    parse_scene(j, "scene.json");
  } catch (const InputError& e) {
    return e.messages();
  }
  ADD_FAILURE() << "accepted: " << j.dump();
  return {};
}

// One error that names the file, the pointer and the rule.
void expect_error(const json& j, const std::string& pointer, const std::string& rule) {
  const auto errors = errors_of(j);
  bool found = false;
  for (const auto& e : errors)
    found = found ||
            (e.rfind("scene.json: " + pointer + ": ", 0) == 0 && e.find(rule) != std::string::npos);
  std::string all;
  for (const auto& e : errors) all += e + "\n";
  EXPECT_TRUE(found) << "expected '" << pointer << "' / '" << rule << "' in:\n" << all;
}

TEST(SceneConfig, DefaultsFilled) {
  const Scene s = parse_scene(minimal_elastic(), "scene.json");
  EXPECT_EQ(s.engine.rho, 20);
  EXPECT_EQ(s.engine.xi, 10);
  EXPECT_EQ(s.engine.eps, 1000);
  EXPECT_EQ(s.engine.mu_s, 0.5);
  EXPECT_DOUBLE_EQ(s.engine.mu_d, 0.45);  // 0.9 mu_s
  EXPECT_EQ(s.engine.l_max, 50);
  EXPECT_EQ(s.engine.seed, 1u);
  EXPECT_EQ(s.engine.shell, ShellKind::Elastic);
  EXPECT_EQ(s.engine.injection_speed, 0.5);
  EXPECT_EQ(s.engine.wire.radius, 0.5e-3);
  EXPECT_EQ(s.engine.wire.youngs_modulus, 1e9);
  EXPECT_DOUBLE_EQ(s.engine.wire.poisson_ratio, 1.0 / 3.0);
  EXPECT_EQ(s.engine.wire.density, 1140);
  EXPECT_EQ(s.engine.numerics.element_length, 0.5e-3);
  EXPECT_EQ(s.engine.numerics.shell_mesh_size, 1e-3);
  EXPECT_EQ(s.engine.numerics.quasistatic_ratio, 0.01);
  EXPECT_EQ(s.engine.numerics.tolerance, 1e-3);
  EXPECT_EQ(s.engine.numerics.damping_ratio, 0.05);
  EXPECT_EQ(s.engine.numerics.twist, EffectMode::Auto);
  EXPECT_EQ(s.output.every_l, 0.1);
  EXPECT_EQ(s.output.snapshots_every_l, 5);

  // The resolved JSON has every key of the schema, each a valid value, except the one added
  // after runs existed whose default leaves them unchanged in physics, bitwise, wherever it is
  // not resolved (shell_inertia_thickness: resolved where it acts, on thin soft shells, t < r
  // and eps > 350; SceneConfig.ShellInertiaResolvedWhereItActs; damping_form and the
  // perturbation keys: where not their defaults), so no such run's id moves.
  for (const auto& spec : scene_schema()) {
    const bool neutral = spec.resolved_where != nullptr;
    EXPECT_EQ(s.resolved.contains(json::json_pointer(spec.pointer)), !neutral) << spec.pointer;
  }
  EXPECT_EQ(s.engine.numerics.shell_inertia_factor, 1.0);
  EXPECT_DOUBLE_EQ(s.resolved["mu_d"].get<double>(), 0.45);
  EXPECT_EQ(s.resolved["/numerics/twist"_json_pointer], "auto");
  // Resolving is idempotent: the resolved scene resolves to itself.
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);
}

// damping_form and the perturbation keys (Engine VI) enter the resolved scene only where they
// differ from their defaults, so every run made before them keeps its id; given, they reach the
// engine and resolve idempotently.
TEST(SceneConfig, DampingFormAndPerturbationResolvedWhereNotDefault) {
  json j = minimal_elastic();
  j["numerics"]["damping_form"] = "relative";
  j["perturbation"] = {{"deflection", 0.05}, {"release_noise", 1e-3}, {"offset", 0}};
  const Scene plain = parse_scene(j, "s.json");
  EXPECT_EQ(plain.resolved, parse_scene(minimal_elastic(), "s.json").resolved);
  EXPECT_EQ(plain.engine.numerics.damping_form, DampingForm::Relative);

  j["numerics"]["damping_form"] = "absolute";
  j["perturbation"]["offset"] = 1e-6;
  const Scene s = parse_scene(j, "s.json");
  EXPECT_EQ(s.engine.numerics.damping_form, DampingForm::Absolute);
  EXPECT_EQ(s.engine.perturbation_offset, 1e-6);
  EXPECT_EQ(s.engine.perturbation_deflection, 0.05);
  EXPECT_EQ(s.resolved["/numerics/damping_form"_json_pointer], "absolute");
  EXPECT_EQ(s.resolved["perturbation"], json({{"offset", 1e-6}}));      // defaults left out
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);  // idempotent

  j["numerics"]["damping_form"] = "viscous";
  EXPECT_THROW(parse_scene(j, "s.json"), InputError);
  j["numerics"]["damping_form"] = "absolute";
  j["perturbation"]["release_noise"] = -1;
  EXPECT_THROW(parse_scene(j, "s.json"), InputError);
}

// shell_inertia_thickness is in the resolved scene (so in the run's id) exactly where it changes
// the result: a thin soft shell (t = R / xi < r, eps > 350), or when given.
TEST(SceneConfig, ShellInertiaResolvedWhereItActs) {
  const auto resolved_has = [](json j) {
    return parse_scene(j, "s.json")
        .resolved.contains("/numerics/shell_inertia_thickness"_json_pointer);
  };
  json thin = minimal_elastic();
  thin["xi"] = 200;
  thin["eps"] = 1e4;
  EXPECT_TRUE(resolved_has(thin));
  const Scene s = parse_scene(thin, "s.json");
  EXPECT_EQ(s.resolved["/numerics/shell_inertia_thickness"_json_pointer], 1.0);
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);  // idempotent
  json stiff = thin;
  stiff["eps"] = 100;  // the cap: no heavier than a physical shell, here t itself
  EXPECT_FALSE(resolved_has(stiff));
  json thick = thin;
  thick["xi"] = 10;  // t = 2 r
  EXPECT_FALSE(resolved_has(thick));
  json given = thick;
  given["numerics"]["shell_inertia_thickness"] = 1;
  EXPECT_TRUE(resolved_has(given));
  EXPECT_FALSE(resolved_has(minimal_rigid()));
}

// friction_stiffness_ratio is resolved where it is given and friction acts (mu_s > 0); absent,
// the engine takes Mindlin's ratio (0 here) and the run's id is the one it had before the key.
TEST(SceneConfig, FrictionStiffnessRatioResolvedWhereGiven) {
  const auto resolved = [](json j) { return parse_scene(j, "s.json").resolved; };
  json j = minimal_elastic();  // mu_s = 0.5
  EXPECT_FALSE(resolved(j).contains("friction_stiffness_ratio"));
  EXPECT_EQ(parse_scene(j, "s.json").engine.friction_stiffness_ratio, 0.0);
  j["friction_stiffness_ratio"] = 0.2;
  const Scene s = parse_scene(j, "s.json");
  EXPECT_EQ(s.engine.friction_stiffness_ratio, 0.2);
  EXPECT_EQ(s.resolved["friction_stiffness_ratio"], 0.2);
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);  // idempotent
  json frictionless = j;
  frictionless["mu_s"] = 0;
  EXPECT_FALSE(resolved(frictionless).contains("friction_stiffness_ratio"));
  j["friction_stiffness_ratio"] = 0;
  expect_error(j, "/friction_stiffness_ratio", "> 0");
  j["friction_stiffness_ratio"] = "stiff";
  expect_error(j, "/friction_stiffness_ratio", "number");
}

// feeder_spin is in the resolved scene exactly where it changes the result: a swivel ("free")
// with twist DOFs (mu_s > 0, or twist "on"). "held" is the engine's behaviour before the key
// existed, so it never enters the id, given or not.
TEST(SceneConfig, FeederSpinResolvedWhereItActs) {
  const auto resolved = [](json j) { return parse_scene(j, "s.json").resolved; };
  json j = minimal_elastic();  // mu_s = 0.5: twist on
  EXPECT_FALSE(resolved(j).contains("feeder_spin"));
  EXPECT_EQ(parse_scene(j, "s.json").engine.feeder_spin, FeederSpin::Held);
  j["feeder_spin"] = "held";
  EXPECT_EQ(resolved(j), resolved(minimal_elastic()));
  j["feeder_spin"] = "free";
  const Scene s = parse_scene(j, "s.json");
  EXPECT_EQ(s.engine.feeder_spin, FeederSpin::Free);
  EXPECT_EQ(s.resolved["feeder_spin"], "free");
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);  // idempotent
  json frictionless = j;
  frictionless["mu_s"] = 0;  // no twist DOFs: nothing to hold
  EXPECT_FALSE(resolved(frictionless).contains("feeder_spin"));
  frictionless["numerics"]["twist"] = "on";
  EXPECT_TRUE(resolved(frictionless).contains("feeder_spin"));
  json bad = j;
  bad["feeder_spin"] = "loose";
  const auto errs = errors_of(bad);
  ASSERT_EQ(errs.size(), 1u);
  EXPECT_NE(errs[0].find("/feeder_spin"), std::string::npos) << errs[0];
  EXPECT_NE(errs[0].find("free"), std::string::npos) << errs[0];
}

TEST(SceneConfig, CanonicalNumbers) {
  // 20 and 20.0 are the same scene, so they resolve to the same JSON text (run ids).
  json a = minimal_elastic(), b = minimal_elastic();
  b["rho"] = 20.0;
  EXPECT_EQ(parse_scene(a, "a").resolved.dump(), parse_scene(b, "b").resolved.dump());
}

TEST(SceneConfig, ExplicitValuesKept) {
  json j = minimal_elastic();
  j["mu_d"] = 0.2;
  j["seed"] = 7;
  j["numerics"] = {{"twist", "off"}, {"element_length", 1e-3}};
  j["output"] = {{"every_l", 0.5}};
  j["wire"] = {{"poisson_ratio", 0}};
  const Scene s = parse_scene(j, "scene.json");
  EXPECT_EQ(s.engine.mu_d, 0.2);
  EXPECT_EQ(s.engine.seed, 7u);
  EXPECT_EQ(s.engine.numerics.twist, EffectMode::Off);
  EXPECT_EQ(s.engine.numerics.element_length, 1e-3);
  EXPECT_EQ(s.engine.wire.poisson_ratio, 0);
  EXPECT_EQ(s.output.every_l, 0.5);
  EXPECT_EQ(s.output.snapshots_every_l, 5);
  EXPECT_EQ(s.engine.numerics.shell_mesh_size, 1e-3);  // sibling default still filled
}

TEST(SceneConfig, RigidMayOmitXiEps) {
  const Scene s = parse_scene(minimal_rigid(), "scene.json");
  EXPECT_EQ(s.engine.shell, ShellKind::Rigid);
  EXPECT_FALSE(s.resolved.contains("xi"));
  EXPECT_FALSE(s.resolved.contains("eps"));
  EXPECT_EQ(s.engine.mu_d, 0);

  // Given for a rigid shell: validated and kept.
  json j = minimal_rigid();
  j["xi"] = 30;
  EXPECT_EQ(parse_scene(j, "scene.json").resolved["xi"], 30.0);
  j["xi"] = 0.5;
  expect_error(j, "/xi", "> 1");
}

TEST(SceneConfig, MissingRequired) {
  json j = minimal_elastic();
  j.erase("rho");
  expect_error(j, "/rho", "required");
  j = minimal_elastic();
  j.erase("xi");
  expect_error(j, "/xi", "required when shell is \"elastic\"");
  j = minimal_elastic();
  j.erase("eps");
  expect_error(j, "/eps", "required");
  j = minimal_elastic();
  j.erase("mu_s");
  expect_error(j, "/mu_s", "required");
  // An invalid shell kind does not add a spurious "xi required".
  j = {{"rho", 20}, {"mu_s", 0}, {"shell", "soft"}};
  const auto errors = errors_of(j);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("/shell: must be one of \"elastic\", \"rigid\""), std::string::npos);
}

TEST(SceneConfig, UnknownKeys) {
  json j = minimal_elastic();
  j["rh0"] = 20;
  expect_error(j, "/rh0",
               "unknown key; valid keys here: eps, feeder_spin, friction_stiffness_ratio, "
               "injection_speed, l_max");
  j = minimal_elastic();
  j["wire"] = {{"radius", 1e-3}, {"diameter", 2e-3}};
  expect_error(j, "/wire/diameter", "valid keys here: density, poisson_ratio, radius");
  j = minimal_elastic();
  j["output"] = {{"every", 1}};
  expect_error(j, "/output/every", "valid keys here: every_l, snapshots_every_l");
}

TEST(SceneConfig, WrongTypes) {
  json j = minimal_elastic();
  j["rho"] = "20";
  expect_error(j, "/rho", "must be a number (got \"20\")");
  j = minimal_elastic();
  j["mu_s"] = true;
  expect_error(j, "/mu_s", "must be a number");
  j = minimal_elastic();
  j["seed"] = 1.5;
  expect_error(j, "/seed", "must be an integer (got 1.5)");
  j = minimal_elastic();
  j["seed"] = -3;
  expect_error(j, "/seed", "must be >= 0 (got -3)");
  j = minimal_elastic();
  j["wire"] = 0.5e-3;  // scalar where an object belongs
  expect_error(j, "/wire", "must be an object");
  j = minimal_elastic();
  j["l_max"] = {{"value", 3}};  // object where a scalar belongs
  expect_error(j, "/l_max", "must be a number (got an object)");
  j = minimal_elastic();
  j["numerics"] = {{"twist", true}};
  expect_error(j, "/numerics/twist", "must be one of \"auto\", \"on\", \"off\"");
  j = minimal_elastic();
  j["l_max"] = json::array({1, 2});
  expect_error(j, "/l_max", "got an array");
}

TEST(SceneConfig, NonFinite) {
  json j = minimal_elastic();
  j["eps"] = std::numeric_limits<double>::infinity();
  expect_error(j, "/eps", "must be a finite number");
  j = minimal_elastic();
  j["wire"] = {{"density", std::numeric_limits<double>::quiet_NaN()}};
  expect_error(j, "/wire/density", "must be a finite number");
}

TEST(SceneConfig, Ranges) {
  json j = minimal_elastic();
  j["rho"] = 2;
  expect_error(j, "/rho", "must be > 2 (got 2)");
  j = minimal_elastic();
  j["numerics"] = {{"element_length", -1e-3}};
  expect_error(j, "/numerics/element_length", "must be > 0 (got -0.001)");
  j = minimal_elastic();
  j["wire"] = {{"poisson_ratio", 0.5}};
  expect_error(j, "/wire/poisson_ratio", "must be in [0, 0.5) (got 0.5)");
  j = minimal_elastic();
  j["numerics"] = {{"damping_ratio", 1.0}};
  expect_error(j, "/numerics/damping_ratio", "must be in [0, 1)");
  j = minimal_elastic();
  j["numerics"] = {{"quasistatic_ratio", 0}};
  expect_error(j, "/numerics/quasistatic_ratio", "must be in (0, 0.5]");
  j = minimal_elastic();
  j["mu_s"] = -0.1;
  expect_error(j, "/mu_s", "must be >= 0");
  j = minimal_elastic();
  j["mu_d"] = 0.6;
  expect_error(j, "/mu_d", "must be <= mu_s = 0.5 (got 0.6)");
  // element_length <= R/4 with R = rho r = 20 * 0.5 mm = 10 mm.
  j = minimal_elastic();
  j["numerics"] = {{"element_length", 2.5e-3}};
  EXPECT_NO_THROW(parse_scene(j, "scene.json"));
  j["numerics"] = {{"element_length", 2.6e-3}};
  expect_error(j, "/numerics/element_length", "must be <= R/4 = 0.0025 m");
}

TEST(SceneConfig, NotAnObject) {
  expect_error(json::array({1, 2}), "/", "a scene must be a JSON object (got an array)");
  expect_error(json(3), "/", "must be a JSON object");
}

TEST(SceneConfig, AllErrorsReported) {
  json j = {{"rho", 1},
            {"mu_s", "x"},
            {"extra", 0},
            {"seed", 0.5},
            {"wire", {{"radius", -1}}},
            {"numerics", {{"twist", "maybe"}}}};
  const auto errors = errors_of(j);
  std::string all;
  for (const auto& e : errors) all += e + "\n";
  for (const char* p : {"/rho:", "/mu_s:", "/extra:", "/seed:", "/wire/radius:", "/xi:", "/eps:",
                        "/numerics/twist:"})
    EXPECT_NE(all.find(std::string("scene.json: ") + p), std::string::npos) << p << "\n" << all;
  EXPECT_EQ(errors.size(), 8u) << all;
}

TEST(SceneConfig, LoadFileParseErrors) {
  TempDir dir;
  const std::string bad = dir.write("bad.json", "{\n  \"rho\": 20,\n  \"mu_s\": 0,,\n}\n");
  try {
    load_scene(bad);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(bad + ": line 3, column"), std::string::npos) << msg;
    EXPECT_NE(msg.find("syntax error"), std::string::npos) << msg;
  }
  // A number that overflows a double is rejected with its pointer.
  const std::string big = dir.write(
      "big.json", R"({"rho": 20, "mu_s": 0, "shell": "rigid", "wire": {"radius": 1e999}})");
  try {
    load_scene(big);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(big + ": /wire/radius: must be a finite number"),
              std::string::npos)
        << e.what();
  }
  // Duplicate keys are reported together with the schema's findings.
  const std::string dup =
      dir.write("dup.json", R"({"rho": 20, "rho": 30, "mu_s": -1, "shell": "rigid"})");
  try {
    load_scene(dup);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    ASSERT_EQ(e.messages().size(), 2u) << e.what();
    EXPECT_EQ(e.messages()[0], dup + ": /rho: duplicate key");
    EXPECT_NE(e.messages()[1].find(dup + ": /mu_s: must be >= 0"), std::string::npos);
  }
  // Missing file.
  EXPECT_THROW(load_scene(dir / "none.json"), InputError);
}

TEST(SceneConfig, ShippedScenesValidate) {
  const std::string dir = WIREPACK_SOURCE_DIR "/scenes/";
  const Scene rigid = load_scene(dir + "rigid_default.json");
  EXPECT_EQ(rigid.engine.shell, ShellKind::Rigid);
  EXPECT_EQ(rigid.engine.l_max, 20);
  const Scene elastic = load_scene(dir + "elastic_example.json");
  EXPECT_EQ(elastic.engine.shell, ShellKind::Elastic);
  EXPECT_EQ(elastic.engine.mu_s, 0.5);
}

TEST(SceneConfig, SchemaMarkdown) {
  const std::string md = schema_markdown();
  EXPECT_EQ(md.rfind("| pointer | type | default | range | doc |\n", 0), 0u);
  for (const auto& spec : scene_schema())
    EXPECT_NE(md.find("| `" + spec.pointer + "` |"), std::string::npos) << spec.pointer;
  EXPECT_NE(md.find("| `/wire/poisson_ratio` | number | 1/3 | [0, 0.5) |"), std::string::npos);
  EXPECT_NE(md.find("| `/mu_d` | number | 0.9 mu_s | >= 0, <= mu_s |"), std::string::npos);
}

// Presets (docs/reference.md "Scene file"): each resolves to its documented settings, scaled by r.
TEST(SceneConfig, NumericsPresetsResolveToTheirSettings) {
  ASSERT_EQ(numerics_presets().size(), 4u);
  for (const auto& p : numerics_presets()) {
    for (const double r : {0.5e-3, 0.25e-3}) {
      json j = minimal_elastic();
      j["wire"] = {{"radius", r}};
      j["numerics"] = p.name;
      const Scene s = parse_scene(j, "scene.json");
      EXPECT_EQ(s.numerics_preset, p.name);
      EXPECT_DOUBLE_EQ(s.engine.numerics.element_length, p.element_per_r * r) << p.name;
      EXPECT_DOUBLE_EQ(s.engine.numerics.shell_mesh_size, p.mesh_per_r * r) << p.name;
      EXPECT_EQ(s.engine.numerics.quasistatic_ratio, p.quasistatic_ratio) << p.name;
      EXPECT_EQ(s.engine.numerics.tolerance, p.tolerance) << p.name;
      EXPECT_EQ(s.engine.numerics.mass_scaling,
                p.mass_scaling == "uniform" ? MassScaling::Uniform : MassScaling::Selective);
      EXPECT_EQ(s.engine.numerics.damping_ratio, 0.05);  // not a preset knob
      EXPECT_FALSE(s.resolved["numerics"].contains("preset"));
    }
  }
  const NumericsPreset& fast = *find_numerics_preset("fast");
  EXPECT_EQ(fast.element_per_r, 2.0);
  EXPECT_EQ(fast.quasistatic_ratio, 0.02);  // with uniform mass scaling 0.03 broke the shell
  const NumericsPreset& acc = *find_numerics_preset("accurate");
  EXPECT_EQ(acc.element_per_r, 0.5);
  EXPECT_EQ(acc.tolerance, 3e-5);
  EXPECT_EQ(find_numerics_preset("slow"), nullptr);
  // inertial: the default's resolution with every mode at the scaled mass (results/crumpling);
  // a given mass_scaling overrides it like any key beside a preset.
  const NumericsPreset& in = *find_numerics_preset("inertial");
  EXPECT_EQ(in.mass_scaling, "uniform");
  EXPECT_EQ(in.quasistatic_ratio, 0.01);
  json j = minimal_elastic();
  j["numerics"] = {{"preset", "inertial"}, {"mass_scaling", "selective"}};
  EXPECT_EQ(parse_scene(j, "s.json").engine.numerics.mass_scaling, MassScaling::Selective);
}

TEST(SceneConfig, DefaultPresetIsTheSameSceneAsNoPreset) {
  json a = minimal_elastic();
  json b = minimal_elastic();
  b["numerics"] = "default";
  json c = minimal_elastic();
  c["numerics"] = {{"preset", "default"}};
  const Scene sa = parse_scene(a, "a.json");
  EXPECT_EQ(sa.numerics_preset, "default");
  EXPECT_EQ(sa.resolved, parse_scene(b, "b.json").resolved);
  EXPECT_EQ(sa.resolved, parse_scene(c, "c.json").resolved);
  EXPECT_EQ(sa.engine.numerics.element_length, 0.5e-3);  // r at the default radius
  EXPECT_EQ(sa.engine.numerics.shell_mesh_size, 1e-3);   // 2 r
}

TEST(SceneConfig, KeysBesideAPresetOverrideIt) {
  json j = minimal_elastic();
  j["numerics"] = {{"preset", "accurate"}, {"tolerance", 1e-3}, {"twist", "off"}};
  const Scene s = parse_scene(j, "scene.json");
  EXPECT_EQ(s.engine.numerics.tolerance, 1e-3);
  EXPECT_EQ(s.engine.numerics.quasistatic_ratio, 0.003);
  EXPECT_EQ(s.engine.numerics.element_length, 0.25e-3);
  EXPECT_EQ(s.engine.numerics.twist, EffectMode::Off);
}

TEST(SceneConfig, UnknownPresetIsAnError) {
  json j = minimal_elastic();
  j["numerics"] = "fastest";
  expect_error(j, "/numerics", "must be a preset: one of \"fast\", \"default\", \"accurate\"");
  j["numerics"] = {{"preset", 3}, {"tolerance", -1}};
  expect_error(j, "/numerics/preset", "got 3");
  expect_error(j, "/numerics/tolerance", "must be in (0, 1]");
  j["numerics"] = 7;
  expect_error(j, "/numerics", "must be an object");
  // The preset's element length is checked like a given one: 2 r > R/4 at rho = 4.
  j = minimal_rigid();
  j["rho"] = 4;
  j["numerics"] = "fast";
  expect_error(j, "/numerics/element_length", "must be <= R/4");
}

TEST(SceneConfig, SchemaListsThePresets) {
  const std::string md = schema_markdown();
  EXPECT_NE(md.find("| `fast` | 2 r | 4 r | 0.02 | 0.001 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `/numerics/element_length` | number | preset: r (wire/radius) |"),
            std::string::npos);
}

// The parameters' roles live in the schema's rows (issue 50: one home per fact): the transition
// parameters, the table columns, the log-scaled one and refine's first choice are read there by
// report/, and the keys resolved only where they act carry what their absence means.
TEST(SceneConfig, ParameterRolesComeFromTheSchema) {
  using Roles = KeySpec::Roles;
  EXPECT_EQ(keys_with(&Roles::transition),
            (std::vector<std::string>{"/rho", "/xi", "/eps", "/mu_s"}));
  EXPECT_EQ(keys_with(&Roles::column), (std::vector<std::string>{"/rho", "/xi", "/eps", "/mu_s",
                                                                 "/mu_d", "/l_max", "/shell"}));
  EXPECT_EQ(keys_with(&Roles::log_scale), std::vector<std::string>{"/eps"});
  EXPECT_EQ(keys_with(&Roles::refine_first), std::vector<std::string>{"/mu_s"});
  EXPECT_EQ(keys_with(&Roles::label), (std::vector<std::string>{"/mu_s", "/shell"}));
  EXPECT_EQ(key_names_with(&Roles::transition), "rho, xi, eps, mu_s");
  for (const auto& ptr : keys_with(&Roles::column))
    EXPECT_TRUE(find_key(ptr)->roles.physical) << ptr;  // a column is a physical parameter
  EXPECT_EQ(find_key("/nope"), nullptr);
  const auto& absent = values_where_not_resolved();
  EXPECT_EQ(absent.at("/feeder_spin"), "held");
  EXPECT_EQ(absent.at("/friction_stiffness_ratio"), "mindlin");
  EXPECT_EQ(absent.at("/numerics/damping_form"), "relative");
  EXPECT_EQ(absent.at("/perturbation/offset"), 0.0);
  EXPECT_FALSE(absent.contains("/numerics/shell_inertia_thickness"));  // absent: not acting
  for (const auto& [ptr, v] : absent) EXPECT_NE(find_key(ptr)->resolved_where, nullptr) << ptr;
}

// shell_material (issue 51): neo_hookean reaches the engine and enters the resolved scene (so
// the run's id); "linear", the default, and any value on a rigid sphere leave the id as it was.
TEST(SceneConfig, ShellMaterialResolvedWhereNeoHookean) {
  json j = minimal_elastic();
  const json plain = parse_scene(j, "s.json").resolved;
  j["shell_material"] = "linear";
  EXPECT_EQ(parse_scene(j, "s.json").resolved, plain);
  j["shell_material"] = "neo_hookean";
  const Scene s = parse_scene(j, "s.json");
  EXPECT_EQ(s.engine.shell_material, ShellMaterialLaw::NeoHookean);
  EXPECT_EQ(s.resolved["shell_material"], "neo_hookean");
  EXPECT_EQ(parse_scene(s.resolved, "resolved").resolved, s.resolved);  // idempotent
  json rigid = minimal_rigid();
  rigid["shell_material"] = "neo_hookean";
  EXPECT_FALSE(parse_scene(rigid, "s.json").resolved.contains("shell_material"));
  j["shell_material"] = "mooney";
  EXPECT_THROW(parse_scene(j, "s.json"), InputError);
}

}  // namespace
}  // namespace wirepack::sweep
