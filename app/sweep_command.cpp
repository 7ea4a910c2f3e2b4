// `vibro sweep SCENE | --preset NAME [-o OUT.json|.csv|.png|.svg] [--threads N] [--plot KIND]
// [--pellet I] [--coordinate dphi|phi]`: runs the scene's sweep on every core (or N threads),
// writes its points (JSON to stdout without -o) or draws it (a bifurcation diagram, a section, an
// impact map or a regime map), and shows a progress bar with the time left on stderr when that is
// a terminal.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/commands.h"
#include "core/sweep.h"
#include "io/sweep_json.h"
#include "render/figure.h"

namespace vibro {
namespace {

void usage_error(const std::string& field, const std::string& message) {
  std::cerr << nlohmann::json{{"error", message}, {"field", field}}.dump() << "\n";
}

// A progress bar redrawn in place: runs done of all, and the time left at the rate so far.
class ProgressBar {
 public:
  void operator()(long done, long total) {
    const std::lock_guard lock(mutex_);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    if (done < total && elapsed - drawn_ < 0.2) return;
    drawn_ = elapsed;
    const int width = 30;
    const int filled = static_cast<int>(width * done / std::max(total, 1L));
    const double left = done > 0 ? elapsed * (total - done) / done : 0.0;
    std::fprintf(stderr, "\r[%s%s] %ld/%ld runs, %.0f s left ", std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), done, total, left);
    if (done == total) std::fprintf(stderr, "\n");
  }

 private:
  std::mutex mutex_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  double drawn_ = -1.0;
};

}  // namespace

int sweep_command(const Args& args) {
  std::size_t next = 0;
  auto scene = load_scene(args, next);
  if (!scene) return 2;
  std::string out;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  PlotSpec plot;
  std::string plot_name;
  for (; next < args.size(); ++next) {
    const std::string& a = args[next];
    if ((a == "-o" || a == "--output") && next + 1 < args.size()) {
      out = args[++next];
    } else if (a == "--threads" && next + 1 < args.size()) {
      try {
        threads = std::stoi(args[++next]);
      } catch (const std::exception&) {
        threads = 0;
      }
      if (threads < 1 || threads > 1024) {
        usage_error("--threads", "must be an integer in [1, 1024]");
        return 2;
      }
    } else if (a == "--pellet" && next + 1 < args.size()) {
      const std::string& v = args[++next];
      plot.pellet = v.size() == 1 && v[0] >= '0' && v[0] <= '9' ? v[0] - '0' : -1;
      if (plot.pellet < 0 || plot.pellet >= scene->model.size()) {
        usage_error("--pellet", "must be a pellet index in 0.." + std::to_string(scene->model.size() - 1));
        return 2;
      }
    } else if (a == "--plot" && next + 1 < args.size()) {
      plot_name = args[++next];
    } else if (a == "--coordinate" && next + 1 < args.size()) {
      const std::string& v = args[++next];
      if (v != "dphi" && v != "phi") {
        usage_error("--coordinate", "must be \"dphi\" or \"phi\"");
        return 2;
      }
      plot.coordinate = v == "phi" ? SectionCoordinate::phi : SectionCoordinate::dphi;
    } else {
      usage_error(a, "is not an option of `vibro sweep`");
      return 2;
    }
  }
  if (!scene->sweep) {
    usage_error("sweep", "the scene has no sweep: add one (API.md, \"Sweeps\")");
    return 2;
  }
  const auto kind = sweep_plot_kind(plot_name, *scene->sweep);
  if (!kind) {
    usage_error("--plot", "must be \"bifurcation\", \"section\", \"impact_map\" or \"regime_map\"");
    return 2;
  }
  plot.kind = *kind;
  const auto image = image_format_of_file(out);
  if (!out.empty() && !out.ends_with(".json") && !out.ends_with(".csv") && !image) {
    usage_error("-o", "name the output OUT.json, OUT.csv, OUT.png, OUT.svg or OUT.pdf");
    return 2;
  }
  ProgressBar bar;
  SweepControl control;
  control.threads = threads;
  if (isatty(STDERR_FILENO)) control.progress = [&bar](long done, long total) { bar(done, total); };
  const SweepResult result = run_sweep(scene->model, scene->sim, *scene->sweep, control);
  std::string text;
  if (image) {
    FigureSpec figure;
    figure.width = scene->figure.width;
    figure.height = scene->figure.height;
    figure.plots = {plot};
    const RenderResult drawn =
        render_figure(figure, scene->model, RunResult{}, *image, {nullptr, &*scene->sweep, &result});
    if (!drawn.ok()) {
      usage_error(drawn.error->field, drawn.error->message);
      return 1;
    }
    text.assign(drawn.bytes.begin(), drawn.bytes.end());
  } else {
    text = out.ends_with(".csv") ? sweep_result_csv(result)
                                 : sweep_result_json(*scene->sweep, result).dump() + "\n";
  }
  if (out.empty()) {
    std::cout << text;
    return 0;
  }
  std::ofstream file(out, std::ios::binary);
  file << text;
  if (!file) {
    usage_error(out, "cannot write the file");
    return 1;
  }
  return 0;
}

}  // namespace vibro
