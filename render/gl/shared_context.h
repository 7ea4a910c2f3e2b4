// The process's one offscreen GL context, lent to one thread at a time. OSMesa contexts
// must stay on one thread while in use, and a server renders from worker threads, so every
// 3-D panel draws through here.
#pragma once

#include <functional>
#include <string>

#include "render/gl/gl_api.h"
#include "render/gl/offscreen_context.h"

namespace vibro::gl {

// Blocks until the context is free, creates it (loading OSMesa) on first use, runs `draw`
// with it bound to the calling thread, then unbinds it. Returns what `draw` returns; false
// with *error set when the context cannot be created.
bool with_shared_context(
    const std::function<bool(OffscreenContext&, const GlApi&, std::string*)>& draw,
    std::string* error);

}  // namespace vibro::gl
