#include "render/gl/gl_api.h"

#include "render/gl/offscreen_context.h"

namespace vibro::gl {

bool load_gl_api(OffscreenContext& context, GlApi* api, std::string* error) {
#define VIBRO_GL_LOAD(name, ret, params)                                              \
  api->name = reinterpret_cast<ret(GLAPIENTRY*) params>(context.gl_proc("gl" #name)); \
  if (api->name == nullptr) {                                                         \
    if (error) *error = "OpenGL entry point gl" #name " not found";                   \
    return false;                                                                     \
  }
  VIBRO_GL_FUNCTIONS(VIBRO_GL_LOAD)
#undef VIBRO_GL_LOAD
  return true;
}

}  // namespace vibro::gl
