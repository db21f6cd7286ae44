#pragma once
// Read-only probe of the wire-shell contact (for output, never for the dynamics): the normal
// contact force that the wire exerts on each shell vertex at a given state. Evaluated by a
// fresh WireShellTerm without friction, so the simulation's own term (its Verlet list, its
// friction history) is untouched and the trajectory stays bitwise the same.
#include "engine/contact/wire_shell.hpp"
#include "engine/shell/shell_term.hpp"
#include "engine/state.hpp"

namespace wirepack {

// Force of the wire on every shell vertex (nv) [N]: Hertz plus the normal dashpot at the
// state's velocities, spread by barycentric weights (the term's own force, friction left out;
// with p.guide, the guide outside the hole included). The wire takes the opposite total
// (action = reaction; of the guide's, the part not on its first node goes to the feeder).
// Needs s.shell_x of the mesh's size.
Vec3List wire_shell_vertex_forces(const ShellMesh& mesh, WireShellParams p, const State& s);

}  // namespace wirepack
