// A sweep's CSV written as its chains finish (`vibro sweep -o OUT.csv`): memory for the chains
// that finished ahead of their turn and for the attractor table, not for the sweep's points.
// The file is the one write_sweep_result_csv writes for the whole result, byte for byte: chains
// are released in their order, each one's runs put in the result's order, and a sweep that
// classifies attractors has its ids, known only once every run is in, put in by a second pass
// over the rows. The file is written whole or not at all (io/whole_file.h).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/attractors.h"
#include "core/analysis/sweep.h"
#include "io/whole_file.h"

namespace vibro {

class SweepCsvStream {
 public:
  SweepCsvStream(const std::string& path, const Model& model, const SweepSpec& spec);
  ~SweepCsvStream();
  // Chain c's runs, from any thread, each chain once (resumed ones too); false once the file
  // cannot be written.
  bool add(int chain, std::vector<SweepRun> runs);
  // After the last chain: the file in place, or why not. The attractors of a sweep that
  // classifies them are in `attractors`.
  std::optional<FileProblem> finish(std::vector<Attractor>* attractors = nullptr);
  const std::string& path() const { return path_; }

 private:
  void release(std::vector<SweepRun>& runs);
  std::optional<FileProblem> renumber_into_place();

  std::string path_;
  std::string rows_path_;  // a sweep that classifies: the rows with provisional classes
  bool classify_;
  std::unique_ptr<WholeFileWriter> out_;
  int rows_fd_ = -1;
  int rows_error_ = 0;
  std::optional<AttractorTable> table_;
  std::mutex mutex_;
  int next_ = 0;                                  // the next chain to write
  std::map<int, std::vector<SweepRun>> waiting_;  // chains finished ahead of their turn
  std::string buffer_;
  bool ok_ = true;
};

}  // namespace vibro
