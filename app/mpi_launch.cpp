#include <cstdlib>

#include "app/mpi_sweep.h"

namespace vibro {

bool launched_by_mpi() {
  // Open MPI's mpirun, Slurm's srun with PMIx, and MPICH's launchers (PMI).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace vibro
