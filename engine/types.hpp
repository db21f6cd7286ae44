#pragma once
// Basic types shared by the engine: 3-vectors in SI units (m, m/s, N).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <stdexcept>
#include <string>
#include <vector>

namespace wirepack {

using Vec3 = Eigen::Vector3d;
using Vec3List = std::vector<Vec3>;

// Thrown when a run cannot continue (NaN, step collapse, tunnelling); `what()` is the reason
// that goes into the run file's `failure` attribute.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wirepack
