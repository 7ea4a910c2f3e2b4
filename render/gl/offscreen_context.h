// A GL context that draws into memory rather than a window, so 3-D panels render on a
// machine with no display. The OSMesa implementation loads libOSMesa only when the first
// context is created: a process that draws only 2-D panels never maps it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace vibro::gl {

class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;

  // Binds the context to the calling thread, drawing into a width × height RGBA8 colour
  // buffer with a depth buffer. False, with *error set, when that size cannot be bound.
  virtual bool make_current(int width, int height, std::string* error) = 0;
  // Unbinds the context from the calling thread, so that another thread may bind it next.
  virtual void release() = 0;

  virtual int width() const = 0;
  virtual int height() const = 0;

  // Waits for drawing to end and returns the colour buffer: RGBA8, rows bottom to top as
  // GL numbers them. Valid until the next make_current.
  virtual std::span<const std::uint8_t> read_rgba() = 0;

  // A GL entry point of the context's library, or nullptr.
  virtual void* gl_proc(const char* name) = 0;
};

// Loads libOSMesa.so.8 (once per process) and creates a context with a 24-bit depth
// buffer. nullptr, with *error set, when the library or the context is unavailable.
std::unique_ptr<OffscreenContext> create_osmesa_context(std::string* error);

// True once this process has loaded libOSMesa.
bool osmesa_loaded();

}  // namespace vibro::gl
