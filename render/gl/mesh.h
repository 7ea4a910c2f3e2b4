// Geometry handed to GL as client-side vertex arrays: one interleaved vertex layout for
// lit triangles and unlit lines alike.
#pragma once

#include <cstdint>
#include <vector>

#include "render/gl/view_math.h"

namespace vibro::gl {

struct Rgb8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

struct Vertex {
  float position[3] = {0.0f, 0.0f, 0.0f};
  float normal[3] = {0.0f, 0.0f, 1.0f};
  std::uint8_t rgba[4] = {0, 0, 0, 255};
};

inline Vertex make_vertex(Vec3 p, Vec3 n, Rgb8 c, std::uint8_t alpha = 255) {
  return {{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)},
          {static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z)},
          {c.r, c.g, c.b, alpha}};
}

// Indexed triangles.
struct Mesh {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
};

// Independent segments (GL_LINES: vertices in pairs) of one width.
struct LineSet {
  std::vector<Vertex> vertices;
  float width_px = 1.0f;  // in output pixels at the reference panel size
};

}  // namespace vibro::gl
