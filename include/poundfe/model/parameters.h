// The structure a parameter file describes: the `Model` section and one
// `Building <i>` section per building (deal.II step-33 style: each struct
// declares and checks its own entries). Parsing uses deal.II's
// ParameterHandler, kept out of this header.
#ifndef poundfe_model_parameters_h
#define poundfe_model_parameters_h

#include <poundfe/base/choices.h>
#include <poundfe/base/input_file.h>
#include <poundfe/laws/bouc_wen.h>
#include <poundfe/model/foundation_parameters.h>
#include <poundfe/model/model.h>
#include <poundfe/model/plan_parameters.h>
#include <poundfe/sections/section_parameters.h>

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace poundfe
{
  enum class BaseFixity
  {
    fixed,
    pinned
  };

  const NameTable<BuildingType>          &building_type_names();
  const NameTable<BaseFixity>            &base_fixity_names();
  const NameTable<RayleighDamping::Kind> &damping_type_names();
  const NameTable<MassMatrixType>        &mass_matrix_names();
  const NameTable<GeometricNonlinearity> &geometric_nonlinearity_names();

  struct ModelParameters;

  struct BuildingParameters
  {
    std::string  name = "";
    BuildingType type = BuildingType::frame;

    // Generated frames and shear buildings.
    unsigned int        n_storeys = 1;
    unsigned int        n_bays    = 1;
    std::vector<double> storey_heights{3.0};
    std::vector<double> bay_widths{6.0};
    std::vector<double> column_youngs_modulus{3.0e10};
    std::vector<double> column_area{0.16};
    std::vector<double> column_second_moment{2.133e-3};
    std::vector<double> beam_youngs_modulus{3.0e10};
    std::vector<double> beam_area{0.12};
    std::vector<double> beam_second_moment{1.6e-3};
    std::vector<double> column_mass_per_length{0.0};
    std::vector<double> beam_mass_per_length{0.0};
    std::vector<double> floor_masses{20000.0};
    /// Vertical loads beyond the floors' weight (dead and live loads without
    /// mass), one for all or one per floor; empty: none (Model/Gravity analysis).
    std::vector<double> floor_loads;
    BaseFixity          base_fixity         = BaseFixity::fixed;
    unsigned int        elements_per_member = 1;

    // Members (model/member_model_parameters.cc): elastic frame elements with
    // Bouc-Wen hinges, or beam-columns on fibre sections of `Sections`.
    std::string              member_model       = "elastic-hinges"; // |fibre
    std::string              member_element     = "force";          // |displacement
    unsigned int             integration_points = 5;
    std::string              member_transformation = "auto"; // |Linear|PDelta
    std::vector<std::string> column_sections, beam_sections; // one or per storey (floor)
    std::vector<std::string> group_sections; // a mesh's: one or per Group ids entry
    /// finalize_member_model: the Sections index of each storey's columns
    /// and beams, of each mesh group (fibre buildings; empty otherwise).
    std::vector<unsigned int> column_section_index, beam_section_index, group_section_index;
    bool fibre() const { return member_model == "fibre"; }
    /// The members' weight in the gravity analysis: nodal (their mass's
    /// weight at their nodes) or distributed (a uniform load along each,
    /// unit weight times area, or the mass's weight when the unit weight is 0).
    std::string member_self_weight = "nodal"; // |distributed
    double      member_unit_weight = 0;       // N/m^3

    // 3D frames (Model/Dimension = 3): bays along y, the sections' second
    // axis and twist (Column I, Beam I: bending in the frame's vertical
    // plane), the columns' local axes and the floor diaphragm.
    unsigned int        n_bays_y = 1;
    std::vector<double> bay_widths_y{6.0};
    std::vector<double> column_shear_modulus;    // G; empty: not given
    std::vector<double> column_second_moment_z;  // Iz
    std::vector<double> column_torsion_constant; // J
    double              column_angle = 0;        // degrees, local axes about the vertical
    std::vector<double> beam_shear_modulus;
    std::vector<double> beam_second_moment_z;
    std::vector<double> beam_torsion_constant;
    std::string         diaphragm = "rigid"; // rigid|none
    std::string         vertical_floor_mass = "joints"; // joints|none
    /// A set-back (model/set_backs.h): from `storey` up to the next entry,
    /// the bays removed from the full grid on the sides -x, +x, -y, +y.
    struct SetBack
    {
      unsigned int                storey = 0; // 1-based
      std::array<unsigned int, 4> removed{{0, 0, 0, 0}};
    };
    std::vector<std::string> set_backs_text; // 'storey: x- x+ y- y+' entries
    std::vector<SetBack>     set_backs;      // parsed, by increasing storey
    // Shear areas (Timoshenko; 0: no shear deformation), one or per storey
    // (floor): Avz goes with Column I / Beam I, Avy with Column Iz / Beam Iz.
    std::vector<double> column_shear_area_y{0.0}, column_shear_area_z{0.0};
    std::vector<double> beam_shear_area_y{0.0}, beam_shear_area_z{0.0};

    // Shear buildings.
    std::vector<double> storey_stiffnesses{5.0e6};
    std::vector<double> storey_damping{0.0};
    double              drawing_width = 0.0;

    // Frames from a Gmsh mesh.
    std::string               mesh_file = "";
    std::vector<unsigned int> group_ids{1};
    std::vector<double>       group_youngs_modulus{3.0e10};
    std::vector<double>       group_area{0.16};
    std::vector<double>       group_second_moment{2.133e-3};
    std::vector<double>       group_mass_per_length{0.0};
    // ... in 3D (Model/Dimension = 3; model/mesh_building_3d.h): Group I is
    // Iy (about the local y axis), and per group G, Iz, J and the vector v
    // in the local x-z plane ({0, 0, 0}: vertical members global X, others
    // global Z).
    std::vector<double>                group_shear_modulus;
    std::vector<double>                group_second_moment_z;
    std::vector<double>                group_torsion_constant;
    std::vector<std::string>           group_orientation_text; // 'vx vy vz' per group
    std::vector<std::array<double, 3>> group_orientations;     // parsed

    // Bouc-Wen hinges at member ends (frames) and hysteretic storeys (shear).
    std::vector<std::string>  hinge_locations;  // column bases|column tops|column ends|beam ends
    std::vector<unsigned int> hinge_groups;     // empty: every group
    std::vector<double>       hinge_yield_moments{0.0};
    std::vector<double>       hinge_yield_rotations{0.0};
    std::vector<double>       hinge_stiffnesses{0.0}; // 0: factor 6 E I / L
    double                    hinge_stiffness_factor = 10.0;
    bool                      hinge_biaxial = false; // 3D: one bidirectional law per end
    std::vector<double>       storey_yield_drifts; // empty or 0: elastic storey
    BoucWenParameters         hysteresis;          // shape; k and u_y come per spring

    // Rayleigh damping.
    RayleighDamping::Kind     damping_type  = RayleighDamping::Kind::modes;
    double                    damping_ratio = 0.05;
    std::vector<unsigned int> damping_modes{1, 2};
    double                    rayleigh_a0 = 0.0;
    double                    rayleigh_a1 = 0.0;
    // Modal damping.
    std::vector<double>       modal_damping_ratios; // Type = modal
    std::vector<std::string>  damping_band_entries; // Type = bands: 'low high ratio'
    std::vector<DampingBand>  damping_bands;        // ... as finalize() reads them
    unsigned int              damped_modes = 0;

    /// The building in plan (Model/Dimension = 3).
    PlanParameters plan;
    /// A compliant foundation (2D shear buildings; off by default).
    FoundationParameters foundation;

    /// Declare the entries of one `Building <i>` subsection (the current one).
    void declare(dealii::ParameterHandler &prm);
    /// Check the values of `Building <number>`; name it B<number> if unnamed.
    /// Throws InputError.
    void finalize(const InputFile &input, unsigned int number);
    /// Dimension 3, Type = frame: check the 3D entries of `<section>` (every
    /// section list given), and set the Plan dimensions to the column grid.
    /// Throws InputError (model/frame_building_3d_parameters.cc).
    void finalize_frame_3d(const InputFile &input, const std::string &section);
    /// Dimension 3, Type = mesh: check the 3D group entries of `<section>`
    /// and read Group orientation. Throws InputError
    /// (model/mesh_building_3d_parameters.cc).
    void finalize_mesh_3d(const InputFile &input, const std::string &section);
    /// Member model = fibre: the section names found in `sections`, the
    /// counts, and the entries a fibre building does not use refused
    /// (model/member_model_parameters.cc). Throws InputError.
    void finalize_member_model(const InputFile &input, const std::string &section,
                               const ModelParameters &model);
    /// Member self-weight and Member unit weight against the gravity
    /// analysis (model/member_model_parameters.cc). Throws InputError.
    void finalize_self_weight(const InputFile &input, const std::string &section,
                              const ModelParameters &model) const;

  private:
    // declare()'s groups, in the order print_parameters shows them
    void declare_frame_entries(dealii::ParameterHandler &prm); // [frame]
    void declare_member_model(dealii::ParameterHandler &prm);  // [frame] members
    void declare_frame_3d_entries(dealii::ParameterHandler &prm); // [3D frame]
    void declare_mesh_entries(dealii::ParameterHandler &prm);  // [mesh]
    void declare_mesh_3d_entries(dealii::ParameterHandler &prm); // [3D mesh]
    void declare_shear_entries(dealii::ParameterHandler &prm); // [shear]
    void declare_hinges(dealii::ParameterHandler &prm);        // Hinges
    void declare_bouc_wen(dealii::ParameterHandler &prm);      // Bouc-Wen
    void declare_damping(dealii::ParameterHandler &prm);       // Damping
    /// A 3D frame (generated or drawn): one element per member, no
    /// resisting planes. Throws InputError.
    void check_one_element_no_planes(const InputFile &input, const std::string &section) const;
    /// Type = modal and bands: ratios in [0, 1), the bands read.
    void finalize_modal_damping(const InputFile &input, const std::string &section);
  };

  /// A list every building of a kind needs: fails with "<need> (one value
  /// or <per>)" naming `path` when empty, unless it has 1 or n values, or a
  /// value is not positive. Throws InputError.
  void require_positive_list(const InputFile &input, const std::string &path,
                             const std::vector<double> &values, std::size_t n,
                             const std::string &need, const std::string &per);

  /// The `Model` section and the buildings it announces.
  struct ModelParameters
  {
    MassMatrixType                  mass_matrix = MassMatrixType::lumped;
    GeometricNonlinearity           geometric_nonlinearity = GeometricNonlinearity::none;
    double                          gravity                = 9.81;
    unsigned int                    dimension              = 2;
    /// Model/Gravity analysis.
    GravityAnalysisSettings         gravity_analysis;
    std::vector<double>             separations{0.05};
    std::vector<BuildingParameters> buildings; // one per `Building <i>`
    /// A copy of the input's `Sections` (InputParameters::finalize sets it
    /// before finalize()), which fibre buildings name.
    SectionsParameters              sections;

    /// `Model/Number of buildings` alone: it shapes the other declarations.
    static void declare_number_of_buildings(dealii::ParameterHandler &prm,
                                            unsigned int             &n_buildings);
    /// The `Model` section and `Building 1` .. `Building <buildings.size()>`.
    void declare(dealii::ParameterHandler &prm);
    /// Check every building and the separations. Throws InputError.
    void finalize(const InputFile &input);
    /// The buildings' Mesh files, those given.
    std::vector<NamedInputFile> input_files() const;

  private:
    /// The subsection Model/Gravity analysis.
    void declare_gravity_analysis(dealii::ParameterHandler &prm);
    /// Dimension 3: shear buildings with their Plan. Throws InputError.
    void finalize_plan(const InputFile &input);
  };
} // namespace poundfe

#endif
