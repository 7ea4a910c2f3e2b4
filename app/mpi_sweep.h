// `vibro sweep` over the processes of an MPI job (mpirun, srun): rank 0 hands out chunks of
// chains (core/analysis/sweep.h) to every worker thread of every rank, the biggest first and
// smaller as the work runs out, gathers their runs as they finish, and returns the result,
// identical to a sweep in one process. Built only when Open MPI is found (VIBRO_HAVE_MPI).
#pragma once

#include <optional>

#include "core/analysis/sweep.h"

namespace vibro {

// Whether this process is one of an MPI job's (the launcher's environment says so).
bool launched_by_mpi();

#ifdef VIBRO_HAVE_MPI
// Joins the job (MPI_Init_thread, every thread may communicate); false with a message on stderr
// when the MPI library cannot. Returns this process's rank in `rank`.
bool mpi_start(int& rank);
void mpi_finish();

// Whether every rank is ready (each passes its own verdict): a rank that stops alone would leave
// the others waiting for it.
bool mpi_all_agree(bool ok);

// Runs the sweep on every rank with control.threads workers each. On rank 0 returns the result
// (control.progress, control.skip and control.chain_done are used there, chain_done as the runs
// arrive); on the others nothing. A worker that fails ends the whole job with a message naming
// the value it was running; so does a crash (a signal), from the rank that crashed.
std::optional<SweepResult> run_sweep_mpi(const Model& model, const SimOptions& options,
                                         const SweepSpec& spec, const SweepControl& control);
#endif

}  // namespace vibro
