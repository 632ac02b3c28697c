#include <poundfe/reliability/reliability_parameters.h>
#include <poundfe/base/input_file.h>
#include <poundfe/base/sweep_parameters.h>
#include <poundfe/model/model_builder.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  void
  MonteCarloParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Monte Carlo");
    prm.add_parameter("Realizations", realizations,
                      "Number of realizations (seed and index 0..N-1 fix each one). Unit: count.",
                      Patterns::Integer(1));
    prm.add_parameter("Drift limits", drift_limits,
                      "Inter-storey drift ratios whose exceedance probability is reported "
                      "(largest over every storey of every building). Unit: dimensionless.",
                      Patterns::List(Patterns::Double(0), 0, 100, ","));
    prm.add_parameter("Histogram bins", histogram_bins, "Bins of the PDF estimates. Unit: count.",
                      Patterns::Integer(2, 1000));
    prm.leave_subsection();
  }

  void
  MonteCarloParameters::check(const InputFile &input) const
  {
    for (const double limit : drift_limits)
      if (!(limit > 0))
        input.fail("Monte Carlo/Drift limits", "every limit must be positive");
    input.distinct("Monte Carlo/Drift limits", drift_limits);
  }

  const NameTable<SubsetResponse> &
  subset_response_names()
  {
    static const NameTable<SubsetResponse> table(
      {{SubsetResponse::peak_drift_ratio, "peak drift ratio"},
       {SubsetResponse::peak_roof_displacement, "peak roof displacement"},
       {SubsetResponse::peak_contact_force, "peak contact force"},
       {SubsetResponse::limit_state, "limit state"}});
    return table;
  }

  void
  SubsetParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Subset simulation");
    add_choice(prm, "Response", response,
               "The response whose exceedance is estimated: the peak inter-storey drift "
               "ratio, the peak roof displacement (m), the peak contact force (N), or limit "
               "state: failure of the system of Random parameters/Limit states (Y = -g > 0; "
               "Threshold is then not used). Unit: -.",
               subset_response_names());
    prm.add_parameter("Building", building_field,
                      "Building of the response: its number (1-based) or its Name. Unit: -.",
                      Patterns::Anything());
    prm.add_parameter("Storey", storey,
                      "Storey of the drift ratio (1-based; 0: largest over the storeys). Unit: -.",
                      Patterns::Integer(0));
    prm.add_parameter("Threshold", threshold,
                      "Failure: response > threshold (drift ratio, m, or N). Unit: that of "
                      "Response (dimensionless, m or N).");
    prm.add_parameter("Samples per level", samples_per_level, "N. Unit: count.",
                      Patterns::Integer(2));
    prm.add_parameter("Conditional probability", conditional_probability,
                      "p0 in (0, 0.5]: the level thresholds are the (1 - p0) quantiles; "
                      "round(p0 N) seeds grow chains of N/round(p0 N) states (when that "
                      "is not whole, chains drawn at random have one state more). Unit: "
                      "dimensionless.");
    prm.add_parameter("Maximum levels", max_levels, "Stop after this many levels. Unit: count.",
                      Patterns::Integer(1, 100));
    prm.add_parameter("Proposal spread", proposal_spread,
                      "Standard deviation of the component-wise Gaussian proposal of the "
                      "modified Metropolis algorithm. Unit: dimensionless.");
    prm.leave_subsection();
  }

  void
  SubsetParameters::check(const InputFile &input, const ModelParameters &model)
  {
    const std::string sp = "Subset simulation/";
    std::vector<std::string> names;
    for (const BuildingParameters &b : model.buildings)
      names.push_back(b.name);
    building = read_building(input, names, trimmed(building_field), sp + "Building",
                             building_field) + 1;
    if (response != SubsetResponse::limit_state)
      input.positive(sp + "Threshold", threshold);
    input.positive(sp + "Proposal spread", proposal_spread);
    // Any p0 in (0, 0.5] (Au & Beck 2001 use 0.1; Papaioannou et al. 2015
    // recommend 0.1-0.3): round(p0 N) seeds, chains of N/seeds states with
    // the remainder spread one each over chains drawn at random (subset.cc).
    const double p0 = conditional_probability;
    if (!(p0 > 0 && p0 <= 0.5))
      input.fail(sp + "Conditional probability", "must lie in (0, 0.5]");
    const double n_seeds = std::round(p0 * samples_per_level);
    if (n_seeds < 1 || n_seeds >= samples_per_level)
      input.fail(sp + "Conditional probability",
                 "p0 N = " + format_value(p0 * samples_per_level) +
                   " must round to at least one seed and fewer than N = " +
                   std::to_string(samples_per_level) + " (more samples per level)");
    if (storey > model.buildings[building - 1].n_storeys &&
             model.buildings[building - 1].type != BuildingType::mesh)
      input.fail(sp + "Storey", "building " + std::to_string(building) + " has " +
                              std::to_string(model.buildings[building - 1].n_storeys) +
                              " storeys");
  }

  void
  FragilityParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Fragility");
    prm.add_parameter("PGA levels", pga_levels,
                      "Intensity levels: target PGA (S0 from the PGA and peak factor). "
                      "Unit: g.",
                      Patterns::List(Patterns::Double(0), 1, 1000, ","));
    prm.add_parameter("Realizations per level", realizations_per_level,
                      "Monte Carlo realizations at each level (the same seeds at every level). "
                      "Unit: count.",
                      Patterns::Integer(1));
    prm.leave_subsection();
  }

  void
  FragilityParameters::check(const InputFile &input) const
  {
    for (const double pga : pga_levels)
      if (!(pga > 0))
        input.fail("Fragility/PGA levels", "every level must be positive");
    input.distinct("Fragility/PGA levels", pga_levels);
  }
} // namespace poundfe
