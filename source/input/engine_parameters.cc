#include <poundfe/input/engine_parameters.h>

#include <poundfe/dynamics/partitioned_history.h>
#include <poundfe/model/model_builder.h>

#include <algorithm>
#include <iostream>
#include <set>

namespace poundfe
{
  namespace
  {
    /// The analysis's warnings on stderr where writes_outputs(), each once
    /// per process: a sweep prepares an analysis per value.
    void
    say_warnings(const Analysis &analysis)
    {
      static std::set<std::string> said;
      if (writes_outputs())
        for (const std::string &warning : analysis.warnings)
          if (said.insert(warning).second)
            std::cerr << "poundfe: warning: " << warning << "\n";
    }
  } // namespace

  namespace
  {
    /// Contact/Model = nonsmooth: the restitution is Newton's impact law's,
    /// whatever the law's damping, so what the builder says of the law's
    /// entries is replaced by one warning per force entry written, each
    /// without effect on rigid contact (model/entry_scope.h's warnings:
    /// terminal and summary.json). With `law_used` (the rigid limit of a
    /// sweep of the penalty law's stiffness) the penalty runs use those
    /// entries and say the builder's warnings themselves: none is added.
    void
    rigid_contact_warnings(const InputParameters &input, const bool law_used,
                           std::vector<std::string> &warnings)
    {
      static const std::vector<std::string> law_entries{
        "Stiffness",       "Damping from",        "Damping", "Coefficient of restitution",
        "Hertz-damp formula", "Effective mass", "Calibration velocity"};
      for (const std::string &entry : law_entries)
        {
          const std::string moot = input.warning("Contact/" + entry, "");
          warnings.erase(std::remove_if(warnings.begin(), warnings.end(),
                                        [&](const std::string &x) { return x.rfind(moot, 0) == 0; }),
                         warnings.end());
          if (!law_used && entry != "Coefficient of restitution" &&
              input.line_of("Contact/" + entry) > 0)
            warnings.push_back(input.warning(
              "Contact/" + entry,
              "has no effect: Contact/Model = nonsmooth is rigid contact (Newton's impact law "
              "with the Coefficient of restitution); the law's force parameters are unused"));
        }
      // the friction-contact problem is solved only with friction
      if (input.time_integration.moreau_jean.friction_coefficient == 0 &&
          input.line_of("Contact/Friction solver") > 0)
        warnings.push_back(input.warning("Contact/Friction solver",
                                         "has no effect: Contact/Friction coefficient is 0 (the "
                                         "contacts' LCP is solved by Contact/LCP solver)"));
    }
  } // namespace

  namespace
  {
    /// prepare_analysis() and prepare_rigid_limit_analysis(): `law_used`
    /// as rigid_contact_warnings() takes it.
    Analysis
    prepare_input_analysis(const InputParameters &input, const bool law_used)
    {
      Analysis analysis = prepare_analysis(input, input.model, input.contact, input.springs,
                                           input.friction, input.modal, input.output.n_modes);
      if (input.time_integration.contact_model == ContactModel::nonsmooth)
        rigid_contact_warnings(input, law_used, analysis.warnings);
      say_warnings(analysis);
      return analysis;
    }
  } // namespace

  Analysis
  prepare_analysis(const InputParameters &input)
  {
    return prepare_input_analysis(input, false);
  }

  Analysis
  prepare_rigid_limit_analysis(const InputParameters &input)
  {
    Assert(input.time_integration.contact_model == ContactModel::nonsmooth,
           dealii::ExcMessage("the rigid limit is a nonsmooth input's"));
    return prepare_input_analysis(input, true);
  }

  Analysis
  prepare_rank_analysis(const InputParameters &input, const MPI_Comm communicator)
  {
    Analysis analysis = prepare_rank_analysis(
      input, build_model(input.model, input.contact, input, input.springs, input.friction),
      input.modal, communicator, input.output.n_modes);
    say_warnings(analysis);
    return analysis;
  }

  TimeHistoryParameters
  time_history_parameters(const InputParameters &input)
  {
    return {input, input.time_integration, input.ground_motion, input.nodal_forces,
            input.initial_conditions};
  }

  RunParameters
  run_parameters(const InputParameters &input)
  {
    return {time_history_parameters(input), input.output, input.spectrum, input.drift_limits,
            input.contact,                 input.section_limits};
  }

  Excitation
  make_excitation(const Analysis &analysis, const InputParameters &input)
  {
    return make_excitation(analysis, time_history_parameters(input));
  }

  std::vector<NamedInputFile>
  named_input_files(const InputParameters &input)
  {
    std::vector<NamedInputFile> files;
    for (std::vector<NamedInputFile> section :
         {input.model.input_files(), input.ground_motion.input_files(),
          input.nodal_forces.input_files(), input.site_hazard.input_files(),
          input.separation.hazard.input_files(), input.ida.input_files(),
          input.msa.input_files(), input.selection.input_files()})
      for (NamedInputFile &file : section)
        {
          file.path = input.resolve(file.name);
          files.push_back(std::move(file));
        }
    return files;
  }
} // namespace poundfe
