#include <poundfe/base/exceptions.h>
#include <poundfe/laws/contact_law.h>
#include <poundfe/model/parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace poundfe
{
  namespace
  {
    using dealii::ParameterHandler;
    namespace Patterns = dealii::Patterns;

    void
    declare_building(ParameterHandler &prm, BuildingParameters &b)
    {
      prm.add_parameter("Name", b.name, "Label used in reports; default 'B<n>'.");
      prm.add_parameter("Type",
                        b.type,
                        "frame: regular frame generated from storeys and bays; "
                        "mesh: frame read from a Gmsh mesh; shear: stick model.",
                        Patterns::Selection("frame|mesh|shear"));
      prm.add_parameter("Number of storeys", b.n_storeys, "Storeys (frame, shear).",
                        Patterns::Integer(1));
      prm.add_parameter("Number of bays", b.n_bays, "Bays (frame).", Patterns::Integer(1));
      prm.add_parameter("Storey heights", b.storey_heights,
                        "Storey heights in m, bottom up: one value for all or one per storey.");
      prm.add_parameter("Bay widths", b.bay_widths,
                        "Bay widths in m, left to right: one value for all or one per bay.");
      prm.add_parameter("Column E", b.column_youngs_modulus,
                        "Column Young's modulus in Pa, one value or one per storey.");
      prm.add_parameter("Column A", b.column_area, "Column area in m^2, one or per storey.");
      prm.add_parameter("Column I", b.column_second_moment,
                        "Column second moment of area in m^4, one or per storey.");
      prm.add_parameter("Beam E", b.beam_youngs_modulus,
                        "Beam Young's modulus in Pa, one or per floor.");
      prm.add_parameter("Beam A", b.beam_area, "Beam area in m^2, one or per floor.");
      prm.add_parameter("Beam I", b.beam_second_moment,
                        "Beam second moment of area in m^4, one or per floor.");
      prm.add_parameter("Column mass per length", b.column_mass_per_length,
                        "Distributed column mass in kg/m, one or per storey.");
      prm.add_parameter("Beam mass per length", b.beam_mass_per_length,
                        "Distributed beam mass in kg/m, one or per floor.");
      prm.add_parameter("Floor masses", b.floor_masses,
                        "Mass of each floor in kg, bottom up (roof last), lumped in equal "
                        "shares at the floor's joints: one value for all or one per floor. "
                        "For shear buildings, the floor mass.");
      prm.add_parameter("Base fixity", b.base_fixity,
                        "Support of the column bases.", Patterns::Selection("fixed|pinned"));
      prm.add_parameter("Elements per member", b.elements_per_member,
                        "Frame elements along each column and beam.", Patterns::Integer(1, 64));
      prm.add_parameter("Storey stiffnesses", b.storey_stiffnesses,
                        "Shear building storey stiffness in N/m, one or per storey.");
      prm.add_parameter("Storey damping", b.storey_damping,
                        "Shear building storey dashpot in N s/m, one or per storey "
                        "(added to the Rayleigh damping).");
      prm.add_parameter("Drawing width", b.drawing_width,
                        "Shear building: width in m used for placement and pictures.");
      prm.add_parameter("Mesh file", b.mesh_file,
                        "Gmsh .msh file (line elements; physical ids are member groups), "
                        "relative to this parameter file.");
      prm.add_parameter("Group ids", b.group_ids, "Mesh member group (physical) ids.");
      prm.add_parameter("Group E", b.group_youngs_modulus, "Young's modulus per group, Pa.");
      prm.add_parameter("Group A", b.group_area, "Area per group, m^2.");
      prm.add_parameter("Group I", b.group_second_moment, "Second moment per group, m^4.");
      prm.add_parameter("Group mass per length", b.group_mass_per_length,
                        "Distributed mass per group, kg/m.");
      prm.enter_subsection("Hinges");
      prm.add_parameter("Locations", b.hinge_locations,
                        "Frames: member ends that get a Bouc-Wen rotational hinge. column "
                        "bases: bottom of the ground-storey columns on clamped supports; "
                        "column tops / column ends: top / both ends of every column; beam "
                        "ends: both ends of every beam. Empty: an elastic frame.",
                        Patterns::List(Patterns::Selection(
                          "column bases|column tops|column ends|beam ends")));
      prm.add_parameter("Groups", b.hinge_groups,
                        "Member groups that get hinges (empty: all). Generated frames: "
                        "group 2i-1 holds the columns of storey i, group 2i the beams of "
                        "floor i; meshes: the physical ids.");
      prm.add_parameter("Yield moment", b.hinge_yield_moments,
                        "Yield moment M_y in N m, one value or one per entry of Groups; "
                        "the yield rotation is M_y / k.");
      prm.add_parameter("Yield rotation", b.hinge_yield_rotations,
                        "Yield rotation in rad, used where the yield moment is 0.");
      prm.add_parameter("Stiffness", b.hinge_stiffnesses,
                        "Elastic rotational stiffness k in N m/rad, one value or one per "
                        "entry of Groups; 0: Stiffness factor x 6 E I / L of the member.");
      prm.add_parameter("Stiffness factor", b.hinge_stiffness_factor,
                        "k = factor x 6 E I / L where Stiffness is 0 (stiff hinges keep the "
                        "elastic frame nearly unchanged; Ibarra & Krawinkler use 10).");
      prm.leave_subsection();
      prm.add_parameter("Storey yield drifts", b.storey_yield_drifts,
                        "Shear buildings: yield drift u_y in m of a Bouc-Wen storey (force "
                        "k u_y at yield), one value or one per storey; empty or 0: elastic.");
      prm.enter_subsection("Bouc-Wen");
      BoucWenParameters &h = b.hysteresis;
      prm.add_parameter("alpha", h.alpha, "Post-yield to elastic stiffness ratio.");
      prm.add_parameter("A", h.A, "A0 (1 with beta + gamma = 1 keeps |z| <= 1).");
      prm.add_parameter("beta", h.beta, "Loop shape.");
      prm.add_parameter("gamma", h.gamma, "Loop shape.");
      prm.add_parameter("n", h.n, "Sharpness of the yield transition (>= 1).");
      prm.add_parameter("delta A", h.delta_A, "Baber-Noori strength degradation of A.");
      prm.add_parameter("delta nu", h.delta_nu, "Baber-Noori strength degradation (nu).");
      prm.add_parameter("delta eta", h.delta_eta, "Baber-Noori stiffness degradation (eta).");
      prm.leave_subsection();
      prm.enter_subsection("Damping");
      prm.add_parameter("Type", b.damping_type,
                        "Rayleigh damping C = a0 M + a1 K of this building: from a damping "
                        "ratio at two modes, from given coefficients, or none.",
                        Patterns::Selection("none|modes|coefficients"));
      prm.add_parameter("Damping ratio", b.damping_ratio, "Damping ratio at both modes.");
      prm.add_parameter("Modes", b.damping_modes,
                        "The two modes (1-based) of this building that get the ratio.");
      prm.add_parameter("a0", b.rayleigh_a0, "Mass-proportional coefficient, 1/s.");
      prm.add_parameter("a1", b.rayleigh_a1, "Stiffness-proportional coefficient, s.");
      prm.leave_subsection();
    }

    void
    declare_ground_motion(ParameterHandler &prm, GroundMotionParameters &g)
    {
      prm.enter_subsection("Ground motion");
      prm.add_parameter("Type", g.type,
                        "Horizontal ground acceleration: a generated Kanai-Tajimi or "
                        "Clough-Penzien sample, plain white noise (intensity S0 or D, held "
                        "over the sample interval), a record, or none.",
                        Patterns::Selection("kanai-tajimi|clough-penzien|white-noise|record|none"));
      prm.add_parameter("Scale factor", g.scale_factor, "Multiplies the motion.");
      prm.enter_subsection("Record");
      prm.add_parameter("File", g.record_file,
                        "PEER .AT2, or text with one (acceleration) or two (time, "
                        "acceleration) columns; relative to this parameter file.");
      prm.add_parameter("Format", g.record_format, "", Patterns::Selection("auto|at2|text"));
      prm.add_parameter("Units", g.record_units, "Units of the values in the file.",
                        Patterns::Selection("g|m/s^2"));
      prm.add_parameter("Time step", g.record_time_step,
                        "Sample interval of a one-column text record, s.");
      prm.add_parameter("Target PGA", g.record_target_pga,
                        "Scale the record to this PGA in g (0: keep it).");
      prm.leave_subsection();
      prm.enter_subsection("Stochastic");
      prm.add_parameter("Soil", g.soil,
                        "Filter parameters preset (Der Kiureghian & Neuenhofer 1992): firm "
                        "15 rad/s, 0.6; medium 10, 0.4; soft 5, 0.2; custom uses omega_g, "
                        "zeta_g. Clough-Penzien presets use omega_f = omega_g/10, zeta_f 0.6.",
                        Patterns::Selection("firm|medium|soft|custom"));
      prm.add_parameter("omega_g", g.omega_g, "Ground filter frequency, rad/s (custom).");
      prm.add_parameter("zeta_g", g.zeta_g, "Ground filter damping ratio (custom).");
      prm.add_parameter("omega_f", g.omega_f, "Clough-Penzien high-pass frequency, rad/s (custom).");
      prm.add_parameter("zeta_f", g.zeta_f, "Clough-Penzien high-pass damping (custom).");
      prm.add_parameter("Method", g.method,
                        "Kanai-Tajimi/Clough-Penzien samples: white noise through the filter "
                        "(exact over each held interval), or the spectral representation "
                        "(sum of cosines with random phases).",
                        Patterns::Selection("filtered-white-noise|spectral-representation"));
      prm.add_parameter("Cutoff frequency", g.cutoff_frequency,
                        "Spectral representation: upper frequency w_u, rad/s (0: min(pi/dt, "
                        "25 omega_g)); needs dt <= pi/w_u.");
      prm.add_parameter("Number of frequencies", g.n_frequencies,
                        "Spectral representation: N (0: w_u duration / pi, so the sample "
                        "does not repeat within twice its duration).");
      prm.add_parameter("S0", g.spectral_intensity,
                        "Two-sided PSD intensity of the white noise, m^2/s^3; 0: from D, or "
                        "from the target PGA and peak factor.");
      prm.add_parameter("D", g.noise_intensity_d,
                        "White-noise intensity in the thesis's convention <w(t) w(t')> = "
                        "2 D delta(t - t'), D = pi S0 (used when S0 = 0).");
      prm.add_parameter("Target PGA", g.target_pga, "Target PGA in g (used when S0 = 0).");
      prm.add_parameter("Peak factor", g.peak_factor, "PGA / standard deviation.");
      prm.add_parameter("Duration", g.duration, "Length of the sample, s.");
      prm.add_parameter("Sample interval", g.sample_interval,
                        "White-noise sample interval, s (0: the analysis time step).");
      prm.add_parameter("Seed", g.seed, "Random seed.");
      prm.add_parameter("Realization", g.realization,
                        "Realization index: (seed, index) fixes the sample.");
      prm.add_parameter("Envelope", g.envelope, "Amplitude modulation.",
                        Patterns::Selection("none|jennings|saragoni-hart|shinozuka-sato"));
      prm.add_parameter("Rise end", g.jennings_rise_end, "Jennings: end of (t/t1)^2 rise, s.");
      prm.add_parameter("Plateau end", g.jennings_plateau_end, "Jennings: end of plateau, s.");
      prm.add_parameter("Decay rate", g.jennings_decay, "Jennings: exp(-c (t - t2)) rate, 1/s.");
      prm.add_parameter("Saragoni b", g.saragoni_b, "Saragoni-Hart t^b e^(-ct): b.");
      prm.add_parameter("Saragoni c", g.saragoni_c, "Saragoni-Hart t^b e^(-ct): c, 1/s.");
      prm.add_parameter("Shinozuka alpha", g.shinozuka_alpha, "e^(-at)-e^(-bt): a, 1/s.");
      prm.add_parameter("Shinozuka beta", g.shinozuka_beta, "e^(-at)-e^(-bt): b, 1/s.");
      prm.leave_subsection();
      prm.leave_subsection();
    }

    void
    declare_all(ParameterHandler &prm, InputParameters &p)
    {
      prm.enter_subsection("Model");
      unsigned int n_buildings = p.buildings.size();
      prm.add_parameter("Number of buildings", n_buildings,
                        "Buildings side by side, left to right; each has a subsection "
                        "'Building <i>'.", Patterns::Integer(1, 100));
      prm.add_parameter("Mass matrix", p.mass_matrix,
                        "Distributed member mass: lumped or consistent.",
                        Patterns::Selection("lumped|consistent"));
      prm.add_parameter("Separations", p.separations,
                        "Clear distance in m between building i and i+1 (one value for "
                        "all pairs or one per pair).");
      prm.leave_subsection();
      for (unsigned int b = 0; b < p.buildings.size(); ++b)
        {
          prm.enter_subsection("Building " + std::to_string(b + 1));
          declare_building(prm, p.buildings[b]);
          prm.leave_subsection();
        }
      declare_ground_motion(prm, p.ground_motion);
      prm.enter_subsection("Contact");
      ContactParameters &k = p.contact;
      {
        // every registered law (laws/contact_law.h)
        std::string names = "none", laws;
        for (const std::string &name : contact_law_names())
          {
            names += "|" + name;
            laws += ", " + name + " (" + contact_law_type(name).formula + ")";
          }
        prm.add_parameter("Law", k.law,
                          "Gap elements between neighbouring buildings (and at barriers): "
                          "none" + laws + ".",
                          Patterns::Selection(names));
      }
      prm.add_parameter("Stiffness", k.stiffness,
                        "k in N/m (linear laws) or k_h, beta in N/m^1.5 (Hertz laws, "
                        "Jankowski; concrete ~2.75e9).");
      prm.add_parameter("Damping from", k.damping_from,
                        "given: the value of Damping; formula: the law's literature formula "
                        "from the coefficient of restitution; calibrated: the value for "
                        "which one impact of the effective mass on a rigid wall returns "
                        "exactly that coefficient.",
                        Patterns::Selection("given|formula|calibrated"));
      prm.add_parameter("Damping", k.damping,
                        "xi (Kelvin-Voigt laws, Jankowski) or xi_bar (Hertz-damp) when given.");
      prm.add_parameter("Coefficient of restitution", k.restitution,
                        "e in (0, 1]; concrete ~0.65.");
      prm.add_parameter("Hertz-damp formula", k.hertz_damp_formula,
                        "xi_bar from e: 3(1 - e^2)/4 (Muthukumar & DesRoches) or "
                        "8(1 - e)/(5e) (Ye, Li & Zhu).",
                        Patterns::Selection("muthukumar-desroches|ye-li-zhu"));
      prm.add_parameter("Effective mass", k.effective_mass,
                        "m_e in kg; 0: m1 m2/(m1 + m2) of the colliding floor masses (the "
                        "floor mass against a barrier).");
      prm.add_parameter("Calibration velocity", k.calibration_velocity,
                        "Approach velocity of the calibration impact, m/s.");
      prm.add_parameter("Between buildings", k.between_buildings,
                        "Gap elements between neighbouring buildings at every floor level "
                        "the lower one has (initial gap: Model/Separations).");
      prm.add_parameter("Floor to column", k.floor_to_column,
                        "Where a floor of one building has no floor of its neighbour at "
                        "the same level, the contact point is on the neighbour's facing "
                        "column at that height (frames).");
      prm.add_parameter("Barriers", k.barriers,
                        "Rigid barriers 'building floor side gap' separated by ';': the "
                        "floor's facing joint touches a barrier on the left or right side "
                        "once it has moved by gap (m) towards it.",
                        Patterns::List(Patterns::Anything(), 0, 1000, ";"));
      prm.add_parameter("Event refinement", k.event_refinement,
                        "A step in which a contact starts or ends is redone in 2^r "
                        "sub-steps around the event, which is then located inside the "
                        "sub-step by interpolation.", Patterns::Integer(0, 12));
      prm.leave_subsection();
      prm.enter_subsection("Nodal forces");
      prm.add_parameter("Harmonic", p.harmonic_forces,
                        "Harmonic forces 'building floor node dof amplitude omega phase', "
                        "separated by ';'. floor 0 is the base, node counts from the left "
                        "(0-based), dof ux|uy|rz, amplitude in N (N m), omega in rad/s.",
                        Patterns::List(Patterns::Anything(), 0, 1000, ";"));
      prm.add_parameter("Tabulated", p.tabulated_forces,
                        "Tabulated forces 'building floor node dof file' separated by ';'; "
                        "the file has two columns: time, force (linear in between, zero "
                        "outside).",
                        Patterns::List(Patterns::Anything(), 0, 1000, ";"));
      prm.add_parameter("White noise", p.white_noise_forces,
                        "Random forces 'building floor node dof S0' separated by ';': white "
                        "noise of two-sided intensity S0 (N^2 s), held over the sample "
                        "interval of Ground motion/Stochastic; part of each realization.",
                        Patterns::List(Patterns::Anything(), 0, 1000, ";"));
      prm.leave_subsection();
      prm.enter_subsection("Time integration");
      prm.add_parameter("Time step", p.time_step, "Analysis time step, s.");
      prm.add_parameter("End time", p.end_time, "0: the length of the ground motion.");
      prm.add_parameter("Newmark gamma", p.newmark_gamma, "");
      prm.add_parameter("Newmark beta", p.newmark_beta, "");
      prm.add_parameter("Linear solver", p.linear_solver,
                        "Direct solver of the effective matrix (factorised once).",
                        Patterns::Selection("eigen-ldlt|umfpack|petsc|trilinos"));
      prm.add_parameter("Newton residual tolerance", p.newton_residual_tolerance,
                        "A nonlinear step has converged when the residual norm is below this "
                        "times the norm of the effective load ...");
      prm.add_parameter("Newton energy tolerance", p.newton_energy_tolerance,
                        "... and the work of the residual on the last correction is below "
                        "this times that of the first iteration.");
      prm.add_parameter("Newton maximum iterations", p.newton_max_iterations,
                        "Iterations before the step is cut.", Patterns::Integer(1, 1000));
      prm.add_parameter("Maximum step cuts", p.max_step_cuts,
                        "A step that fails is halved and retried, down to Time step / "
                        "2^cuts; then the run stops (exit 2).", Patterns::Integer(0, 40));
      prm.add_parameter("Tangent update", p.tangent_update,
                        "How the tangent of nonlinear elements enters the solve: woodbury "
                        "keeps the one factorisation of the linear part and adds a dense "
                        "correction of rank = the elements' total rank (one per uniaxial "
                        "element); refactorize refactorises every iteration; auto picks "
                        "woodbury up to a total rank of 100.",
                        Patterns::Selection("auto|woodbury|refactorize"));
      prm.add_parameter("Hysteresis integration", p.hysteresis_integration,
                        "Bouc-Wen z over a step: trapezoidal (second order) or "
                        "backward-euler (first order, most robust).",
                        Patterns::Selection("trapezoidal|backward-euler"));
      prm.add_parameter("Law tolerance", p.law_tolerance,
                        "Tolerance of the local Newton iteration of a law (on z).");
      prm.add_parameter("Law maximum iterations", p.law_max_iterations,
                        "Local iterations before the law reports failure.",
                        Patterns::Integer(1, 1000));
      prm.leave_subsection();
      prm.enter_subsection("Output");
      prm.add_parameter("Directory", p.output_directory,
                        "Results directory (relative to the working directory).");
      prm.add_parameter("Output interval", p.output_interval,
                        "Interval of CSV rows, s (0: every step).");
      prm.add_parameter("VTU interval", p.vtu_interval,
                        "Interval of VTU frames, s (0: none).");
      prm.add_parameter("Plots", p.plots, "Make PNG plots with gnuplot.");
      prm.add_parameter("Number of modes", p.n_modes, "Modes reported.", Patterns::Integer(1));
      prm.enter_subsection("Recorders");
      p.recorders.declare(prm);
      prm.leave_subsection();
      prm.leave_subsection();

      prm.enter_subsection("Monte Carlo");
      MonteCarloParameters &mc = p.monte_carlo;
      prm.add_parameter("Realizations", mc.realizations,
                        "Number of realizations (seed and index 0..N-1 fix each one).",
                        Patterns::Integer(1));
      prm.add_parameter("Drift limits", mc.drift_limits,
                        "Inter-storey drift ratios whose exceedance probability is reported "
                        "(largest over every storey of every building).",
                        Patterns::List(Patterns::Double(0), 0, 100, ","));
      prm.add_parameter("Histogram bins", mc.histogram_bins, "Bins of the PDF estimates.",
                        Patterns::Integer(2, 1000));
      prm.leave_subsection();

      prm.enter_subsection("Subset simulation");
      SubsetParameters &ss = p.subset;
      prm.add_parameter("Response", ss.response, "The response whose exceedance is estimated.",
                        Patterns::Selection(
                          "peak drift ratio|peak roof displacement|peak contact force"));
      prm.add_parameter("Building", ss.building, "Building of the response (1-based).",
                        Patterns::Integer(1));
      prm.add_parameter("Storey", ss.storey,
                        "Storey of the drift ratio (1-based; 0: largest over the storeys).",
                        Patterns::Integer(0));
      prm.add_parameter("Threshold", ss.threshold,
                        "Failure: response > threshold (drift ratio, m, or N).");
      prm.add_parameter("Samples per level", ss.samples_per_level, "N.", Patterns::Integer(2));
      prm.add_parameter("Conditional probability", ss.conditional_probability,
                        "p0: the level thresholds are the (1 - p0) quantiles; p0 N and 1/p0 "
                        "must be whole numbers.");
      prm.add_parameter("Maximum levels", ss.max_levels, "Stop after this many levels.",
                        Patterns::Integer(1, 100));
      prm.add_parameter("Proposal spread", ss.proposal_spread,
                        "Standard deviation of the component-wise Gaussian proposal of the "
                        "modified Metropolis algorithm.");
      prm.leave_subsection();

      prm.enter_subsection("Fragility");
      FragilityParameters &fr = p.fragility;
      prm.add_parameter("PGA levels", fr.pga_levels,
                        "Intensity levels: target PGA in g (S0 from the PGA and peak factor).",
                        Patterns::List(Patterns::Double(0), 1, 1000, ","));
      prm.add_parameter("Realizations per level", fr.realizations_per_level,
                        "Monte Carlo realizations at each level (the same seeds at every level).",
                        Patterns::Integer(1));
      prm.leave_subsection();
    }

    std::string
    collapse_whitespace(const std::string &text)
    {
      std::string out;
      bool        space = false;
      for (const char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += c;
            space = false;
          }
      return out;
    }

    /// deal.II's messages carry "Line <n> of file <f>": turn them into ours.
    [[noreturn]] void
    rethrow_parse_error(const std::string &file, const dealii::ExceptionBase &e)
    {
      std::ostringstream info;
      e.print_info(info);
      std::string text = collapse_whitespace(info.str());
      int         line = 0;
      std::smatch match;
      static const std::regex where("Line <([0-9]+)> of file <[^>]*>:? ?");
      if (std::regex_search(text, match, where))
        {
          line = std::stoi(match[1]);
          text = match.prefix().str() + match.suffix().str();
        }
      if (text.empty())
        text = collapse_whitespace(e.what());
      throw InputError(file, line, "", text);
    }

    void
    index_lines(InputParameters &p)
    {
      std::ifstream            in(p.file);
      std::string              line;
      std::vector<std::string> sections;
      static const std::regex  subsection("^\\s*subsection\\s+(.*?)\\s*$");
      static const std::regex  end("^\\s*end\\s*$");
      static const std::regex  set("^\\s*set\\s+(.*?)\\s*=.*$");
      for (int number = 1; std::getline(in, line); ++number)
        {
          const auto hash = line.find('#');
          if (hash != std::string::npos)
            line.erase(hash);
          std::smatch m;
          if (std::regex_match(line, m, subsection))
            sections.push_back(m[1]);
          else if (std::regex_match(line, end) && !sections.empty())
            sections.pop_back();
          else if (std::regex_match(line, m, set))
            {
              std::string path;
              for (const auto &s : sections)
                path += s + "/";
              p.lines[path + m[1].str()] = number;
            }
        }
    }

    void
    parse(ParameterHandler &prm, const std::string &file, const bool skip_undefined)
    {
      try
        {
          prm.parse_input(file, "", skip_undefined);
        }
      catch (const dealii::ExceptionBase &e)
        {
          rethrow_parse_error(file, e);
        }
    }

    // --- checks of values that no Pattern expresses ---

    struct Checker
    {
      const InputParameters &p;

      [[noreturn]] void
      fail(const std::string &path, const std::string &problem) const
      {
        throw InputError(p.file, p.line_of(path), path, problem);
      }
      void
      positive(const std::string &path, const double v) const
      {
        if (!(v > 0) || !std::isfinite(v))
          fail(path, "must be positive and finite, got " + std::to_string(v));
      }
      void
      non_negative(const std::string &path, const double v) const
      {
        if (!(v >= 0) || !std::isfinite(v))
          fail(path, "must be zero or positive, got " + std::to_string(v));
      }
      template <typename T>
      void
      list(const std::string &path, const std::vector<T> &values, const std::size_t n,
           const bool allow_zero, const std::string &what) const
      {
        if (values.size() != 1 && values.size() != n)
          fail(path, "needs 1 value or " + std::to_string(n) + " (" + what + "), got " +
                       std::to_string(values.size()));
        for (const T v : values)
          allow_zero ? non_negative(path, v) : positive(path, v);
      }
    };

    void
    check(const InputParameters &p)
    {
      const Checker c{p};
      for (unsigned int i = 0; i < p.buildings.size(); ++i)
        {
          const BuildingParameters &b = p.buildings[i];
          const std::string         s = "Building " + std::to_string(i + 1) + "/";
          const unsigned int        n = b.n_storeys;
          if (b.type == "frame" || b.type == "shear")
            {
              c.list(s + "Storey heights", b.storey_heights, n, false, "one per storey");
              c.list(s + "Floor masses", b.floor_masses, n, false, "one per floor");
            }
          if (b.type == "frame")
            {
              c.list(s + "Bay widths", b.bay_widths, b.n_bays, false, "one per bay");
              c.list(s + "Column E", b.column_youngs_modulus, n, false, "one per storey");
              c.list(s + "Column A", b.column_area, n, false, "one per storey");
              c.list(s + "Column I", b.column_second_moment, n, false, "one per storey");
              c.list(s + "Beam E", b.beam_youngs_modulus, n, false, "one per floor");
              c.list(s + "Beam A", b.beam_area, n, false, "one per floor");
              c.list(s + "Beam I", b.beam_second_moment, n, false, "one per floor");
              c.list(s + "Column mass per length", b.column_mass_per_length, n, true,
                     "one per storey");
              c.list(s + "Beam mass per length", b.beam_mass_per_length, n, true,
                     "one per floor");
            }
          if (b.type == "shear")
            {
              c.list(s + "Storey stiffnesses", b.storey_stiffnesses, n, false, "one per storey");
              c.list(s + "Storey damping", b.storey_damping, n, true, "one per storey");
              c.non_negative(s + "Drawing width", b.drawing_width);
            }
          if (b.type == "mesh")
            {
              if (b.mesh_file.empty())
                c.fail(s + "Mesh file", "a mesh building needs a mesh file");
              const std::size_t g = b.group_ids.size();
              c.list(s + "Group E", b.group_youngs_modulus, g, false, "one per group id");
              c.list(s + "Group A", b.group_area, g, false, "one per group id");
              c.list(s + "Group I", b.group_second_moment, g, false, "one per group id");
              c.list(s + "Group mass per length", b.group_mass_per_length, g, true,
                     "one per group id");
              for (const double m : b.floor_masses)
                c.non_negative(s + "Floor masses", m);
            }
          const std::size_t n_groups = std::max<std::size_t>(1, b.hinge_groups.size());
          if (b.type != "shear" && !b.hinge_locations.empty())
            {
              c.list(s + "Hinges/Yield moment", b.hinge_yield_moments, n_groups, true,
                     "one per hinge group");
              c.list(s + "Hinges/Yield rotation", b.hinge_yield_rotations, n_groups, true,
                     "one per hinge group");
              c.list(s + "Hinges/Stiffness", b.hinge_stiffnesses, n_groups, true,
                     "one per hinge group");
              c.positive(s + "Hinges/Stiffness factor", b.hinge_stiffness_factor);
              for (std::size_t g = 0; g < n_groups; ++g)
                if (b.hinge_yield_moments[b.hinge_yield_moments.size() == 1 ? 0 : g] == 0 &&
                    b.hinge_yield_rotations[b.hinge_yield_rotations.size() == 1 ? 0 : g] == 0)
                  c.fail(s + "Hinges/Yield moment",
                         "hinges need a yield moment or a yield rotation (both are 0)");
            }
          if (b.type == "shear" && !b.storey_yield_drifts.empty())
            c.list(s + "Storey yield drifts", b.storey_yield_drifts, n, true, "one per storey");
          const bool hysteretic = (b.type != "shear" && !b.hinge_locations.empty()) ||
                                  (b.type == "shear" && !b.storey_yield_drifts.empty());
          if (hysteretic)
            {
              const BoucWenParameters &h  = b.hysteresis;
              const std::string        bw = s + "Bouc-Wen/";
              if (!(h.alpha >= 0 && h.alpha <= 1))
                c.fail(bw + "alpha", "must lie in [0, 1], got " + std::to_string(h.alpha));
              c.positive(bw + "A", h.A);
              if (!(h.n >= 1) || !std::isfinite(h.n))
                c.fail(bw + "n", "must be >= 1, got " + std::to_string(h.n));
              if (!(h.beta + h.gamma > 0))
                c.fail(bw + "beta", "beta + gamma must be positive (|z| stays bounded)");
              if (!(h.beta >= std::abs(h.gamma)) && !(h.gamma >= std::abs(h.beta)))
                c.fail(bw + "gamma", "needs beta >= |gamma| or gamma >= |beta|");
              c.non_negative(bw + "delta A", h.delta_A);
              c.non_negative(bw + "delta nu", h.delta_nu);
              c.non_negative(bw + "delta eta", h.delta_eta);
            }
          if (b.damping_type == "modes")
            {
              if (!(b.damping_ratio >= 0 && b.damping_ratio < 1))
                c.fail(s + "Damping/Damping ratio",
                       "must lie in [0, 1), got " + std::to_string(b.damping_ratio));
              if (b.damping_modes.size() != 2 || b.damping_modes[0] < 1 ||
                  b.damping_modes[1] < 1 || b.damping_modes[0] == b.damping_modes[1])
                c.fail(s + "Damping/Modes", "needs two different mode numbers >= 1");
            }
          if (b.damping_type == "coefficients")
            {
              c.non_negative(s + "Damping/a0", b.rayleigh_a0);
              c.non_negative(s + "Damping/a1", b.rayleigh_a1);
            }
        }
      if (p.buildings.size() > 1)
        c.list("Model/Separations", p.separations, p.buildings.size() - 1, true,
               "one per neighbouring pair");

      const GroundMotionParameters &g = p.ground_motion;
      const std::string             gm = "Ground motion/";
      if (g.type == "record" && g.record_file.empty())
        c.fail(gm + "Record/File", "a record ground motion needs a file");
      c.non_negative(gm + "Record/Time step", g.record_time_step);
      c.non_negative(gm + "Record/Target PGA", g.record_target_pga);
      if (!std::isfinite(g.scale_factor))
        c.fail(gm + "Scale factor", "must be finite");
      if (g.type == "white-noise" && !(g.spectral_intensity > 0 || g.noise_intensity_d > 0))
        c.fail(gm + "Stochastic/S0", "white noise needs S0 > 0 or D > 0 (it has no finite PGA)");
      if (g.type == "kanai-tajimi" || g.type == "clough-penzien" || g.type == "white-noise")
        {
          const std::string st = gm + "Stochastic/";
          c.non_negative(st + "D", g.noise_intensity_d);
          c.non_negative(st + "Cutoff frequency", g.cutoff_frequency);
          const double dt = stochastic_sample_interval(p);
          if (g.method == "spectral-representation" && g.cutoff_frequency * dt > M_PI)
            c.fail(st + "Cutoff frequency",
                   "exceeds pi / sample interval = " + std::to_string(M_PI / dt) + " rad/s");
          c.positive(st + "omega_g", g.omega_g);
          if (!(g.zeta_g > 0 && g.zeta_g < 1))
            c.fail(st + "zeta_g", "must lie in (0, 1)");
          c.positive(st + "omega_f", g.omega_f);
          if (!(g.zeta_f > 0 && g.zeta_f < 1))
            c.fail(st + "zeta_f", "must lie in (0, 1)");
          c.non_negative(st + "S0", g.spectral_intensity);
          c.non_negative(st + "Target PGA", g.target_pga);
          c.positive(st + "Peak factor", g.peak_factor);
          c.positive(st + "Duration", g.duration);
          c.non_negative(st + "Sample interval", g.sample_interval);
          c.positive(st + "Rise end", g.jennings_rise_end);
          if (g.jennings_plateau_end < g.jennings_rise_end)
            c.fail(st + "Plateau end", "must not be before the rise end");
          c.non_negative(st + "Decay rate", g.jennings_decay);
          c.positive(st + "Saragoni b", g.saragoni_b);
          c.positive(st + "Saragoni c", g.saragoni_c);
          c.positive(st + "Shinozuka alpha", g.shinozuka_alpha);
          if (!(g.shinozuka_beta > g.shinozuka_alpha))
            c.fail(st + "Shinozuka beta", "must exceed Shinozuka alpha");
        }
      c.positive("Time integration/Time step", p.time_step);
      c.non_negative("Time integration/End time", p.end_time);
      if (!(p.newmark_gamma >= 0.5))
        c.fail("Time integration/Newmark gamma", "must be >= 1/2 for stability");
      if (!(p.newmark_beta >= 0.25 * (0.5 + p.newmark_gamma) * (0.5 + p.newmark_gamma) - 1e-12))
        c.fail("Time integration/Newmark beta",
               "must be >= (1/2 + gamma)^2 / 4 for unconditional stability");
      if (p.contact.law != "none")
        {
          const ContactParameters &k = p.contact;
          c.positive("Contact/Stiffness", k.stiffness);
          if (!(k.restitution > 0 && k.restitution <= 1))
            c.fail("Contact/Coefficient of restitution",
                   "must lie in (0, 1], got " + std::to_string(k.restitution));
          c.non_negative("Contact/Damping", k.damping);
          c.non_negative("Contact/Effective mass", k.effective_mass);
          c.positive("Contact/Calibration velocity", k.calibration_velocity);
        }
      c.positive("Time integration/Newton residual tolerance", p.newton_residual_tolerance);
      c.positive("Time integration/Newton energy tolerance", p.newton_energy_tolerance);
      c.positive("Time integration/Law tolerance", p.law_tolerance);
      for (const double limit : p.monte_carlo.drift_limits)
        if (!(limit > 0))
          c.fail("Monte Carlo/Drift limits", "every limit must be positive");
      {
        const SubsetParameters &ss = p.subset;
        const std::string       sp = "Subset simulation/";
        c.positive(sp + "Threshold", ss.threshold);
        c.positive(sp + "Proposal spread", ss.proposal_spread);
        const double p0 = ss.conditional_probability;
        if (!(p0 > 0 && p0 < 1))
          c.fail(sp + "Conditional probability", "must lie in (0, 1)");
        const double n_seeds = p0 * ss.samples_per_level, chain = 1 / p0;
        if (std::abs(n_seeds - std::round(n_seeds)) > 1e-9 * n_seeds ||
            std::abs(chain - std::round(chain)) > 1e-9 * chain || std::round(n_seeds) < 1)
          c.fail(sp + "Conditional probability",
                 "p0 N and 1/p0 must be whole numbers (N = " +
                   std::to_string(ss.samples_per_level) + ")");
        if (ss.building > p.buildings.size())
          c.fail(sp + "Building", "there are " + std::to_string(p.buildings.size()) + " buildings");
        else if (ss.storey > p.buildings[ss.building - 1].n_storeys &&
                 p.buildings[ss.building - 1].type != "mesh")
          c.fail(sp + "Storey", "building " + std::to_string(ss.building) + " has " +
                                  std::to_string(p.buildings[ss.building - 1].n_storeys) +
                                  " storeys");
      }
      for (const double pga : p.fragility.pga_levels)
        if (!(pga > 0))
          c.fail("Fragility/PGA levels", "every level must be positive");
      c.non_negative("Output/Output interval", p.output_interval);
      c.non_negative("Output/VTU interval", p.vtu_interval);
      if (p.output_directory.empty())
        c.fail("Output/Directory", "must not be empty");
    }
  } // namespace

  double
  stochastic_sample_interval(const InputParameters &input)
  {
    return input.ground_motion.sample_interval > 0 ? input.ground_motion.sample_interval :
                                                     input.time_step;
  }

  int
  InputParameters::line_of(const std::string &path) const
  {
    const auto it = lines.find(path);
    return it == lines.end() ? 0 : it->second;
  }

  std::string
  InputParameters::resolve(const std::string &relative) const
  {
    const std::filesystem::path path(relative);
    if (path.is_absolute() || directory.empty())
      return relative;
    return (std::filesystem::path(directory) / path).lexically_normal().string();
  }

  InputParameters
  read_parameters(const std::string &file)
  {
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(file, 0, "", "cannot open the parameter file");
    }
    const std::string extension = std::filesystem::path(file).extension().string();
    if (extension != ".prm" && extension != ".json")
      throw InputError(file, 0, "", "parameter files end in .prm or .json");

    InputParameters p;
    p.file      = file;
    p.directory = std::filesystem::path(file).parent_path().string();
    if (extension == ".prm")
      index_lines(p);

    // First pass: only the number of buildings, which shapes the declarations.
    unsigned int n_buildings = 1;
    {
      ParameterHandler prm;
      prm.enter_subsection("Model");
      prm.add_parameter("Number of buildings", n_buildings, "", Patterns::Integer(1, 100));
      prm.leave_subsection();
      parse(prm, file, true);
    }
    p.buildings.resize(n_buildings);
    ParameterHandler prm;
    declare_all(prm, p);
    parse(prm, file, false);
    for (unsigned int b = 0; b < p.buildings.size(); ++b)
      {
        BuildingParameters &building = p.buildings[b];
        if (building.name.empty())
          building.name = "B" + std::to_string(b + 1);
        building.hysteresis.theta = p.hysteresis_integration == "trapezoidal" ? 0.5 : 1.0;
        building.hysteresis.tolerance      = p.law_tolerance;
        building.hysteresis.max_iterations = p.law_max_iterations;
      }
    p.recorders.finalize(file, p.line_of("Output/Recorders/Record"), p.output_interval);
    check(p);
    return p;
  }

  void
  print_parameters(std::ostream &out)
  {
    InputParameters p;
    p.buildings.resize(1);
    ParameterHandler prm;
    declare_all(prm, p);
    out << "# poundfe parameters. 'Building 1' stands for every 'Building <i>',\n"
        << "# i = 1 .. Number of buildings. Lists are comma separated.\n";
    prm.print_parameters(out, ParameterHandler::PRM);
  }
} // namespace poundfe
