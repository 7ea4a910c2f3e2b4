#include "render/gl/offscreen_context.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <vector>

namespace vibro::gl {
namespace {

// The OSMesa entry points, taken from the library with dlsym so that the build never
// links it.
struct OsmesaLibrary {
  void* handle = nullptr;
  OSMesaContext(GLAPIENTRY* create_context_ext)(GLenum, GLint, GLint, GLint,
                                                OSMesaContext) = nullptr;
  GLboolean(GLAPIENTRY* make_current)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  OSMESAproc(GLAPIENTRY* get_proc_address)(const char*) = nullptr;
  void(GLAPIENTRY* destroy_context)(OSMesaContext) = nullptr;
  void(GLAPIENTRY* finish)() = nullptr;
  std::string error;  // why loading failed; empty on success
};

std::atomic<bool> g_loaded{false};

template <typename Fn>
bool resolve(OsmesaLibrary& lib, const char* name, Fn* out) {
  *out = reinterpret_cast<Fn>(dlsym(lib.handle, name));
  if (*out == nullptr) lib.error = std::string("libOSMesa.so.8 lacks ") + name;
  return *out != nullptr;
}

OsmesaLibrary load_library() {
  // llvmpipe otherwise starts one rasteriser thread per core for every context; the panels
  // are small and a server renders several requests side by side. A caller's setting wins.
  setenv("LP_NUM_THREADS", "2", /*overwrite=*/0);
  OsmesaLibrary lib;
  lib.handle = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
  if (lib.handle == nullptr) {
    const char* why = dlerror();
    lib.error = std::string("cannot load libOSMesa.so.8: ") + (why ? why : "unknown error");
    return lib;
  }
  g_loaded = true;
  // The handle stays open for the life of the process: Mesa does not support being
  // unloaded while its threads and dispatch tables exist.
  if (resolve(lib, "OSMesaCreateContextExt", &lib.create_context_ext) &&
      resolve(lib, "OSMesaMakeCurrent", &lib.make_current) &&
      resolve(lib, "OSMesaGetProcAddress", &lib.get_proc_address) &&
      resolve(lib, "OSMesaDestroyContext", &lib.destroy_context)) {
    lib.finish = reinterpret_cast<void(GLAPIENTRY*)()>(lib.get_proc_address("glFinish"));
    if (lib.finish == nullptr) lib.error = "libOSMesa.so.8 lacks glFinish";
  }
  return lib;
}

const OsmesaLibrary& library() {
  static const OsmesaLibrary lib = load_library();
  return lib;
}

class OsmesaContext final : public OffscreenContext {
 public:
  OsmesaContext(const OsmesaLibrary& lib, OSMesaContext context) : lib_(lib), context_(context) {}
  ~OsmesaContext() override { lib_.destroy_context(context_); }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  bool make_current(int width, int height, std::string* error) override {
    if (width <= 0 || height <= 0) {
      if (error) *error = "offscreen buffer size must be positive";
      return false;
    }
    pixels_.assign(static_cast<std::size_t>(width) * height * 4, 0);
    if (!lib_.make_current(context_, pixels_.data(), GL_UNSIGNED_BYTE, width, height)) {
      if (error) {
        *error =
            "OSMesaMakeCurrent failed for " + std::to_string(width) + "x" + std::to_string(height);
      }
      return false;
    }
    width_ = width;
    height_ = height;
    return true;
  }

  void release() override { lib_.make_current(nullptr, nullptr, 0, 0, 0); }

  int width() const override { return width_; }
  int height() const override { return height_; }

  std::span<const std::uint8_t> read_rgba() override {
    lib_.finish();
    return pixels_;
  }

  void* gl_proc(const char* name) override {
    return reinterpret_cast<void*>(lib_.get_proc_address(name));
  }

 private:
  const OsmesaLibrary& lib_;
  OSMesaContext context_;
  std::vector<std::uint8_t> pixels_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace

std::unique_ptr<OffscreenContext> create_osmesa_context(std::string* error) {
  const OsmesaLibrary& lib = library();
  if (!lib.error.empty()) {
    if (error) *error = lib.error;
    return nullptr;
  }
  OSMesaContext context = lib.create_context_ext(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (context == nullptr) {
    if (error) *error = "OSMesaCreateContextExt failed";
    return nullptr;
  }
  return std::make_unique<OsmesaContext>(lib, context);
}

bool osmesa_loaded() { return g_loaded; }

}  // namespace vibro::gl
