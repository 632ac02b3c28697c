#include <poundfe/dynamics/realization.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/output/demand_table.h>
#include <poundfe/output/floor_response.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <deal.II/base/exceptions.h>

namespace poundfe
{
  RealizationRunner::RealizationRunner(const Analysis &analysis_,
                                       const TimeHistoryParameters &parameters_)
    : analysis(analysis_)
    , parameters(parameters_)
    , excitation(make_excitation(analysis_, parameters_))
    , load(parameters_.ground_motion, parameters_.time_integration.newmark.time_step, excitation)
    , history(std::make_unique<TimeHistory>(analysis_, parameters_))
    , peaks(std::make_unique<PeakResponse>(analysis_.model, history->nonlinear_elements()))
  {
    const InputFile &input = parameters.input;
    if (load.n_variables() == 0)
      throw InputError(input.file, input.line_of("Ground motion/Type"),
                       "Ground motion/Type",
                       "a probabilistic analysis needs random loading: a kanai-tajimi, "
                       "clough-penzien or white-noise ground motion, or white-noise nodal forces");
    const FloorResponse floors(analysis.model);
    names = floors.column_names("storey", "peak_drift_ratio");
    first_floor_column = names.size();
    for (const std::string &n : floors.column_names("floor", "peak_acc_m_s2"))
      names.push_back(n);
    first_roof_column = names.size();
    for (unsigned int b = 0; b < analysis.model.buildings.size(); ++b)
      {
        names.push_back("peak_roof_displacement_" + analysis.model.buildings[b].name);
        roof_floor.push_back(floors.index(b, analysis.model.buildings[b].floors.size() - 1));
      }
    max_drift_column = names.size();
    names.push_back("max_drift_ratio");
    names.push_back("max_floor_acceleration");
    if (has_gaps())
      for (const char *n : {"n_impacts", "peak_contact_force", "min_clearance", "pounded"})
        names.push_back(n);
    first_plan_column = names.size();
    for (const std::string &n : plan_scalar_names(analysis.model))
      names.push_back(n);
    if (!SectionLimitStates(analysis.model, history->nonlinear_elements(), section_limits).empty())
      for (const std::string &n : floors.column_names("storey", "damage_state"))
        {
          damage_columns.push_back(names.size());
          names.push_back(n);
        }
    first_parameter_column = first_residual_column = names.size();
  }

  std::vector<RealizationRunner::OptionalResponse>
  RealizationRunner::optional_responses() const
  {
    std::vector<OptionalResponse> result;
    const std::vector<std::string> residual =
      FloorResponse(analysis.model).column_names("storey", "residual_drift_ratio");
    for (unsigned int i = 0; i < residual.size(); ++i)
      result.push_back({OptionalResponse::residual_drift, i, residual[i]});
    const std::pair<OptionalResponse::Kind, const char *> per_gap[] = {
      {OptionalResponse::peak_force, "_peak_contact_force"},
      {OptionalResponse::impacts, "_impacts"},
      {OptionalResponse::impact_velocity, "_peak_impact_velocity"}};
    for (const auto &[kind, suffix] : per_gap)
      for (unsigned int g = 0; g < analysis.model.gaps.size(); ++g)
        result.push_back({kind, g, "gap" + std::to_string(g + 1) + suffix});
    result.push_back({OptionalResponse::ground_acceleration, 0, "peak_ground_acc_m_s2"});
    if (analysis.model.dimension == 3)
      {
        const std::vector<std::string> rotation =
          FloorResponse(analysis.model).column_names("floor", "peak_rotation_rad");
        for (unsigned int i = 0; i < rotation.size(); ++i)
          result.push_back({OptionalResponse::rotation, i, rotation[i]});
        const std::vector<std::string> residual_y =
          FloorResponse(analysis.model, Component::uy).column_names("storey", "residual_drift_ratio_y");
        for (unsigned int i = 0; i < residual_y.size(); ++i)
          result.push_back({OptionalResponse::residual_drift_y, i, residual_y[i]});
        result.push_back({OptionalResponse::ground_acceleration_y, 1, "peak_ground_acc_y_m_s2"});
      }
    return result;
  }

  std::vector<std::string>
  RealizationRunner::optional_response_names() const
  {
    std::vector<std::string> names;
    for (const OptionalResponse &o : optional_responses())
      names.push_back(o.name);
    return names;
  }

  void
  RealizationRunner::add_optional_responses(const std::vector<std::string> &wanted)
  {
    Assert(!structure && first_parameter_column == names.size(),
           dealii::ExcMessage("optional responses come before the random parameters"));
    const auto asked = [&](const std::string &name) {
      return std::find(wanted.begin(), wanted.end(), name) != wanted.end() ||
             std::any_of(chosen.begin(), chosen.end(),
                         [&](const OptionalResponse &o) { return o.name == name; });
    };
    // the columns in the order of the list, whatever the order asked in
    std::vector<OptionalResponse> now;
    for (const OptionalResponse &o : optional_responses())
      if (asked(o.name) &&
          std::find(names.begin(), names.begin() + first_residual_column, o.name) ==
            names.begin() + first_residual_column)
        now.push_back(o);
    chosen = std::move(now);
    names.resize(first_residual_column);
    for (const OptionalResponse &o : chosen)
      names.push_back(o.name);
    first_parameter_column = names.size();
  }

