// A sweep's chains as bytes and in a checkpoint file: exact to the bit, a record cut off by a
// crash left out, another scene's or another version's checkpoint or another file refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>
#include <cstring>

#include "io/presets.h"
#include "io/scene_json.h"
#include "io/sweep_checkpoint.h"

namespace vibro {
namespace {

SweepRun awkward_run(int k) {
  SweepRun r;
  r.value = 0.1 + k / 3.0;  // not a short decimal
  r.value2 = -std::nextafter(1.0, 2.0);
  r.start = k;
  r.direction = -1;
  r.points = {{1, 2.5, 1e-300, -0.0, 6.283185307179586, 0, false}, {0, 3.0, 7.0, 8.0, 0.0, -1, true}};
  r.period = 2;
  r.impacts_per_period = 1.0 / 7.0;
  r.at_rest = true;
  r.trusted = false;
  r.trusted_until = 12.25;
  r.termination = Termination::step_limit;
  r.message = "stopped at t = 3 s: the run reached its limit";
  r.error_estimate = 3e-9;
  // Every form the exponent takes: none, −infinity, a value that is no short decimal.
  if (k % 3 == 1) r.lyapunov = -std::numeric_limits<double>::infinity();
  if (k % 3 == 2) r.lyapunov = -0.1 - k / 7.0;
  return r;
}

void expect_same(const SweepRun& a, const SweepRun& b) {
  EXPECT_EQ(std::memcmp(&a.value, &b.value, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.value2, &b.value2, sizeof(double)), 0);
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.direction, b.direction);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    EXPECT_EQ(a.points[k].pellet, b.points[k].pellet);
    EXPECT_EQ(std::memcmp(&a.points[k].phi, &b.points[k].phi, sizeof(double)), 0);  // −0 too
    EXPECT_EQ(std::memcmp(&a.points[k].dphi, &b.points[k].dphi, sizeof(double)), 0);
    EXPECT_EQ(a.points[k].t, b.points[k].t);
    EXPECT_EQ(a.points[k].phase, b.points[k].phase);
    EXPECT_EQ(a.points[k].limiter, b.points[k].limiter);
    EXPECT_EQ(a.points[k].trusted, b.points[k].trusted);
  }
  EXPECT_EQ(a.period, b.period);
  EXPECT_EQ(a.impacts_per_period, b.impacts_per_period);
  EXPECT_EQ(a.at_rest, b.at_rest);
  EXPECT_EQ(a.sticks, b.sticks);
  EXPECT_EQ(a.trusted, b.trusted);
  EXPECT_EQ(a.trusted_until, b.trusted_until);
  EXPECT_EQ(a.termination, b.termination);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.error_estimate, b.error_estimate);
  ASSERT_EQ(a.lyapunov.has_value(), b.lyapunov.has_value());
  if (a.lyapunov) {
    EXPECT_EQ(std::memcmp(&*a.lyapunov, &*b.lyapunov, sizeof(double)), 0);
  }
}

TEST(SweepWire, ChainsComeBackToTheBit) {
  std::string bytes;
  append_chain(bytes, {7, {awkward_run(0), awkward_run(1), awkward_run(2)}});
  append_chain(bytes, {3, {}});
  const ReadChains read = read_chains(bytes);
  EXPECT_FALSE(read.malformed);
  EXPECT_EQ(read.consumed, bytes.size());
  ASSERT_EQ(read.chains.size(), 2u);
  EXPECT_EQ(read.chains[0].chain, 7);
  ASSERT_EQ(read.chains[0].runs.size(), 3u);
  for (int k = 0; k < 3; ++k) expect_same(read.chains[0].runs[k], awkward_run(k));
  EXPECT_EQ(read.chains[1].chain, 3);
  EXPECT_TRUE(read.chains[1].runs.empty());
}

