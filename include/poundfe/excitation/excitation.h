// The right-hand side p(t) = -M r a_g(t) + sum of nodal forces, on the
// equations. Built once from the input; evaluated per step without allocation.
#ifndef poundfe_excitation_excitation_h
#define poundfe_excitation_excitation_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/base/input_file.h>
#include <poundfe/excitation/excitation_parameters.h>
#include <poundfe/excitation/ground_motion.h>
#include <poundfe/excitation/stochastic.h>
#include <poundfe/model/model.h>

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

namespace poundfe
{
  struct NodalForce
  {
    enum class Kind
    {
      harmonic,
      tabulated,
      white_noise
    };
    unsigned int        equation  = 0;
    std::string         label;
    Kind                kind      = Kind::harmonic;
    double              amplitude = 0, omega = 0, phase = 0; // harmonic
    std::vector<double> times, values; // tabulated (linear), white noise (held)
    double              sample_interval = 0, intensity = 0; // white noise: dt, S0

    double value(double t) const;
  };

  class Excitation
  {
  public:
    Excitation(const LinearSystem &system, GroundMotion ground, std::vector<NodalForce> forces);
    /// -M r of every component (the pair's and the vertical's too) from
    /// `system`'s M: a realization with random masses (dynamics/realization.h).
    void set_mass(const LinearSystem &system);

    /// Dimension 3: the second horizontal component g_2 and the incidence
    /// angle a (rad); the load is then -M (r_x a_x + r_y a_y) with
    /// (a_x, a_y) = R(a) (g_1, g_2).
    void set_horizontal_pair(const LinearSystem &system, GroundMotion second, double angle);
    /// (a_x, a_y) at t (a_y = 0 without a pair).
    std::array<double, 2> horizontal_acceleration(double t) const;
    /// The peaks of |a_x| and |a_y| as applied (after the incidence
    /// rotation), over the samples of both components: the PGA along each
    /// axis of the model, m/s^2.
    std::array<double, 2> applied_horizontal_peaks() const;
    bool has_horizontal_pair() const { return pair; }
    const GroundMotion &second_ground_motion() const { return second; }
    /// In-place access for a new realization (StochasticLoad).
    GroundMotion &second_ground_motion_for_update() { return second; }

    /// Components = 3: the vertical component a_z, on the influence vector
    /// r_z of the vertical translations (LinearSystem::influence_z); the
    /// load gains -M r_z a_z, not rotated by the incidence angle.
    void set_vertical(const LinearSystem &system, GroundMotion vertical);
    bool has_vertical() const { return vertical_motion; }
    const GroundMotion &vertical_ground_motion() const { return vertical; }
    /// In-place access for a new realization (StochasticLoad).
    GroundMotion &vertical_ground_motion_for_update() { return vertical; }
    /// (a_x, a_y, a_z) at t (a_z = 0 without a vertical component).
    std::array<double, 3> ground_acceleration_vector(double t) const;

    /// p(t) into `load` (sized n_equations).
    void load(double t, Vector &load) const;
    /// a_x(t): the first component, or the x component of a rotated pair.
    double ground_acceleration(double t) const { return horizontal_acceleration(t)[0]; }
    const GroundMotion &ground_motion() const { return ground; }
    const std::vector<NodalForce> &nodal_forces() const { return forces; }
    /// In-place access for a new realization (StochasticLoad).
    GroundMotion            &ground_motion_for_update() { return ground; }
    std::vector<NodalForce> &nodal_forces_for_update() { return forces; }

  private:
    GroundMotion            ground;
    std::vector<NodalForce> forces;
    Vector                  mass_times_influence;
    bool                    pair = false;
    GroundMotion            second;
    double                  cos_angle = 1, sin_angle = 0;
    Vector                  mass_times_influence_y;
    bool                    vertical_motion = false;
    GroundMotion            vertical;
    Vector                  mass_times_influence_z;
  };

