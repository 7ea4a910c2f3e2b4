#include "io/sweep_checkpoint.h"

#include <fcntl.h>
#include <libdeflate.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>

#include "io/scene_json.h"

namespace vibro {
namespace {

constexpr char kKind[] = "vibro sweep checkpoint ";
// The version of the records; v2: runs carry their Lyapunov exponent; v3: each record framed
// with its length and a CRC-32; v4: runs carry whether they rest (a basin sweep's rest attractor).
constexpr char kVersion[] = "v4";

std::string header(std::uint64_t fingerprint) {
  char line[96];
  std::snprintf(line, sizeof line, "%s%s %016llx\n", kKind, kVersion,
                static_cast<unsigned long long>(fingerprint));
  return line;
}

// A record: its length (u64), the chain's bytes (io/sweep_wire.h), a CRC-32 (u32) over the
// scene's fingerprint, the length and the bytes. Native byte order, like the chain's bytes.
constexpr std::size_t kLengthBytes = sizeof(std::uint64_t);
constexpr std::size_t kCrcBytes = sizeof(std::uint32_t);

std::uint32_t record_crc(std::uint64_t fingerprint, std::uint64_t length, std::string_view bytes) {
  std::uint32_t crc = libdeflate_crc32(0, &fingerprint, sizeof fingerprint);
  crc = libdeflate_crc32(crc, &length, sizeof length);
  return libdeflate_crc32(crc, bytes.data(), bytes.size());
}

template <class T>
T read_at(std::string_view bytes, std::size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

// Reads the records after the header, checking each against the scene's sweep.
class RecordReader {
 public:
  RecordReader(const std::string& path, const Scene& scene)
      : path_(path),
        fingerprint_(scene_fingerprint(scene)),
        chains_(sweep_chain_count(*scene.sweep)),
        runs_per_chain_(static_cast<std::size_t>(sweep_runs(*scene.sweep) / chains_)) {}

  std::variant<Checkpoint, std::string> read(std::string_view bytes, std::size_t at) {
    Checkpoint c;
    std::set<int> seen;
    for (int record = 1; bytes.size() - at >= kLengthBytes; ++record) {
      const auto length = read_at<std::uint64_t>(bytes, at);
      const std::size_t left = bytes.size() - at - kLengthBytes;
      if (left < kCrcBytes || left - kCrcBytes < length) break;  // cut off by a crash: left out
      const std::string_view body = bytes.substr(at + kLengthBytes, length);
      const std::string where =
          path_ + ": record " + std::to_string(record) + " (at byte " + std::to_string(at) + ")";
      if (read_at<std::uint32_t>(bytes, at + kLengthBytes + length) !=
          record_crc(fingerprint_, length, body))
        return where + " fails its checksum: the file is damaged or was edited" + kStartAfresh;
      ReadChains read = read_chains(body);
      if (read.malformed || read.chains.size() != 1 || read.consumed != body.size())
        return where + " is not one chain's runs" + kStartAfresh;
      ChainRuns& chain = read.chains[0];
      if (auto why = wrong_chain(chain, seen)) return where + *why + kStartAfresh;
      c.runs += chain.runs.size();
      c.chains.push_back(std::move(chain));
      at += kLengthBytes + length + kCrcBytes;
    }
    return c;
  }

 private:
  static constexpr char kStartAfresh[] = "; remove it to start the sweep afresh";

  std::optional<std::string> wrong_chain(const ChainRuns& chain, std::set<int>& seen) const {
    const std::string which = " holds chain " + std::to_string(chain.chain);
    if (chain.chain < 0 || chain.chain >= chains_)
      return which + ", but the sweep's chains are 0.." + std::to_string(chains_ - 1);
    if (chain.runs.size() != runs_per_chain_)
      return which + " with " + std::to_string(chain.runs.size()) + " runs, but each chain of " +
             "the sweep has " + std::to_string(runs_per_chain_);
    if (!seen.insert(chain.chain).second) return which + ", which an earlier record holds";
    return std::nullopt;
  }

  std::string path_;
  std::uint64_t fingerprint_;
  int chains_;
  std::size_t runs_per_chain_;
};

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

std::string checkpoint_record(std::uint64_t fingerprint, const ChainRuns& chain) {
  std::string body;
  append_chain(body, chain);
  const std::uint64_t length = body.size();
  const std::uint32_t crc = record_crc(fingerprint, length, body);
  std::string record(kLengthBytes, '\0');
  std::memcpy(record.data(), &length, kLengthBytes);
  record += body;
  record.append(reinterpret_cast<const char*>(&crc), kCrcBytes);
  return record;
}

std::variant<Checkpoint, std::string> read_checkpoint(const std::string& path, const Scene& scene) {
  auto file = read_whole_file(path);
  if (auto* problem = std::get_if<FileProblem>(&file)) {
    if (problem->error == ENOENT)
      return path + " does not exist: there is no partial sweep to resume";
    return problem->message;
  }
  const std::string& bytes = std::get<std::string>(file);
  const std::string head = header(scene_fingerprint(scene));
  if (!bytes.starts_with(kKind)) return path + " is not a vibro sweep checkpoint";
  if (!std::string_view(bytes).substr(sizeof kKind - 1).starts_with(std::string(kVersion) + " "))
    return path +
           " was written by another version of vibro, whose runs this one cannot read: "
           "remove it to start afresh";
  if (!bytes.starts_with(head))
    return path + " belongs to another scene or other options: resume with the scene that made it";
  return RecordReader(path, scene).read(bytes, head.size());
}

CheckpointWriter::CheckpointWriter(const std::string& path, std::uint64_t fingerprint,
                                   const Checkpoint* keep)
    : path_(path), fingerprint_(fingerprint) {
  // Rewritten whole on resume: a record cut off by a crash must not stay between whole ones.
  std::string bytes = header(fingerprint);
  if (keep)
    for (const ChainRuns& chain : keep->chains) bytes += checkpoint_record(fingerprint, chain);
  problem_ = write_whole_file(path, bytes);
  if (problem_) return;
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) {
    const int error = errno;
    problem_ = FileProblem{path + " cannot be written: " + std::strerror(error), error};
    return;
  }
  size_ = bytes.size();
  chains_ = keep ? keep->chains.size() : 0;
}

CheckpointWriter::~CheckpointWriter() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<FileProblem> CheckpointWriter::problem() const {
  const std::lock_guard lock(mutex_);
  return problem_;
}

std::size_t CheckpointWriter::chains() const {
  const std::lock_guard lock(mutex_);
  return chains_;
}

bool CheckpointWriter::add(const ChainRuns& chain) {
  const std::string record = checkpoint_record(fingerprint_, chain);
  const std::lock_guard lock(mutex_);
  if (fd_ < 0) return false;
  if (const int error = write_all(fd_, record)) {
    // Half a record would make every record after it unreadable; the file keeps what was whole.
    [[maybe_unused]] const int cut = ::ftruncate(fd_, static_cast<off_t>(size_));
    ::close(fd_);
    fd_ = -1;
    problem_ = FileProblem{path_ + " cannot be written: " + std::strerror(error), error};
    return false;
  }
  size_ += record.size();
  ++chains_;
  return true;
}

void CheckpointWriter::remove() {
  const std::lock_guard lock(mutex_);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(path_.c_str());
}

}  // namespace vibro
