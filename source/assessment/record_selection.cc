// Least-squares selection and scaling of records (record_selection.h).
#include <poundfe/assessment/record_selection.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace poundfe
{
  double
  least_squares_scale(const std::vector<double> &spectrum, const std::vector<double> &target)
  {
    Assert(spectrum.size() == target.size() && !target.empty(), dealii::ExcMessage("sizes"));
    double sum = 0;
    for (std::size_t i = 0; i < target.size(); ++i)
      sum += std::log(target[i] / spectrum[i]);
    return std::exp(sum / target.size());
  }

  double
  log_misfit(const std::vector<double> &spectrum, const double scale,
             const std::vector<double> &target)
  {
    double sum = 0;
    for (std::size_t i = 0; i < target.size(); ++i)
      {
        const double e = std::log(scale * spectrum[i] / target[i]);
        sum += e * e;
      }
    return std::sqrt(sum / target.size());
  }

  RecordSelection
  select_records(const std::vector<std::vector<double>> &spectra, const TargetSpectrum &target,
                 const unsigned int n, const double min_scale, const double max_scale,
                 const std::vector<double> &scales)
  {
    RecordSelection             selection;
    std::vector<SelectedRecord> candidates;
    for (unsigned int r = 0; r < spectra.size(); ++r)
      {
        const double s =
          scales.empty() ? least_squares_scale(spectra[r], target.median) : scales.at(r);
        if (s >= min_scale && s <= max_scale)
          candidates.push_back({r, s, log_misfit(spectra[r], s, target.median)});
      }
    selection.n_within = candidates.size();
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const SelectedRecord &a, const SelectedRecord &b) { return a.misfit < b.misfit; });
    candidates.resize(std::min<std::size_t>(n, candidates.size()));
    selection.records = candidates;
    if (candidates.empty())
      return selection;
    const double k = candidates.size();
    for (std::size_t i = 0; i < target.periods.size(); ++i)
      {
        double mean = 0, squares = 0;
        for (const SelectedRecord &c : candidates)
          mean += std::log(c.scale * spectra[c.index][i]) / k;
        for (const SelectedRecord &c : candidates)
          squares += std::pow(std::log(c.scale * spectra[c.index][i]) - mean, 2);
        selection.mean.push_back(std::exp(mean));
        selection.sigma.push_back(k > 1 ? std::sqrt(squares / (k - 1)) : 0.0);
        selection.max_mean_misfit =
          std::max(selection.max_mean_misfit, std::abs(mean - std::log(target.median[i])));
      }
    return selection;
  }
} // namespace poundfe
