// The render fuzzer (issue 31): scenes from tests/fuzz/render_scenes.h, read from their JSON as a
// request's body is, simulated within the server's limits and drawn to PNG, SVG and PDF. Each
// render must succeed with a well-formed image (tests/fuzz/image_checks.h) or be refused with a
// FieldError naming its field; each run must keep the run's contract
// (tests/robustness/run_invariants.h). A crash, a sanitizer report or a hang (a scene running
// past --scene-limit seconds) ends the process; the scene is then in render_fuzz-current.json.
//
//   render_fuzz [--seconds S] [--scenes N] [--seed X] [--first I] [--out DIR]
//               [--scene-limit S] [--print I] [--replay FILE]
//
// Bounded by S seconds (default 60) and N scenes, whichever ends first; the environment's
// VIBRO_RENDER_FUZZ_SECONDS, VIBRO_RENDER_FUZZ_SCENES and VIBRO_RENDER_FUZZ_SEED override the
// command line. Scene i of a seed is always the same: --print I writes its JSON, --replay FILE
// checks one scene file. A failing scene is kept as DIR/render_fuzz-failure-SEED-I.json and the
// exit status is 1.
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/analysis/checked_run.h"
#include "io/scene_json.h"
#include "render/figure.h"
#include "render/run_plan.h"
#include "server/config.h"
#include "server/run_scene.h"
#include "tests/fuzz/image_checks.h"
#include "tests/fuzz/render_scenes.h"
#include "tests/robustness/run_invariants.h"

namespace vibro::fuzz {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Options {
  double seconds = 60.0;
  long scenes = std::numeric_limits<long>::max();
  std::uint64_t seed = 31;
  long first = 0;
  std::string out = ".";
  double scene_limit_s = 300.0;
  long print = -1;
  std::string replay;
};

// What the server allows a request, by default (server/config.h's Limits): the reader's bounds,
// and the run's.
const server::Limits kServerLimits;

// Seconds a scene took in each stage: the run, and the drawing in each format.
using Stages = std::map<std::string, double>;

struct Tally {
  long scenes = 0;
  long refused_by_reader = 0;
  std::map<std::string, long> drawn, refused, terminations;
  std::map<std::string, long> refusal_fields;
  Stages stages;  // of the scene being checked
  double slowest_s = 0.0;
  long slowest = -1;
  Stages slowest_stages;
  long failures = 0;
};

const char* format_name(ImageFormat f) {
  return f == ImageFormat::png ? "png" : f == ImageFormat::svg ? "svg" : "pdf";
}

// The field without its indices: "plots[3].pellet" -> "plots[].pellet".
std::string field_kind(const std::string& field) {
  std::string kind;
  bool in_index = false;
  for (char c : field) {
    if (c == ']') in_index = false;
    if (!in_index) kind += c;
    if (c == '[') in_index = true;
  }
  return kind;
}

// A refusal is an answer when it names its field.
std::string refusal_defect(const FieldError& e, const std::string& where, Tally& tally) {
  if (e.field.empty()) return where + " refused without naming a field: " + e.message;
  ++tally.refusal_fields[field_kind(e.field)];
  return {};
}

// Draws the run in one format; empty when the answer is a well-formed image or a refusal.
std::string draw_defect(const Scene& scene, const RunResult& run, ImageFormat format,
                        Tally& tally) {
  const char* name = format_name(format);
  const Clock::time_point t0 = Clock::now();
  const RenderResult image = render_figure(scene.figure, scene.model, run, format);
  tally.stages[name] = seconds_since(t0);
  if (!image.ok()) {
    ++tally.refused[name];
    return refusal_defect(*image.error, std::string(name) + " rendering", tally);
  }
  ++tally.drawn[name];
  const std::string d = image_defect(image, format, scene.figure.width, scene.figure.height);
  return d.empty() ? d : std::string(name) + ": " + d;
}

// Reads, runs and draws one scene; empty when every answer keeps its contract.
std::string scene_defect(const std::string& text, Tally& tally) {
  SceneOrError parsed = scene_from_text(text, kServerLimits);
  if (const auto* e = std::get_if<FieldError>(&parsed)) {
    ++tally.refused_by_reader;
    return refusal_defect(*e, "the reader", tally);
  }
  const Scene& scene = std::get<Scene>(parsed);
  std::vector<ImageFormat> formats;
  for (ImageFormat f : {ImageFormat::png, ImageFormat::svg, ImageFormat::pdf}) {
    if (const auto e = validate_figure(scene.figure, scene.model, f)) {
      ++tally.refused[format_name(f)];
      if (std::string d = refusal_defect(*e, "validate_figure", tally); !d.empty()) return d;
    } else {
      formats.push_back(f);
    }
  }
  if (formats.empty()) return {};
  const RunPlan plan = plan_run(scene.figure, scene.sim, scene.model.size());
  const SimOptions options = server::bounded_options(plan.options, kServerLimits);
  const Clock::time_point t0 = Clock::now();
  const RunResult run = simulate(scene.model, options);
  tally.stages["run"] = seconds_since(t0);
  ++tally.terminations[std::string(termination_name(run.stats.termination))];
  if (std::string v = robustness::run_violation(run, scene.model, options.t_end); !v.empty())
    return "the run: " + v;
  for (ImageFormat f : formats)
    if (std::string d = draw_defect(scene, run, f, tally); !d.empty()) return d;
  return {};
}

// Aborts the process when one scene runs past the limit: a hang is a finding too, and its
// scene is in the current-scene file.
class Watchdog {
 public:
  Watchdog(double limit_s, std::string scene_file)
      : limit_s_(limit_s), scene_file_(std::move(scene_file)), thread_([this] { watch(); }) {}
  ~Watchdog() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  void begin(long index) {
    std::lock_guard lock(mutex_);
    index_ = index;
    since_ = Clock::now();
  }

