#include <poundfe/base/console.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <unistd.h>

namespace poundfe
{
  bool
  writes_outputs()
  {
    int initialized = 0;
    MPI_Initialized(&initialized);
    return !initialized || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  }

  void
  print_timing(const dealii::TimerOutput &timer)
  {
    // both: under Open MPI's mpirun a rank's stdout is a pseudo-terminal even
    // when mpirun's goes to a file, its stderr a pipe
    if (::isatty(STDOUT_FILENO) == 1 && ::isatty(STDERR_FILENO) == 1)
      timer.print_summary();
  }
} // namespace poundfe
