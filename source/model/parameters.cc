#include <poundfe/base/numbers.h>
#include <poundfe/laws/bouc_wen_bounds.h>
#include <poundfe/model/entry_scope.h>
#include <poundfe/model/member_rigidities.h>
#include <poundfe/model/parameters.h>
#include <poundfe/model/section_shorthands.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

namespace poundfe
{
  namespace Patterns = dealii::Patterns;

  namespace
  {
    const char *const number_of_buildings_text =
      "Buildings side by side, left to right; each has a subsection 'Building <i>'. Unit: count.";

    /// The bidirectional law (Park, Wen & Ang 1986) is published for n = 2
    /// without degradation; its |z|^(n-2) extension needs n >= 2.
    void
    check_bidirectional_bouc_wen(const InputFile &input, const std::string &bw,
                                 const BoucWenParameters &h)
    {
      const std::string why = " (Plan/Storey law or Hinges/Biaxial interaction is bidirectional)";
      if (!(h.n >= 2))
        input.fail(bw + "n", "the bidirectional Bouc-Wen law needs n >= 2, got " +
                               number_text(h.n) + why);
      using Entry = std::pair<const char *, double>;
      for (const Entry &entry : {Entry{"delta A", h.delta_A}, Entry{"delta nu", h.delta_nu},
                                 Entry{"delta eta", h.delta_eta}})
        if (const auto &[name, value] = entry; value != 0)
          input.fail(bw + name, "the bidirectional Bouc-Wen law has no degradation: must be 0" +
                                  why);
    }

    /// Counts beyond any building: the model of a billion storeys would ask
    /// for more memory than a machine has, long after the file was read.
    constexpr unsigned int largest_storey_count = 100000;
    constexpr unsigned int largest_bay_count    = 10000;

    /// A floor load beyond any floor: 1e10 N is a million tonnes' weight,
    /// more than the heaviest building weighs in all (about 5e9 N). A load
    /// far beyond it (1e200 N) passed the input and failed only in the
    /// gravity analysis, as a numerical failure (exit 2).
    constexpr double largest_floor_load = 1e10;
    constexpr const char *largest_floor_load_why = "a million tonnes' weight on one floor";

    /// The counts of a generated frame or a shear building, before the
    /// lists are sized by them.
    void
    check_building_sizes(const InputFile &input, const std::string &s,
                         const BuildingParameters &p)
    {
      if (p.n_storeys > largest_storey_count)
        input.fail(s + "Number of storeys",
                   "got " + std::to_string(p.n_storeys) + ", at most " +
                     std::to_string(largest_storey_count) +
                     " (beyond any building; the model would not fit in memory)");
      if (p.type == BuildingType::frame && p.n_bays > largest_bay_count)
        input.fail(s + "Number of bays", "got " + std::to_string(p.n_bays) + ", at most " +
                                           std::to_string(largest_bay_count) +
                                           " (beyond any building; the model would not fit "
                                           "in memory)");
    }

    /// The lengths of a generated frame or a shear building, once each is
    /// known to be positive.
    void
    check_building_lengths(const InputFile &input, const std::string &s,
                           const BuildingParameters &p)
    {
      const std::string why = "10 km is beyond any building";
      for (const double h : p.storey_heights)
        input.at_most(s + "Storey heights", h, largest_building_length, "m", why);
      if (p.type == BuildingType::frame)
        for (const double w : p.bay_widths)
          input.at_most(s + "Bay widths", w, largest_building_length, "m", why);
    }
  } // namespace

  void
  check_member_rigidities(const InputFile &input, const std::string &section,
                          const std::string &member, const std::vector<double> &E,
                          const std::vector<double> &A, const std::vector<double> &I)
  {
    const auto at = [](const std::vector<double> &v, const std::size_t i) {
      return v[std::min(i, v.size() - 1)];
    };
    const std::size_t n = std::max({E.size(), A.size(), I.size()});
    if (E.empty() || A.empty() || I.empty())
      return;
    for (std::size_t i = 0; i < n; ++i)
      for (const auto &[name, value, unit] :
           {std::tuple<const char *, double, const char *>{" A", at(A, i), "N"},
            {" I", at(I, i), "N m^2"}})
        if (at(E, i) * value > largest_model_value)
          input.fail(section + member + name,
                     "gives the " + std::string(member == "Column" ? "columns'" : "beams'") +
                       " rigidity E" + (name + 1) + " = " + number_text(at(E, i) * value) +
                       " " + unit + ", beyond " + number_text(largest_model_value) +
                       " (no structure comes near it; the solvers square the stiffnesses)");
  }

  const NameTable<BuildingType> &
  building_type_names()
  {
    static const NameTable<BuildingType> table(
      {{BuildingType::frame, "frame"}, {BuildingType::mesh, "mesh"}, {BuildingType::shear, "shear"}});
    return table;
  }

