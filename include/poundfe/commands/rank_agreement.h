// The ranks of an MPI job agree, before any collective work, that each has
// read its command line and parameter file and that they were all given the
// same: one rank that cannot read its file, or ranks given different
// models (mpirun's "-np 1 poundfe run a.prm : -np 1 poundfe run b.prm"),
// would otherwise leave the others waiting in a collective call forever, or
// mix two models in one result. Each rank reduces what it read to a list of
// items (the command line, every entry of the input, the bytes of every
// file the input names) and a digest of them; one MPI_Allreduce compares
// the digests and the ranks' exit statuses; only when they differ are the
// messages or the items gathered on rank 0, which names the rank and the
// item.
#ifndef poundfe_commands_rank_agreement_h
#define poundfe_commands_rank_agreement_h

#include <mpi.h>

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace poundfe
{
  struct InputParameters;

  /// One thing the ranks must agree on: its name for the message ("the
  /// command", "'Model/Number of buildings'", "the contents of rec.txt
  /// ('Ground motion/Record/File')") and the digest of its value.
  struct InputItem
  {
    std::string   name;
    std::uint64_t digest = 0;
    /// A named file this rank could not read: why ("" otherwise).
    std::string unreadable;
  };

  /// What one rank read before the command runs.
  struct RankInput
  {
    /// 0 when it read its input; else its exit status (1 bad input)
    int status = 0;
    /// Its message when it could not: the prefix ("poundfe: error: "), the
    /// problem, and what follows the problem (the usage text, or "").
    std::string prefix, problem, trailer;
    /// What it read, in order (when status is 0).
    std::vector<InputItem> items;
  };

  /// The items of a command line and its input: the command's name, the
  /// --output and --realizations given, every entry of `input` and the
  /// contents of every file it names (named_input_files, input/engine_parameters.h).
  std::vector<InputItem> input_items(const std::string &command, const std::string &output,
                                     unsigned int n_realizations, const InputParameters &input);

  /// Nothing when every rank of `communicator` read its input and they all
  /// read the same; otherwise the exit status every rank returns (the
  /// largest of the ranks' statuses; 1 for different inputs), after rank 0
  /// printed on `err` the message of the first rank that could not read its
  /// input (naming the rank, unless it is 0), or which rank's input differs
  /// from rank 0's and in which item. Collective.
  std::optional<int> ranks_disagree(const RankInput &mine, MPI_Comm communicator,
                                    std::ostream &err);
} // namespace poundfe

#endif
