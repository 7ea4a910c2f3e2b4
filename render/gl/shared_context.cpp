#include "render/gl/shared_context.h"

#include <memory>
#include <mutex>

namespace vibro::gl {
namespace {

struct Shared {
  std::mutex mutex;
  std::unique_ptr<OffscreenContext> context;
  GlApi gl;
};

Shared& shared() {
  // Never destroyed: Mesa's own teardown at exit may already have run when static
  // destructors do.
  static Shared* s = new Shared;
  return *s;
}

}  // namespace

bool with_shared_context(
    const std::function<bool(OffscreenContext&, const GlApi&, std::string*)>& draw,
    std::string* error) {
  Shared& s = shared();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.context) {
    std::unique_ptr<OffscreenContext> context = create_osmesa_context(error);
    if (!context) return false;
    GlApi gl;
    if (!load_gl_api(*context, &gl, error)) return false;
    s.context = std::move(context);
    s.gl = gl;
  }
  const bool ok = draw(*s.context, s.gl, error);
  s.context->release();
  return ok;
}

}  // namespace vibro::gl
