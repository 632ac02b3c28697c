// The one dispatch of a command of the table (commands/dispatch.h), for the
// command line and the Python module alike: every rule of the row checked
// here, from its columns, never from the command's name.
#include <poundfe/assembly/linear_solver.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/commands/command_guard.h>
#include <poundfe/commands/command_table.h>
#include <poundfe/commands/dispatch.h>
#include <poundfe/commands/rank_agreement.h>
#include <poundfe/input/override_origin.h>

#include <deal.II/base/mpi.h>

#include <iostream>
#include <optional>

namespace poundfe
{
  bool
  initialises_mpi_first(const Command &command, const unsigned int launched_processes)
  {
    if (!command.has(CommandRule::reads_file))
      return false;
    const bool spreads_one_run = command.has(CommandRule::distributed_solver) ||
                                 command.has(CommandRule::partition_by_building);
    return command.has(CommandRule::over_mpi) || (spreads_one_run && launched_processes > 1);
  }

  namespace
  {
    bool
    dispatch_has_mpi()
    {
      return dealii::Utilities::MPI::job_supports_mpi();
    }

    bool
    dispatch_on_several_ranks()
    {
      return dispatch_has_mpi() && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
    }

    /// Refuses (CommandLineError) what the row does not take: the number of
    /// arguments (a row of script arguments needs its script), --realizations,
    /// --set without a file.
    void
    check_request(const Command &command, const CommandRequest &request)
    {
      if (command.has(CommandRule::script_arguments) && request.arguments.empty())
        throw CommandLineError("'" + command.name + "' needs a script", usage_text());
      const bool reads_file = command.has(CommandRule::reads_file);
      if (reads_file && request.arguments.size() != 1)
        throw CommandLineError("'" + command.name + "' needs exactly one parameter file",
                               usage_text());
      if (request.n_realizations > 0 && !command.has(CommandRule::takes_realizations))
        throw CommandLineError("--realizations belongs to " +
                               command_names(CommandRule::takes_realizations));
      if (request.write_at2 && !command.has(CommandRule::writes_at2))
        throw CommandLineError("--write-at2 belongs to " + command_names(CommandRule::writes_at2));
      if (request.write_at2 && request.n_realizations == 0)
        throw CommandLineError("--write-at2 writes the realizations of --realizations N: give N");
      if (request.memory && !command.has(CommandRule::in_memory))
        throw CommandLineError("results in memory belong to " +
                               command_names(CommandRule::in_memory) +
                               ": give an output directory");
      if (!reads_file && !request.overrides.empty())
        throw CommandLineError("--set sets an entry of a parameter file, and '" + command.name +
                               "' reads none");
    }

    /// Refuses (InputError at the entry's line) an input that asks for what
    /// the row does not allow: a distributed linear solver on several ranks
    /// (the probabilistic commands give each rank its own realizations),
    /// Partition = buildings, XDMF fields from a command that writes none.
    void
    check_rules(const Command &command, const InputParameters &input, const bool several_ranks)
    {
      const std::string &solver = input.time_integration.linear_solver;
      if (several_ranks && linear_solver_is_distributed(solver) &&
          !command.has(CommandRule::distributed_solver))
        input.fail("Time integration/Linear solver",
                   solver + " spreads one run over the MPI ranks: on more than one rank only " +
                     command_names(CommandRule::distributed_solver, "'") + " can use it, not '" +
                     command.name + "'");
      if (input.time_integration.partition == RunPartition::buildings &&
          !command.has(CommandRule::partition_by_building))
        input.fail("Time integration/Partition",
                   "buildings spreads one run over the MPI ranks: only " +
                     command_names(CommandRule::partition_by_building, "'") + " takes it, not '" +
                     command.name + "'");
      if (input.time_integration.partition == RunPartition::buildings)
        for (unsigned int b = 0; b < input.model.buildings.size(); ++b)
          if (input.model.buildings[b].fibre()) // a rank observes only its own members
            input.fail("Time integration/Partition",
                       "buildings does not follow the limit states of fibre members over the "
                       "ranks (summary.json's section_limit_states); Building " +
                         std::to_string(b + 1) +
                         " has Member model = fibre: run it unpartitioned (Partition = none)");
      if (input.time_integration.contact_model == ContactModel::nonsmooth &&
          !command.has(CommandRule::rigid_contact))
        input.fail("Contact/Model",
                   "nonsmooth (rigid contact) is taken by " +
                     command_names(CommandRule::rigid_contact, "'") + " only, not '" +
                     command.name + "'" +
                     (command.without_rigid_contact.empty() ?
                        std::string(" so far") :
                        ": " + command.without_rigid_contact));
      if (input.output.field_format == FieldFormat::xdmf && !command.has(CommandRule::field_output))
        input.fail("Output/Field format",
                   "xdmf chooses the field output of " +
                     command_names(CommandRule::field_output, "'") + "; '" + command.name +
                     "' writes no fields (leave it at vtu)");
    }

