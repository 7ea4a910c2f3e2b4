#include "render/gl/view_math.h"

namespace vibro::gl {

Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += a[4 * k + r] * b[4 * c + k];
      m[4 * c + r] = s;
    }
  }
  return m;
}

Mat4 frustum(double left, double right, double bottom, double top, double near, double far) {
  Mat4 m{};
  m[0] = 2.0 * near / (right - left);
  m[5] = 2.0 * near / (top - bottom);
  m[8] = (right + left) / (right - left);
  m[9] = (top + bottom) / (top - bottom);
  m[10] = -(far + near) / (far - near);
  m[11] = -1.0;
  m[14] = -2.0 * far * near / (far - near);
  return m;
}

Vec3 transform_point(const Mat4& m, Vec3 p) {
  const double w = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
  return {(m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12]) / w,
          (m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13]) / w,
          (m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]) / w};
}

Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
  const Vec3 f = normalized(target - eye);
  const Vec3 s = normalized(cross(f, up));
  const Vec3 u = cross(s, f);
  return {s.x,          u.x,          -f.x,        0.0,  //
          s.y,          u.y,          -f.y,        0.0,  //
          s.z,          u.z,          -f.z,        0.0,  //
          -dot(s, eye), -dot(u, eye), dot(f, eye), 1.0};
}

Mat4 crop_to_tile(const Mat4& projection, int width, int height, int x0, int y0, int x1, int y1) {
  // Normalised device x of the tile runs over [a, b]; map it onto [-1, 1], likewise y.
  const double ax = 2.0 * x0 / width - 1.0, bx = 2.0 * x1 / width - 1.0;
  const double ay = 2.0 * y0 / height - 1.0, by = 2.0 * y1 / height - 1.0;
  const double sx = 2.0 / (bx - ax), sy = 2.0 / (by - ay);
  Mat4 crop{};
  crop[0] = sx;
  crop[5] = sy;
  crop[10] = 1.0;
  crop[15] = 1.0;
  crop[12] = -0.5 * (ax + bx) * sx;
  crop[13] = -0.5 * (ay + by) * sy;
  return crop * projection;
}

}  // namespace vibro::gl
