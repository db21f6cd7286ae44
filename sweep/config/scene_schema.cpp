// The scene file's schema and the numerics presets (docs/design.md §4.1): the table every
// scene is validated against, its Markdown form (wirepack schema) and the presets.
#include <sstream>

#include "engine/scene.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/format.hpp"

namespace wirepack::sweep {

using json = nlohmann::json;
using Type = KeySpec::Type;
using Need = KeySpec::Need;
using Bound = KeySpec::Bound;

namespace {

double num(const json& v) {
  return v.get<double>();
}

}  // namespace

// The scene schema (docs/design.md §4.1). Order: documentation order; /shell is read first anyway.
const std::vector<KeySpec>& scene_schema() {
  static const std::vector<KeySpec> table = {
      {.pointer = "/rho",
       .type = Type::Number,
       .need = Need::Required,
       .min = Bound{2, false},
       .roles = {.column = true, .physical = true, .transition = true},
       .doc = "R / r: sphere radius over wire radius",
       .apply = [](Scene& s, const json& v) { s.engine.rho = num(v); }},
      {.pointer = "/xi",
       .type = Type::Number,
       .need = Need::RequiredIfElastic,
       .min = Bound{1, false},
       .roles = {.column = true, .physical = true, .transition = true},
       .doc = "R / t: sphere radius over shell thickness (ignored for a rigid shell)",
       .apply = [](Scene& s, const json& v) { s.engine.xi = num(v); }},
      {.pointer = "/eps",
       .type = Type::Number,
       .need = Need::RequiredIfElastic,
       .min = Bound{0, false},
       .roles = {.column = true, .physical = true, .transition = true, .log_scale = true},
       .doc = "E_w / E_s: wire over shell Young's modulus (ignored for a rigid shell)",
       .apply = [](Scene& s, const json& v) { s.engine.eps = num(v); }},
      {.pointer = "/mu_s",
       .type = Type::Number,
       .need = Need::Required,
       .min = Bound{0, true},
       .roles = {.column = true,
                 .physical = true,
                 .transition = true,
                 .refine_first = true,
                 .label = true},
       .doc = "static friction coefficient (wire-wire and wire-shell)",
       .apply = [](Scene& s, const json& v) { s.engine.mu_s = num(v); }},
      {.pointer = "/mu_d",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "0.9 mu_s",
       .min = Bound{0, true},
       .extra_rule = "<= mu_s",
       .roles = {.column = true, .physical = true},
       .doc = "dynamic (sliding) friction coefficient",
       .apply = [](Scene& s, const json& v) { s.engine.mu_d = num(v); }},
      {.pointer = "/l_max",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 50.0,
       .min = Bound{0, false},
       .roles = {.column = true, .physical = true},
       .doc = "final injected length l = L / R",
       .apply = [](Scene& s, const json& v) { s.engine.l_max = num(v); }},
      {.pointer = "/seed",
       .type = Type::Integer,
       .need = Need::Optional,
       .fallback = std::uint64_t{1},
       .min = Bound{0, true},
       .doc = "seed of the run's RNG (initial transverse perturbation)",
       .apply = [](Scene& s, const json& v) { s.engine.seed = v.get<std::uint64_t>(); }},
      {.pointer = "/shell",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "elastic",
       .choices = {"elastic", "rigid"},
       .roles = {.column = true, .physical = true, .label = true},
       .doc = "elastic shell, or an analytic rigid sphere of radius R",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.shell = v == "rigid" ? ShellKind::Rigid : ShellKind::Elastic;
           }},
      {.pointer = "/shell_material",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "linear",
       .choices = {"linear", "neo_hookean"},
       .roles = {.physical = true},
       .resolved_where =
           [](const Scene& s, bool) {
             return s.engine.shell == ShellKind::Elastic &&
                    s.engine.shell_material != ShellMaterialLaw::Linear;
           },
       .when_absent = "linear",
       .doc = "the elastic shell membrane's law: linear (the paper's, St. Venant-Kirchhoff) or "
              "neo_hookean (compressible, equal to it at small strain, softer in tension and "
              "stiffening without bound in compression) (resolved where neo_hookean)",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.shell_material =
                 v == "neo_hookean" ? ShellMaterialLaw::NeoHookean : ShellMaterialLaw::Linear;
           }},
      {.pointer = "/injection_speed",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.5,
       .min = Bound{0, false},
       .roles = {.physical = true},
       .doc = "injection speed v [m/s]",
       .apply = [](Scene& s, const json& v) { s.engine.injection_speed = num(v); }},
      {.pointer = "/feeder_spin",
       .type = Type::Choice,
       .need = Need::Optional,
       .default_text = "\"held\" (resolved where it acts)",
       .choices = {"held", "free"},
       .resolved_where =
           [](const Scene& s, bool) {
             return s.engine.feeder_spin == FeederSpin::Free && s.engine.twist_enabled();
           },
       .when_absent = "held",
       .doc = "the wire's spin about its axis at the hole: held (the feeder clamps the "
              "cross-section, twist winds up against it) or free (a swivel: no twisting moment "
              "at the hole); acts only with twist DOFs",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.feeder_spin = v == "free" ? FeederSpin::Free : FeederSpin::Held;
           }},
      {.pointer = "/friction_stiffness_ratio",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "Mindlin: 2 (1 - nu_w) / (2 - nu_w) (resolved where given)",
       .min = Bound{0, false},
       .resolved_where = [](const Scene& s, bool given) { return given && s.engine.mu_s != 0.0; },
       .when_absent = "mindlin",
       .doc = "k_t / k_n: tangential over normal stiffness of a sticking contact (every "
              "contact type); acts only with friction",
       .apply = [](Scene& s, const json& v) { s.engine.friction_stiffness_ratio = num(v); }},
      {.pointer = "/perturbation/deflection",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.05,
       .min = Bound{0, true},
       .resolved_where = [](const Scene& s,
                            bool) { return s.engine.perturbation_deflection != 0.05; },
       .when_absent = 0.05,
       .doc = "rms transverse deflection of the initial wire's tip, in r (resolved where not "
              "0.05) [-]",
       .apply = [](Scene& s, const json& v) { s.engine.perturbation_deflection = num(v); }},
      {.pointer = "/perturbation/release_noise",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 1e-3,
       .min = Bound{0, true},
       .resolved_where = [](const Scene& s,
                            bool) { return s.engine.perturbation_release_noise != 1e-3; },
       .when_absent = 1e-3,
       .doc = "rms transverse offset of each node released through the hole, in r (resolved "
              "where not 1e-3) [-]",
       .apply = [](Scene& s, const json& v) { s.engine.perturbation_release_noise = num(v); }},
      {.pointer = "/perturbation/offset",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.0,
       .resolved_where = [](const Scene& s, bool) { return s.engine.perturbation_offset != 0.0; },
       .when_absent = 0.0,
       .doc = "fixed x offset of the initial wire's tip, in r (quadratic from the hole): twin "
              "runs of one seed differ by it (resolved where not 0) [-]",
       .apply = [](Scene& s, const json& v) { s.engine.perturbation_offset = num(v); }},
      {.pointer = "/wire/radius",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.5e-3,
       .min = Bound{0, false},
       .doc = "wire radius r [m]",
       .apply = [](Scene& s, const json& v) { s.engine.wire.radius = num(v); }},
      {.pointer = "/wire/youngs_modulus",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 1e9,
       .min = Bound{0, false},
       .doc = "wire Young's modulus E_w [Pa]",
       .apply = [](Scene& s, const json& v) { s.engine.wire.youngs_modulus = num(v); }},
      {.pointer = "/wire/poisson_ratio",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 1.0 / 3.0,
       .default_text = "1/3",
       .min = Bound{0, true},
       .max = Bound{0.5, false},
       .doc = "wire Poisson ratio nu_w [-]",
       .apply = [](Scene& s, const json& v) { s.engine.wire.poisson_ratio = num(v); }},
      {.pointer = "/wire/density",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 1140.0,
       .min = Bound{0, false},
       .doc = "wire density [kg/m^3] (polyamide): the mass of rigid and slow motions "
              "(numerics/mass_scaling)",
       .apply = [](Scene& s, const json& v) { s.engine.wire.density = num(v); }},
      {.pointer = "/numerics/element_length",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "preset: r (wire/radius)",
       .min = Bound{0, false},
       .extra_rule = "<= R/4",
       .doc = "rest length of a wire element [m]",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.element_length = num(v); }},
      {.pointer = "/numerics/shell_mesh_size",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "preset: 2 r",
       .min = Bound{0, false},
       .doc = "target shell triangle edge length [m] (elastic shell only)",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.shell_mesh_size = num(v); }},
      {.pointer = "/numerics/quasistatic_ratio",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "preset: 0.01",
       .min = Bound{0, false},
       .max = Bound{0.5, true},
       .doc = "injection speed over the axial wave speed of the element-scale modes; sets "
              "the mass scaling [-]",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.quasistatic_ratio = num(v); }},
      {.pointer = "/numerics/mass_scaling",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "selective",
       .choices = {"selective", "uniform"},
       .doc = "selective: only the element-scale modes get the scaled mass, rigid and slow "
              "motions keep the physical density; uniform: every mode scaled",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.numerics.mass_scaling =
                 v == "uniform" ? MassScaling::Uniform : MassScaling::Selective;
           }},
      {.pointer = "/numerics/tolerance",
       .type = Type::Number,
       .need = Need::Optional,
       .default_text = "preset: 1e-3",
       .min = Bound{0, false},
       .max = Bound{1, true},
       .doc = "local position error allowed per step, in units of r [-]",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.tolerance = num(v); }},
      {.pointer = "/numerics/damping_ratio",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.05,
       .min = Bound{0, true},
       .max = Bound{1, false},
       .doc = "viscous damping ratio zeta, subcritical [-]",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.damping_ratio = num(v); }},
      {.pointer = "/numerics/damping_form",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "relative",
       .choices = {"relative", "absolute"},
       .resolved_where =
           [](const Scene& s, bool) {
             return s.engine.numerics.damping_form == DampingForm::Absolute;
           },
       .when_absent = "relative",
       .doc = "what the wire's viscous drag acts on: relative, the transverse velocity only "
              "(sliding along the wire is free); absolute, the whole velocity and spin "
              "(mass-proportional damping: the wire sliding in is dragged too) (resolved where "
              "given as absolute)",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.numerics.damping_form =
                 v == "absolute" ? DampingForm::Absolute : DampingForm::Relative;
           }},
      {.pointer = "/numerics/twist",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "auto",
       .choices = {"auto", "on", "off"},
       .doc = "twist degrees of freedom; auto: on iff mu_s > 0",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.numerics.twist = v == "on"    ? EffectMode::On
                                       : v == "off" ? EffectMode::Off
                                                    : EffectMode::Auto;
           }},
      {.pointer = "/numerics/shell_self_contact",
       .type = Type::Choice,
       .need = Need::Optional,
       .fallback = "auto",
       .choices = {"auto", "on", "off"},
       .doc = "shell-shell contact where the shell folds onto itself; auto and on: in elastic "
              "scenes (a rigid sphere cannot fold)",
       .apply =
           [](Scene& s, const json& v) {
             s.engine.numerics.shell_self_contact = v == "on"    ? EffectMode::On
                                                    : v == "off" ? EffectMode::Off
                                                                 : EffectMode::Auto;
           }},
      {.pointer = "/numerics/shell_inertia_thickness",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 1.0,
       .default_text = "1 (resolved where it acts)",
       .min = Bound{0, true},
       .resolved_where =
           [](const Scene& s, bool given) {
             const SceneParams& e = s.engine;
             return given ||
                    (e.shell == ShellKind::Elastic && shell_mass_thickness(e) > e.R() / e.xi);
           },
       .doc = "the elastic shell's vertex masses are those of thickness max(t, this x r) (0: t), "
              "at most a physical shell's at the wire's density, its drag that of t: heavier "
              "vertices for thin soft shells (xi > rho, eps > 350), whose contacts would set "
              "the step [-]",
       .apply = [](Scene& s, const json& v) { s.engine.numerics.shell_inertia_factor = num(v); }},
      {.pointer = "/output/every_l",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 0.1,
       .min = Bound{0, false},
       .doc = "interval in l between recorded series rows",
       .apply = [](Scene& s, const json& v) { s.output.every_l = num(v); }},
      {.pointer = "/output/snapshots_every_l",
       .type = Type::Number,
       .need = Need::Optional,
       .fallback = 5.0,
       .min = Bound{0, false},
       .doc = "interval in l between configuration snapshots",
       .apply = [](Scene& s, const json& v) { s.output.snapshots_every_l = num(v); }},
  };
  return table;
}