    /// The parameter file of `request` read with its overrides, MPI started
    /// when the row or the input needs it, and checked against the row.
    InputParameters
    read_command_input(const Command &command, const CommandRequest &request,
                       const MpiStarter &start_mpi)
    {
      InputParameters input = read_parameters(request.arguments[0], request.overrides);
      if (!dispatch_has_mpi() &&
          (command.has(CommandRule::over_mpi) ||
           linear_solver_needs_mpi(input.time_integration.linear_solver) ||
           input.time_integration.partition == RunPartition::buildings))
        start_mpi();
      check_rules(command, input, dispatch_on_several_ranks());
      return input;
    }

    /// What a rank that could not read its input tells the others.
    RankInput
    refused_rank(const std::exception_ptr &refusal)
    {
      try
        {
          std::rethrow_exception(refusal);
        }
      catch (const CommandLineError &e)
        {
          return {1, "poundfe: error: ", e.what(), e.trailer(), {}};
        }
      catch (const NumericalError &e)
        {
          return {2, "poundfe: numerical failure: ", e.what(), "", {}};
        }
      catch (const std::exception &e)
        {
          return {1, "poundfe: error: ", e.what(), "", {}};
        }
      catch (...)
        {
          return {1, "poundfe: error: ", "the input could not be read", "", {}};
        }
    }

    /// The command run on its input inside the guard, writing its results
    /// on the rank that writes.
    int
    run_guarded(const Command &command, const CommandRequest &request,
                const InputParameters &input, std::ostream &err)
    {
      const std::string directory = request.output.empty() ? input.output.directory : request.output;
      const bool        writes =
        !dispatch_has_mpi() || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const MPI_Comm communicator = dispatch_has_mpi() ? MPI_COMM_WORLD : MPI_COMM_SELF;
      // results in memory: the guard writes no file either (no directory named, no summary)
      return guard_command({command, input, directory, writes && !request.memory}, [&]() -> int {
        return command.run({request.arguments, &input, directory, request.n_realizations,
                            communicator, err, writes ? std::cout : silent_stream(),
                            request.write_at2, request.memory});
      });
    }
  } // namespace

  int
  dispatch_command(const Command &command, const CommandRequest &request,
                   const MpiStarter &start_mpi, std::ostream &err)
  {
    if (!command.has(CommandRule::reads_file)) // print-parameters, template
      {
        check_request(command, request);
        return command.run(
          {request.arguments, nullptr, request.output, 0, MPI_COMM_SELF, err, std::cout});
      }
    std::optional<InputParameters> input;
    std::exception_ptr             refusal;
    try
      {
        check_request(command, request);
        input.emplace(read_command_input(command, request, start_mpi));
      }
    catch (...)
      {
        refusal = std::current_exception();
      }
    if (dispatch_on_several_ranks()) // every rank read the same, or all stop
      {
        RankInput rank = refusal ? refused_rank(refusal) : RankInput();
        if (!refusal)
          rank.items = input_items(command.name, request.output, request.n_realizations, *input);
        if (const std::optional<int> status = ranks_disagree(rank, MPI_COMM_WORLD, err))
          return *status;
      }
    else if (refusal)
      std::rethrow_exception(refusal);
    try
      {
        return run_guarded(command, request, *input, err);
      }
    catch (const SweepValueError &) // its origin named by the sweep
      {
        throw;
      }
    catch (const InputError &e) // the model builder's, of an entry a --set gave
      {
        throw with_override_origin(e, request.overrides);
      }
  }
} // namespace poundfe