  /// Penzien & Watabe (1975): the two horizontal components are uncorrelated
  /// along their principal axes. From two independent samples z_1 = g_1 and
  /// z_2 = g_2 of one process, g_2 becomes gamma (rho z_1 + sqrt(1 - rho^2)
  /// z_2): Var g_2 = gamma^2 Var g_1 and the correlation of (g_1, g_2) is
  /// rho (rho = 0: uncorrelated, the pair is along its principal axes with
  /// the intensity ratio gamma). Both sample vectors have the same grid.
  void correlate_second_component(const std::vector<double> &first, std::vector<double> &second,
                                  double intensity_ratio, double correlation);

  /// Refuses Ground motion/Incidence angle on a planar model (file, line,
  /// entry): it has no y direction to turn a record into, and an angle
  /// silently ignored would give the results of another input.
  void refuse_incidence_angle_in_plane(const Model &model, const GroundMotionParameters &g,
                                       const InputFile &input);

  /// Model/Dimension = 3: the second horizontal component of `parameters`
  /// and its incidence angle, onto `excitation`. Throws InputError (two
  /// components asked of a 2D model, a bad second record).
  void add_horizontal_component(Excitation &excitation, const LinearSystem &system,
                                const Model &model, const GroundMotionParameters &parameters,
                                const InputFile &input, double time_step);

  /// The second horizontal component of `parameters` (Components >= 2 in
  /// 3D; none otherwise), a stochastic one correlated with `first` (the
  /// first component) as the section asks. Throws InputError.
  GroundMotion second_horizontal_motion(const GroundMotion &first,
                                        const GroundMotionParameters &parameters,
                                        const InputFile &input, double time_step);
  /// The vertical component of `parameters` (Components = 3): a record
  /// scaled by File's factor to the Target PGA, a stochastic sample
  /// independent of `first` with the vertical ratio. Throws InputError.
  GroundMotion vertical_motion_of(const GroundMotion &first, const GroundMotionParameters &parameters,
                                  const InputFile &input, double time_step);

  /// Components = 3: the vertical component of `parameters` onto
  /// `excitation` (after add_horizontal_component). Throws InputError for a
  /// model with a shear building (it has no vertical DOF) or a bad third
  /// record.
  void add_vertical_component(Excitation &excitation, const LinearSystem &system,
                              const Model &model, const GroundMotionParameters &parameters,
                              const InputFile &input, double time_step);

  /// The ground motion of `Ground motion` (generated, recorded or none);
  /// `time_step` is the analysis time step, `input` names the file in
  /// messages and resolves the record's path.
  GroundMotion make_ground_motion(const GroundMotionParameters &parameters, const InputFile &input,
                                  double time_step);
  /// The same, naming `record_path` (the record file's parameter) in messages.
  GroundMotion make_ground_motion(const GroundMotionParameters &parameters, const InputFile &input,
                                  double time_step, const std::string &record_path);

  /// The generator of the input's stochastic ground motion (kanai-tajimi,
  /// clough-penzien or white-noise types).
  MotionGenerator make_motion_generator(const GroundMotionParameters &parameters, double time_step);

  /// A DOF named 'building floor node dof' (building and floor 1-based,
  /// node 0-based from the left, dof ux|uy|rz) and its label.
  struct NodeDof
  {
    unsigned int equation;
    std::string  label; // "A3 floor 2 node 0 ux"
  };

  /// The DOF whose name starts `fields` (the text `entry` of parameter
  /// `path`, for messages). Throws InputError for a bad or fixed DOF.
  NodeDof find_node_dof(const InputFile &input, const Model &model, std::istringstream &fields,
                        const std::string &path, const std::string &entry);

  /// Parse the 'Nodal forces' entries against the model. Throws InputError.
  /// White-noise forces are held over the stochastic ground motion's sample
  /// interval and last its duration.
  std::vector<NodalForce> make_nodal_forces(const NodalForceParameters   &parameters,
                                            const GroundMotionParameters &ground_motion,
                                            double time_step, const InputFile &input,
                                            const Model &model);
} // namespace poundfe

#endif