const std::vector<NumericsPreset>& numerics_presets() {
  // Chosen from the accuracy-vs-time study (results/accuracy, docs/measurements.md "Presets").
  static const std::vector<NumericsPreset> table = {
      {"fast", 2.0, 4.0, 0.02, 1e-3, "quick looks and broad scans"},
      {"default", 1.0, 2.0, 0.01, 1e-3, "production nights"},
      {"accurate", 0.5, 1.0, 0.003, 3e-5, "convergence checks and references"},
      // Engine VI (results/crumpling): every mode at the scaled mass, ~350x the physical inertia
      // of the wire sliding in; the paper's crumpled phase at l <= 50 and independent seeds.
      {"inertial", 1.0, 2.0, 0.01, 1e-3,
       "the paper's crumpled phase: uniform mass scaling (every mode ~350x the physical "
       "inertia; results/crumpling)",
       "uniform"},
  };
  return table;
}

const NumericsPreset* find_numerics_preset(const std::string& name) {
  for (const auto& p : numerics_presets())
    if (p.name == name) return &p;
  return nullptr;
}

std::string preset_names() {
  std::string out;
  for (const auto& p : numerics_presets()) out += (out.empty() ? "\"" : ", \"") + p.name + "\"";
  return out;
}

std::string KeySpec::type_name() const {
  switch (type) {
    case Type::Number:
      return "number";
    case Type::Integer:
      return "integer";
    case Type::Choice:
      return "string";
  }
  return "?";
}

