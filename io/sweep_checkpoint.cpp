#include "io/sweep_checkpoint.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "io/scene_json.h"

namespace vibro {
namespace {

constexpr char kKind[] = "vibro sweep checkpoint ";
// The version of the records (io/sweep_wire.cpp); v2: runs carry their Lyapunov exponent.
constexpr char kVersion[] = "v2";

std::string header(std::uint64_t fingerprint) {
  char line[96];
  std::snprintf(line, sizeof line, "%s%s %016llx\n", kKind, kVersion,
                static_cast<unsigned long long>(fingerprint));
  return line;
}

}  // namespace

std::string checkpoint_path(const std::string& out) { return out + ".partial"; }

std::uint64_t scene_fingerprint(const Scene& scene) {
  // FNV-1a: stable across builds and machines, unlike std::hash.
  // What decides the runs only: the model, the solver and the sweep, not the figure or the name.
  Scene runs;
  runs.model = scene.model;
  runs.sim = scene.sim;
  runs.sweep = scene.sweep;
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : scene_to_json(runs).dump()) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

std::variant<Checkpoint, std::string> read_checkpoint(const std::string& path,
                                                      std::uint64_t fingerprint) {
  std::ifstream file(path, std::ios::binary);
  if (!file) return path + " does not exist: there is no partial sweep to resume";
  const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string head = header(fingerprint);
  if (!bytes.starts_with(kKind)) return path + " is not a vibro sweep checkpoint";
  if (!std::string_view(bytes).substr(sizeof kKind - 1).starts_with(std::string(kVersion) + " "))
    return path +
           " was written by another version of vibro, whose runs this one cannot read: "
           "remove it to start afresh";
  if (!bytes.starts_with(head))
    return path + " belongs to another scene or other options: resume with the scene that made it";
  const ReadChains read = read_chains(std::string_view(bytes).substr(head.size()));
  if (read.malformed) return path + " is damaged after " + std::to_string(read.chains.size()) + " chains";
  Checkpoint c;
  for (const ChainRuns& chain : read.chains) c.runs += chain.runs.size();
  c.chains = read.chains;
  return c;
}

CheckpointWriter::CheckpointWriter(const std::string& path, std::uint64_t fingerprint,
                                   const Checkpoint* keep)
    : path_(path) {
  // Rewritten whole on resume: a record cut off by a crash must not stay between whole ones.
  std::string bytes = header(fingerprint);
  if (keep)
    for (const ChainRuns& chain : keep->chains) append_chain(bytes, chain);
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) return;
  std::fwrite(bytes.data(), 1, bytes.size(), file_);
  std::fflush(file_);
}

CheckpointWriter::~CheckpointWriter() {
  if (file_) std::fclose(file_);
}

void CheckpointWriter::add(const ChainRuns& chain) {
  std::string bytes;
  append_chain(bytes, chain);
  const std::lock_guard lock(mutex_);
  if (!file_) return;
  std::fwrite(bytes.data(), 1, bytes.size(), file_);
  std::fflush(file_);
}

void CheckpointWriter::remove() {
  const std::lock_guard lock(mutex_);
  if (file_) std::fclose(file_);
  file_ = nullptr;
  std::remove(path_.c_str());
}

}  // namespace vibro
