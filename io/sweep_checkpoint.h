// A sweep's finished chains kept in a file as they finish (OUT.partial beside the output OUT), so
// that a sweep stopped by a failure, a killed job or Ctrl-C loses nothing and can resume: its
// first line says what it is, the version of its records and which scene it belongs to, the
// records (io/sweep_wire.h) follow.
#pragma once

#include <cstdint>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <variant>

#include "io/scene.h"
#include "io/sweep_wire.h"

namespace vibro {

// The checkpoint file of an output: OUT.partial.
std::string checkpoint_path(const std::string& out);

// What identifies a scene to its checkpoint: a hash of its canonical JSON (model, solver, sweep).
std::uint64_t scene_fingerprint(const Scene& scene);

struct Checkpoint {
  std::vector<ChainRuns> chains;
  std::size_t runs = 0;
};

// Reads a checkpoint written for the scene of `fingerprint`; an error a person reads when the
// file is missing, another scene's, another version's, or not a checkpoint. A last record cut off
// mid-write is left out (and overwritten when the sweep resumes).
std::variant<Checkpoint, std::string> read_checkpoint(const std::string& path,
                                                      std::uint64_t fingerprint);

// Appends chains to a checkpoint file, each flushed as it comes; safe from any thread.
class CheckpointWriter {
 public:
  // Starts the file afresh, or (resume) keeps the header and the whole records of `keep`.
  CheckpointWriter(const std::string& path, std::uint64_t fingerprint, const Checkpoint* keep);
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  bool ok() const { return file_ != nullptr; }
  void add(const ChainRuns& chain);
  // The sweep finished and its output is written: the checkpoint goes.
  void remove();

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::mutex mutex_;
};

}  // namespace vibro
