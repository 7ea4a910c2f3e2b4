// A sweep's chains as bytes and in a checkpoint file: exact to the bit, a record cut off by a
// crash left out, another scene's or another version's checkpoint or another file refused.
#include "io/sweep_checkpoint.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "io/presets.h"
#include "io/scene_json.h"

namespace vibro {
namespace {

SweepRun awkward_run(int k) {
  SweepRun r;
  r.value = 0.1 + k / 3.0;  // not a short decimal
  r.value2 = -std::nextafter(1.0, 2.0);
  r.start = k;
  r.direction = -1;
  r.points = {{1, 2.5, 1e-300, -0.0, 6.283185307179586, 0, false},
              {0, 3.0, 7.0, 8.0, 0.0, -1, true}};
  r.period = 2;
  r.impacts_per_period = 1.0 / 7.0;
  r.at_rest = true;
  r.rests = k % 2 == 1;
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
  EXPECT_EQ(a.rests, b.rests);
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

// The impact oscillator's sweep without continuation over 10 values: chains 0..9 of one run.
Scene sweep_scene() {
  Scene scene = std::get<Scene>(scene_from_text(*preset_json("impact-oscillator")));
  scene.sweep->continuation = Continuation::none;
  scene.sweep->axis.count = 10;
  return scene;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

std::string temporary_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("vibro-" + std::to_string(::getpid()) + "-" + name))
      .string();
}

// The refusal of reading `path` for `scene`, or "" when it was read.
std::string refusal(const std::string& path, const Scene& scene) {
  const auto read = read_checkpoint(path, scene);
  const auto* why = std::get_if<std::string>(&read);
  return why ? *why : "";
}

TEST(SweepCheckpoint, KeepsChainsForItsSceneOnlyAndResumesWhole) {
  const std::string path = temporary_path("checkpoint.partial");
  const Scene scene = sweep_scene();
  const std::uint64_t fp = scene_fingerprint(scene);
  {
    CheckpointWriter w(path, fp, nullptr);
    ASSERT_FALSE(w.problem());
    EXPECT_TRUE(w.add({2, {awkward_run(0)}}));
    EXPECT_TRUE(w.add({5, {awkward_run(1)}}));
    EXPECT_EQ(w.chains(), 2u);
  }
  auto read = read_checkpoint(path, scene);
  ASSERT_TRUE(std::holds_alternative<Checkpoint>(read)) << std::get<std::string>(read);
  Checkpoint c = std::get<Checkpoint>(read);
  ASSERT_EQ(c.chains.size(), 2u);
  EXPECT_EQ(c.runs, 2u);
  EXPECT_EQ(c.chains[0].chain, 2);
  EXPECT_EQ(c.chains[1].chain, 5);
  expect_same(c.chains[0].runs[0], awkward_run(0));
  expect_same(c.chains[1].runs[0], awkward_run(1));

  // What decides the runs decides the fingerprint; the figure does not.
  Scene drawn = scene;
  drawn.figure.width = 640;
  EXPECT_EQ(scene_fingerprint(drawn), fp);
  Scene other = scene;
  other.sweep->axis.count += 1;
  EXPECT_NE(scene_fingerprint(other), fp);
  EXPECT_NE(refusal(path, other).find("another scene"), std::string::npos);

  // A crash mid-write leaves half a record: it is left out, and a resumed writer rewrites the
  // file whole before it adds.
  const std::string before = slurp(path);
  const std::string half = checkpoint_record(fp, {9, {awkward_run(3)}});
  for (std::size_t cut = 1; cut < half.size(); cut += 13) {
    std::ofstream(path, std::ios::binary) << before << half.substr(0, cut);
    read = read_checkpoint(path, scene);
    ASSERT_TRUE(std::holds_alternative<Checkpoint>(read)) << cut << std::get<std::string>(read);
    EXPECT_EQ(std::get<Checkpoint>(read).chains.size(), 2u) << cut;
  }
  c = std::get<Checkpoint>(read);
  {
    CheckpointWriter w(path, fp, &c);
    EXPECT_EQ(slurp(path), before);
    w.add({9, {awkward_run(3)}});
    EXPECT_EQ(slurp(path), before + half);
    w.remove();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_NE(refusal(path, scene).find("does not exist"), std::string::npos);

  // A checkpoint of an earlier version, whose records do not carry what these do.
  std::string v3 = before;
  v3.replace(v3.find(" v4 "), 4, " v3 ");
  std::ofstream(path, std::ios::binary) << v3;
  EXPECT_NE(refusal(path, scene).find("another version"), std::string::npos);

  std::ofstream(path) << "x,y\n1,2\n";
  EXPECT_NE(refusal(path, scene).find("not a vibro sweep checkpoint"), std::string::npos);
  std::filesystem::remove(path);
}

// A file of the scene's header and `records`, written as CheckpointWriter writes them (so that
// every checksum holds unless a test changes the bytes after).
std::string checkpoint_of(const Scene& scene, const std::vector<ChainRuns>& chains) {
  const std::string path = temporary_path("made.partial");
  {
    CheckpointWriter w(path, scene_fingerprint(scene), nullptr);
    for (const ChainRuns& c : chains) w.add(c);
  }
  std::string bytes = slurp(path);
  std::filesystem::remove(path);
  return bytes;
}

// Reading `bytes` as the scene's checkpoint is refused with a message holding each of `words`.
void expect_refused(const Scene& scene, const std::string& bytes,
                    const std::vector<std::string>& words) {
  const std::string path = temporary_path("tampered.partial");
  std::ofstream(path, std::ios::binary) << bytes;
  const std::string why = refusal(path, scene);
  std::filesystem::remove(path);
  ASSERT_FALSE(why.empty()) << "read as a checkpoint";
  for (const std::string& w : words) EXPECT_NE(why.find(w), std::string::npos) << why;
}

// Each tampering that once changed, lost or duplicated the rows of a resumed sweep is refused,
// naming the record.
TEST(SweepCheckpoint, RefusesDamagedAndInconsistentRecords) {
  const Scene scene = sweep_scene();
  const std::string good = checkpoint_of(scene, {{1, {awkward_run(0)}}, {4, {awkward_run(1)}}});
  const std::size_t head = good.find('\n') + 1;
  const std::size_t second = head + checkpoint_record(0, {1, {awkward_run(0)}}).size();

  // Every single bit flipped in the records: no run changes silently.
  for (std::size_t byte = head; byte < good.size(); ++byte) {
    for (int bit : {0, 5}) {
      std::string flipped = good;
      flipped[byte] = static_cast<char>(flipped[byte] ^ (1 << bit));
      const std::string path = temporary_path("flipped.partial");
      std::ofstream(path, std::ios::binary) << flipped;
      const auto read = read_checkpoint(path, scene);
      std::filesystem::remove(path);
      // A flipped length may make the last record look cut off (left out, run again); else
      // the checksum fails. Never are the runs read changed.
      if (const auto* c = std::get_if<Checkpoint>(&read)) {
        ASSERT_EQ(c->chains.size(), byte < second ? 0u : 1u) << byte;
        if (!c->chains.empty()) expect_same(c->chains[0].runs[0], awkward_run(0));
      }
    }
  }
  std::string flipped = good;
  flipped[second - 9] ^= 1;  // a byte of the first record's runs
  expect_refused(scene, flipped, {"record 1 (at byte " + std::to_string(head) + ")", "checksum"});

  // Relabelled: the first record's chain index rewritten in place (the checksum covers it).
  std::string relabelled = good;
  const std::int32_t four = 4;
  std::memcpy(relabelled.data() + head + 8 + 12, &four, sizeof four);  // length, mark, length
  expect_refused(scene, relabelled, {"record 1", "checksum"});

  // Records with good checksums that the sweep cannot have made.
  expect_refused(scene, good + checkpoint_record(scene_fingerprint(scene), {4, {awkward_run(1)}}),
                 {"record 3", "holds chain 4, which an earlier record holds"});
  expect_refused(scene, checkpoint_of(scene, {{1000000, {awkward_run(0)}}}),
                 {"record 1", "chain 1000000", "0..9"});
  expect_refused(scene, checkpoint_of(scene, {{-5, {awkward_run(0)}}}),
                 {"record 1", "chain -5", "0..9"});
  expect_refused(scene, checkpoint_of(scene, {{1, {awkward_run(0)}}, {3, {}}}),
                 {"record 2", "chain 3 with 0 runs", "has 1"});
  expect_refused(scene, checkpoint_of(scene, {{3, {awkward_run(0), awkward_run(1)}}}),
                 {"record 1", "with 2 runs"});

  // Another scene's records after this scene's header: their checksums hold the other scene.
  Scene other = scene;
  other.sweep->axis.to += 1.0;
  const std::string theirs = checkpoint_of(other, {{2, {awkward_run(2)}}});
  expect_refused(scene, good + theirs.substr(theirs.find('\n') + 1), {"record 3", "checksum"});

  // A checkpoint that is a directory, not a file.
  const std::string dir = temporary_path("dir.partial");
  std::filesystem::create_directory(dir);
  EXPECT_NE(refusal(dir, scene).find("is a directory"), std::string::npos);
  std::filesystem::remove(dir);
}

}  // namespace
}  // namespace vibro
