// The `Site hazard/Site study` section (thesis §2.3.1, Table 2.3): the site
// intensities of chosen return periods by several methods (typed in, from an
// intensity-frequency relation, or from the catalogue's fit), and the
// earthquake coefficient, OBE and MCE they give (hazard/site_study.h).
#ifndef poundfe_hazard_site_study_parameters_h
#define poundfe_hazard_site_study_parameters_h

#include <poundfe/base/input_file.h>
#include <poundfe/hazard/site_hazard.h>
#include <poundfe/hazard/site_study.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  struct SiteStudyParameters
  {
    std::vector<std::string> intensities{};          // "method scale T I" entries
    std::vector<double>      return_periods{100, 250}; // of the relations, years
    double                   relation_a = 0, relation_b = 0; // log10 N_c = a - b I; b = 0: none
    bool                     from_catalogue = false;
    SiteStudySettings        settings{};

    /// Declare the subsection (inside Site hazard; entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Every value, the entries parsed. Throws InputError.
    void check(const InputFile &input) const;
    /// Whether a study is asked for.
    bool given() const { return !intensities.empty() || relation_b > 0 || from_catalogue; }
    /// The typed-in entries. Throws InputError naming the entry.
    std::vector<SiteStudyEntry> typed_entries(const InputFile &input) const;
    /// The entries of the study: the typed-in ones, then the relation's and
    /// the catalogue fit's (`catalogue`: nullptr when there is none) at each
    /// return period and at the OBE's. Throws InputError.
    std::vector<SiteStudyEntry> entries(const InputFile &input,
                                        const IntensityHazard *catalogue) const;
  };
} // namespace poundfe

#endif
