#pragma once
#include <array>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab {

// An indexed triangle mesh (metres). Faces index into vertices, CCW seen from
// the side the normals point to.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> faces;
  std::vector<Vec3> normals;  // per vertex; empty or vertices.size()

  bool operator==(const Mesh&) const = default;
};

}  // namespace sketchlab
