#pragma once
// The type of an energy term: how Simulation::energies() reports its energy (docs/design.md §5.7),
// by type and not by the term's name, so a renamed term cannot silently report 0.

namespace wirepack {

enum class TermType {
  kStretch,       // wire stretching, U_s
  kBend,          // wire bending, U_b
  kTwist,         // wire twisting, U_t
  kMembrane,      // shell membrane, U_m
  kShellBending,  // shell bending, U_sb
  kWall,          // wire against the rigid sphere (contact)
  kSelfContact,   // wire against itself (contact)
  kWireShell,     // wire against the elastic shell (contact)
  kShellSelf,     // shell against itself (contact)
};
inline constexpr int kTermTypes = 9;

}  // namespace wirepack
