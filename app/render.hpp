#pragma once
// `wirepack render` (issue 18): a picture and/or a movie of a run file. ParaView's pvbatch runs
// scripts/render_paraview.py (under xvfb-run when there is no display): the wire as a tube
// coloured by kappa R, the shell translucent and coloured by a field. Without ParaView it says
// so and falls back to the gnuplot renderer results/render.sh (and ffmpeg for a movie).
#include <cstddef>
#include <ostream>
#include <string>

namespace wirepack::app {

struct RenderOptions {
  std::string run_file;
  std::string out;                           // picture (PNG); "" = none
  std::string movie;                         // movie over all snapshots (MP4); "" = none
  int snapshot = -1;                         // snapshot of the picture; -1 = the last
  bool half_radius = false;                  // the wire at half its radius
  std::string shell_field = "area_stretch";  // area_stretch, contact_pressure, clamped, none
  std::string size = "1200x900";             // picture size WxH [pixels]
  std::string kappa_range = "0,3";           // kappa R at the ends of the colour map
  std::string title;                         // "" = the run file's name
};

// What check_render found in the run file.
struct RenderPlan {
  int snapshot = 0;           // snapshot of the picture
  std::size_t snapshots = 0;  // snapshots in the run file (frames of a movie)
};

// Checks the options and the run file; throws sweep::InputError (nothing written) on bad input:
// no output, an output not .png / .mp4, a bad --size or --kappa-range, a run file that cannot
// be read or has no snapshots, a snapshot index out of range.
RenderPlan check_render(const RenderOptions& o);

// Renders what `o` asks for. Progress and the renderer's messages go to `log`, the written
// paths to `out`. Returns 0 when everything asked for was written, 1 when the renderer failed
// (nothing left behind). Environment: WIREPACK_PVBATCH, the pvbatch to use (default: pvbatch
// on PATH; a path that is not an executable means "not installed"); WIREPACK_SOURCE_DIR, where
// scripts/ and results/ are (default: the source tree this binary was built from).
int render_run(const RenderOptions& o, const RenderPlan& plan, std::ostream& out,
               std::ostream& log);

}  // namespace wirepack::app
