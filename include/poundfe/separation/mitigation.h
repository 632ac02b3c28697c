// A mitigation study of one pair of adjacent buildings under one ground
// motion (the `mitigation` command): the bare pair against the pair linked
// by viscous dampers of each coefficient of a list and against bumpers of
// each thickness, over the same realizations of the motion (a record: one).
//   Per case and realization: each building's peak drift ratio, the peak
//   absolute floor acceleration, the number of impacts and the largest
//   impact force (with contact), and the largest approach D = max over the
//   pair's common levels and time of u_left - u_right WITHOUT contact (the
//   separation command's time-history value, separation/separation.h).
//   Per case over the realizations: the means, P(pounding) = the fraction
//   of realizations with an impact, the required gap = the mean of D (as
//   the separation command takes the mean of the response histories,
//   EN 1998-1 §4.3.3.4.3(3)) and the gap for Separation/Target probability
//   (the type-7 quantile of D). A bumper of thickness t fills t of the gap
//   and leaves the free motion as it is: its required gap is D_bare + t.
//   The dampers' places are built once (one model with and one without
//   contact); each case writes its c into them (dynamics/model_parameter.h,
//   Links/Viscous dampers): only the nonlinear elements are made again, M,
//   K, C and their factorisations stay. A damper with c = 0 carries no
//   force: that case equals the bare pair.
// Sources: dampers between adjacent buildings, Y.L. Xu, Q. He & J.M. Ko,
// Eng. Struct. 21 (1999) 135-148; bumpers, K.T. Polycarpou, P. Komodromos
// & A.C. Polycarpou, EESD 42 (2013) 81; doc/theory.md §1.17.
#ifndef poundfe_separation_mitigation_h
#define poundfe_separation_mitigation_h

#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/laws/bumper.h>
#include <poundfe/reliability/montecarlo.h>
#include <poundfe/separation/mitigation_parameters.h>
#include <poundfe/separation/separation.h>

#include <memory>
#include <string>
#include <vector>

namespace poundfe
{
  struct MitigationCase
  {
    enum class Kind
    {
      bare,
      damper,
      bumper
    };
    Kind             kind = Kind::bare;
    std::string      name; // "bare", "damper1", ..., "bumper1", ...
    double           damper_coefficient = 0;
    BumperParameters bumper;
  };

  /// The cases of `p`: the bare pair, one per damper coefficient, one per bumper.
  std::vector<MitigationCase> mitigation_cases(const MitigationParameters &p);

  /// The models of a study, built by the caller from the input (the same
  /// pair, ground motion and time integration in all).
  struct MitigationModels
  {
    const Analysis *bare = nullptr, *bare_free = nullptr; // with and without contact
    /// With the study's dampers (any c: each case writes its own); null
    /// without damper cases.
    const Analysis *damped = nullptr, *damped_free = nullptr;
    std::vector<const Analysis *> bumpered; // one per bumper case
  };

  /// One case's statistics over the completed realizations.
  struct MitigationRow
  {
    MitigationCase      study_case;
    unsigned long       n_realizations = 0;
    std::vector<double> peak_drift_ratio; // mean, per building
    double max_drift_ratio = 0;           // mean of the larger of the buildings'
    double peak_floor_acceleration = 0;   // mean, m/s^2
    double n_impacts = 0;                 // mean
    double peak_impact_force = 0;         // mean of each realization's largest, N
    double max_impact_force  = 0;         // largest over the realizations, N
    double pounding_probability = 0;      // fraction of realizations with an impact
    double required_gap = 0;              // mean largest approach (+ t), m
    double required_gap_at_target = 0;    // its (1 - target) quantile, m
  };

  class StudyModel;

  /// The study's realizations: job() runs every case on realization r (the
  /// record's one run when the ground motion is not random) for
  /// run_realizations; rows() takes the statistics of its table.
  class MitigationStudy
  {
  public:
    /// `random`: the ground motion is random (realizations r of its seed).
    /// Throws InputError (through `parameters.input`) for a model that is
    /// not one 2D pair.
    MitigationStudy(const MitigationModels &models, const TimeHistoryParameters &parameters,
                    const MitigationParameters &study, Eigensolver eigensolver, bool random);
    ~MitigationStudy();

    const std::vector<MitigationCase> &cases() const { return study_cases; }
    /// realizations.csv's columns and the run of one realization; the
    /// study must outlive it.
    RealizationJob job();
    /// Each case's statistics over the table's completed realizations.
    std::vector<MitigationRow> rows(const MonteCarloTable &table, double target_probability) const;
    /// The names of the buildings (the pair: left, right).
    const std::vector<std::string> &building_names() const { return names; }

  private:
    /// The case's contact run and, for the bare and damper cases, its free
    /// run, appended to `row`.
    bool run_case(const MitigationCase &c, std::uint64_t r, std::vector<double> &row);

    std::vector<MitigationCase>              study_cases;
    std::vector<AdjacentPair>                pairs;
    std::vector<std::string>                 names;
    std::unique_ptr<StudyModel>              bare, bare_free, damped, damped_free;
    std::vector<std::unique_ptr<StudyModel>> bumpered;
    std::unique_ptr<SeparationObserver>      observer;
    std::uint64_t                            seed = 0;
  };
} // namespace poundfe

#endif
