// One orbit or sweep request carried out as `vibro serve` carries it out (server/api.cpp,
// server/jobs.cpp): read with the server's scene limits (which check the specs' budgets too),
// run with the options bounded by the server's limits, and written with the
// io/ writers the server answers with. What the answer must keep is checked on the way:
// a refusal names a field of the request; an accepted request ends within 5 × its deadline
// + 1 s; its JSON (and a sweep's CSV) holds no NaN or infinity; a sweep runs only values
// inside its range, each a valid model; a branch's points are valid models.
#pragma once

#include <string>
#include <vector>

#include "server/config.h"

namespace vibro::robustness {

struct EdgeOutcome {
  bool accepted = false;
  std::string field, message;         // the refusal
  double ms = 0.0;                    // the whole request, reading included
  std::vector<std::string> findings;  // each broken promise, in words
};

// POST /api/periodic-orbit: without a continuation the search on a worker, with one the job,
// cancelled as DELETE /api/jobs/ID would cancel it once limits.deadline_ms has passed.
EdgeOutcome orbit_request(const std::string& body, const server::Limits& limits);

// POST /api/sweeps: the job, cancelled after `runs` runs or once limits.deadline_ms has passed.
EdgeOutcome sweep_request(const std::string& body, const server::Limits& limits, long runs = 3);

}  // namespace vibro::robustness