 private:
  void watch() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::seconds(1), [this] { return done_; })) {
      if (index_ < 0 || seconds_since(since_) <= limit_s_) continue;
      std::fprintf(stderr, "render_fuzz: scene %ld has run for %.0f s (a hang?); it is in %s\n",
                   index_, seconds_since(since_), scene_file_.c_str());
      std::abort();
    }
  }

  double limit_s_;
  std::string scene_file_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  long index_ = -1;
  Clock::time_point since_;
  std::thread thread_;
};

void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

template <class Number>
std::string counts(const std::map<std::string, Number>& m) {
  std::ostringstream s;
  s.precision(3);
  for (const auto& [name, n] : m) s << (s.tellp() > 0 ? ", " : "") << name << " " << n;
  return s.str().empty() ? "none" : s.str();
}

void print_tally(const Options& o, const Tally& t, double elapsed) {
  std::printf("render_fuzz: seed %llu, scenes %ld..%ld (%ld) in %.1f s\n",
              static_cast<unsigned long long>(o.seed), o.first, o.first + t.scenes - 1, t.scenes,
              elapsed);
  std::printf("  refused by the reader: %ld; runs: %s\n", t.refused_by_reader,
              counts(t.terminations).c_str());
  std::printf("  drawn: %s; refused: %s\n", counts(t.drawn).c_str(), counts(t.refused).c_str());
  std::printf("  refusals by field: %s\n", counts(t.refusal_fields).c_str());
  std::printf("  slowest scene: %ld (%.2f s: %s); failures: %ld\n", t.slowest, t.slowest_s,
              counts(t.slowest_stages).c_str(), t.failures);
}

int fuzz(const Options& o) {
  const std::string current = o.out + "/render_fuzz-current.json";
  Watchdog watchdog(o.scene_limit_s, current);
  Tally tally;
  const Clock::time_point start = Clock::now();
  for (long i = o.first; tally.scenes < o.scenes && seconds_since(start) < o.seconds; ++i) {
    const std::string text = scene_to_json(render_scene_at(o.seed, i)).dump();
    write_file(current, text);
    watchdog.begin(i);
    const Clock::time_point t0 = Clock::now();
    tally.stages.clear();
    const std::string defect = scene_defect(text, tally);
    ++tally.scenes;
    if (seconds_since(t0) > tally.slowest_s) {
      tally.slowest_s = seconds_since(t0);
      tally.slowest = i;
      tally.slowest_stages = tally.stages;
    }
    if (defect.empty()) continue;
    ++tally.failures;
    const std::string kept = o.out + "/render_fuzz-failure-" + std::to_string(o.seed) + "-" +
                             std::to_string(i) + ".json";
    write_file(kept, text);
    std::printf("render_fuzz: FAILED scene %ld: %s (kept in %s)\n", i, defect.c_str(),
                kept.c_str());
  }
  watchdog.begin(-1);
  print_tally(o, tally, seconds_since(start));
  return tally.failures ? 1 : 0;
}

int replay(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (!file && text.empty()) {
    std::fprintf(stderr, "render_fuzz: cannot read %s\n", path.c_str());
    return 2;
  }
  Tally tally;
  const std::string defect = scene_defect(text, tally);
  std::printf("render_fuzz: %s: %s (s: %s)\n", path.c_str(), defect.empty() ? "ok" : defect.c_str(),
              counts(tally.stages).c_str());
  return defect.empty() ? 0 : 1;
}

// The command line, then the environment (so that CI and a long run can set the bounds of the
// test ctest registers).
Options options_from(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--seconds")
      o.seconds = std::stod(value);
    else if (flag == "--scenes")
      o.scenes = std::stol(value);
    else if (flag == "--seed")
      o.seed = std::stoull(value);
    else if (flag == "--first")
      o.first = std::stol(value);
    else if (flag == "--out")
      o.out = value;
    else if (flag == "--scene-limit")
      o.scene_limit_s = std::stod(value);
    else if (flag == "--print")
      o.print = std::stol(value);
    else if (flag == "--replay")
      o.replay = value;
    else
      throw std::invalid_argument("unknown option " + flag);
  }
  if (const char* s = std::getenv("VIBRO_RENDER_FUZZ_SECONDS")) o.seconds = std::stod(s);
  if (const char* s = std::getenv("VIBRO_RENDER_FUZZ_SCENES")) o.scenes = std::stol(s);
  if (const char* s = std::getenv("VIBRO_RENDER_FUZZ_SEED")) o.seed = std::stoull(s);
  return o;
}

}  // namespace
}  // namespace vibro::fuzz

int main(int argc, char** argv) {
  using namespace vibro::fuzz;
  Options o;
  try {
    o = options_from(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "render_fuzz: %s\n", e.what());
    return 2;
  }
  if (o.print >= 0) {
    std::printf("%s\n", vibro::scene_to_json(render_scene_at(o.seed, o.print)).dump(2).c_str());
    return 0;
  }
  if (!o.replay.empty()) return replay(o.replay);
  return fuzz(o);
}
