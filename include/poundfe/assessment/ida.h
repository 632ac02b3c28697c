// Incremental dynamic analysis (Vamvatsikos & Cornell 2002) of a record
// suite, and what is made of it.
//
// Hunt and fill (Vamvatsikos & Cornell 2004), per record, on an intensity
// measure IM that scales with the record (excitation/intensity_measures.h):
//   hunt:    x_1 = s0, x_{k+1} = x_k + s0 + k ds (steps growing by ds), until
//            a run collapses or x reaches the upper intensity x_max (run at
//            x_max itself; no collapse there: "no collapse below x_max",
//            reported, not an error);
//   bracket: between the highest intensity that did not collapse below the
//            lowest that did (x_lo, x_hi), bisection until x_hi - x_lo <= tol;
//   fill:    while runs remain (Runs per record), the widest gap between
//            the intensities run at or below x_hi (0 included) gets its
//            midpoint, down to gaps of tol.
// Collapse: the run fails to converge (a NumericalError ends it: RunStatus
// failed) or its largest peak drift ratio exceeds the collapse limit. The
// record's collapse intensity is x_hi, within tol above the highest
// intensity survived below it. Each next intensity is a function of the
// runs done so far alone, so a run resumed from its journal repeats the
// same intensities.
//
// Collapse fragility, lognormal, P(C | IM = x) = Phi(ln(x / theta) / beta),
// by maximum likelihood from the records' collapse intensities x_i:
//   ln theta = (1/n) sum ln x_i,  beta^2 = (1/n) sum (ln x_i - ln theta)^2
// (the MLE of a normal on ln x; beta's MLE divides by n). Records that did
// not collapse below x_max are right-censored at x_max: the likelihood is
//   L = prod_collapsed phi(z_i) / (beta x_i) * prod_censored (1 - Phi(z_max)),
// z = ln(x / theta) / beta (Cohen 1959: the singly censored normal),
// maximised over (ln theta, ln beta) by nested golden-section searches
// (ln theta for each ln beta), the log-likelihood being concave in
// (ln theta / beta, 1 / beta) and so unimodal along both.
//
// Fractile IDA curves: at each intensity of a grid, every record's demand
// interpolated linearly along its curve (a record collapsed at or below
// that intensity: infinite demand), and the 16, 50 and 84 % fractiles over
// the records (linear interpolation of the sorted values, the empirical
// quantile of type 7 of Hyndman & Fan 1996); a fractile that is infinite
// (more records collapsed than its level admits) is left out.
//   Vamvatsikos, D. & Cornell, C. A. (2002). Incremental dynamic analysis.
//     Earthquake Engng Struct. Dyn. 31(3), 491-514.
//   Vamvatsikos, D. & Cornell, C. A. (2004). Applied incremental dynamic
//     analysis. Earthquake Spectra 20(2), 523-553.
//   Cohen, A. C. (1959). Simplified estimators for the normal distribution
//     when samples are singly censored or truncated. Technometrics 1, 217-237.
#ifndef poundfe_assessment_ida_h
#define poundfe_assessment_ida_h

#include <poundfe/assessment/ida_parameters.h>
#include <poundfe/dynamics/time_history.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/record_suite.h>