TEST(SweepWire, ARecordCutOffIsLeftOutAndForeignBytesAreMalformed) {
  std::string bytes;
  append_chain(bytes, {0, {awkward_run(0)}});
  const std::size_t whole = bytes.size();
  append_chain(bytes, {1, {awkward_run(1)}});
  for (std::size_t cut = whole; cut < bytes.size(); cut += 7) {
    const ReadChains read = read_chains(std::string_view(bytes).substr(0, cut));
    EXPECT_FALSE(read.malformed) << cut;
    EXPECT_EQ(read.chains.size(), 1u) << cut;
    EXPECT_EQ(read.consumed, whole) << cut;
  }
  std::string damaged = bytes;
  damaged[whole] ^= 0x5a;  // the second record's mark
  EXPECT_TRUE(read_chains(damaged).malformed);
  EXPECT_TRUE(read_chains("x,y\n1,2\n and more text than a record head").malformed);
}

Scene scene_of(const char* preset) {
  return std::get<Scene>(scene_from_text(*preset_json(preset)));
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(SweepCheckpoint, KeepsChainsForItsSceneOnlyAndResumesWhole) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("vibro-checkpoint-" + std::to_string(::getpid()) + ".partial"))
                               .string();
  const Scene scene = scene_of("impact-oscillator");
  const std::uint64_t fp = scene_fingerprint(scene);
  {
    CheckpointWriter w(path, fp, nullptr);
    ASSERT_TRUE(w.ok());
    w.add({2, {awkward_run(0)}});
    w.add({5, {awkward_run(1), awkward_run(2)}});
  }
  auto read = read_checkpoint(path, fp);
  ASSERT_TRUE(std::holds_alternative<Checkpoint>(read)) << std::get<std::string>(read);
  Checkpoint c = std::get<Checkpoint>(read);
  ASSERT_EQ(c.chains.size(), 2u);
  EXPECT_EQ(c.runs, 3u);
  expect_same(c.chains[0].runs[0], awkward_run(0));
  expect_same(c.chains[1].runs[0], awkward_run(1));
  expect_same(c.chains[1].runs[1], awkward_run(2));

  // What decides the runs decides the fingerprint; the figure does not.
  Scene drawn = scene;
  drawn.figure.width = 640;
  EXPECT_EQ(scene_fingerprint(drawn), fp);
  Scene other = scene;
  other.sweep->axis.count += 1;
  EXPECT_NE(scene_fingerprint(other), fp);
  auto refused = read_checkpoint(path, scene_fingerprint(other));
  ASSERT_TRUE(std::holds_alternative<std::string>(refused));
  EXPECT_NE(std::get<std::string>(refused).find("another scene"), std::string::npos);

  // A crash mid-write leaves half a record: it is left out, and a resumed writer rewrites the
  // file whole before it adds.
  const std::string before = slurp(path);
  std::string half;
  append_chain(half, {9, {awkward_run(3)}});
  {
    std::ofstream f(path, std::ios::binary | std::ios::app);
    f << half.substr(0, half.size() / 2);
  }
  read = read_checkpoint(path, fp);
  ASSERT_TRUE(std::holds_alternative<Checkpoint>(read));
  c = std::get<Checkpoint>(read);
  EXPECT_EQ(c.chains.size(), 2u);
  {
    CheckpointWriter w(path, fp, &c);
    EXPECT_EQ(slurp(path), before);
    w.add({9, {awkward_run(3)}});
    EXPECT_EQ(slurp(path), before + half);
    w.remove();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  refused = read_checkpoint(path, fp);
  ASSERT_TRUE(std::holds_alternative<std::string>(refused));
  EXPECT_NE(std::get<std::string>(refused).find("does not exist"), std::string::npos);

  // A checkpoint of an earlier version, whose records do not carry what these do.
  std::string v1 = before;
  v1.replace(v1.find(" v2 "), 4, " v1 ");
  std::ofstream(path, std::ios::binary) << v1;
  refused = read_checkpoint(path, fp);
  ASSERT_TRUE(std::holds_alternative<std::string>(refused));
  EXPECT_NE(std::get<std::string>(refused).find("another version"), std::string::npos);

  std::ofstream(path) << "x,y\n1,2\n";
  refused = read_checkpoint(path, fp);
  ASSERT_TRUE(std::holds_alternative<std::string>(refused));
  EXPECT_NE(std::get<std::string>(refused).find("not a vibro sweep checkpoint"), std::string::npos);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace vibro
