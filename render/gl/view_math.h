// The small amount of linear algebra the 3-D panels need: vectors, and the column-major
// 4×4 matrices that glLoadMatrixd takes.
#pragma once

#include <array>
#include <cmath>

namespace vibro::gl {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
// a scaled to length 1; a itself when it has no direction.
inline Vec3 normalized(Vec3 a) {
  const double n = norm(a);
  return n > 0.0 ? (1.0 / n) * a : a;
}

// Column-major, as OpenGL stores it: element (row r, column c) is m[4 * c + r].
using Mat4 = std::array<double, 16>;

Mat4 operator*(const Mat4& a, const Mat4& b);

// glFrustum: the view volume through [left, right] × [bottom, top] on the near plane.
Mat4 frustum(double left, double right, double bottom, double top, double near, double far);

// Where `m` takes p, divided through by w.
Vec3 transform_point(const Mat4& m, Vec3 p);

// gluLookAt.
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up);

// Restricts a projection to the sub-rectangle [x0, x1) × [y0, y1) of a width × height
// viewport (pixels, y up), so a large image can be drawn tile by tile with the same result.
Mat4 crop_to_tile(const Mat4& projection, int width, int height, int x0, int y0, int x1, int y1);

}  // namespace vibro::gl
