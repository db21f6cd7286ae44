#include "report/settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "report/critical_table.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/parse_number.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

using json = nlohmann::json;
using sweep::describe_value;
using sweep::InputError;
using sweep::pointer_child;

const std::vector<ExponentSpec>& exponent_specs() {
  static const std::vector<ExponentSpec> specs = {{"alpha", "R_t"}, {"beta", "R_x"},
                                                  {"gamma", "R_y"}, {"delta", "U_b_hat"},
                                                  {"lambda", "K"},  {"tau", "N"}};
  return specs;
}

bool is_order_parameter(const std::string& name) {
  return name == "D" || name == "D_chord" || name == "D_kappa";
}

AnalysisSettings default_analysis_settings() {
  AnalysisSettings s;
  for (const auto& e : exponent_specs()) s.fit_windows[e.name] = LWindow{};
  return s;
}

namespace {

constexpr const char* kWindowRule = "must be [l_min, l_max] with 0 <= l_min < l_max";
constexpr int kMaxBins = 1000;
constexpr int kMaxResamples = 100000;

constexpr const char* kRangeRule = "must be [x_min, x_max] with x_min < x_max";

std::optional<std::pair<double, double>> range_from_json(const json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return {};
  const double a = v[0].get<double>(), b = v[1].get<double>();
  if (!std::isfinite(a) || !std::isfinite(b) || !(a < b)) return {};
  return std::pair{a, b};
}

std::optional<LWindow> window_from_json(const json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return {};
  const double a = v[0].get<double>(), b = v[1].get<double>();
  if (!std::isfinite(a) || !std::isfinite(b) || a < 0 || !(a < b)) return {};
  return LWindow{a, b};
}

// The offending value for a message: short arrays in full ("[50,5]"), else describe_value.
std::string got_text(const json& v) {
  if (v.is_array() && v.dump().size() <= 40) return v.dump();
  return describe_value(v);
}

std::string exponent_names() {
  std::string s;
  for (const auto& e : exponent_specs()) s += (s.empty() ? "" : ", ") + e.name;
  return s;
}

bool is_exponent(const std::string& name) {
  for (const auto& e : exponent_specs())
    if (e.name == name) return true;
  return false;
}

using sweep::to_double;

}  // namespace

LWindow parse_l_window(const std::string& text, const std::string& flag) {
  const auto comma = text.find(',');
  if (comma != std::string::npos) {
    const auto a = to_double(text.substr(0, comma));
    const auto b = to_double(text.substr(comma + 1));
    if (a && b && *a >= 0 && *a < *b) return LWindow{*a, *b};
  }
  throw InputError(flag + ": must be L_MIN,L_MAX with 0 <= L_MIN < L_MAX, e.g. 5,50 (got \"" +
                   text + "\")");
}

void apply_analysis_block(const json& block, const std::string& source, const std::string& pointer,
                          AnalysisSettings& s) {
  const std::string where = source + ": " + (pointer.empty() ? std::string("/") : pointer);
  if (!block.is_object())
    throw InputError(where + ": must be an object (got " + describe_value(block) + ")");
  std::vector<std::string> errors;
  const auto fail = [&](const std::string& key, const std::string& rule, const json& got) {
    errors.push_back(source + ": " + pointer_child(pointer, key) + ": " + rule + " (got " +
                     got_text(got) + ")");
  };
  static const std::vector<std::string> keys = {
      "D_window",        "fit_window",     "fit_windows",
      "distribution_l",  "histogram_bins", "bootstrap_resamples",
      "critical_ranges", "fit_auto",       "order_parameter"};
  for (const auto& [key, value] : block.items()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string valid;
    for (const auto& k : keys) valid += (valid.empty() ? "" : ", ") + k;
    errors.push_back(source + ": " + pointer_child(pointer, key) +
                     ": unknown key; valid keys: " + valid);
  }
  if (const auto it = block.find("D_window"); it != block.end()) {
    if (const auto w = window_from_json(*it))
      s.D_window = *w;
    else
      fail("D_window", kWindowRule, *it);
  }
  // fit_window sets every exponent's window, fit_windows then sets single ones.
  if (const auto it = block.find("fit_window"); it != block.end()) {
    if (const auto w = window_from_json(*it)) {
      for (auto& [name, fw] : s.fit_windows) fw = *w;
    } else {
      fail("fit_window", kWindowRule, *it);
    }
  }
  if (const auto it = block.find("fit_windows"); it != block.end()) {
    if (!it->is_object()) {
      fail("fit_windows", "must be an object {\"<exponent>\": [l_min, l_max]}", *it);
    } else {
      const std::string ptr = pointer_child(pointer, "fit_windows");
      for (const auto& [name, value] : it->items()) {
        if (!is_exponent(name)) {
          errors.push_back(source + ": " + pointer_child(ptr, name) +
                           ": unknown exponent; valid: " + exponent_names());
        } else if (const auto w = window_from_json(value)) {
          s.fit_windows[name] = *w;
        } else {
          errors.push_back(source + ": " + pointer_child(ptr, name) + ": " + kWindowRule +
                           " (got " + got_text(value) + ")");
        }
      }
    }
  }
  if (const auto it = block.find("distribution_l"); it != block.end()) {
    if (it->is_null())
      s.distribution_l.reset();
    else if (it->is_number() && std::isfinite(it->get<double>()) && it->get<double>() >= 0)
      s.distribution_l = it->get<double>();
    else
      fail("distribution_l", "must be a number >= 0, or null for the last common snapshot", *it);
  }
  if (const auto it = block.find("histogram_bins"); it != block.end()) {
    if (it->is_number_integer() && it->get<long long>() >= 1 && it->get<long long>() <= kMaxBins)
      s.histogram_bins = it->get<int>();
    else
      fail("histogram_bins", "must be an integer in [1, " + std::to_string(kMaxBins) + "]", *it);
  }
  if (const auto it = block.find("bootstrap_resamples"); it != block.end()) {
    if (it->is_number_integer() && it->get<long long>() >= 0 &&
        it->get<long long>() <= kMaxResamples)
      s.bootstrap_resamples = it->get<int>();
    else
      fail("bootstrap_resamples",
           "must be an integer in [0, " + std::to_string(kMaxResamples) + "] (0: no bootstrap)",
           *it);
  }
  if (const auto it = block.find("critical_ranges"); it != block.end()) {
    if (!it->is_object()) {
      fail("critical_ranges", "must be an object {\"<parameter>\": [x_min, x_max]}", *it);
    } else {
      const std::string ptr = pointer_child(pointer, "critical_ranges");
      for (const auto& [name, value] : it->items()) {
        if (!is_transition_axis("/" + name)) {
          errors.push_back(source + ": " + pointer_child(ptr, name) +
                           ": not a transition parameter; valid: " +
                           sweep::key_names_with(&sweep::KeySpec::Roles::transition));
        } else if (const auto r = range_from_json(value)) {
          s.critical_ranges["/" + name] = *r;
        } else {
          errors.push_back(source + ": " + pointer_child(ptr, name) + ": " + kRangeRule + " (got " +
                           got_text(value) + ")");
        }
      }
    }
  }
  if (const auto it = block.find("fit_auto"); it != block.end()) {
    if (it->is_boolean()) {
      s.fit_auto.clear();
      if (it->get<bool>())
        for (const auto& e : exponent_specs()) s.fit_auto.insert(e.name);
    } else if (it->is_array() && std::all_of(it->begin(), it->end(), [](const json& v) {
                 return v.is_string() && is_exponent(v.get<std::string>());
               })) {
      s.fit_auto.clear();
      for (const auto& v : *it) s.fit_auto.insert(v.get<std::string>());
    } else {
      fail("fit_auto", "must be true, false or a list of exponents (" + exponent_names() + ")",
           *it);
    }
  }
  if (const auto it = block.find("order_parameter"); it != block.end()) {
    if (it->is_string() && is_order_parameter(it->get<std::string>()))
      s.order_parameter = it->get<std::string>();
    else
      fail("order_parameter", "must be one of \"D\", \"D_chord\", \"D_kappa\"", *it);
  }
  if (!errors.empty()) throw InputError(errors);
}

