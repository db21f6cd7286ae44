#pragma once
// gnuplot output of `wirepack analyze`: self-contained scripts (the data inline as datablocks, so
// a script can be edited and rerun alone: `gnuplot NAME.gp` writes NAME.png) and their
// rendering to PNG through a temporary name and a rename.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace wirepack::report::plots {

// One row of a curve: x, y and one or two more columns (see Curve::Style); the unused are 0.
using Row = std::array<double, 4>;

// One data set of a panel.
struct Curve {
  enum class Style {
    ErrorLines,     // rows (x, y, y error): points joined by lines, with error bars
    IntervalLines,  // rows (x, y, y low, y high): points joined by lines, bars from low to high
    Points,         // rows (x, y, -)
    Lines,          // rows (x, y, -)
    Boxes,          // rows (x centre, y, box width): a histogram
    Dots,           // rows (x, y, -): small grey points (a shell's vertices under a packing)
  };
  std::string title;  // key entry ("" = none)
  Style style = Style::Points;
  std::vector<Row> rows;  // rows with a non-finite x or y are left out
  // Drawn at x * 10^x_offset on a log x axis, x + x_offset on a linear one; the datablock keeps
  // x as it is. Lets curves that share x values sit side by side.
  double x_offset = 0;
};

struct Panel {
  std::string title, xlabel, ylabel;
  bool logx = false, logy = false;
  bool y_from_zero = false;  // y range starts at 0
  // A margin on every side and the ranges fitted to the data, not widened to the next tick (on a
  // log axis gnuplot widens to whole decades), so points and bars at the ends clear the frame.
  bool margins = false;
  bool equal_axes = false;       // one unit is as long on x as on y (pictures of packings)
  std::string key = "top left";  // where the key goes (gnuplot `set key` position)
  std::vector<Curve> curves;
  // Where the panel sits on the page, as fractions of it: origin x, y, width, height (an inset
  // over another panel); empty: the layout's place. Any placed panel makes the page a free
  // multiplot, so every panel of such a page is placed.
  std::optional<std::array<double, 4>> place;
  std::optional<std::array<double, 2>> xrange;  // x range drawn (empty: automatic)
  std::vector<double> xtics;                    // major x ticks at these values (empty: gnuplot's)
  std::vector<double> vlines;                   // dashed vertical lines at these x
  std::vector<std::array<double, 2>> bands;     // shaded x intervals [lo, hi] behind the data
};

// Tick intervals at most on a panel's fixed linear x range (`Panel::xrange`): an inset a third of
// the page wide has room for about four labels.
constexpr int kMaxRangeTickIntervals = 3;

// The tick spacing 1, 2 or 5 x 10^k, the smallest that cuts [lo, hi] into at most
// `max_intervals` intervals; 0 when the range is empty or not finite.
double tick_step(double lo, double hi, int max_intervals);

// A script drawing `panels` in a rows x cols layout under `page_title` (one panel: no multiplot,
// the page title heads the panel's) into the PNG named by the gnuplot variable `out`, default
// `png_name`; `comment` heads the script (lines prefixed with "# "). A panel without any finite
// point shows "no data".
std::string script(const std::string& comment, const std::string& page_title,
                   const std::vector<Panel>& panels, int rows, int cols,
                   const std::string& png_name, int width, int height);

// The program's path: `program` itself when it contains a '/', else the first executable
// PATH entry of that name; "" when there is none.
std::string find_program(const std::string& program);

// Runs `gnuplot -e "out='PNG.tmp'" SCRIPT`, then renames PNG.tmp to PNG. Returns "" on success,
// else what went wrong (gnuplot's messages are then in PNG.log; nothing else is left behind).
std::string render(const std::string& gnuplot, const std::string& script_path,
                   const std::string& png_path);

}  // namespace wirepack::report::plots
