// The mitigation study (separation/mitigation.h): the cases' models run on
// the same realizations; each case's statistics over them.
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/model_parameter.h>
#include <poundfe/dynamics/realization.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/reliability/statistics.h>
#include <poundfe/separation/mitigation.h>

#include <algorithm>
#include <limits>

namespace poundfe
{
  std::vector<MitigationCase>
  mitigation_cases(const MitigationParameters &p)
  {
    std::vector<MitigationCase> cases{{MitigationCase::Kind::bare, "bare", 0, {}}};
    for (std::size_t k = 0; k < p.damper_coefficients.size(); ++k)
      cases.push_back({MitigationCase::Kind::damper, "damper" + std::to_string(k + 1),
                       p.damper_coefficients[k], {}});
    for (unsigned int k = 0; k < p.bumper_thicknesses.size(); ++k)
      cases.push_back(
        {MitigationCase::Kind::bumper, "bumper" + std::to_string(k + 1), 0, p.bumper(k)});
    return cases;
  }

  /// One case's peaks on one realization.
  struct CasePeaks
  {
    std::vector<double> drift; // per building, the largest over its storeys
    double floor_acceleration = 0, n_impacts = 0, impact_force = 0;
  };

  /// Each building's largest peak drift ratio from the per-floor ones
  /// (FloorResponse order: building by building, bottom to top; entries
  /// after the last floor are not read).
  std::vector<double>
  building_drifts(const Model &model, const std::vector<double> &floor_drifts)
  {
    std::vector<double> drift;
    std::size_t         first = 0;
    for (const Building &building : model.buildings)
      {
        const auto begin = floor_drifts.begin() + first;
        drift.push_back(*std::max_element(begin, begin + building.floors.size()));
        first += building.floors.size();
      }
    return drift;
  }

  /// One model of the study and its runs: over a random motion a
  /// RealizationRunner, under a record one TimeHistory. With dampers, their
  /// c is the model's one parameter (Links/Viscous dampers, every damper):
  /// set_damping() writes it and only the nonlinear elements are made again.
  class StudyModel
  {
  public:
    StudyModel(const Analysis &analysis, const TimeHistoryParameters &parameters,
               const bool random, const bool damped, const Eigensolver eigensolver)
      : model(analysis.model)
    {
      std::vector<ModelParameter> dampers;
      if (damped)
        dampers.push_back(model_parameter("Links/Viscous dampers", analysis.model));
      if (random)
        {
          runner = std::make_unique<RealizationRunner>(analysis, parameters);
          if (damped) // a realization's value of c is the case's, whatever its normal
            runner->set_random_parameters(
              dampers, {"damper_coefficient"},
              [this](const std::vector<double> &, std::vector<double> &x) { x.assign(1, c); },
              eigensolver);
          return;
        }
      if (damped)
        structure = std::make_unique<ModelRealization>(analysis, dampers, eigensolver);
      const Analysis &working = structure ? structure->analysis() : analysis;
      excitation = std::make_unique<Excitation>(make_excitation(working, parameters));
      history    = std::make_unique<TimeHistory>(working, parameters);
      peaks      = std::make_unique<PeakResponse>(working.model, history->nonlinear_elements());
    }

    void
    set_damping(const double coefficient)
    {
      c = coefficient;
      if (!structure)
        return;
      structure->apply({c});
      history->replace_nonlinear_elements(structure->analysis().model);
    }

    /// The contact run of realization r.
    bool
    run(const std::uint64_t r, CasePeaks &out)
    {
      if (runner)
        {
          const bool completed = runner->run(r, responses);
          out.drift = building_drifts(model, responses); // the drift columns come first
          out.floor_acceleration = responses[runner->column("max_floor_acceleration")];
          out.n_impacts          = responses[runner->column("n_impacts")];
          out.impact_force       = responses[runner->column("peak_contact_force")];
          return completed;
        }
      const RunStatus status = history->run(*excitation, {peaks.get()});
      const FloorResponse &floors = peaks->floors();
      out.drift = building_drifts(model, floors.peak_drift_ratio());
      out.floor_acceleration =
        *std::max_element(floors.peak_acceleration().begin(), floors.peak_acceleration().end());
      const std::vector<Impact> &impacts = history->state().impact_log().impacts();
      out.n_impacts    = impacts.size();
      out.impact_force = 0;
      for (const Impact &impact : impacts)
        out.impact_force = std::max(out.impact_force, impact.peak_force);
      return status.completed();
    }

    /// The free run of realization r, watched by `observer`.
    bool
    run(const std::uint64_t r, SeparationObserver &observer)
    {
      if (runner)
        return runner->run(r, Observers{&observer});
      return history->run(*excitation, {&observer}).completed();
    }

    std::uint64_t
    seed() const
    {
      return runner ? runner->stochastic_load().seed() : 0;
    }

  private:
    const Model                      &model;
    double                            c = 0;
    std::unique_ptr<RealizationRunner> runner;
    std::vector<double>               responses;
    std::unique_ptr<ModelRealization> structure;
    std::unique_ptr<Excitation>       excitation;
    std::unique_ptr<TimeHistory>      history;
    std::unique_ptr<PeakResponse>     peaks;
  };

