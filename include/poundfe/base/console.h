// What a command says on the terminal: which process speaks (rank 0 of
// MPI_COMM_WORLD), and its timer table (dealii::TimerOutput) on a terminal only.
#ifndef poundfe_base_console_h
#define poundfe_base_console_h

namespace dealii
{
  class TimerOutput;
}

namespace poundfe
{
  /// Whether this process writes files and messages: rank 0 of
  /// MPI_COMM_WORLD, or the only process when MPI is not initialised.
  /// (With a solver that needs MPI, every rank of `mpirun -np P poundfe
  /// run` runs the same analysis; rank 0 alone writes.)
  bool writes_outputs();

  /// A command's timer table, on a terminal only (stdout and stderr are
  /// terminals: pipes, log files and tests see nothing).
  void print_timing(const dealii::TimerOutput &timer);
} // namespace poundfe

#endif
