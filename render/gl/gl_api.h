// The legacy GL entry points the 3-D panels use, resolved at run time from the offscreen
// context's library: nothing here links libGL or libOSMesa, so a 2-D-only process never
// loads them.
#pragma once

#include <GL/gl.h>

#include <string>

namespace vibro::gl {

class OffscreenContext;

// X-macro list: (name, return type, parameter list). One place to add an entry point.
#define VIBRO_GL_FUNCTIONS(X)                                     \
  X(Viewport, void, (GLint, GLint, GLsizei, GLsizei))             \
  X(ClearColor, void, (GLclampf, GLclampf, GLclampf, GLclampf))   \
  X(Clear, void, (GLbitfield))                                    \
  X(Enable, void, (GLenum))                                       \
  X(Disable, void, (GLenum))                                      \
  X(MatrixMode, void, (GLenum))                                   \
  X(LoadIdentity, void, ())                                       \
  X(LoadMatrixd, void, (const GLdouble*))                         \
  X(Lightfv, void, (GLenum, GLenum, const GLfloat*))              \
  X(LightModelfv, void, (GLenum, const GLfloat*))                 \
  X(LightModeli, void, (GLenum, GLint))                           \
  X(Materialfv, void, (GLenum, GLenum, const GLfloat*))           \
  X(Materialf, void, (GLenum, GLenum, GLfloat))                   \
  X(ColorMaterial, void, (GLenum, GLenum))                        \
  X(ShadeModel, void, (GLenum))                                   \
  X(BlendFunc, void, (GLenum, GLenum))                            \
  X(DepthMask, void, (GLboolean))                                 \
  X(DepthFunc, void, (GLenum))                                    \
  X(CullFace, void, (GLenum))                                     \
  X(PolygonOffset, void, (GLfloat, GLfloat))                      \
  X(LineWidth, void, (GLfloat))                                   \
  X(Fogi, void, (GLenum, GLint))                                  \
  X(Fogf, void, (GLenum, GLfloat))                                \
  X(Fogfv, void, (GLenum, const GLfloat*))                        \
  X(EnableClientState, void, (GLenum))                            \
  X(DisableClientState, void, (GLenum))                           \
  X(VertexPointer, void, (GLint, GLenum, GLsizei, const GLvoid*)) \
  X(NormalPointer, void, (GLenum, GLsizei, const GLvoid*))        \
  X(ColorPointer, void, (GLint, GLenum, GLsizei, const GLvoid*))  \
  X(DrawArrays, void, (GLenum, GLint, GLsizei))                   \
  X(DrawElements, void, (GLenum, GLsizei, GLenum, const GLvoid*)) \
  X(GetError, GLenum, ())

struct GlApi {
#define VIBRO_GL_MEMBER(name, ret, params) ret(GLAPIENTRY* name) params = nullptr;
  VIBRO_GL_FUNCTIONS(VIBRO_GL_MEMBER)
#undef VIBRO_GL_MEMBER
};

// Fills *api from the context's library. False, with *error naming the first missing entry
// point, when one cannot be found.
bool load_gl_api(OffscreenContext& context, GlApi* api, std::string* error);

}  // namespace vibro::gl
