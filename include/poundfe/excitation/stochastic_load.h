// The random part of an input's loading: the stochastic ground motion and the
// white-noise nodal forces, as one function of a vector of independent
// standard normals xi = [ground..., second ground..., vertical ground...,
// force 1..., force 2..., ...] (the second horizontal component of a 3D
// model's stochastic pair, its normals those of (Second seed, realization),
// and the vertical component's those of (Vertical seed, realization), so
// that a realization is the run of the same Realization). Monte Carlo
// draws xi from (seed, realization); Subset Simulation moves it by Markov
// chains. Set up once; apply() writes a realization into an Excitation in
// place, so a new realization never rebuilds the model or the excitation.
#ifndef poundfe_excitation_stochastic_load_h
#define poundfe_excitation_stochastic_load_h

#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/stochastic.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace poundfe
{
  class StochasticLoad
  {
  public:
    /// The random parts of `excitation`, which was made from `ground_motion`
    /// (and nodal forces) with the analysis time step `time_step`.
    StochasticLoad(const GroundMotionParameters &ground_motion, double time_step,
                   const Excitation &excitation);

    unsigned int  n_variables() const { return n_random; }
    std::uint64_t seed() const { return random_seed; }
    /// The input's stochastic ground motion, if any.
    const MotionGenerator *ground_generator() const { return ground ? &*ground : nullptr; }

    /// xi of realization `realization`, every entry from (Seed, realization)
    /// but the second ground component's, from (Second seed, realization);
    /// xi is resized to n_variables() if it is shorter (what follows is
    /// the caller's: random model parameters).
    void standard_normals(std::uint64_t realization, std::vector<double> &xi) const;

    /// Writes the sample of xi into the excitation (built from the same input),
    /// with every random amplitude multiplied by amplitude_factor.
    void apply(const std::vector<double> &xi, Excitation &excitation,
               double amplitude_factor = 1) const;

  private:
    std::optional<MotionGenerator> ground;
    double                         ground_scale = 1;
    std::optional<MotionGenerator> second_ground; // a 3D model's stochastic pair
    double                         intensity_ratio = 1, correlation = 0;
    std::uint64_t                  second_seed = 0;
    std::optional<MotionGenerator> vertical_ground; // Components = 3
    double                         vertical_ratio = 1;
    std::uint64_t                  vertical_seed  = 0;
    std::vector<unsigned int>      noise_forces; // indices in Excitation::nodal_forces()
    std::vector<double>            noise_scales; // sqrt(2 pi S0 / dt)
    std::vector<unsigned int>      noise_lengths;
    unsigned int                   n_random    = 0;
    std::uint64_t                  random_seed = 1;
  };
} // namespace poundfe

#endif
