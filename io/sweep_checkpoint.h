// A sweep's finished chains kept in a file as they finish (OUT.partial beside the output OUT), so
// that a sweep stopped by a failure, a killed job or Ctrl-C loses nothing and can resume: its
// first line says what it is, the version of its records and which scene it belongs to; the
// records follow, one per chain, each a chain's runs (io/sweep_wire.h) with a CRC-32 over them,
// their length and the scene's fingerprint, so that a damaged, spliced or relabelled record is
// refused, never read as runs.
#pragma once

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <variant>

#include "io/scene.h"
#include "io/sweep_wire.h"
#include "io/whole_file.h"

namespace vibro {

// The checkpoint file of an output: OUT.partial.
std::string checkpoint_path(const std::string& out);

// What identifies a scene to its checkpoint: a hash of its canonical JSON (model, solver, sweep).
std::uint64_t scene_fingerprint(const Scene& scene);

struct Checkpoint {
  std::vector<ChainRuns> chains;
  std::size_t runs = 0;
};

// Reads the checkpoint of `scene` (which has a sweep). Refused, with a sentence a person reads
// naming the file (and the record, counted from 1, and its byte offset): a file that is missing
// or unreadable, another scene's, another version's or not a checkpoint; a record whose
// checksum fails, that is no chain record, names a chain the sweep does not have, holds other
// than a chain's number of runs, or repeats a chain. A last record cut off mid-write is left out
// (and overwritten when the sweep resumes).
std::variant<Checkpoint, std::string> read_checkpoint(const std::string& path, const Scene& scene);

// Appends chains to a checkpoint file, each written through to the file as it comes; safe from
// any thread. After a write fails nothing more is added, and the file is cut back to its whole
// records.
class CheckpointWriter {
 public:
  // Starts the file afresh, or (resume) with the header and the records of `keep`; written whole
  // or not at all (io/whole_file.h), so a failure leaves an earlier file as it was.
  CheckpointWriter(const std::string& path, std::uint64_t fingerprint, const Checkpoint* keep);
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  // Why the file could not be started or a chain added; nothing while every write succeeded.
  std::optional<FileProblem> problem() const;
  // The chains the file holds whole.
  std::size_t chains() const;
  // False when the chain could not be added (now or by an earlier failure).
  bool add(const ChainRuns& chain);
  // The sweep finished and its output is written: the checkpoint goes.
  void remove();

 private:
  std::string path_;
  std::uint64_t fingerprint_;
  int fd_ = -1;
  std::size_t size_ = 0;  // bytes of the header and the whole records
  std::size_t chains_ = 0;
  std::optional<FileProblem> problem_;
  mutable std::mutex mutex_;
};

// One record of a checkpoint of the scene of `fingerprint`, as the file holds it; for tests.
std::string checkpoint_record(std::uint64_t fingerprint, const ChainRuns& chain);

}  // namespace vibro