  RealizationRunner::~RealizationRunner() = default;

  void
  RealizationRunner::set_random_parameters(std::vector<ModelParameter>     random_parameters,
                                           const std::vector<std::string> &parameter_names,
                                           ParameterTransform              transform,
                                           const Eigensolver               eigensolver)
  {
    Assert(!structure, dealii::ExcMessage("random parameters are set once"));
    AssertDimension(random_parameters.size(), parameter_names.size());
    if (random_parameters.empty())
      return;
    structure   = std::make_unique<ModelRealization>(analysis, std::move(random_parameters), eigensolver);
    to_physical = std::move(transform);
    names.insert(names.end(), parameter_names.begin(), parameter_names.end());
    // the engine runs on the working model from now on
    peaks.reset();
    history = std::make_unique<TimeHistory>(structure->analysis(), parameters);
    peaks   = std::make_unique<PeakResponse>(structure->analysis().model,
                                           history->nonlinear_elements());
  }

  void
  RealizationRunner::apply_parameters(const std::vector<double> &xi)
  {
    parameter_normals.assign(xi.begin() + load.n_variables(), xi.end());
    to_physical(parameter_normals, parameter_values);
    structure->apply(parameter_values);
    const Analysis &working = structure->analysis();
    // rigid contact (Contact/Model = nonsmooth) reads the gaps' widths when
    // its engine is made: a new one for every realization
    const bool rigid = parameters.time_integration.contact_model == ContactModel::nonsmooth;
    if (structure->changes_linear_part() || rigid)
      { // new M, K, C: a new engine (the factorisations change)
        const auto &targets = structure->parameters();
        if (std::any_of(targets.begin(), targets.end(), [](const ModelParameter &p) {
              return p.enters_mass();
            })) // -M r a_g of the new M (every component's)
          excitation.set_mass(working.system);
        peaks.reset();
        history.reset();
        history = std::make_unique<TimeHistory>(working, parameters);
        peaks = std::make_unique<PeakResponse>(working.model, history->nonlinear_elements());
      }
    else // the same M, K, C and factorisations: new element laws only
      history->replace_nonlinear_elements(working.model);
  }

  unsigned int
  RealizationRunner::column(const std::string &name) const
  {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw std::out_of_range("no response '" + name + "'");
    return it - names.begin();
  }

  std::vector<unsigned int>
  RealizationRunner::drift_columns(const unsigned int building, const unsigned int storey) const
  {
    // drift columns come first, in FloorResponse order; a 3D model's drifts
    // along y are the first plan columns, in the same order
    const FloorResponse       floors(analysis.model);
    std::vector<unsigned int> columns;
    for (unsigned int f = 0; f < analysis.model.buildings.at(building - 1).floors.size(); ++f)
      if (storey == 0 || f + 1 == storey)
        {
          columns.push_back(floors.index(building - 1, f));
          if (analysis.model.dimension == 3)
            columns.push_back(first_plan_column + floors.index(building - 1, f));
        }
    return columns;
  }

  unsigned int
  RealizationRunner::roof_displacement_column(const unsigned int building) const
  {
    return first_roof_column + building - 1;
  }

  bool
  RealizationRunner::run(const std::uint64_t realization, std::vector<double> &responses,
                         const double amplitude_factor)
  {
    xi.resize(n_variables());
    load.standard_normals(realization, xi);
    return run(xi, responses, amplitude_factor);
  }

  bool
  RealizationRunner::run(const std::uint64_t realization, const Observers &observers,
                         const double amplitude_factor)
  {
    xi.resize(n_variables());
    load.standard_normals(realization, xi);
    return run_with(xi, observers, amplitude_factor).completed();
  }

  double
  RealizationRunner::reference_pga(const std::string &purpose) const
  {
    const InputFile              &input = parameters.input;
    const GroundMotionParameters &g     = parameters.ground_motion;
    if (g.type != GroundMotionType::kanai_tajimi && g.type != GroundMotionType::clough_penzien)
      throw InputError(input.file, input.line_of("Ground motion/Type"), "Ground motion/Type",
                       purpose + " scale a Kanai-Tajimi or Clough-Penzien motion to each PGA "
                       "level; got '" + ground_motion_type_names().name(g.type) + "'");
    const MotionGenerator &generator = *load.ground_generator();
    return g.peak_factor *
           std::sqrt(generator.motion().spectral_intensity *
                     stationary_variance_per_unit_s0(generator.motion().filter)) *
           g.scale_factor / standard_gravity;
  }

