// The wirepack executable (DESIGN §6): subcommands wire the layers together.
// Exit codes: 0 success, 2 bad input (nothing is written), 1 a run failed.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "sweep/errors.hpp"
#include "sweep/export.hpp"
#include "sweep/run.hpp"
#include "sweep/run_file.hpp"
#include "sweep/scene_config.hpp"

namespace {

namespace fs = std::filesystem;
using namespace wirepack::sweep;

constexpr int kOk = 0;
constexpr int kRunFailed = 1;
constexpr int kBadInput = 2;

// The output's directory must exist and be writable before any work starts, so an hours-long
// run cannot end in an unwritable path.
void check_output_path(const std::string& out) {
  const fs::path path(out);
  fs::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (path.filename().empty() || fs::is_directory(path, ec))
    throw InputError(out + ": --out must name a file, not a directory");
  // A missing directory is created (the scene has been validated by now).
  if (!fs::is_directory(dir, ec) && !fs::create_directories(dir, ec))
    throw InputError(out + ": directory " + dir.string() + " cannot be created");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(out + ": directory " + dir.string() + " is not writable");
}

int cmd_run(const std::string& scene_path, const std::string& out) {
  const Scene scene = scene_path.empty()
                          ? parse_scene(default_scene_json(), "<embedded default scene>")
                          : load_scene(scene_path);
  check_output_path(out);
  const RunOutcome outcome = run_scene(scene, out, &std::cerr);
  if (outcome.status != RunStatus::Complete) {
    std::cerr << "wirepack: run failed: " << outcome.failure << " (run file " << out << ")\n";
    return kRunFailed;
  }
  std::cout << out << '\n';
  return kOk;
}

int cmd_validate(const std::string& path) {
  const Scene scene = load_scene(path);
  std::cout << scene.resolved.dump(2) << '\n';
  return kOk;
}

int cmd_export(const std::string& run_file, const std::string& csv, const std::string& xmf) {
  try {
    if (!csv.empty()) export_csv(run_file, csv);
    if (!xmf.empty()) export_xdmf(run_file, xmf);
  } catch (const RunFileError& e) {
    throw InputError(e.what());
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "wirepack: elastic wires injected into spherical shells (Vetter, Wittel, "
      "Herrmann, EPL 112, 44003, 2015)"};
  app.footer("Exit codes: 0 success, 2 bad input (nothing written), 1 a run failed.");
  app.set_version_flag("--version", build_version() + " (" + build_git() + ")");
  app.require_subcommand(1);

  std::string scene_path, out_path;
  auto* run = app.add_subcommand("run",
                                 "simulate one scene; progress on stderr, then the run "
                                 "file's path on stdout");
  run->add_option("scene", scene_path,
                  "scene file (JSON); without one, the embedded default scene (rigid sphere, "
                  "rho = 20, mu_s = 0, l_max = 20; see scenes/rigid_default.json)");
  run->add_option("-o,--out", out_path, "run file to write (HDF5)")->required();

  std::string validate_path;
  auto* validate =
      app.add_subcommand("validate", "check a scene file and print it resolved (all defaults)");
  validate->add_option("file", validate_path, "scene file (JSON)")->required();

  std::string run_file, csv_path, xmf_path;
  auto* exp = app.add_subcommand("export",
                                 "convert a run file: series to CSV, snapshots to "
                                 "an XDMF sidecar for ParaView");
  exp->add_option("run_file", run_file, "run file (HDF5)")->required();
  auto* outputs = exp->add_option_group("outputs", "at least one of");
  outputs->add_option("--csv", csv_path, "write the series as CSV");
  outputs->add_option("--xdmf", xmf_path, "write an XDMF file referencing the run file");
  outputs->require_option(1, 2);

  auto* schema = app.add_subcommand("schema", "print the scene file keys as a Markdown table");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help (code 0) or the usage error
    return code == 0 ? kOk : kBadInput;
  }

  try {
    if (*run) return cmd_run(scene_path, out_path);
    if (*validate) return cmd_validate(validate_path);
    if (*exp) return cmd_export(run_file, csv_path, xmf_path);
    if (*schema) {
      std::cout << schema_markdown();
      return kOk;
    }
  } catch (const InputError& e) {
    for (const auto& m : e.messages()) std::cerr << m << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "wirepack: " << e.what() << '\n';
    return kRunFailed;
  }
  return kBadInput;
}
