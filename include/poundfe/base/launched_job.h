// This process's place in mpirun's job as its launcher says it in the
// environment (Open MPI's OMPI_COMM_WORLD_*, PMIx's PMIX_RANK, MPICH's
// PMI_*), read without MPI: the program before it initialises MPI
// (program.cc), and the OpenSees interpreter, which never does (its getPID
// and getNP, and which rank prints its messages).
#ifndef poundfe_base_launched_job_h
#define poundfe_base_launched_job_h

#include <algorithm>
#include <cstdlib>
#include <string>

namespace poundfe
{
  /// This process's rank in mpirun's job; 0 when launched alone.
  inline int
  launched_rank()
  {
    for (const char *name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
      if (const char *rank = std::getenv(name))
        return std::max(0, std::atoi(rank));
    return 0;
  }

  /// The number of processes of mpirun's job; 1 when launched alone.
  inline int
  launched_size()
  {
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
      if (const char *size = std::getenv(name))
        return std::max(1, std::atoi(size));
    return 1;
  }

  /// A message as this rank prints it: prefixed "rank N: " on the ranks
  /// other than 0 of a job of several ranks, so that a rank's own failure
  /// (a script may differ per rank through getPID) says whose it is.
  inline std::string
  from_this_rank(const std::string &message)
  {
    const int rank = launched_rank();
    return rank > 0 && launched_size() > 1 ? "rank " + std::to_string(rank) + ": " + message :
                                             message;
  }
} // namespace poundfe

#endif