void apply_flags(const AnalyzeOptions& o, AnalysisSettings& s) {
  if (o.D_window) s.D_window = parse_l_window(*o.D_window, "--d-window");
  for (const auto& text : o.fit_windows) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) {
      const LWindow w = parse_l_window(text, "--fit-window");
      for (auto& [name, fw] : s.fit_windows) fw = w;
      continue;
    }
    const std::string name = text.substr(0, eq);
    if (!is_exponent(name))
      throw InputError("--fit-window: unknown exponent \"" + name +
                       "\"; valid: " + exponent_names());
    s.fit_windows[name] = parse_l_window(text.substr(eq + 1), "--fit-window " + name);
  }
  if (o.at_l) {
    if (!std::isfinite(*o.at_l) || *o.at_l < 0)
      throw InputError("--at-l: must be a number >= 0 (got " + sweep::csv_number(*o.at_l) + ")");
    s.distribution_l = *o.at_l;
  }
  if (o.bins) {
    if (*o.bins < 1 || *o.bins > kMaxBins)
      throw InputError("--bins: must be an integer in [1, " + std::to_string(kMaxBins) + "] (got " +
                       std::to_string(*o.bins) + ")");
    s.histogram_bins = *o.bins;
  }
  if (o.resamples) {
    if (*o.resamples < 0 || *o.resamples > kMaxResamples)
      throw InputError("--resamples: must be an integer in [0, " + std::to_string(kMaxResamples) +
                       "] (got " + std::to_string(*o.resamples) + ")");
    s.bootstrap_resamples = *o.resamples;
  }
  for (const auto& text : o.critical_ranges) {
    const auto eq = text.find('=');
    const auto comma = text.find(',', eq == std::string::npos ? 0 : eq);
    const std::string name = text.substr(0, eq);
    std::optional<double> a, b;
    if (eq != std::string::npos && comma != std::string::npos) {
      a = to_double(text.substr(eq + 1, comma - eq - 1));
      b = to_double(text.substr(comma + 1));
    }
    if (eq == std::string::npos || !is_transition_axis("/" + name) || !a || !b || !(*a < *b))
      throw InputError("--critical-range: must be NAME=X_MIN,X_MAX with NAME one of " +
                       sweep::key_names_with(&sweep::KeySpec::Roles::transition) +
                       " and X_MIN < X_MAX, e.g. mu_s=0,0.6 (got \"" + text + "\")");
    s.critical_ranges["/" + name] = {*a, *b};
  }
  for (const auto& name : o.fit_auto) {
    if (name == "all") {
      for (const auto& e : exponent_specs()) s.fit_auto.insert(e.name);
    } else if (is_exponent(name)) {
      s.fit_auto.insert(name);
    } else {
      throw InputError("--fit-auto: must be all or an exponent (" + exponent_names() + ") (got \"" +
                       name + "\")");
    }
  }
  if (o.order_parameter) {
    if (!is_order_parameter(*o.order_parameter))
      throw InputError("--order-parameter: must be one of D, D_chord, D_kappa (got \"" +
                       *o.order_parameter + "\")");
    s.order_parameter = *o.order_parameter;
  }
}

}  // namespace wirepack::report
