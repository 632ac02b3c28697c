#include <poundfe/base/exceptions.h>
#include <poundfe/excitation/stochastic_load.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  StochasticLoad::StochasticLoad(const GroundMotionParameters &ground_motion, const double time_step,
                                 const Excitation &excitation)
    : random_seed(ground_motion.seed)
  {
    if (ground_motion.is_stochastic())
      {
        ground.emplace(make_motion_generator(ground_motion, time_step));
        ground_scale = ground_motion.scale_factor;
        n_random     = ground->n_variables();
        if (excitation.has_horizontal_pair() && ground_motion.n_components == 2)
          {
            const GroundMotionParameters second = ground_motion.second_component();
            second_ground.emplace(make_motion_generator(second, time_step));
            second_seed     = second.seed;
            intensity_ratio = ground_motion.intensity_ratio;
            correlation     = ground_motion.correlation;
            n_random += second_ground->n_variables();
          }
        if (excitation.has_vertical())
          {
            const GroundMotionParameters vertical = ground_motion.vertical_component();
            vertical_ground.emplace(make_motion_generator(vertical, time_step));
            vertical_seed  = vertical.seed;
            vertical_ratio = ground_motion.vertical_ratio;
            n_random += vertical_ground->n_variables();
          }
      }
    const std::vector<NodalForce> &forces = excitation.nodal_forces();
    for (unsigned int i = 0; i < forces.size(); ++i)
      if (forces[i].kind == NodalForce::Kind::white_noise)
        {
          noise_forces.push_back(i);
          noise_scales.push_back(std::sqrt(2 * M_PI * forces[i].intensity / forces[i].sample_interval));
          noise_lengths.push_back(forces[i].values.size());
          n_random += forces[i].values.size();
        }
  }

  void
  StochasticLoad::standard_normals(const std::uint64_t realization, std::vector<double> &xi) const
  {
    if (xi.size() < n_random)
      xi.resize(n_random);
    poundfe::standard_normals(random_seed, realization, xi);
    if (second_ground)
      {
        std::vector<double> second(second_ground->n_variables());
        poundfe::standard_normals(second_seed, realization, second);
        std::copy(second.begin(), second.end(), xi.begin() + ground->n_variables());
      }
    if (vertical_ground)
      {
        std::vector<double> vertical(vertical_ground->n_variables());
        poundfe::standard_normals(vertical_seed, realization, vertical);
        const unsigned int offset =
          ground->n_variables() + (second_ground ? second_ground->n_variables() : 0);
        std::copy(vertical.begin(), vertical.end(), xi.begin() + offset);
      }
  }

  void
  StochasticLoad::apply(const std::vector<double> &xi, Excitation &excitation,
                        const double amplitude_factor) const
  {
    Assert(xi.size() == n_random, dealii::ExcInternalError());
    unsigned int offset = 0;
    if (ground)
      {
        const double factor = ground_scale * amplitude_factor;
        // one component's sample from the next normals of xi, scaled
        const auto generate = [&](const MotionGenerator &generator, std::vector<double> &samples) {
          generator.generate(xi.data() + offset, samples);
          for (double &a : samples)
            a *= factor;
          offset += generator.n_variables();
        };
        std::vector<double> &samples = excitation.ground_motion_for_update().samples_for_update();
        generate(*ground, samples);
        if (second_ground)
          {
            std::vector<double> &second =
              excitation.second_ground_motion_for_update().samples_for_update();
            generate(*second_ground, second);
            correlate_second_component(samples, second, intensity_ratio, correlation);
          }
        if (vertical_ground)
          {
            std::vector<double> &vertical =
              excitation.vertical_ground_motion_for_update().samples_for_update();
            generate(*vertical_ground, vertical);
            // an independent sample of the same process, sigma_z = ratio sigma_x
            correlate_second_component(samples, vertical, vertical_ratio, 0);
          }
      }
    std::vector<NodalForce> &forces = excitation.nodal_forces_for_update();
    for (unsigned int i = 0; i < noise_forces.size(); ++i)
      {
        std::vector<double> &values = forces[noise_forces[i]].values;
        const double         scale  = noise_scales[i] * amplitude_factor;
        for (unsigned int k = 0; k < noise_lengths[i]; ++k)
          values[k] = scale * xi[offset + k];
        offset += noise_lengths[i];
      }
  }
} // namespace poundfe
