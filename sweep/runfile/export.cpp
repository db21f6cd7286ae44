#include "sweep/runfile/export.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/state_archive.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/run_checkpoint.hpp"
#include "sweep/runfile/run_file.hpp"

namespace wirepack::sweep {

namespace fs = std::filesystem;

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Path of the run file as seen from the directory of the .xmf file.
std::string relative_run_path(const std::string& run_file, const std::string& xmf_path) {
  const fs::path run = fs::absolute(run_file).lexically_normal();
  const fs::path dir = fs::absolute(xmf_path).lexically_normal().parent_path();
  const fs::path rel = run.lexically_relative(dir);
  return (rel.empty() ? run : rel).generic_string();
}

// XDMF number types of the run file's datasets.
constexpr const char* kFloat64 = "NumberType=\"Float\" Precision=\"8\"";
constexpr const char* kFloat32 = "NumberType=\"Float\" Precision=\"4\"";
constexpr const char* kInt32 = "NumberType=\"Int\" Precision=\"4\"";
constexpr const char* kUInt8 = "NumberType=\"UChar\" Precision=\"1\"";

}  // namespace

RunRecord read_run_for_export(const std::string& run_file) {
  const std::string part = ".part";
  if (run_file.ends_with(part))
    throw RunFileError(run_file +
                       ": a partial run file (its run was killed or is still being written); "
                       "export the finished " +
                       run_file.substr(0, run_file.size() - part.size()) +
                       ", or its checkpoint (.h5.ckpt) while the run is part-way");
  if (run_file.ends_with(".ckpt")) {
    try {
      return read_checkpoint_record(run_file);
    } catch (const CheckpointError& e) {
      throw RunFileError(e.what());
    }
  }
  return read_run_file(run_file);
}

void export_csv(const std::string& run_file, const std::string& csv_path) {
  const RunRecord r = read_run_for_export(run_file);
  std::ostringstream out;
  std::size_t rows = 0;
  for (std::size_t c = 0; c < r.series.size(); ++c) {
    out << (c ? "," : "") << r.series[c].name;
    rows = std::max(rows, r.series[c].values.size());
  }
  out << '\n';
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t c = 0; c < r.series.size(); ++c) {
      const auto& v = r.series[c].values;
      out << (c ? "," : "") << (i < v.size() ? format_number(v[i]) : "");
    }
    out << '\n';
  }
  write_file_atomic(csv_path, out.str());
}

void check_xdmf_source(const std::string& run_file) {
  if (run_file.ends_with(".ckpt"))
    throw RunFileError(run_file +
                       ": a checkpoint has no HDF5 datasets for an XDMF file to reference; "
                       "export its series (--csv) or a snapshot (--profile) now, the XDMF "
                       "from the run file once the run has finished");
}

void export_xdmf(const std::string& run_file, const std::string& xmf_path) {
  check_xdmf_source(run_file);
  const RunRecord r = read_run_for_export(run_file);
  const std::string h5 = xml_escape(relative_run_path(run_file, xmf_path));
  // An attribute of `rows` values (times `cols` components) stored at <snap>/<name>, named
  // after the dataset, on the grid's nodes or cells.
  const auto attribute = [&](const std::string& name, const char* center, std::size_t rows,
                             const char* number_type, const std::string& snap, int cols = 1) {
    std::ostringstream a;
    a << "          <Attribute Name=\"" << name << "\" AttributeType=\""
      << (cols == 1 ? "Scalar" : "Vector") << "\" Center=\"" << center << "\">\n"
      << "            <DataItem Dimensions=\"" << rows << (cols == 1 ? "" : " 3") << "\" "
      << number_type << " Format=\"HDF\">" << h5 << ':' << snap << '/' << name << "</DataItem>\n"
      << "          </Attribute>\n";
    return a.str();
  };
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n"
    << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
    << "  <Domain>\n"
    << "    <Grid Name=\"run\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
    const Snapshot& s = r.snapshots[k];
    const std::size_t n = s.wire.size();
    const std::size_t m = s.shell_vertices.size();
    const std::size_t f = s.shell_triangles.size();
    const bool has_wire = n >= 2;  // a polyline needs a segment
    const bool has_shell = m > 0 && f > 0;
    const std::string snap = "/snapshots/" + std::to_string(k);
    if (!has_wire && !has_shell) {
      x << "      <!-- snapshot " << k << " (l = " << format_number(s.l)
        << "): fewer than two wire nodes, nothing to draw -->\n";
      continue;
    }
    // One spatial collection per time step: the wire and, if present, the shell.
    x << "      <Grid Name=\"snapshot_" << k << "\" GridType=\"Collection\" "
      << "CollectionType=\"Spatial\">\n"
      << "        <Time Value=\"" << format_number(s.l) << "\" />\n";
    if (has_wire) {
      x << "        <Grid Name=\"wire\" GridType=\"Uniform\">\n"
        << "          <Topology TopologyType=\"Polyline\" NumberOfElements=\"" << n - 1
        << "\" NodesPerElement=\"2\">\n"
        << "            <DataItem Dimensions=\"" << n - 1
        << " 2\" NumberType=\"Int\" Precision=\"4\" Format=\"XML\">";
      for (std::size_t i = 0; i + 1 < n; ++i) x << (i ? " " : "") << i << ' ' << i + 1;
      x << "</DataItem>\n"
        << "          </Topology>\n"
        << "          <Geometry GeometryType=\"XYZ\">\n"
        << "            <DataItem Dimensions=\"" << n
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ':' << snap
        << "/wire</DataItem>\n"
        << "          </Geometry>\n";
      if (s.curvature.size() == n) x << attribute("curvature", "Node", n, kFloat64, snap);
      if (s.wire_contacts.size() == n) x << attribute("wire_contacts", "Node", n, kInt32, snap);
      x << "        </Grid>\n";
    }
    if (has_shell) {
      x << "        <Grid Name=\"shell\" GridType=\"Uniform\">\n"
        << "          <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << f << "\">\n"
        << "            <DataItem Dimensions=\"" << f
        << " 3\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << h5 << ':'
        << shell_triangles_path(r, k) << "</DataItem>\n"
        << "          </Topology>\n"
        << "          <Geometry GeometryType=\"XYZ\">\n"
        << "            <DataItem Dimensions=\"" << m
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5 << ':' << snap
        << "/shell_vertices</DataItem>\n"
        << "          </Geometry>\n";
      if (s.shell_area_stretch.size() == f)
        x << attribute("shell_area_stretch", "Cell", f, kFloat32, snap);
      if (s.shell_contact_force.size() == m)
        x << attribute("shell_contact_force", "Node", m, kFloat64, snap, 3);
      if (s.shell_clamped.size() == m) x << attribute("shell_clamped", "Node", m, kUInt8, snap);
      x << "        </Grid>\n";
    }
    x << "      </Grid>\n";
  }
  x << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";
  write_file_atomic(xmf_path, x.str());
}

}  // namespace wirepack::sweep
