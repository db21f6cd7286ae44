#pragma once
// The wire's circular cross-section (paper Eq. (1)), the one place its constants are derived:
// the engine's rod material, the analysis's dimensionless bending energy and the report's
// Purohit model read them here. Header-only, floor 0 (docs/design.md §1).
#include <cmath>
#include <numbers>

namespace wirepack {

// Area pi r^2 [m^2] of a wire of radius r [m].
inline double section_area(double r) {
  return std::numbers::pi * r * r;
}
// Second moment of area pi r^4 / 4 [m^4]; the polar moment is twice it.
inline double section_second_moment(double r) {
  return std::numbers::pi * std::pow(r, 4) / 4.0;
}

}  // namespace wirepack
