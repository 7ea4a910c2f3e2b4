#include "render/gl/cylinder_view.h"

#include <algorithm>
#include <cmath>

#include "render/gl/cylinder_camera.h"
#include "render/gl/cylinder_guides.h"
#include "render/gl/downsample.h"
#include "render/gl/shared_context.h"
#include "render/gl/trajectory_tube.h"

namespace vibro::gl {
namespace {

// Samples per pixel along each axis.
constexpr int kSupersample = 2;
// Largest side of one supersampled tile: bounds the colour and depth buffers (32 MB) for
// any panel size.
constexpr int kMaxTile = 2048;
constexpr double kTubeRadius = 0.014;
// Line widths are given for a panel of this size and grow with larger ones, so a figure
// rendered big for print keeps its proportions.
constexpr double kReferenceSide = 800.0;

struct Geometry {
  Mesh tube;
  Mesh wall;
  std::vector<LineSet> lines;
};

std::string check_request(const Camera& camera, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxCylinderViewSide || height > kMaxCylinderViewSide) {
    return "cylinder view size " + std::to_string(width) + "x" + std::to_string(height) +
           " is outside 1.." + std::to_string(kMaxCylinderViewSide);
  }
  if (!std::isfinite(camera.azimuth_deg) || !std::isfinite(camera.elevation_deg)) {
    return "cylinder view camera angles must be finite";
  }
  if (!std::isfinite(camera.distance) || camera.distance <= 0.0) {
    return "cylinder view camera distance must be positive";
  }
  return {};
}

void draw_vertices(const GlApi& gl, const std::vector<Vertex>& v, bool with_normals) {
  gl.VertexPointer(3, GL_FLOAT, sizeof(Vertex), v.data()->position);
  gl.ColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), v.data()->rgba);
  if (with_normals) {
    gl.EnableClientState(GL_NORMAL_ARRAY);
    gl.NormalPointer(GL_FLOAT, sizeof(Vertex), v.data()->normal);
  } else {
    gl.DisableClientState(GL_NORMAL_ARRAY);
  }
}

void draw_mesh(const GlApi& gl, const Mesh& mesh) {
  if (mesh.indices.empty()) return;
  draw_vertices(gl, mesh.vertices, true);
  gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()), GL_UNSIGNED_INT,
                  mesh.indices.data());
}