std::string KeySpec::range_text() const {
  std::string out;
  if (type == Type::Choice) {
    for (const auto& c : choices) out += (out.empty() ? "\"" : ", \"") + c + "\"";
  } else if (min && max) {
    out = std::string(min->inclusive ? "[" : "(") + format_number(min->value) + ", " +
          format_number(max->value) + (max->inclusive ? "]" : ")");
  } else if (min) {
    out = std::string(min->inclusive ? ">= " : "> ") + format_number(min->value);
  } else if (max) {
    out = std::string(max->inclusive ? "<= " : "< ") + format_number(max->value);
  }
  if (!extra_rule.empty()) out += (out.empty() ? "" : ", ") + extra_rule;
  return out;
}

const KeySpec* find_key(const std::string& pointer) {
  for (const auto& spec : scene_schema())
    if (spec.pointer == pointer) return &spec;
  return nullptr;
}

std::vector<std::string> keys_with(bool KeySpec::Roles::*role) {
  std::vector<std::string> out;
  for (const auto& spec : scene_schema())
    if (spec.roles.*role) out.push_back(spec.pointer);
  return out;
}

std::string key_names_with(bool KeySpec::Roles::*role) {
  std::string out;
  for (const auto& ptr : keys_with(role)) out += (out.empty() ? "" : ", ") + ptr.substr(1);
  return out;
}

