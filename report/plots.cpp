#include "report/plots.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sweep/format.hpp"

extern char** environ;

namespace wirepack::report::plots {

namespace fs = std::filesystem;
using sweep::format_number;

namespace {

// A gnuplot double-quoted string literal.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '\n') {
      out += "\\n";  // a line break inside the string
      continue;
    }
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// Rows a panel can draw: finite x and y, positive where the axis is logarithmic.
std::vector<Row> drawable(const Panel& p, const Curve& c) {
  std::vector<Row> rows;
  for (const auto& r : c.rows) {
    if (!std::isfinite(r[0]) || !std::isfinite(r[1])) continue;
    if ((p.logx && r[0] <= 0) || (p.logy && r[1] <= 0)) continue;
    if (c.style == Curve::Style::IntervalLines) {
      // A bar with an end that is not finite (or not positive on a log axis) is drawn as none.
      const auto end = [&](double v) { return std::isfinite(v) && !(p.logy && v <= 0) ? v : r[1]; };
      rows.push_back({r[0], r[1], end(r[2]), end(r[3])});
    } else {
      rows.push_back({r[0], r[1], std::isfinite(r[2]) ? r[2] : 0.0, 0.0});
    }
  }
  return rows;
}

// The `using` x column: column 1, or column 1 shifted by the curve's x_offset.
std::string x_column(const Panel& p, const Curve& c) {
  if (c.x_offset == 0) return "1";
  return p.logx ? "($1*10**(" + format_number(c.x_offset) + "))"
                : "($1+(" + format_number(c.x_offset) + "))";
}

// The plot clause of a curve whose x column is `x` (see x_column).
std::string style_text(Curve::Style s, const std::string& x) {
  const std::string u = "using " + x + ":";
  switch (s) {
    case Curve::Style::ErrorLines:
      return u + "2:3 with yerrorlines pointtype 7 pointsize 0.8";
    case Curve::Style::IntervalLines:
      return u + "2:3:4 with yerrorlines pointtype 7 pointsize 0.8";
    case Curve::Style::Points:
      return u + "2 with points pointtype 7 pointsize 0.5";
    case Curve::Style::Lines:
      return u + "2 with lines linewidth 2";
    case Curve::Style::Boxes:
      return u + "2:3 with boxes fill solid 0.3 border";
    case Curve::Style::Dots:
      return u + "2 with points pointtype 7 pointsize 0.25 linecolor rgb \"#b8b8b8\"";
  }
  return "";
}

}  // namespace