void set_lighting(const GlApi& gl) {
  // One directional light over the viewer's left shoulder, fixed to the eye so every view
  // is lit alike; loaded while the modelview matrix is the identity.
  const GLfloat direction[4] = {-0.35f, 0.55f, 0.76f, 0.0f};
  const GLfloat diffuse[4] = {0.75f, 0.75f, 0.75f, 1.0f};
  const GLfloat ambient[4] = {0.38f, 0.38f, 0.38f, 1.0f};
  const GLfloat specular[4] = {0.35f, 0.35f, 0.35f, 1.0f};
  const GLfloat no_ambient[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  gl.Lightfv(GL_LIGHT0, GL_POSITION, direction);
  gl.Lightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  gl.Lightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  gl.Lightfv(GL_LIGHT0, GL_SPECULAR, specular);
  gl.LightModelfv(GL_LIGHT_MODEL_AMBIENT, no_ambient);
  gl.Materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
  gl.Materialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
  gl.ColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  gl.Enable(GL_COLOR_MATERIAL);
  gl.Enable(GL_LIGHT0);
  gl.ShadeModel(GL_SMOOTH);
}

// Draws the whole scene into the bound buffer through `projection`: opaque parts first,
// then the translucent wall far side before near side, which is back-to-front for a
// convex body.
void draw_scene(const GlApi& gl, const Geometry& geometry, const ViewSetup& setup,
                const Mat4& projection, double line_scale) {
  gl.ClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl.MatrixMode(GL_PROJECTION);
  gl.LoadMatrixd(projection.data());
  gl.MatrixMode(GL_MODELVIEW);
  gl.LoadIdentity();
  set_lighting(gl);
  gl.LoadMatrixd(setup.view.data());
  const GLfloat white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  gl.Fogi(GL_FOG_MODE, GL_LINEAR);
  gl.Fogfv(GL_FOG_COLOR, white);
  gl.Fogf(GL_FOG_START, setup.fog_start);
  gl.Fogf(GL_FOG_END, setup.fog_end);
  gl.Enable(GL_FOG);
  gl.Enable(GL_DEPTH_TEST);
  gl.DepthFunc(GL_LEQUAL);
  gl.EnableClientState(GL_VERTEX_ARRAY);
  gl.EnableClientState(GL_COLOR_ARRAY);

  gl.Enable(GL_LIGHTING);
  gl.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
  gl.Enable(GL_CULL_FACE);
  gl.CullFace(GL_BACK);
  draw_mesh(gl, geometry.tube);

  gl.Disable(GL_LIGHTING);
  gl.Disable(GL_CULL_FACE);
  for (const LineSet& lines : geometry.lines) {
    if (lines.vertices.empty()) continue;
    gl.LineWidth(static_cast<GLfloat>(lines.width_px * line_scale));
    draw_vertices(gl, lines.vertices, false);
    gl.DrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.vertices.size()));
  }

  // The wall lies on the limiter lines and rims: push it back so they are not veiled
  // where they touch it.
  gl.Enable(GL_LIGHTING);
  gl.LightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl.DepthMask(GL_FALSE);
  gl.Enable(GL_POLYGON_OFFSET_FILL);
  gl.PolygonOffset(1.0f, 4.0f);
  gl.Enable(GL_CULL_FACE);
  for (GLenum culled : {GL_FRONT, GL_BACK}) {
    gl.CullFace(culled);
    draw_mesh(gl, geometry.wall);
  }
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_POLYGON_OFFSET_FILL);
  gl.DepthMask(GL_TRUE);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_LIGHTING);
}

// Draws the panel tile by tile into *out, each tile supersampled then averaged down.
bool draw_tiles(OffscreenContext& context, const GlApi& gl, const Geometry& geometry,
                const ViewSetup& setup, Image* out, std::string* error) {
  const int f = kSupersample;
  const int tile = kMaxTile / f;  // output pixels per tile side
  const double line_scale = f * std::max(0.75, std::min(out->width, out->height) / kReferenceSide);
  for (int top = 0; top < out->height; top += tile) {
    for (int left = 0; left < out->width; left += tile) {
      const int w = std::min(tile, out->width - left);
      const int h = std::min(tile, out->height - top);
      if (!context.make_current(w * f, h * f, error)) return false;
      gl.Viewport(0, 0, w * f, h * f);
      const int bottom = out->height - top - h;  // GL counts rows from the bottom
      const Mat4 projection = crop_to_tile(setup.projection, out->width * f, out->height * f,
                                           left * f, bottom * f, (left + w) * f, (bottom + h) * f);
      draw_scene(gl, geometry, setup, projection, line_scale);
      if (const GLenum e = gl.GetError(); e != GL_NO_ERROR) {
        if (error) *error = "OpenGL error " + std::to_string(e) + " drawing the cylinder view";
        return false;
      }
      downsample_tile(context.read_rgba(), w * f, h * f, f, left, top, out);
    }
  }
  return true;
}

}  // namespace

Image render_cylinder_view(const CylinderScene& scene, int width, int height, std::string* error) {
  if (std::string problem = check_request(scene.camera, width, height); !problem.empty()) {
    if (error) *error = std::move(problem);
    return {};
  }
  const HeightScale scale = height_scale(scene);
  Geometry geometry{trajectory_tube(scene, scale, kTubeRadius), cylinder_wall(),
                    guide_lines(scale)};
  geometry.lines.push_back(limiter_lines(scene.limiter_angles));
  const ViewSetup setup = cylinder_camera(scene.camera, width, height);

  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  const bool ok = with_shared_context(
      [&](OffscreenContext& context, const GlApi& gl, std::string* why) {
        return draw_tiles(context, gl, geometry, setup, &image, why);
      },
      error);
  return ok ? image : Image{};
}

}  // namespace vibro::gl