std::string schema_markdown() {
  std::ostringstream out;
  out << "| pointer | type | default | range | doc |\n";
  out << "| --- | --- | --- | --- | --- |\n";
  for (const auto& spec : scene_schema()) {
    std::string def = spec.default_text;
    if (def.empty()) {
      if (spec.need == Need::Required)
        def = "required";
      else if (spec.need == Need::RequiredIfElastic)
        def = "required if shell is \"elastic\"";
      else if (spec.fallback.is_number_float())
        def = format_number(spec.fallback.get<double>());
      else
        def = spec.fallback.dump();
    }
    out << "| `" << spec.pointer << "` | " << spec.type_name() << " | " << def << " | "
        << spec.range_text() << " | " << spec.doc << " |\n";
  }
  out << "\nNumerics presets (`\"numerics\": \"NAME\"`, or `\"preset\": \"NAME\"` beside "
         "numerics keys, which override it; default \"default\"; `wirepack validate` prints the "
         "one "
         "used, and section \"Accuracy and presets\" what each costs and buys):\n\n";
  out << "| preset | element_length | shell_mesh_size | quasistatic_ratio | tolerance | "
         "mass_scaling | use |\n";
  out << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const auto& p : numerics_presets())
    out << "| `" << p.name << "` | " << format_number(p.element_per_r) << " r | "
        << format_number(p.mesh_per_r) << " r | " << format_number(p.quasistatic_ratio) << " | "
        << format_number(p.tolerance) << " | " << p.mass_scaling << " | " << p.summary << " |\n";
  return out.str();
}

}  // namespace wirepack::sweep