#include <mpi.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace poundfe
{
  class PeakResponse;
  class Progress;

  /// The search of one record: the intensities run and whether each collapsed.
  class HuntFill
  {
  public:
    struct Settings
    {
      double       initial_step = 0.1, step_increment = 0.05, upper = 5, tolerance = 0.02;
      unsigned int max_runs = 12;
    };
    explicit HuntFill(const Settings &settings);

    /// The next intensity to run; nothing when the record is done.
    std::optional<double> next() const;
    void record(double intensity, bool collapsed);

    /// The lowest intensity that collapsed (nothing: none did).
    std::optional<double> collapse_intensity() const;
    /// The highest intensity survived below the collapse intensity (or any).
    double highest_survived() const;
    unsigned int n_runs() const { return intensities.size(); }

  private:
    std::optional<double> fill() const;

    Settings            settings;
    std::vector<double> intensities;
    std::vector<bool>   collapsed;
  };

  /// A lognormal collapse fragility and the data it was fitted to.
  struct CollapseFragility
  {
    double       theta = 0, beta = 0; // median (IM unit), log standard deviation
    unsigned int n_collapsed = 0, n_censored = 0;
    bool         fitted = false; // false: fewer than two collapses
    std::string  note;
  };

  /// The maximum-likelihood fit (above) of `collapse` intensities, with
  /// `n_censored` records that survived `upper`.
  CollapseFragility fit_collapse_fragility(const std::vector<double> &collapse,
                                           unsigned int n_censored = 0, double upper = 0);

  /// The empirical quantile (type 7) of `values` at p in [0, 1]; +inf
  /// values allowed (sorted last).
  double empirical_quantile(std::vector<double> values, double p);

  /// One run of one record at one intensity.
  struct IdaPoint
  {
    double              intensity = 0, scale_factor = 0;
    bool                collapsed = false;
    std::vector<double> demands; // in the order of IdaRunner::demand_names()
  };

  /// Refuses (InputError naming IDA/Period, or IDA/Sa_avg range for Sa_avg
  /// when the period itself lies within) the measure's periods outside
  /// those every record of `suite` resolves (record_suite.h); nothing for a
  /// measure of no period. `first_period`: the model's, for IDA/Period = 0.
  void refuse_periods_the_records_do_not_resolve(const IdaParameters &ida, double first_period,
                                                 const RecordSuite &suite, const InputFile &input);

  /// Runs records of a suite at given intensities through the model; built
  /// once (model, integrator and factorisations), like a RealizationRunner.
  class IdaRunner
  {
  public:
    /// Throws InputError (pairs on a 2D model, no first period for Sa).
    IdaRunner(const Analysis &analysis, const TimeHistoryParameters &parameters,
              const IdaParameters &ida, RecordSuite suite);
    ~IdaRunner();

    /// Every demand traced: per storey the peak drift ratio, per floor the
    /// peak absolute acceleration (m/s^2), per storey the residual drift
    /// ratio (at the end), the largest peak drift ratio, and per gap the
    /// impacts, the largest peak force (N) and approach velocity (m/s);
    /// then, for a 3D model, per storey the peak drift ratio along y, per
    /// floor the peak absolute acceleration along y (m/s^2) and the peak
    /// rotation |theta_z| (rad), per storey the residual drift ratio along
    /// y (at the end). A 3D model is shaken by a single record
    /// along Ground motion/Incidence angle, by a pair turned by it.
    const std::vector<std::string> &demand_names() const { return names; }
    /// Column of the largest peak drift ratio in the demands.
    unsigned int max_drift_column() const { return max_drift; }
    /// Column of a 3D model's first y drift (the number of columns in 2D).
    unsigned int plan_column() const { return plan; }
    /// The PGA along x and y of each record as applied, at its intensity
    /// in the suite (m/s^2).
    const std::vector<std::array<double, 2>> &ground_peaks() const { return peaks_xy; }
    const RecordSuite &suite() const { return records; }
    const Model &model() const { return analysis.model; }
    /// The measure of each record as scaled in the suite (IM unit).
    const std::vector<double> &base_intensities() const { return base; }
    const std::vector<double> &measure_periods() const { return periods; }
    HuntFill::Settings search() const;

    /// Record r scaled to `intensity`.
    IdaPoint run(unsigned int r, double intensity);

  private:
    const Analysis                &analysis;
    const IdaParameters            ida;
    RecordSuite                    records;
    std::vector<double>            periods, base;
    std::unique_ptr<TimeHistory>   history;
    std::unique_ptr<PeakResponse>  peaks;
    std::vector<std::string>       names;
    unsigned int                   max_drift = 0, plan = 0;
    double                         angle = 0; // rad, Ground motion/Incidence angle
    std::vector<std::array<double, 2>> peaks_xy;

    /// The excitation of record r scaled by `factor` (with `free_vibration` s of rest).
    Excitation excitation(unsigned int r, double factor, bool free_vibration) const;
  };

  /// What an IDA found for one record: its points in ascending intensity.
  struct IdaRecordResult
  {
    std::vector<IdaPoint> points;
    std::optional<double> collapse_intensity;
    double                highest_survived = 0;
    bool                  done = false; // false: interrupted before its end
  };

  struct IdaResult
  {
    std::vector<IdaRecordResult> records;
    unsigned long                n_runs = 0, n_run_now = 0;
    double                       wall_time = 0; // s
    bool                         interrupted = false;
    /// A journal kept in memory (an empty journal folder: results in
    /// memory): the text each realizations.csv would hold, by its name
    /// under the journal folder ("realizations.csv", "stripes/...").
    std::vector<std::pair<std::string, std::string>> journals;
  };

  /// One run to do: a record at an intensity.
  struct IdaTask
  {
    unsigned int record    = 0;
    double       intensity = 0;
  };

  /// What a run computes: the journal row of a task (ida_row below).
  using IdaRun = std::function<std::vector<double>(const IdaTask &)>;

  /// The runs a dealer deals (ida_scheduler.cc), held on rank 0: which run
  /// to deal next and what came back.
  class DealtRuns
  {
  public:
    virtual ~DealtRuns() = default;
    /// Whether a journaled row (record, intensity, ...) is one of these runs.
    virtual bool holds(const std::vector<double> &row) const = 0;
    /// The next run to deal, then under way; nothing: none until a run
    /// under way comes back (or none is left).
    virtual std::optional<IdaTask> next() = 0;
    /// The row of a run, journaled or fresh: no longer under way.
    virtual void take(const std::vector<double> &row) = 0;
    /// Nothing left to deal and nothing under way.
    virtual bool finished() const = 0;
  };

  /// Rows of `runs` dealt over the ranks of `comm` (ida_scheduler.cc).
  struct DealtRows
  {
    std::vector<std::vector<double>> rows; // journaled ones first, then in the order taken
    unsigned long                    n_run_now = 0; // by this call, over every rank
    bool                             interrupted = false; // runs are left
    std::string                      journal; // the journal's text, when kept in memory
  };

  /// Deals `runs` (rank 0's; nullptr on the others) run by run to whichever
  /// rank is free, every rank computing rows with `run` (each must call
  /// it); journaled by rank 0 in `file` (a realizations.csv with the
  /// columns `names`: a call with the same file resumes: the journaled
  /// rows are read back, not run; InputError when one is not of `runs`);
  /// `offset` runs are counted done for the progress line. The rows are on
  /// every rank. An empty `file`: no journal read or written; its text is
  /// kept in DealtRows::journal on rank 0 (results in memory).
  DealtRows deal_runs(const IdaRun &run, DealtRuns *runs, const std::vector<std::string> &names,
                      const std::string &file, MPI_Comm comm, Progress *progress,
                      unsigned long offset = 0);

  /// Runs `tasks` (each independent of the others) over the ranks of
  /// `comm` (each must call it) by deal_runs, journaled in `file`; `offset`
  /// runs are counted done for the progress line. Returns each task's row
  /// (record, intensity, collapsed, the demands) done, on every rank; adds
  /// the runs of this call to result.n_run_now and an interruption to
  /// result.interrupted.
  std::vector<std::vector<double>>
  run_ida_tasks(const IdaRun &run, const std::vector<std::string> &names,
                const std::vector<IdaTask> &tasks, const std::string &file, MPI_Comm comm,
                Progress *progress, unsigned long offset, IdaResult &result);
  /// The same with the runner's rows (ida_row).
  std::vector<std::vector<double>>
  run_ida_tasks(IdaRunner &runner, const std::vector<IdaTask> &tasks, const std::string &file,
                MPI_Comm comm, Progress *progress, unsigned long offset, IdaResult &result);

  /// The journal row of a run: record, intensity, collapsed (0/1), then the
  /// demands of IdaRunner::demand_names().
  std::vector<double> ida_row(IdaRunner &runner, const IdaTask &task);
  /// The names of a journal row's columns.
  std::vector<std::string> ida_row_names(const IdaRunner &runner);

  /// Hunt and fill every record of the runner's suite over the ranks of
  /// `comm` (each must call it), dealt run by run (ida_scheduler.cc): rank 0
  /// holds every record's search and deals the next intensity of a record
  /// with no run under way (the one with the fewest runs first) to whichever
  /// rank is free, keeping a few runs queued at each worker so that none
  /// waits for rank 0, which runs records itself between its messages. A
  /// record's next intensity depends on its own runs alone, so the result is
  /// the same on any number of ranks. Each run is appended by rank 0 to
  /// journal/realizations.csv as it comes back, so that a run started again
  /// resumes (the runs journaled are read back, not run). SIGINT/SIGTERM:
  /// stops after the runs under way. The result is on every rank. An empty
  /// `journal`: no file, the journal's text in IdaResult::journals.
  IdaResult run_ida(IdaRunner &runner, const std::string &journal, MPI_Comm comm,
                    Progress *progress = nullptr);
} // namespace poundfe

#endif