  const NameTable<BaseFixity> &
  base_fixity_names()
  {
    static const NameTable<BaseFixity> table(
      {{BaseFixity::fixed, "fixed"}, {BaseFixity::pinned, "pinned"}});
    return table;
  }

  const NameTable<RayleighDamping::Kind> &
  damping_type_names()
  {
    static const NameTable<RayleighDamping::Kind> table(
      {{RayleighDamping::Kind::none, "none"},
       {RayleighDamping::Kind::modes, "modes"},
       {RayleighDamping::Kind::coefficients, "coefficients"},
       {RayleighDamping::Kind::modal, "modal"},
       {RayleighDamping::Kind::bands, "bands"}});
    return table;
  }

  const NameTable<MassMatrixType> &
  mass_matrix_names()
  {
    static const NameTable<MassMatrixType> table(
      {{MassMatrixType::lumped, "lumped"}, {MassMatrixType::consistent, "consistent"}});
    return table;
  }

  const NameTable<GeometricNonlinearity> &
  geometric_nonlinearity_names()
  {
    static const NameTable<GeometricNonlinearity> table(
      {{GeometricNonlinearity::none, "none"}, {GeometricNonlinearity::p_delta, "p-delta"}});
    return table;
  }

  void
  BuildingParameters::declare(dealii::ParameterHandler &prm)
  {
    // Declared (and printed: print_parameters keeps this order) by the kind
    // of building they apply to, each tagged [frame], [shear], [mesh] or a
    // combination; untagged entries apply to every Type.
    prm.add_parameter("Name", name,
                      "Label used in reports, and to name the building in entries that "
                      "take a building (Barriers, Nodal forces, Springs, Friction: its "
                      "number or its Name); default 'B<n>'. Unit: -.");
    add_choice(prm, "Type", type,
               "frame: regular frame generated from storeys and bays; "
               "mesh: frame read from a Gmsh mesh; shear: stick model. The entries "
               "tagged [frame], [shear] or [mesh] apply only to that Type, those tagged "
               "[3D] only with Model/Dimension = 3 ([3D frame], [3D shear], [3D mesh]: "
               "and that Type), those tagged fibre only with Member model = fibre; such "
               "an entry written for a building it does not apply to is refused. Unit: -.",
               building_type_names());
    prm.add_parameter("Floor masses", floor_masses,
                      "Mass of each floor, bottom up (roof last): one value for all or one "
                      "per floor. Frames: lumped in equal shares at the floor's joints; "
                      "shear buildings: the floor mass. Unit: kg.");
    prm.add_parameter("Floor loads", floor_loads,
                      "Vertical loads beyond the floors' weight (dead and live loads "
                      "without mass), bottom up: one value for all or one per floor; empty: "
                      "none. A 2D frame's floor load is shared equally by its joints and "
                      "enters the gravity analysis (Model/Gravity analysis) and the P-Delta "
                      "axial forces; a shear building's adds to the P-Delta compression of "
                      "the storeys below it. At most 1e10 N each (a million tonnes' weight, "
                      "more than the heaviest building's whole weight). Unit: N.");
    declare_frame_entries(prm);
    declare_member_model(prm);
    declare_frame_3d_entries(prm);
    declare_mesh_entries(prm);
    declare_mesh_3d_entries(prm);
    declare_shear_entries(prm);
    declare_hinges(prm);
    declare_bouc_wen(prm);
    declare_damping(prm);
  }