  MitigationStudy::MitigationStudy(const MitigationModels &models,
                                   const TimeHistoryParameters &parameters,
                                   const MitigationParameters &study, const Eigensolver eigensolver,
                                   const bool random)
    : study_cases(mitigation_cases(study))
    , pairs(adjacent_pairs(models.bare_free->model))
  {
    const InputFile &input = parameters.input;
    const Model     &model = models.bare->model;
    if (model.dimension != 2 || model.buildings.size() != 2 || pairs.size() != 1 ||
        pairs[0].levels.empty())
      input.fail("Model/Number of buildings",
                 "a mitigation study is of one 2D pair of adjacent buildings with a level in "
                 "common (Model/Dimension = 2, Number of buildings = 2)");
    if (model.gaps.empty())
      input.fail("Contact/Law", "a mitigation study needs the gap's contact law (not none)");
    for (const Building &building : model.buildings)
      names.push_back(building.name);
    const auto make = [&](const Analysis *analysis, const bool damped) {
      return std::make_unique<StudyModel>(*analysis, parameters, random, damped, eigensolver);
    };
    bare      = make(models.bare, false);
    bare_free = make(models.bare_free, false);
    if (models.damped)
      {
        damped      = make(models.damped, true);
        damped_free = make(models.damped_free, true);
      }
    for (const Analysis *analysis : models.bumpered)
      bumpered.push_back(make(analysis, false));
    observer = std::make_unique<SeparationObserver>(models.bare_free->model, pairs);
    seed     = bare->seed();
  }

  MitigationStudy::~MitigationStudy() = default;

  bool
  MitigationStudy::run_case(const MitigationCase &c, const std::uint64_t r,
                            std::vector<double> &row)
  {
    StudyModel *contact = bare.get(), *free = bare_free.get();
    if (c.kind == MitigationCase::Kind::damper)
      {
        contact = damped.get(), free = damped_free.get();
        contact->set_damping(c.damper_coefficient);
        free->set_damping(c.damper_coefficient);
      }
    else if (c.kind == MitigationCase::Kind::bumper)
      { // the bumper cases come last
        const std::size_t k = (&c - study_cases.data()) - (study_cases.size() - bumpered.size());
        contact             = bumpered[k].get();
      }
    CasePeaks  peaks;
    bool       completed = contact->run(r, peaks);
    row.insert(row.end(), peaks.drift.begin(), peaks.drift.end());
    for (const double x : {peaks.floor_acceleration, peaks.n_impacts, peaks.impact_force})
      row.push_back(x);
    if (c.kind == MitigationCase::Kind::bumper) // the free motion is the bare pair's: D + t
      {
        const std::size_t bare_approach = names.size() + 3; // the bare case's columns come first
        row.push_back(row[bare_approach] + c.bumper.thickness);
        return completed;
      }
    completed = free->run(r, *observer) && completed;
    double approach = -std::numeric_limits<double>::infinity();
    for (const SeparationObserver::LevelResponse &level : observer->responses()[0])
      approach = std::max(approach, level.max_approach);
    row.push_back(approach);
    return completed;
  }

  RealizationJob
  MitigationStudy::job()
  {
    RealizationJob job;
    for (const MitigationCase &c : study_cases)
      {
        for (const std::string &building : names)
          job.names.push_back(c.name + "_peak_drift_ratio_" + building);
        for (const char *what : {"_peak_floor_acc_m_s2", "_n_impacts", "_peak_impact_force_N",
                                 "_largest_approach_m"})
          job.names.push_back(c.name + what);
      }
    job.seed = seed;
    job.run  = [this](const std::uint64_t r, std::vector<double> &row) {
      row.clear();
      bool completed = true;
      for (const MitigationCase &c : study_cases)
        completed = run_case(c, r, row) && completed;
      return completed;
    };
    return job;
  }

  std::vector<MitigationRow>
  MitigationStudy::rows(const MonteCarloTable &table, const double target_probability) const
  {
    const unsigned int         n_columns = names.size() + 4; // per case
    std::vector<MitigationRow> rows;
    for (unsigned int k = 0; k < study_cases.size(); ++k)
      {
        const unsigned int first = k * n_columns;
        const auto mean = [&](const unsigned int c) { return describe(table.completed_values(c)).mean; };
        MitigationRow row;
        row.study_case     = study_cases[k];
        row.n_realizations = table.completed_values(first).size();
        std::vector<double> larger(row.n_realizations, 0.0);
        for (unsigned int b = 0; b < names.size(); ++b)
          {
            row.peak_drift_ratio.push_back(mean(first + b));
            const std::vector<double> drift = table.completed_values(first + b);
            for (std::size_t i = 0; i < drift.size(); ++i)
              larger[i] = std::max(larger[i], drift[i]);
          }
        row.max_drift_ratio         = describe(larger).mean;
        const unsigned int c        = first + names.size();
        row.peak_floor_acceleration = mean(c);
        row.n_impacts               = mean(c + 1);
        row.peak_impact_force       = mean(c + 2);
        const std::vector<double> impacts = table.completed_values(c + 1);
        const std::vector<double> forces  = table.completed_values(c + 2);
        row.max_impact_force = forces.empty() ? 0 : *std::max_element(forces.begin(), forces.end());
        row.pounding_probability =
          impacts.empty() ? 0 :
                            double(std::count_if(impacts.begin(), impacts.end(),
                                                 [](const double n) { return n > 0; })) /
                              impacts.size();
        const std::vector<double> approach = table.completed_values(c + 3);
        row.required_gap           = mean(c + 3);
        row.required_gap_at_target = approach.empty() ? 0 :
                                       gap_for_probability(approach, target_probability);
        rows.push_back(row);
      }
    return rows;
  }
} // namespace poundfe
