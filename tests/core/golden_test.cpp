// The event lists of every preset under every method, against the lists recorded in
// tests/core/golden/. A change of the event core that is meant to keep behaviour must keep these;
// one that is meant to change it (a fix) re-records them with VIBRO_UPDATE_GOLDEN=1 and says in
// its commit which lines moved and why.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/analysis/checked_run.h"
#include "io/presets.h"
#include "scenes.h"

#ifndef VIBRO_GOLDEN_DIR
#error "VIBRO_GOLDEN_DIR must name tests/core/golden"
#endif

namespace vibro {
namespace {

struct GoldenEvent {
  std::string method;
  std::string kind;
  std::string pellets;
  int limiter = -1;
  double t = 0.0;
};

std::string pellet_list(const std::vector<int>& pellets) {
  std::string s;
  for (int i : pellets) s += (s.empty() ? "" : " ") + std::to_string(i);
  return s;
}

std::vector<GoldenEvent> record(const std::string& preset) {
  const Scene scene = testing::preset(preset);
  std::vector<GoldenEvent> out;
  for (Method m : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    SimOptions o = scene.sim;
    o.method = m;
    const RunResult run = simulate(scene.model, o);
    for (const Event& e : run.events) {
      out.push_back({std::string(method_name(m)), std::string(event_kind_name(e.kind)),
                     pellet_list(e.pellets), e.limiter, e.t});
    }
  }
  return out;
}

std::string path_of(const std::string& preset) {
  return std::string(VIBRO_GOLDEN_DIR) + "/" + preset + ".csv";
}

void write(const std::string& preset, const std::vector<GoldenEvent>& events) {
  std::ofstream f(path_of(preset));
  f << "method,kind,pellets,limiter,t\n";
  char t[64];
  for (const GoldenEvent& e : events) {
    std::snprintf(t, sizeof t, "%.17g", e.t);
    f << e.method << ',' << e.kind << ',' << e.pellets << ',' << e.limiter << ',' << t << '\n';
  }
}

std::vector<GoldenEvent> read(const std::string& preset) {
  std::ifstream f(path_of(preset));
  std::vector<GoldenEvent> out;
  std::string line;
  std::getline(f, line);  // header
  while (std::getline(f, line)) {
    std::istringstream row(line);
    GoldenEvent e;
    std::string limiter, t;
    std::getline(row, e.method, ',');
    std::getline(row, e.kind, ',');
    std::getline(row, e.pellets, ',');
    std::getline(row, limiter, ',');
    std::getline(row, t, ',');
    e.limiter = std::stoi(limiter);
    e.t = std::stod(t);
    out.push_back(e);
  }
  return out;
}

TEST(Golden, EveryPresetUnderEveryMethodListsTheRecordedEvents) {
  const bool update = std::getenv("VIBRO_UPDATE_GOLDEN") != nullptr;
  for (const PresetText& p : presets()) {
    const std::string name(p.name);
    const std::vector<GoldenEvent> now = record(name);
    if (update) {
      write(name, now);
      continue;
    }
    const std::vector<GoldenEvent> then = read(name);
    ASSERT_FALSE(then.empty() && !now.empty()) << name << ": no golden file " << path_of(name);
    ASSERT_EQ(now.size(), then.size()) << name;
    for (std::size_t k = 0; k < now.size(); ++k) {
      const GoldenEvent& a = now[k];
      const GoldenEvent& b = then[k];
      ASSERT_TRUE(a.method == b.method && a.kind == b.kind && a.pellets == b.pellets &&
                  a.limiter == b.limiter)
          << name << " event " << k << " (" << a.method << "): " << a.kind << " [" << a.pellets
          << "] limiter " << a.limiter << " at t = " << a.t << ", recorded " << b.kind << " ["
          << b.pellets << "] limiter " << b.limiter << " at t = " << b.t;
      // Recorded to 17 digits; round-off of a reordered sum may move a time, nothing more.
      EXPECT_NEAR(a.t, b.t, 1e-12 * (1.0 + std::abs(b.t)))
          << name << " event " << k << " (" << a.method << ") " << a.kind;
    }
  }
}

}  // namespace
}  // namespace vibro
