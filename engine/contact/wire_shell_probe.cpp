#include "engine/contact/wire_shell_probe.hpp"

namespace wirepack {

Vec3List wire_shell_vertex_forces(const ShellMesh& mesh, WireShellParams p, const State& s) {
  p.friction = FrictionParams{};  // normal force only: a fresh history has no tangential part
  WireShellTerm term(mesh, p);
  Forces f;
  f.reset(s);
  term.accumulate(s, f);
  return f.shell_f;
}

}  // namespace wirepack