  void
  BuildingParameters::declare_frame_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Number of storeys", n_storeys, "[frame, shear] Storeys. Unit: count.",
                      Patterns::Integer(1));
    prm.add_parameter("Storey heights", storey_heights,
                      "[frame, shear] Storey heights, bottom up: one value for all or one "
                      "per storey. Unit: m.");

    prm.add_parameter("Number of bays", n_bays, "[frame] Bays. Unit: count.",
                      Patterns::Integer(1));
    prm.add_parameter("Bay widths", bay_widths,
                      "[frame] Bay widths, left to right: one value for all or one per bay. "
                      "Unit: m.");
    prm.add_parameter("Column E", column_youngs_modulus,
                      "[frame] Column Young's modulus, one value or one per storey. Unit: Pa.");
    prm.add_parameter("Column A", column_area,
                      "[frame] Column area, one or per storey. Unit: m^2.");
    prm.add_parameter("Column I", column_second_moment,
                      "[frame] Column second moment of area, one or per storey. Unit: m^4.");
    prm.add_parameter("Beam E", beam_youngs_modulus,
                      "[frame] Beam Young's modulus, one or per floor. Unit: Pa.");
    prm.add_parameter("Beam A", beam_area, "[frame] Beam area, one or per floor. Unit: m^2.");
    prm.add_parameter("Beam I", beam_second_moment,
                      "[frame] Beam second moment of area, one or per floor. Unit: m^4.");
    declare_section_shorthands(prm);
    prm.add_parameter("Column mass per length", column_mass_per_length,
                      "[frame] Distributed column mass, one or per storey. Unit: kg/m.");
    prm.add_parameter("Beam mass per length", beam_mass_per_length,
                      "[frame] Distributed beam mass, one or per floor. Unit: kg/m.");
    prm.add_parameter("Elements per member", elements_per_member,
                      "[frame] Frame elements along each column and beam. Unit: count.",
                      Patterns::Integer(1, 64));
    add_choice(prm, "Base fixity", base_fixity,
               "[frame, mesh] Support of the column bases: fixed (clamped) or pinned. "
               "Unit: -.",
               base_fixity_names());
  }

  std::vector<NamedInputFile>
  ModelParameters::input_files() const
  {
    std::vector<NamedInputFile> files;
    for (std::size_t b = 0; b < buildings.size(); ++b)
      if (!buildings[b].mesh_file.empty())
        files.push_back({"Building " + std::to_string(b + 1) + "/Mesh file", "mesh file",
                         buildings[b].mesh_file, ""});
    return files;
  }

  void
  BuildingParameters::declare_mesh_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Mesh file", mesh_file,
                      "[mesh] Gmsh .msh file (line elements; physical ids are member groups), "
                      "relative to this parameter file. Unit: -.");
    // the lists of unsigned entries with explicit ranges: deal.II's pattern
    // for unsigned int has none, and "-1" would be read as 4294967295
    prm.add_parameter("Group ids", group_ids, "[mesh] Mesh member group (physical) ids. Unit: -.",
                      Patterns::List(Patterns::Integer(0)));
    prm.add_parameter("Group E", group_youngs_modulus,
                      "[mesh] Young's modulus per group. Unit: Pa.");
    prm.add_parameter("Group A", group_area, "[mesh] Area per group. Unit: m^2.");
    prm.add_parameter("Group I", group_second_moment,
                      "[mesh] Second moment of area per group (3D: Iy, about the local y "
                      "axis, bending in the local x-z plane). Unit: m^4.");
    prm.add_parameter("Group mass per length", group_mass_per_length,
                      "[mesh] Distributed mass per group. Unit: kg/m.");
  }

  void
  BuildingParameters::declare_shear_entries(dealii::ParameterHandler &prm)
  {
    prm.add_parameter("Storey stiffnesses", storey_stiffnesses,
                      "[shear] Storey stiffness, one or per storey; 0 where only Springs "
                      "hold the floor (the SD or Duffing oscillator). Unit: N/m.");
    prm.add_parameter("Storey damping", storey_damping,
                      "[shear] Storey dashpot, one or per storey (added to the Rayleigh "
                      "damping); at most 1e150, the largest value of a model. Unit: N s/m.");
    prm.add_parameter("Storey yield drifts", storey_yield_drifts,
                      "[shear] Yield drift u_y of a Bouc-Wen storey (force k u_y at yield), "
                      "one value or one per storey; empty or 0: elastic; at most 1e4 m (beyond any "
                      "storey). Unit: m.");
    prm.add_parameter("Drawing width", drawing_width,
                      "[shear] Width used for placement and pictures. Unit: m.");
  }

  void
  BuildingParameters::declare_hinges(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Hinges");
    prm.add_parameter("Locations", hinge_locations,
                      "[frame, mesh] Member ends that get a Bouc-Wen rotational hinge. column "
                      "bases: bottom of the ground-storey columns on clamped supports; "
                      "column tops / column ends: top / both ends of every column; beam "
                      "ends: both ends of every beam. Empty: an elastic frame. Unit: -. "
                      "Allowed: a comma-separated list of column bases, column tops, column "
                      "ends, beam ends.",
                      Patterns::List(Patterns::Selection(
                        "column bases|column tops|column ends|beam ends")));
    prm.add_parameter("Groups", hinge_groups,
                      "[frame, mesh] Member groups that get hinges (empty: all). Generated "
                      "frames: group 2i-1 holds the columns of storey i, group 2i the beams "
                      "of floor i; meshes: the physical ids. Unit: -.",
                      Patterns::List(Patterns::Integer(0)));
    prm.add_parameter("Yield moment", hinge_yield_moments,
                      "[frame, mesh] Yield moment M_y, one value or one per entry of Groups; "
                      "the yield rotation is M_y / k. Unit: N m.");
    prm.add_parameter("Yield rotation", hinge_yield_rotations,
                      "[frame, mesh] Yield rotation, used where the yield moment is 0. "
                      "Unit: rad.");
    prm.add_parameter("Stiffness", hinge_stiffnesses,
                      "[frame, mesh] Elastic rotational stiffness k, one value or one per "
                      "entry of Groups; 0: Stiffness factor x 6 E I / L of the member. "
                      "Unit: N m/rad.");
    prm.add_parameter("Stiffness factor", hinge_stiffness_factor,
                      "[frame, mesh] k = factor x 6 E I / L where Stiffness is 0 (stiff "
                      "hinges keep the elastic frame nearly unchanged; Ibarra & Krawinkler "
                      "use 10). Unit: dimensionless.");
    prm.add_parameter("Biaxial interaction", hinge_biaxial,
                      "[3D frame, mesh] false: the hinges about a member end's two bending axes "
                      "are independent uniaxial Bouc-Wen laws; true: one Park-Wen-Ang "
                      "bidirectional Bouc-Wen law on both rotations (circular yield surface "
                      "in the moments over their yield moments; Bouc-Wen n >= 2, no "
                      "degradation). Unit: -.");
    prm.leave_subsection();
  }

  void
  BuildingParameters::declare_bouc_wen(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Bouc-Wen");
    BoucWenParameters &h = hysteresis;
    prm.add_parameter("alpha", h.alpha,
                      "Of the hinges [frame, mesh] and hysteretic storeys [shear]: post-yield "
                      "to elastic stiffness ratio. Unit: dimensionless.");
    prm.add_parameter("A", h.A,
                      "A0 (1 with beta + gamma = 1 keeps |z| <= 1), in [0.01, 100]: the "
                      "hysteretic part's initial stiffness is A (1 - alpha) k. "
                      "Unit: dimensionless.");
    prm.add_parameter("beta", h.beta,
                      "Loop shape, at most 100 in size; beta + gamma > 0, beta >= |gamma| or "
                      "gamma >= |beta|, and the largest |z|, (A / (beta + gamma))^(1/n), in "
                      "[0.01, 100] (the strength near k u_y). Unit: dimensionless.");
    prm.add_parameter("gamma", h.gamma,
                      "Loop shape, at most 100 in size (see beta). Unit: dimensionless.");
    prm.add_parameter("n", h.n,
                      "Sharpness of the yield transition, in [1, 100] (at 100 the law is "
                      "already bilinear). Unit: dimensionless.");
    prm.add_parameter("delta A", h.delta_A,
                      "Baber-Noori strength degradation of A. Unit: dimensionless.");
    prm.add_parameter("delta nu", h.delta_nu,
                      "Baber-Noori strength degradation (nu). Unit: dimensionless.");
    prm.add_parameter("delta eta", h.delta_eta,
                      "Baber-Noori stiffness degradation (eta). Unit: dimensionless.");
    prm.leave_subsection();
  }

  void
  BuildingParameters::declare_damping(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Damping");
    add_choice(prm, "Type", damping_type,
               "Damping of this building: Rayleigh C = a0 M + a1 K from a damping ratio "
               "at two modes (modes) or from given coefficients (coefficients); modal "
               "C = M Phi diag(2 zeta_i omega_i) Phi^T M over its first modes with a "
               "ratio per mode (modal) or per frequency band (bands); or none. Unit: -.",
               damping_type_names());
    prm.add_parameter("Damping ratio", damping_ratio,
                      "Damping ratio at both modes (Type = modes). Unit: dimensionless.");
    prm.add_parameter("Modes", damping_modes,
                      "The two modes (1-based) of this building that get the ratio (Type = "
                      "modes); two sway modes, not vertical ones. Unit: -.",
                      Patterns::List(Patterns::Integer(0)));
    prm.add_parameter("a0", rayleigh_a0,
                      "Mass-proportional coefficient (Type = coefficients); at most 1e150, as every "
                      "entry of C = a0 M + a1 K. Unit: 1/s.");
    prm.add_parameter("a1", rayleigh_a1,
                      "Stiffness-proportional coefficient (Type = coefficients); at most 1e150, as "
                      "every entry of C = a0 M + a1 K. Unit: s.");
    prm.add_parameter("Modal ratios", modal_damping_ratios,
                      "Damping ratio of modes 1, 2, ... of this building (Type = modal); "
                      "the modes beyond the list are undamped. Unit: dimensionless.");
    prm.add_parameter("Bands", damping_band_entries,
                      "Frequency bands 'low high ratio' (Hz, Hz, dimensionless), ';' between "
                      "them (Type = bands): each of the first Damped modes modes whose "
                      "frequency lies in [low, high) gets the band's ratio, the others none. "
                      "Unit: per field.",
                      dealii::Patterns::List(dealii::Patterns::Anything(), 0, 1000, ";"));
    prm.add_parameter("Damped modes", damped_modes,
                      "How many modes of this building the bands damp (Type = bands). "
                      "Unit: -.",
                      Patterns::Integer(0)); // not "-1" read as 4294967295
    prm.leave_subsection();
    plan.declare(prm);
    foundation.declare(prm);
  }

  namespace
  {
    /// A floor mass or storey stiffness (kg, N/m) is at least this: a
    /// nondimensional model's 1 lies far above it, and below it a value is
    /// no structure but a typing error (1e-300 gave periods of 1e-150 s).
    constexpr double smallest_mass_or_stiffness = 1e-6;
    /// ... and at least this fraction of the building's largest of the
    /// list: below it, a floor or storey adds nothing but ill-conditioning
    /// (the matrices' 16 digits cannot hold both).
    constexpr double smallest_relative_mass_or_stiffness = 1e-8;

    /// Each nonzero value of `values` (a list already checked) within the
    /// two lower bounds above.
    void
    check_lower_bounds(const InputFile &input, const std::string &path,
                       const std::vector<double> &values, const std::string &unit)
    {
      double largest = 0;
      for (const double x : values)
        largest = std::max(largest, std::abs(x));
      const double bound = std::max(smallest_mass_or_stiffness,
                                    smallest_relative_mass_or_stiffness * largest);
      for (const double x : values)
        if (x != 0 && x < bound)
          input.fail(path, "must be at least " + number_text(bound) + " " + unit +
                             " (got " + number_text(x) + "): the larger of " +
                             number_text(smallest_mass_or_stiffness) + " " + unit + " and " +
                             number_text(smallest_relative_mass_or_stiffness) +
                             " of the largest in the list; a smaller one is a typing error, "
                             "not a floor or storey");
    }

    /// The members' lists of a frame, shear or mesh building: one value per
    /// storey, floor, bay or group id.
    void
    finalize_building_members(const InputFile &input, const std::string &s, BuildingParameters &b)
    {
      const unsigned int n = b.n_storeys;
      if (b.type == BuildingType::frame || b.type == BuildingType::shear)
        {
          check_building_sizes(input, s, b);
          input.list(s + "Storey heights", b.storey_heights, n, false, "one per storey");
          input.list(s + "Floor masses", b.floor_masses, n, false, "one per floor");
          check_lower_bounds(input, s + "Floor masses", b.floor_masses, "kg");
          if (!b.floor_loads.empty())
            input.list(s + "Floor loads", b.floor_loads, n, true, "one per floor");
        }
      for (const double q : b.floor_loads)
        input.at_most(s + "Floor loads", q, largest_floor_load, "N", largest_floor_load_why);
      if (b.type == BuildingType::frame)
        {
          input.list(s + "Bay widths", b.bay_widths, b.n_bays, false, "one per bay");
          input.list(s + "Column E", b.column_youngs_modulus, n, false, "one per storey");
          input.list(s + "Column A", b.column_area, n, false, "one per storey");
          input.list(s + "Column I", b.column_second_moment, n, false, "one per storey");
          input.list(s + "Beam E", b.beam_youngs_modulus, n, false, "one per floor");
          input.list(s + "Beam A", b.beam_area, n, false, "one per floor");
          input.list(s + "Beam I", b.beam_second_moment, n, false, "one per floor");
          check_member_rigidities(input, s, "Column", b.column_youngs_modulus, b.column_area,
                                  b.column_second_moment);
          check_member_rigidities(input, s, "Beam", b.beam_youngs_modulus, b.beam_area,
                                  b.beam_second_moment);
          input.list(s + "Column mass per length", b.column_mass_per_length, n, true,
                 "one per storey");
          input.list(s + "Beam mass per length", b.beam_mass_per_length, n, true,
                 "one per floor");
        }
      if (b.type == BuildingType::frame || b.type == BuildingType::shear)
        check_building_lengths(input, s, b);
      if (b.type == BuildingType::shear)
        {
          input.list(s + "Storey stiffnesses", b.storey_stiffnesses, n, true, "one per storey");
          check_lower_bounds(input, s + "Storey stiffnesses", b.storey_stiffnesses, "N/m");
          input.list(s + "Storey damping", b.storey_damping, n, true, "one per storey");
          for (const double c : b.storey_damping) // 1e200 ran with exit 0
            input.at_most(s + "Storey damping", c, largest_model_value, "N s/m",
                          "the largest value of a model");
          input.non_negative(s + "Drawing width", b.drawing_width);
        }
      if (b.type == BuildingType::mesh)
        {
          if (b.mesh_file.empty())
            input.fail(s + "Mesh file", "a mesh building needs a mesh file");
          const std::size_t g = b.group_ids.size();
          input.list(s + "Group E", b.group_youngs_modulus, g, false, "one per group id");
          input.list(s + "Group A", b.group_area, g, false, "one per group id");
          input.list(s + "Group I", b.group_second_moment, g, false, "one per group id");
          input.list(s + "Group mass per length", b.group_mass_per_length, g, true,
                 "one per group id");
          for (const double m : b.floor_masses)
            input.non_negative(s + "Floor masses", m);
          for (const double q : b.floor_loads)
            input.non_negative(s + "Floor loads", q);
        }
    }

    /// The hinges or hysteretic storeys and their Bouc-Wen shape.
    void
    finalize_building_hysteresis(const InputFile &input, const std::string &s, BuildingParameters &b)
    {
      const unsigned int n = b.n_storeys;
      const std::size_t n_groups = std::max<std::size_t>(1, b.hinge_groups.size());
      if (b.type != BuildingType::shear && !b.hinge_locations.empty())
        {
          input.list(s + "Hinges/Yield moment", b.hinge_yield_moments, n_groups, true,
                 "one per hinge group");
          for (const double m_y : b.hinge_yield_moments) // 1e200 came out as a NaN energy
            input.at_most(s + "Hinges/Yield moment", m_y, largest_model_value, "N m",
                          "the largest value of a model");
          input.list(s + "Hinges/Yield rotation", b.hinge_yield_rotations, n_groups, true,
                 "one per hinge group");
          input.list(s + "Hinges/Stiffness", b.hinge_stiffnesses, n_groups, true,
                 "one per hinge group");
          input.positive(s + "Hinges/Stiffness factor", b.hinge_stiffness_factor);
          for (std::size_t g = 0; g < n_groups; ++g)
            if (b.hinge_yield_moments[b.hinge_yield_moments.size() == 1 ? 0 : g] == 0 &&
                b.hinge_yield_rotations[b.hinge_yield_rotations.size() == 1 ? 0 : g] == 0)
              input.fail(s + "Hinges/Yield moment",
                     "hinges need a yield moment or a yield rotation (both are 0)");
        }
      if (b.type == BuildingType::shear && !b.storey_yield_drifts.empty())
        input.list(s + "Storey yield drifts", b.storey_yield_drifts, n, true, "one per storey");
      for (const double u_y : b.storey_yield_drifts) // the force k u_y overflowed past it
        input.at_most(s + "Storey yield drifts", u_y, largest_building_length, "m",
                      "a drift beyond any storey");
      const bool hysteretic = (b.type != BuildingType::shear && !b.hinge_locations.empty()) ||
                              (b.type == BuildingType::shear && !b.storey_yield_drifts.empty());
      if (hysteretic)
        {
          const BoucWenParameters &h  = b.hysteresis;
          const std::string        bw = s + "Bouc-Wen/";
          if (const BoucWenShapeProblem shape = bouc_wen_shape_problem(h); !shape.entry.empty())
            input.fail(bw + shape.entry, shape.problem);
          input.non_negative(bw + "delta A", h.delta_A);
          input.non_negative(bw + "delta nu", h.delta_nu);
          input.non_negative(bw + "delta eta", h.delta_eta);
        }
    }

    /// Rayleigh damping from two modes or from given coefficients.
    void
    finalize_building_damping(const InputFile &input, const std::string &s, BuildingParameters &b)
    {
      if (b.damping_type == RayleighDamping::Kind::modes)
        {
          if (!(b.damping_ratio >= 0 && b.damping_ratio < 1))
            input.fail(s + "Damping/Damping ratio",
                   "must lie in [0, 1), got " + number_text(b.damping_ratio));
          if (b.damping_modes.size() != 2 || b.damping_modes[0] < 1 ||
              b.damping_modes[1] < 1 || b.damping_modes[0] == b.damping_modes[1])
            input.fail(s + "Damping/Modes", "needs two different mode numbers >= 1");
        }
      if (b.damping_type == RayleighDamping::Kind::coefficients)
        {
          input.non_negative(s + "Damping/a0", b.rayleigh_a0);
          input.non_negative(s + "Damping/a1", b.rayleigh_a1);
          // C = a0 M + a1 K, whose entries are held to the same bound
          // (dynamics/analysis.cc): a coefficient beyond it cannot meet it
          input.at_most(s + "Damping/a0", b.rayleigh_a0, largest_model_value, "1/s",
                        "the largest value of a model");
          input.at_most(s + "Damping/a1", b.rayleigh_a1, largest_model_value, "s",
                        "the largest value of a model");
        }
    }

  } // namespace

  void
  BuildingParameters::finalize(const InputFile &input, const unsigned int number)
  {
    if (name.empty())
      name = "B" + std::to_string(number);
    const std::string s = "Building " + std::to_string(number) + "/";
    finalize_building_members(input, s, *this);
    finalize_building_hysteresis(input, s, *this);
    finalize_building_damping(input, s, *this);
    finalize_modal_damping(input, s + "Damping/");
    foundation.finalize(input, s, type);
  }

  void
  BuildingParameters::finalize_modal_damping(const InputFile &input, const std::string &s)
  {
    const auto check_ratio = [&](const std::string &path, const double ratio) {
      if (!(ratio >= 0 && ratio < 1))
        input.fail(path, "a damping ratio must lie in [0, 1), got " + number_text(ratio));
    };
    if (damping_type == RayleighDamping::Kind::modal)
      {
        if (modal_damping_ratios.empty())
          input.fail(s + "Modal ratios", "Type = modal needs a damping ratio per mode");
        for (const double ratio : modal_damping_ratios)
          check_ratio(s + "Modal ratios", ratio);
      }
    if (damping_type != RayleighDamping::Kind::bands)
      return;
    if (damping_band_entries.empty())
      input.fail(s + "Bands", "Type = bands needs bands 'low high ratio'");
    if (damped_modes < 1)
      input.fail(s + "Damped modes", "Type = bands needs the number of modes it damps (>= 1)");
    damping_bands.clear();
    for (const std::string &entry : damping_band_entries)
      {
        std::istringstream words(entry);
        DampingBand        band;
        std::string        rest;
        read_number(words, band.low);
        read_number(words, band.high);
        if (!read_number(words, band.damping_ratio) || (words >> rest))
          input.fail(s + "Bands", "'" + trimmed(entry) + "' is not 'low high ratio'");
        if (!(band.low >= 0 && band.high > band.low))
          input.fail(s + "Bands", "'" + trimmed(entry) + "': needs 0 <= low < high (Hz)");
        check_ratio(s + "Bands", band.damping_ratio);
        for (const DampingBand &other : damping_bands)
          if (band.low < other.high && other.low < band.high)
            input.fail(s + "Bands", "'" + trimmed(entry) + "' overlaps another band");
        damping_bands.push_back(band);
      }
  }

  void
  ModelParameters::finalize_plan(const InputFile &input)
  {
    for (unsigned int b = 0; b < buildings.size(); ++b)
      {
        const std::string s = "Building " + std::to_string(b + 1) + "/";
        if (geometric_nonlinearity != GeometricNonlinearity::none &&
            buildings[b].type == BuildingType::shear && buildings[b].foundation.enabled())
          input.fail("Model/Geometric nonlinearity",
                     "P-Delta of a torsionally coupled shear building takes a fixed base; "
                     "building " + std::to_string(b + 1) + " has a compliant foundation");
        if (buildings[b].type == BuildingType::mesh)
          buildings[b].finalize_mesh_3d(input, s);
        if (buildings[b].type == BuildingType::frame)
          buildings[b].finalize_frame_3d(input, s);
        // a mesh's floors are counted when it is read (model/mesh_building_3d.h)
        buildings[b].plan.finalize(input, s,
                                   buildings[b].type == BuildingType::mesh ?
                                     buildings[b].plan.polar_moments.size() :
                                     buildings[b].n_storeys);
        if (buildings[b].type != BuildingType::mesh) // a mesh's slab is its floor's outline
          buildings[b].plan.check_mass_on_slab(input, s);
        if (buildings[b].plan.storey_law != "planes" || buildings[b].hinge_biaxial)
          check_bidirectional_bouc_wen(input, s + "Bouc-Wen/", buildings[b].hysteresis);
        buildings[b].foundation.finalize_3d(input, s);
        if (buildings[b].type != BuildingType::shear && buildings[b].foundation.enabled() &&
            buildings[b].base_fixity == BaseFixity::pinned)
          input.fail(s + "Base fixity", "a 3D frame on a compliant foundation has its column "
                                        "bases clamped to the foundation (pinned: 2D only)");
      }
  }

  void
  ModelParameters::declare_number_of_buildings(dealii::ParameterHandler &prm,
                                               unsigned int             &n_buildings)
  {
    prm.enter_subsection("Model");
    prm.add_parameter("Number of buildings", n_buildings, number_of_buildings_text,
                      Patterns::Integer(1, 100));
    prm.leave_subsection();
  }

  void
  ModelParameters::declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Model");
    // the entry without an action: the first pass read it into buildings.size().
    // An action bound to a local variable here would write into this frame
    // after it is gone, when the file is parsed (found by fuzz_parameters).
    prm.declare_entry("Number of buildings", std::to_string(buildings.size()),
                      Patterns::Integer(1, 100), number_of_buildings_text);
    add_choice(prm, "Mass matrix", mass_matrix, "Distributed member mass. Unit: -.",
               mass_matrix_names());
    add_choice(prm, "Geometric nonlinearity", geometric_nonlinearity,
               "p-delta: the geometric stiffness of the gravity loads (every mass times "
               "Gravity), linearised and added to K once: frame members from their axial "
               "forces in a linear static gravity analysis (3D frames too: z up), "
               "shear-building storeys -P/h with P the weight above (3D shear: also "
               "-P r^2/h in torsion, r the polar radius of gyration of the floors above). none: "
               "small displacements. Unit: -.",
               geometric_nonlinearity_names());
    prm.add_parameter("Dimension", dimension,
                      "2: planar frames and stick models (x horizontal, y up). 3: "
                      "torsionally coupled shear buildings and 3D frames in plan (x, y "
                      "horizontal, z up; each floor a rigid diaphragm moving ux, uy, rz; "
                      "Building <i>/Plan), with contact between the slab outlines. Unit: -.",
                      Patterns::Integer(2, 3));
    prm.add_parameter("Gravity", gravity,
                      "Acceleration of gravity for the P-Delta loads. Unit: m/s^2.");
    prm.add_parameter("Separations", separations,
                      "Clear distance between building i and i+1 (one value for "
                      "all pairs or one per pair); at most 1e7, the bound of site "
                      "coordinates (Plan/Position). Unit: m.");
    declare_gravity_analysis(prm);
    prm.leave_subsection();
    for (unsigned int b = 0; b < buildings.size(); ++b)
      {
        prm.enter_subsection("Building " + std::to_string(b + 1));
        buildings[b].declare(prm);
        prm.leave_subsection();
      }
  }

  void
  ModelParameters::declare_gravity_analysis(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Gravity analysis");
    prm.declare_entry("Type", "none", Patterns::Selection("none|static"),
                      "static: before any dynamics, a load-controlled Newton analysis of the "
                      "gravity loads (every mass times Gravity, and each building's Floor "
                      "loads) with the nonlinear elements; the dynamics start from its state "
                      "(displacements, hinges, axial forces of P-Delta) with the loads held "
                      "constant, and every displacement reported is the total. none: the "
                      "dynamics start from the undeformed state. Unit: -.");
    prm.add_action("Type", [this](const std::string &value) {
      gravity_analysis.enabled = value == "static";
    });
    prm.add_parameter("Number of steps", gravity_analysis.n_steps,
                      "Equal load steps from 0 to the whole gravity load (each halved on "
                      "non-convergence, Maximum step cuts times). Unit: -.",
                      Patterns::Integer(1, 100000));
    prm.add_parameter("Tolerance", gravity_analysis.tolerance,
                      "Newton converges when the residual's norm is at most this times the "
                      "gravity load's. Unit: -.");
    prm.add_parameter("Max iterations", gravity_analysis.max_iterations,
                      "Newton iterations per load step. Unit: -.", Patterns::Integer(1, 1000));
    prm.add_parameter("Max step cuts", gravity_analysis.max_step_cuts,
                      "How often a load step that does not converge is halved. Unit: -.",
                      Patterns::Integer(0, 30));
    prm.leave_subsection();
  }

  void
  ModelParameters::finalize(const InputFile &input)
  {
    // first: an entry of another Type or dimension is the mistake to name,
    // not whatever its value would break further on
    refuse_entries_without_effect(input, *this);
    input.positive("Model/Gravity analysis/Tolerance", gravity_analysis.tolerance);
    if (!(gravity_analysis.tolerance < 1))
      input.fail("Model/Gravity analysis/Tolerance",
                 "must be below 1, got " + number_text(gravity_analysis.tolerance));
    for (unsigned int b = 0; b < buildings.size(); ++b)
      if (dimension == 3 && !buildings[b].floor_loads.empty())
        input.fail("Building " + std::to_string(b + 1) + "/Floor loads",
                   "floor loads are for 2D models (Model/Dimension = 2)");
    for (unsigned int b = 0; b < buildings.size(); ++b)
      {
        buildings[b].finalize(input, b + 1);
        buildings[b].finalize_member_model(input, "Building " + std::to_string(b + 1) + "/",
                                           *this);
        buildings[b].finalize_self_weight(input, "Building " + std::to_string(b + 1) + "/",
                                          *this);
      }
    input.positive("Model/Gravity", gravity);
    if (dimension == 3)
      finalize_plan(input);
    if (buildings.size() > 1)
      input.list("Model/Separations", separations, buildings.size() - 1, true,
                 "one per neighbouring pair");
    for (const double gap : separations) // 1e200 ran with exit 0 (no contact ever)
      input.at_most("Model/Separations", gap, largest_site_coordinate, "m",
                    "the bound of site coordinates, Plan/Position: buildings that far apart "
                    "are on no common site");
  }
} // namespace poundfe
