// A sweep chain's runs as bytes, every double to the bit: what the processes of an MPI sweep send
// to rank 0 and what a sweep's checkpoint file keeps. Native byte order: the machines of one job
// share it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/analysis/sweep.h"

namespace vibro {

struct ChainRuns {
  int chain = 0;
  std::vector<SweepRun> runs;
};

// Appends one record (a length-prefixed chain) to `bytes`.
void append_chain(std::string& bytes, const ChainRuns& chain);

struct ReadChains {
  std::vector<ChainRuns> chains;
  std::size_t consumed = 0;  // bytes of whole records read; a cut-off last record is left out
  bool malformed = false;    // a record that is not one (another file, or damage)
};

// Reads the records of `bytes` up to the first incomplete or malformed one.
ReadChains read_chains(std::string_view bytes);

}  // namespace vibro
