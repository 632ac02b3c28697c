// The `Selection` section (selection_parameters.h).
#include <poundfe/assessment/selection_parameters.h>

#include <poundfe/base/numbers.h>

#include <deal.II/base/parameter_handler.h>

namespace poundfe
{
  const NameTable<SelectionTarget> &
  selection_target_names()
  {
    static const NameTable<SelectionTarget> names{{{SelectionTarget::ec8_type_1, "ec8-type-1"},
                                                   {SelectionTarget::ec8_type_2, "ec8-type-2"},
                                                   {SelectionTarget::asce7, "asce7"},
                                                   {SelectionTarget::table, "table"},
                                                   {SelectionTarget::cms, "cms"}}};
    return names;
  }

  void
  SelectionParameters::declare(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.enter_subsection("Selection");
    prm.add_parameter("Candidates", candidates,
                      "The suite to select from (a .csv, .json or folder of .AT2, as "
                      "IDA/Suite; a flatfile of records is a suite .csv); empty: IDA/Suite. "
                      "Unit: -.");
    prm.add_parameter("Records", n_records, "How many to select. Unit: count.", Integer(1, 1000));
    add_choice(prm, "Target", target,
               "ec8-type-1/ec8-type-2 (Spectrum/Ground type and Design ground acceleration, "
               "at IDA/Damping ratio), asce7 (SDS, SD1, TL), table (Spectrum table) or cms "
               "(the conditional mean spectrum of BSSA14 with Baker & Jayaram's correlation). "
               "Unit: -.", selection_target_names());
    prm.add_parameter("Minimum period", min_period, "Of the fit. Unit: s.", Double(0));
    prm.add_parameter("Maximum period", max_period, "Of the fit. Unit: s.", Double(0));
    prm.add_parameter("Number of periods", n_periods,
                      "Log-spaced over the range. Unit: count.", Integer(2, 500));
    prm.add_parameter("Scale limits", scale_limits,
                      "Smallest and largest scale factor a selected record may have. Unit: -.",
                      dealii::Patterns::List(Double(0), 2, 2, ","));
    add_choice(prm, "Scaling", scale_to_intensity ? "intensity" : "least-squares",
               "least-squares (each record's best fit to the target over the range) or "
               "intensity (each record scaled to Target intensity of IDA/Intensity measure; "
               "then ranked by its misfit). Unit: -.",
               {"least-squares", "intensity"},
               [this](const std::string &s) { scale_to_intensity = s == "intensity"; });
    prm.add_parameter("Target intensity", target_intensity,
                      "With Scaling = intensity. Unit: that of IDA/Intensity measure.", Double(0));
    prm.add_parameter("Spectrum table", table,
                      "Target = table: a CSV with columns period_s and sa_g (relative to the "
                      "input). Unit: -.");
    prm.add_parameter("SDS", sds, "ASCE 7-16 short-period design Sa. Unit: g.", Double(0));
    prm.add_parameter("SD1", sd1, "ASCE 7-16 design Sa at 1 s. Unit: g.", Double(0));
    prm.add_parameter("TL", tl, "ASCE 7-16 long-period transition period. Unit: s.", Double(0));
    prm.add_parameter("Magnitude", scenario.magnitude, "CMS scenario (BSSA14: 3 to 8.5). Unit: -.",
                      Double(3, 8.5));
    prm.add_parameter("Distance", scenario.rjb_km,
                      "CMS scenario's Joyner-Boore distance (BSSA14: up to 400 km). Unit: km.",
                      Double(0, 400));
    prm.add_parameter("Vs30", scenario.vs30_m_s, "CMS site (BSSA14: 150 to 1500 m/s). Unit: m/s.",
                      Double(150, 1500));
    add_choice(prm, "Mechanism", scenario.mechanism, "CMS scenario's fault mechanism. Unit: -.",
               fault_mechanism_names());
    prm.add_parameter("Conditioning period", conditioning_period,
                      "CMS: the period T* of the conditioning Sa. Unit: s.", Double(0));
    prm.add_parameter("Epsilon", epsilon,
                      "CMS: epsilon of Sa(T*) (from the hazard's deaggregation). Unit: -.",
                      Double(-5, 5));
    prm.leave_subsection();
  }

  std::vector<NamedInputFile>
  SelectionParameters::input_files() const
  {
    std::vector<NamedInputFile> files;
    if (!candidates.empty())
      files.push_back({"Selection/Candidates", "record suite", candidates, ""});
    if (target == SelectionTarget::table && !table.empty())
      files.push_back({"Selection/Spectrum table", "spectrum table", table, ""});
    return files;
  }

  void
  SelectionParameters::check(const InputFile &input) const
  {
    input.positive("Selection/Minimum period", min_period);
    if (!(max_period > min_period))
      input.fail("Selection/Maximum period", "must exceed Selection/Minimum period");
    if (!(scale_limits[0] > 0 && scale_limits[1] >= scale_limits[0]))
      input.fail("Selection/Scale limits", "expected 0 < smallest <= largest");
    if (scale_to_intensity)
      input.positive("Selection/Target intensity", target_intensity);
    if (target == SelectionTarget::table && table.empty())
      input.fail("Selection/Spectrum table", "Target = table needs a spectrum table");
    if (target == SelectionTarget::asce7)
      for (const auto &[path, value] : {std::pair{"Selection/SDS", sds},
                                        std::pair{"Selection/SD1", sd1}, std::pair{"Selection/TL", tl}})
        input.positive(path, value);
    if (target == SelectionTarget::cms)
      {
        const double low = bssa14_min_period(), high = bssa14_max_period();
        for (const auto &[path, value] :
             {std::pair{"Selection/Minimum period", min_period},
              std::pair{"Selection/Maximum period", max_period},
              std::pair{"Selection/Conditioning period", conditioning_period}})
          if (value < low || value > high)
            input.fail(path, "is outside BSSA14's periods (" + rounded(low) + " to " + rounded(high) +
                               " s)");
      }
  }
} // namespace poundfe