double tick_step(double lo, double hi, int max_intervals) {
  const double raw = (hi - lo) / std::max(1, max_intervals);
  if (!(raw > 0) || !std::isfinite(raw)) return 0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

std::string script(const std::string& comment, const std::string& page_title,
                   const std::vector<Panel>& panels, int rows, int cols,
                   const std::string& png_name, int width, int height) {
  std::ostringstream s;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) s << "# " << line << '\n';
  s << "# Render: gnuplot " << fs::path(png_name).replace_extension(".gp").string() << '\n'
    << "if (!exists(\"out\")) out = " << quoted(png_name) << '\n'
    << "if (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) {\n"
    << "  set terminal pngcairo noenhanced size " << width << "," << height << '\n'
    << "} else {\n"
    << "  set terminal png noenhanced size " << width << "," << height << '\n'
    << "}\n"
    << "set output out\n"
    << "set grid\n"
    << "set key top left\n";
  // Every curve's rows as a datablock $dP_C.
  for (std::size_t p = 0; p < panels.size(); ++p) {
    for (std::size_t c = 0; c < panels[p].curves.size(); ++c) {
      s << "$d" << p << "_" << c << " << EOD\n";
      const bool four = panels[p].curves[c].style == Curve::Style::IntervalLines;
      for (const auto& r : drawable(panels[p], panels[p].curves[c])) {
        s << format_number(r[0]) << ' ' << format_number(r[1]) << ' ' << format_number(r[2]);
        if (four) s << ' ' << format_number(r[3]);
        s << '\n';
      }
      s << "EOD\n";
    }
  }
  const bool multi = panels.size() > 1;
  const bool placed = multi && panels.front().place.has_value();
  if (placed)
    s << "set multiplot title " << quoted(page_title) << '\n';
  else if (multi)
    s << "set multiplot layout " << rows << "," << cols << " title " << quoted(page_title) << '\n';
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Panel& panel = panels[p];
    s << "reset\nset grid\nset key " << panel.key << "\n"
      << "set title "
      << quoted(multi || page_title.empty() ? panel.title : page_title + "\n" + panel.title) << '\n'
      << "set xlabel " << quoted(panel.xlabel) << '\n'
      << "set ylabel " << quoted(panel.ylabel) << '\n';
    int objects = 0;  // gnuplot objects of this panel (drawn in order of their tags)
    if (placed && panel.place) {
      const auto& q = *panel.place;
      s << "set origin " << format_number(q[0]) << ", " << format_number(q[1]) << '\n'
        << "set size " << format_number(q[2]) << ", " << format_number(q[3]) << '\n';
      // An inset hides what is under it.
      if (p > 0)
        s << "set object " << ++objects << " rect from screen " << format_number(q[0])
          << ", screen " << format_number(q[1]) << " to screen " << format_number(q[0] + q[2])
          << ", screen " << format_number(q[1] + q[3])
          << " behind fillcolor rgb \"white\" fillstyle solid 1.0 noborder\n";
    }
    if (panel.xrange) {
      const auto [x0, x1] = *panel.xrange;
      s << "set xrange [" << format_number(x0) << ":" << format_number(x1) << "]\n";
      // A narrow panel (an inset) over a short range: gnuplot's own ticks overlap their labels.
      if (!panel.logx) {
        const double step = tick_step(x0, x1, kMaxRangeTickIntervals);
        if (step > 0) s << "set xtics " << format_number(step) << '\n';
      }
    }
    if (!panel.xtics.empty()) {
      s << "set xtics (";
      for (std::size_t t = 0; t < panel.xtics.size(); ++t)
        s << (t ? ", " : "") << format_number(panel.xtics[t]);
      s << ")\n";
    }
    for (std::size_t b = 0; b < panel.bands.size(); ++b)
      s << "set object " << ++objects << " rect from " << format_number(panel.bands[b][0])
        << ", graph 0 to " << format_number(panel.bands[b][1])
        << ", graph 1 behind fillcolor rgb \"#e4e4e4\" fillstyle solid 1.0 noborder\n";
    for (const double x : panel.vlines)
      s << "set arrow from " << format_number(x) << ", graph 0 to " << format_number(x)
        << ", graph 1 nohead dashtype 2 linecolor rgb \"#505050\"\n";
    std::vector<std::size_t> drawn;
    for (std::size_t c = 0; c < panel.curves.size(); ++c)
      if (!drawable(panel, panel.curves[c]).empty()) drawn.push_back(c);
    if (drawn.empty()) {
      s << "set label 1 \"no data\" at graph 0.5, 0.5 center\n"
        << "plot [0:1][0:1] NaN notitle\n"
        << "unset label 1\n";
      continue;
    }
    if (panel.logx) s << "set logscale x\n";
    if (panel.logy) s << "set logscale y\n";
    // Margins inside the frame, so points at the ends of the range stay visible.
    if (panel.y_from_zero)
      s << "set yrange [0:*]\nset offsets graph 0.03, graph 0.03, graph 0.05, 0\n";
    else if (panel.margins)
      s << "set autoscale fix\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
    if (panel.equal_axes) s << "set size ratio -1\n";
    s << "plot ";
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      const Curve& c = panel.curves[drawn[k]];
      const std::string style = style_text(c.style, x_column(panel, c));
      s << (k ? ", \\\n     " : "") << "$d" << p << "_" << drawn[k] << ' ' << style << ' '
        << (c.title.empty() ? "notitle" : "title " + quoted(c.title));
    }
    s << '\n';
  }
  if (multi) s << "unset multiplot\n";
  s << "set output\n";
  return s.str();
}

std::string find_program(const std::string& program) {
  if (program.empty()) return "";
  if (program.find('/') != std::string::npos)
    return ::access(program.c_str(), X_OK) == 0 ? program : "";
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate.string();
  }
  return "";
}

std::string render(const std::string& gnuplot, const std::string& script_path,
                   const std::string& png_path) {
  const std::string tmp = png_path + ".tmp";
  const std::string log = png_path + ".log";
  std::string out_arg = "out='";  // a gnuplot single-quoted string: ' is doubled
  for (char c : tmp) out_arg += c == '\'' ? std::string("''") : std::string(1, c);
  out_arg += "'";

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<std::string> args = {gnuplot, "-e", out_arg, script_path};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  std::error_code ec;
  if (err != 0) {
    fs::remove(log, ec);
    return "cannot start " + gnuplot + ": " + std::strerror(err);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return "waitpid: " + std::string(std::strerror(errno));
  }
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(tmp, ec) &&
                  fs::file_size(tmp, ec) > 0;
  if (!ok) {
    fs::remove(tmp, ec);
    return "gnuplot failed on " + script_path + " (messages in " + log + ")";
  }
  fs::rename(tmp, png_path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    return "cannot rename " + tmp + " to " + png_path + ": " + ec.message();
  }
  fs::remove(log, ec);
  return "";
}

}  // namespace wirepack::report::plots
