// PNG encoders side by side on the paper figure's pixels (1200×800, the preset's figure drawn
// once): vibro's figure deflater (render/png.h), cairo's own writer (libpng, zlib level 6 with
// adaptive filters), and the same filter-0 rows through zlib and libdeflate at their fastest
// and default levels. Each encoder's output size is the `bytes` counter.
#include <benchmark/benchmark.h>
#include <cairo.h>
#include <libdeflate.h>
#include <zlib.h>

#include <cstring>

#include "bench_scenes.h"
#include "core/analysis/checked_run.h"
#include "render/figure.h"
#include "render/png.h"
#include "render/run_plan.h"
#include "tests/render/png_decode.h"

namespace vibro::bench {
namespace {

// The paper figure as an RGB24 surface over decoded pixels, drawn and decoded once (by the
// tests' decoder, cairo's PNG reader).
cairo_surface_t* paper_surface() {
  static testing::Decoded pixels = [] {
    const Scene scene = preset_scene("paper");
    const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
    return testing::decode_png(render_figure(scene.figure, scene.model,
                                             simulate(scene.model, plan.options), ImageFormat::png)
                                   .bytes);
  }();
  static cairo_surface_t* surface = cairo_image_surface_create_for_data(
      reinterpret_cast<unsigned char*>(pixels.argb.data()), CAIRO_FORMAT_RGB24, pixels.width,
      pixels.height, 4 * pixels.width);
  return surface;
}

// The surface as PNG rows, filter type 0 (what the general-purpose deflaters compress).
std::vector<std::uint8_t> filter0_rows(cairo_surface_t* s) {
  const int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  std::vector<std::uint8_t> rows;
  rows.reserve(static_cast<std::size_t>(h) * (1 + 3 * w));
  for (int y = 0; y < h; ++y) {
    rows.push_back(0);
    for (int x = 0; x < w; ++x) {
      std::uint32_t p;
      std::memcpy(&p, data + y * stride + 4 * x, 4);
      rows.insert(rows.end(), {static_cast<std::uint8_t>(p >> 16),
                               static_cast<std::uint8_t>(p >> 8), static_cast<std::uint8_t>(p)});
    }
  }
  return rows;
}

void BM_EncodeVibro(benchmark::State& state) {
  cairo_surface_t* s = paper_surface();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto png = render::encode_png_argb32(
        cairo_image_surface_get_data(s), cairo_image_surface_get_width(s),
        cairo_image_surface_get_height(s), cairo_image_surface_get_stride(s), true);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_EncodeVibro)->Unit(benchmark::kMillisecond);

cairo_status_t count_bytes(void* closure, const unsigned char*, unsigned int length) {
  *static_cast<std::size_t*>(closure) += length;
  return CAIRO_STATUS_SUCCESS;
}

void BM_EncodeCairoLibpng(benchmark::State& state) {
  cairo_surface_t* s = paper_surface();
  std::size_t bytes = 0;
  for (auto _ : state) {
    bytes = 0;
    cairo_surface_write_to_png_stream(s, count_bytes, &bytes);
  }
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_EncodeCairoLibpng)->Unit(benchmark::kMillisecond);

// Row conversion included, as an encoder must do it.
void BM_EncodeZlib(benchmark::State& state) {
  cairo_surface_t* s = paper_surface();
  const int level = static_cast<int>(state.range(0));
  std::vector<std::uint8_t> out;
  uLongf size = 0;
  for (auto _ : state) {
    const auto rows = filter0_rows(s);
    out.resize(compressBound(rows.size()));
    size = out.size();
    compress2(out.data(), &size, rows.data(), rows.size(), level);
  }
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_EncodeZlib)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond);

void BM_EncodeLibdeflate(benchmark::State& state) {
  cairo_surface_t* s = paper_surface();
  libdeflate_compressor* c = libdeflate_alloc_compressor(static_cast<int>(state.range(0)));
  std::vector<std::uint8_t> out;
  std::size_t size = 0;
  for (auto _ : state) {
    const auto rows = filter0_rows(s);
    out.resize(libdeflate_zlib_compress_bound(c, rows.size()));
    size = libdeflate_zlib_compress(c, rows.data(), rows.size(), out.data(), out.size());
  }
  libdeflate_free_compressor(c);
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_EncodeLibdeflate)->Arg(1)->Arg(6)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace vibro::bench

BENCHMARK_MAIN();
