// The `Spectrum` section: the periods and damping ratios of the response
// spectra (the `spectrum` command and a run's floor spectra), the design
// spectrum they are compared with (Eurocode 8) and the period at which a
// stochastic motion's intensity is matched to it.
#ifndef poundfe_excitation_spectrum_parameters_h
#define poundfe_excitation_spectrum_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/response_spectrum.h>

#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  const NameTable<DesignSpectrum> &design_spectrum_names();
  const NameTable<GroundType>     &ground_type_names();

  struct SpectrumParameters
  {
    double              min_period       = 0.02; // s
    double              max_period       = 4.0;  // s
    unsigned int        n_periods        = 100;
    bool                logarithmic      = true;
    std::vector<double> damping_ratios{0.05};
    DesignSpectrum      target           = DesignSpectrum::none;
    GroundType          ground_type      = GroundType::B;
    double              design_ground_acceleration = 0.25; // a_g, in g
    double              matching_period  = 0;              // s; 0: the model's first period

    /// Declare the section (entered and left here).
    void declare(dealii::ParameterHandler &prm);
    /// Throws InputError.
    void check(const InputFile &input) const;

    std::vector<double> periods() const;
    /// Se(T) of the target for damping ratio zeta, m/s^2 (target none: 0).
    double target_psa(double zeta, double period) const;
  };
} // namespace poundfe

#endif
