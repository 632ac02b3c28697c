#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>

#include <deal.II/base/exceptions.h>
#include <poundfe/excitation/excitation.h>
#include <poundfe/excitation/ground_motion_filter.h>
#include <poundfe/model/model_builder.h>
#include <poundfe/excitation/records.h>
#include <poundfe/excitation/stochastic.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace poundfe
{
  double
  NodalForce::value(const double t) const
  {
    if (kind == Kind::harmonic)
      return amplitude * std::sin(omega * t + phase);
    if (kind == Kind::white_noise)
      {
        const double k = t / sample_interval + 1e-9; // t = k dt may land just below
        return k >= 0 && k < values.size() ? values[static_cast<std::size_t>(k)] : 0;
      }
    if (times.empty() || t < times.front() || t > times.back())
      return 0;
    const auto   upper = std::upper_bound(times.begin(), times.end(), t);
    if (upper == times.end())
      return values.back();
    const auto   i     = upper - times.begin() - 1;
    const double f     = (t - times[i]) / (times[i + 1] - times[i]);
    return (1 - f) * values[i] + f * values[i + 1];
  }

  Excitation::Excitation(const LinearSystem &system, GroundMotion ground_motion,
                         std::vector<NodalForce> nodal_forces)
    : ground(std::move(ground_motion))
    , forces(std::move(nodal_forces))
    , mass_times_influence(system.mass * system.influence)
  {}

  void
  Excitation::set_mass(const LinearSystem &system)
  {
    mass_times_influence = system.mass * system.influence;
    if (pair)
      mass_times_influence_y = system.mass * system.influence_y;
    if (vertical_motion)
      mass_times_influence_z = system.mass * system.influence_z;
  }

  void
  Excitation::set_horizontal_pair(const LinearSystem &system, GroundMotion second_motion,
                                  const double angle)
  {
    Assert(system.influence_y.size() == system.mass.rows(),
           dealii::ExcMessage("a horizontal pair needs a 3D model"));
    pair                   = true;
    second                 = std::move(second_motion);
    cos_angle              = std::cos(angle);
    sin_angle              = std::sin(angle);
    mass_times_influence_y = system.mass * system.influence_y;
  }

  std::array<double, 2>
  Excitation::horizontal_acceleration(const double t) const
  {
    if (!pair)
      return {{ground.value(t), 0.0}};
    const double g1 = ground.value(t), g2 = second.value(t);
    return {{cos_angle * g1 - sin_angle * g2, sin_angle * g1 + cos_angle * g2}};
  }

  std::array<double, 2>
  Excitation::applied_horizontal_peaks() const
  {
    std::array<double, 2> peaks{{0, 0}};
    // every sample of either component (a rotated pair peaks at one of them)
    for (const GroundMotion *motion : {&ground, &second})
      if (!motion->empty())
        for (double t = 0, n = 0; t <= motion->duration() * (1 + 1e-12); t = ++n * motion->time_step())
          {
            const std::array<double, 2> a = horizontal_acceleration(t);
            for (unsigned int d = 0; d < 2; ++d)
              peaks[d] = std::max(peaks[d], std::abs(a[d]));
          }
    return peaks;
  }

  void
  Excitation::set_vertical(const LinearSystem &system, GroundMotion vertical_component)
  {
    AssertDimension(system.influence_z.size(), system.mass.rows());
    vertical_motion        = true;
    vertical               = std::move(vertical_component);
    mass_times_influence_z = system.mass * system.influence_z;
  }

  std::array<double, 3>
  Excitation::ground_acceleration_vector(const double t) const
  {
    const std::array<double, 2> a = horizontal_acceleration(t);
    return {{a[0], a[1], vertical_motion ? vertical.value(t) : 0.0}};
  }

  void
  Excitation::load(const double t, Vector &load) const
  {
    if (pair)
      {
        const auto a = horizontal_acceleration(t);
        load         = (-a[0]) * mass_times_influence - a[1] * mass_times_influence_y;
      }
    else
      load = (-ground.value(t)) * mass_times_influence;
    if (vertical_motion)
      load -= vertical.value(t) * mass_times_influence_z;
    for (const NodalForce &f : forces)
      load[f.equation] += f.value(t);
  }

  MotionGenerator
  make_motion_generator(const GroundMotionParameters &g, const double time_step)
  {
    StochasticMotion s;
    s.filter = ground_motion_filter(g);
    s.method = g.type == GroundMotionType::white_noise ? StochasticMethod::white_noise : g.method;
    const double given   = given_spectral_intensity(g);
    s.spectral_intensity = given > 0 ? given :
                                       intensity_from_pga(s.filter, g.target_pga * standard_gravity,
                                                          g.peak_factor);
    s.duration               = g.duration;
    s.sample_interval        = g.held_interval(time_step);
    s.cutoff_frequency       = g.cutoff_frequency;
    s.n_frequencies          = g.n_frequencies;
    s.envelope.kind          = g.envelope;
    s.envelope.rise_end      = g.jennings_rise_end;
    s.envelope.plateau_end   = g.jennings_plateau_end;
    s.envelope.decay         = g.jennings_decay;
    s.envelope.b             = g.saragoni_b;
    s.envelope.c             = g.saragoni_c;
    s.envelope.alpha         = g.shinozuka_alpha;
    s.envelope.beta          = g.shinozuka_beta;
    s.seed                   = g.seed;
    s.realization            = g.realization;
    return MotionGenerator(s);
  }

  namespace
  {
    /// A scaled record whose samples overflow, or underflow into denormals,
    /// is refused, naming the parameter that scaled it.
    void
    check_scaled(const GroundMotion &motion, const InputFile &input, const std::string &path)
    {
      const std::size_t i = motion.first_unusable_sample();
      if (i < motion.samples().size())
        input.fail(path, "scales sample " + std::to_string(i + 1) + " of the ground motion to " +
                           number_text(motion.samples()[i]) +
                           " m/s^2: not a finite, normal number (check the record's values "
                           "and units)");
    }
  } // namespace

  GroundMotion
  make_ground_motion(const GroundMotionParameters &g, const InputFile &input,
                     const double time_step)
  {
    return make_ground_motion(g, input, time_step, "Ground motion/Record/File");
  }

  GroundMotion
  make_ground_motion(const GroundMotionParameters &g, const InputFile &input,
                     const double time_step, const std::string &path)
  {
    GroundMotion motion;
    if (g.type == GroundMotionType::record)
      {
        RecordFormat format;
        format.format    = g.record_format;
        format.units     = g.record_units;
        format.time_step = g.record_time_step;
        try
          {
            motion = read_record(input.resolve(g.record_file), format);
          }
        catch (const InputError &e)
          {
            throw InputError(input.file, input.line_of(path), path, e.what());
          }
        if (g.record_target_pga > 0)
          {
            if (motion.peak() == 0)
              throw InputError(input.file, input.line_of("Ground motion/Record/Target PGA"),
                               "Ground motion/Record/Target PGA",
                               "cannot scale a record of zero PGA");
            motion.scale(g.record_target_pga * standard_gravity / motion.peak());
            check_scaled(motion, input, "Ground motion/Record/Target PGA");
          }
      }
    else if (g.type != GroundMotionType::none)
      motion = make_motion_generator(g, time_step).ground_motion();
    // The Scale factor multiplies the motion after any Target PGA, for a
    // record as for a generated motion (whose Target PGA sets S0): the PGA
    // is Target PGA x Scale factor either way.
    motion.scale(g.scale_factor);
    if (g.type == GroundMotionType::record) // generated motions may underflow harmlessly
      check_scaled(motion, input, "Ground motion/Scale factor");
    return motion;
  }

  void
  correlate_second_component(const std::vector<double> &first, std::vector<double> &second,
                             const double intensity_ratio, const double correlation)
  {
    AssertDimension(first.size(), second.size());
    if (intensity_ratio == 1 && correlation == 0)
      return; // independent components of equal intensity: as generated
    const double independent = std::sqrt(1 - correlation * correlation);
    for (std::size_t k = 0; k < second.size(); ++k)
      second[k] = intensity_ratio * (correlation * first[k] + independent * second[k]);
  }

  void
  refuse_incidence_angle_in_plane(const Model &model, const GroundMotionParameters &g,
                                  const InputFile &input)
  {
    if (model.dimension != 3 && g.incidence_angle != 0)
      input.fail("Ground motion/Incidence angle", "an incidence angle needs "
                                                  "Model/Dimension = 3");
  }

  void
  add_horizontal_component(Excitation &excitation, const LinearSystem &system, const Model &model,
                           const GroundMotionParameters &g, const InputFile &input,
                           const double time_step)
  {
    if (model.dimension != 3)
      {
        if (g.n_components == 2)
          input.fail("Ground motion/Components", "two horizontal components need "
                                                 "Model/Dimension = 3");
        if (!g.second_record_file.empty())
          input.fail("Ground motion/Record/Second file",
                     "a planar model has no y direction: Components = 3 shakes it along x "
                     "and vertically (File and Third file)");
        refuse_incidence_angle_in_plane(model, g, input);
        return;
      }
    excitation.set_horizontal_pair(system,
                                   second_horizontal_motion(excitation.ground_motion(), g, input,
                                                            time_step),
                                   g.incidence_angle * M_PI / 180);
  }

  GroundMotion
  second_horizontal_motion(const GroundMotion &first, const GroundMotionParameters &g,
                           const InputFile &input, const double time_step)
  {
    if (g.n_components < 2)
      return {}; // none: the first component alone, rotated
    if (g.type == GroundMotionType::record && g.second_record_file.empty())
      // Components = 3 in 3D: x, y and z (Components = 2 is checked with the section)
      throw InputError(input.file, input.line_of("Ground motion/Components"),
                       "Ground motion/Record/Second file",
                       "Components = 3 with a record in 3D needs a second (y) file "
                       "besides the third (vertical) one");
    GroundMotion second = make_ground_motion(g.second_component(), input, time_step,
                                             "Ground motion/Record/Second file");
    if (g.is_stochastic())
      correlate_second_component(first.samples(), second.samples_for_update(), g.intensity_ratio,
                                 g.correlation);
    return second;
  }

  GroundMotion
  vertical_motion_of(const GroundMotion &first, const GroundMotionParameters &g,
                     const InputFile &input, const double time_step)
  {
    GroundMotionParameters component = g.vertical_component();
    if (g.type == GroundMotionType::record && g.record_target_pga > 0)
      {
        // the factor that brought File to the Target PGA, so that the
        // recorded ratio of the vertical to the horizontal motion is kept
        GroundMotionParameters unscaled = g;
        unscaled.record_target_pga      = 0;
        unscaled.scale_factor           = 1;
        const double peak = make_ground_motion(unscaled, input, time_step).peak();
        component.record_target_pga = 0;
        component.scale_factor = g.scale_factor * g.record_target_pga * standard_gravity / peak;
      }
    GroundMotion vertical =
      make_ground_motion(component, input, time_step, "Ground motion/Record/Third file");
    if (g.is_stochastic()) // an independent sample, sigma_z = ratio sigma_x
      correlate_second_component(first.samples(), vertical.samples_for_update(),
                                 g.vertical_ratio, 0);
    return vertical;
  }

  void
  add_vertical_component(Excitation &excitation, const LinearSystem &system, const Model &model,
                         const GroundMotionParameters &g, const InputFile &input,
                         const double time_step)
  {
    if (!g.has_vertical())
      return;
    for (const Building &building : model.buildings)
      if (building.type == BuildingType::shear)
        input.fail("Ground motion/Components",
                   "Components = 3 shakes the model vertically, but building '" + building.name +
                     "' is a shear building (stick model): it has no vertical DOF; use frames "
                     "or Components = " + (model.dimension == 3 ? "2" : "1"));
    excitation.set_vertical(system,
                            vertical_motion_of(excitation.ground_motion(), g, input, time_step));
  }

  NodeDof
  find_node_dof(const InputFile &input, const Model &model, std::istringstream &fields,
                const std::string &path, const std::string &entry)
  {
    const FloorNode at =
      read_floor_node(input, model, fields, path, entry, "building floor node dof ...");
    const int   line = input.line_of(path);
    std::string dof;
    Component   c;
    if (!(fields >> dof))
      throw InputError(input.file, line, path,
                       "'" + entry + "': expected 'building floor node dof ...'");
    if (dof == "ux")
      c = Component::ux;
    else if (dof == "uy")
      c = Component::uy;
    else if (dof == "rz")
      c = Component::rz;
    else
      throw InputError(input.file, line, path, "'" + entry + "': dof must be ux, uy or rz");
    const int equation = model.equation(Model::dof(at.node, c));
    if (equation < 0)
      throw InputError(input.file, line, path, "'" + entry + "': that DOF is fixed");
    return {static_cast<unsigned int>(equation), at.label + " " + dof};
  }

  namespace
  {
    /// Each non-blank entry of `entries`: the force with its target set, and
    /// the fields after 'building floor node dof' for `read_rest`.
    void
    parse_forces(const InputFile &input, const Model &model,
                 const std::vector<std::string> &entries, const std::string &path,
                 const NodalForce::Kind kind, std::vector<NodalForce> &forces,
                 const std::function<void(std::istringstream &, const std::string &, NodalForce &)>
                   &read_rest)
    {
      for (const std::string &entry : entries)
        {
          if (entry.find_first_not_of(" \t") == std::string::npos)
            continue;
          std::istringstream fields(entry);
          const NodeDof      target = find_node_dof(input, model, fields, path, entry);
          NodalForce         f;
          f.equation = target.equation;
          f.label    = target.label;
          f.kind     = kind;
          read_rest(fields, entry, f);
          forces.push_back(std::move(f));
        }
    }
  } // namespace

  std::vector<NodalForce>
  make_nodal_forces(const NodalForceParameters &parameters, const GroundMotionParameters &ground_motion,
                    const double time_step, const InputFile &input, const Model &model)
  {
    std::vector<NodalForce> forces;
    const std::string       harmonic_path = "Nodal forces/Harmonic";
    parse_forces(input, model, parameters.harmonic, harmonic_path, NodalForce::Kind::harmonic,
                 forces, [&](std::istringstream &fields, const std::string &entry, NodalForce &f) {
                   std::string rest;
                   if (!read_number(read_number(fields, f.amplitude), f.omega) ||
                       (!(fields >> std::ws).eof() && !read_number(fields, f.phase)) ||
                       (fields >> rest))
                     throw InputError(input.file, input.line_of(harmonic_path), harmonic_path,
                                      "'" + entry + "': expected '... amplitude omega [phase]' "
                                      "(numbers, nothing after them)");
                 });
    const std::string tabulated_path = "Nodal forces/Tabulated";
    parse_forces(input, model, parameters.tabulated, tabulated_path, NodalForce::Kind::tabulated,
                 forces, [&](std::istringstream &fields, const std::string &entry, NodalForce &f) {
                   std::string file;
                   if (!(fields >> file))
                     throw InputError(input.file, input.line_of(tabulated_path), tabulated_path,
                                      "'" + entry + "': expected '... file'");
                   const ColumnTable table = read_columns(input.resolve(file));
                   if (table.columns != 2)
                     throw InputError(input.resolve(file), 0, tabulated_path,
                                      "a force table has two columns: time, force");
                   for (std::size_t i = 1; i < table.times.size(); ++i)
                     if (!(table.times[i] > table.times[i - 1]))
                       throw InputError(input.resolve(file), 0, tabulated_path,
                                        "times must increase (row " + std::to_string(i + 1) + ")");
                   f.times  = table.times;
                   f.values = table.values;
                 });
    const std::string noise_path = "Nodal forces/White noise";
    parse_forces(input, model, parameters.white_noise, noise_path, NodalForce::Kind::white_noise,
                 forces, [&](std::istringstream &fields, const std::string &entry, NodalForce &f) {
                   std::string rest;
                   if (!read_number(fields, f.intensity) || (fields >> rest) ||
                       !(f.intensity > 0))
                     throw InputError(input.file, input.line_of(noise_path), noise_path,
                                      "'" + entry + "': expected '... S0' with S0 > 0 (a "
                                      "number, nothing after it)");
                   f.sample_interval = ground_motion.held_interval(time_step);
                   // the white-noise forces last as long as the stochastic ground motion would
                   f.values.assign(n_samples(ground_motion.duration, f.sample_interval), 0.0);
                 });
    return forces;
  }
} // namespace poundfe
