// libFuzzer target over the scene and sweep parsers and validators (issue 19, part 3): JSON text
// in, then either an InputError whose every message names the source (`fuzz.json: ...`), or a
// valid scene or sweep whose resolved form parses again to the same identity. Anything else (a
// crash, another exception, a sanitizer report, a resolved form that does not round-trip) is a
// finding. Built with clang by scripts/fuzz.sh (CMake option WIREPACK_FUZZ).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/analyze.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"

namespace {

using namespace wirepack::report;
using namespace wirepack::sweep;

constexpr const char* kSource = "fuzz.json";

[[noreturn]] void finding(const std::string& what) {
  std::cerr << "fuzz_config: " << what << std::endl;
  std::abort();
}

void check_messages(const InputError& e) {
  if (e.messages().empty()) finding("an InputError without a message");
  for (const auto& m : e.messages())
    if (m.rfind(std::string(kSource) + ": ", 0) != 0)
      finding("a message that does not name the file: " + m);
}

void scene(const nlohmann::json& j) {
  const Scene s = parse_scene(j, kSource);
  // The resolved scene is valid and resolves to itself (it is the run's identity).
  const Scene again = parse_scene(s.resolved, "resolved");
  if (canonical_json(again.resolved) != canonical_json(s.resolved))
    finding("resolved scene does not round-trip: " + s.resolved.dump());
}

void sweep(const nlohmann::json& j) {
  const Sweep s = parse_sweep(j, kSource);
  AnalysisSettings settings = default_analysis_settings();
  apply_analysis_block(s.analysis, kSource, "/analysis", settings);
  const Sweep again = parse_sweep(s.resolved, "resolved");
  if (again.runs.size() != s.runs.size()) finding("resolved sweep expands differently");
  for (std::size_t i = 0; i < s.runs.size(); ++i)
    if (again.runs[i].id != s.runs[i].id || again.runs[i].file != s.runs[i].file)
      finding("resolved sweep gives another run " + std::to_string(i));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    std::vector<std::string> soft;
    const nlohmann::json j = parse_json_text(text, kSource, &soft);
    if (is_sweep_json(j))
      sweep(j);
    else
      scene(j);
  } catch (const InputError& e) {
    check_messages(e);
  }
  return 0;
}