  bool
  RealizationRunner::run(const std::vector<double> &normals, std::vector<double> &responses,
                         const double amplitude_factor)
  {
    const RunStatus      status = run_with(normals, {peaks.get()}, amplitude_factor, true);
    const FloorResponse &floors = peaks->floors();

    responses.assign(names.size(), 0.0);
    const std::vector<double> &drift = floors.peak_drift_ratio();
    const std::vector<double> &acceleration = floors.peak_acceleration();
    std::copy(drift.begin(), drift.end(), responses.begin());
    std::copy(acceleration.begin(), acceleration.end(), responses.begin() + first_floor_column);
    for (unsigned int b = 0; b < roof_floor.size(); ++b)
      responses[first_roof_column + b] = floors.peak_displacement()[roof_floor[b]];
    responses[max_drift_column]     = peaks->largest_drift_ratio();
    responses[max_drift_column + 1] = *std::max_element(acceleration.begin(), acceleration.end());
    if (has_gaps())
      {
        const std::vector<Impact> &impacts = history->state().impact_log().impacts();
        double                     peak_force = 0;
        for (const Impact &impact : impacts)
          peak_force = std::max(peak_force, impact.peak_force);
        unsigned int c = max_drift_column + 2;
        responses[c++] = impacts.size();
        responses[c++] = peak_force;
        responses[c++] = peaks->min_clearance();
        responses[c++] = impacts.empty() ? 0 : 1;
      }
    std::vector<double> plan;
    append_plan_scalars(model(), *peaks, plan);
    std::copy(plan.begin(), plan.end(), responses.begin() + first_plan_column);
    fill_damage_states(responses);
    fill_optional_responses(responses);
    std::copy(parameter_values.begin(), parameter_values.end(),
              responses.begin() + first_parameter_column);
    return status.completed();
  }

  void
  RealizationRunner::fill_damage_states(std::vector<double> &responses) const
  {
    if (damage_columns.empty())
      return;
    const FloorResponse floors(model());
    for (unsigned int b = 0; b < model().buildings.size(); ++b)
      {
        const std::vector<int> worst = section_states->storey_worst_limits(model(), b);
        for (unsigned int f = 0; f < worst.size(); ++f) // the damage state's number
          responses[damage_columns[floors.index(b, f)]] = worst[f] + 1;
      }
  }

  void
  RealizationRunner::fill_optional_responses(std::vector<double> &responses) const
  {
    if (chosen.empty())
      return;
    std::vector<double> count, force, velocity;
    gap_demands(model(), history->state().impact_log().impacts(), peaks->n_hysteretic(), count,
                force, velocity);
    ResponseDemands plan; // the PGA as applied, a 3D model's rotations
    add_plan_demands(*peaks, excitation, plan);
    unsigned int c = first_residual_column;
    for (const OptionalResponse &o : chosen)
      switch (o.kind)
        {
          case OptionalResponse::residual_drift: // the last observed step: the end
            responses[c++] = peaks->floors().drift_ratio()[o.index];
            break;
          case OptionalResponse::peak_force:
            responses[c++] = force[o.index];
            break;
          case OptionalResponse::impacts:
            responses[c++] = count[o.index];
            break;
          case OptionalResponse::impact_velocity:
            responses[c++] = velocity[o.index];
            break;
          case OptionalResponse::ground_acceleration:
            responses[c++] = plan.pga;
            break;
          case OptionalResponse::rotation:
            responses[c++] = plan.peak_rotation[o.index];
            break;
          case OptionalResponse::ground_acceleration_y:
            responses[c++] = plan.pga_y;
            break;
          case OptionalResponse::residual_drift_y:
            responses[c++] = plan.residual_drift_y[o.index];
            break;
        }
  }

  RunStatus
  RealizationRunner::run_with(const std::vector<double> &normals, const Observers &observers,
                              const double amplitude_factor, const bool damage)
  {
    AssertDimension(normals.size(), n_variables());
    // parameters that enter the linear part make a new engine and a new
    // PeakResponse: the caller's pointer to the old one is replaced (it
    // would dangle)
    Observers         in_use = observers;
    const StepObserver *old_peaks = peaks.get();
    if (structure)
      apply_parameters(normals);
    for (StepObserver *&observer : in_use)
      if (observer == old_peaks)
        observer = peaks.get();
    section_states.reset();
    if (damage && !damage_columns.empty()) // on the elements this run steps
      {
        const Model &working = structure ? structure->analysis().model : analysis.model;
        section_states =
          std::make_unique<SectionLimitStates>(working, history->nonlinear_elements(), section_limits);
        in_use.push_back(section_states.get());
      }
    load.apply(std::vector<double>(normals.begin(), normals.begin() + load.n_variables()),
               excitation, amplitude_factor);
    return history->run(excitation, in_use);
  }
} // namespace poundfe
