#include <poundfe/dynamics/analysis.h>
#include <poundfe/dynamics/modal_damping_assembly.h>
#include <poundfe/assembly/modal_damping.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/model/model_builder.h>

#include <poundfe/base/numbers.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace poundfe
{
  namespace
  {
    /// The equations of the buildings [first, last).
    EquationRange
    equations_of(const Model &model, const std::array<unsigned int, 2> buildings)
    {
      if (buildings[0] == buildings[1])
        return {{0, 0}};
      return {{model.equation_range(buildings[0])[0], model.equation_range(buildings[1] - 1)[1]}};
    }

    /// Friction surfaces on the equations `kept` (the others' stick laws
    /// are another rank's to fit: doc/theory.md §3.5d).
    void
    set_stick_stiffnesses(const InputFile &input, const LinearSystem &system,
                          const EquationRange kept, Model &model)
    {
      for (FrictionSurface &surface : model.friction_surfaces)
        surface.automatic_stick_stiffness = surface.law.stick_stiffness == 0;
      fit_stick_laws(system, model);
      for (const FrictionSurface &surface : model.friction_surfaces)
        if (const unsigned int equation = model.equation(Model::dof(surface.node, Component::ux));
            equation >= kept[0] && equation < kept[1] && !(surface.law.stick_stiffness > 0))
          input.fail("Friction/Stick stiffness",
                     surface.label + ": no linear stiffness at the node to take the "
                                     "automatic stick stiffness from; give one");
    }

    /// P-Delta must leave every building stable under its own weight: a
    /// K_E + K_G without a Cholesky factor means gravity above the buckling
    /// load, where the linearised model has no meaning.
    void
    check_stable_under_gravity(const InputFile &input, const Model &model,
                               const std::array<unsigned int, 2> buildings,
                               const LinearSystem &system)
    {
      if (model.geometric_nonlinearity != GeometricNonlinearity::p_delta)
        return;
      std::ostringstream g;
      g << model.gravity;
      for (unsigned int b = buildings[0]; b < buildings[1]; ++b)
        if (!is_positive_definite(block(system.stiffness, model.equation_range(b))))
          input.fail("Model/Geometric nonlinearity",
                     "building '" + model.buildings[b].name +
                       "' buckles under its own weight: with the P-Delta stiffness of its "
                       "gravity loads (g = " + g.str() +
                       " m/s^2) K is not positive definite, the weight exceeds the elastic "
                       "critical load (stiffen the columns or storeys, or check the masses)");
    }

    /// Dimension 3: the effective modal masses along y and about z of the
    /// model's and each building's modes.
    void
    add_plan_participations(Analysis &analysis)
    {
      const LinearSystem &system = analysis.system;
      add_plan_participation(analysis.modes, system.mass, system.influence_y, system.influence_rz);
      for (unsigned int b = 0; b < analysis.building_modes.size(); ++b)
        {
          const auto range = analysis.model.equation_range(b);
          const auto n     = range[1] - range[0];
          add_plan_participation(analysis.building_modes[b], block(system.mass, range),
                                 system.influence_y.segment(range[0], n),
                                 system.influence_rz.segment(range[0], n));
        }
    }

    /// The entry named for an out-of-range entry (global row and column)
    /// of building b's matrix: for K and M the building, their sources
    /// being many; for C the largest of its terms a0 M, a1 K and the storey
    /// dashpots (the rest).
    using BlameOfEntry = std::function<std::string(unsigned int b, int row, int column)>;

    /// Every entry of building b's part of `matrix` (K, M or C) finite and at
    /// most 1e150 in size: an absurd stiffness, modulus, section property or
    /// mass (1e308) made K infinite and the eigensolver lose modes, reported
    /// as a damping-modes problem; an absurd C (a0 = 1e149) ran with exit 0.
    /// The eigensolvers and Newton square entries (norms), so 1e150 is where
    /// they stop being safe; no structure comes near it.
    void
    check_matrix_in_range(const InputFile &input, const Model &model,
                          const std::array<unsigned int, 2> buildings, const SparseMatrix &matrix,
                          const std::string &name, const std::string &sources,
                          const BlameOfEntry &blame)
    {
      for (unsigned int b = buildings[0]; b < buildings[1]; ++b)
        {
          const unsigned int first = model.equation_range(b)[0];
          const SparseMatrix part  = block(matrix, model.equation_range(b));
          for (int k = 0; k < part.outerSize(); ++k)
            for (SparseMatrix::InnerIterator entry(part, k); entry; ++entry)
              if (!(std::abs(entry.value()) <= largest_model_value))
                {
                  std::ostringstream value;
                  value << entry.value();
                  const std::string path = blame(b, first + entry.row(), first + entry.col());
                  throw InputError(input.file, input.line_of(path), path,
                                   "building '" + model.buildings[b].name + "' has a " + name +
                                     " matrix entry of " + value.str() + " (at most 1e150): " +
                                     sources + " is out of any physical range");
                }
        }
    }

    /// K and M in range (check_matrix_in_range).
    void
    check_matrices_in_range(const InputFile &input, const Model &model,
                            const std::array<unsigned int, 2> buildings,
                            const LinearSystem &system)
    {
      const BlameOfEntry building = [](const unsigned int b, int, int) {
        return "Building " + std::to_string(b + 1);
      };
      check_matrix_in_range(input, model, buildings, system.stiffness, "stiffness",
                            "a stiffness, modulus or section property", building);
      check_matrix_in_range(input, model, buildings, system.mass, "mass", "a mass or density",
                            building);
    }

    /// C in range (check_matrix_in_range), once assembled: the Rayleigh
    /// terms of M and K (the superstructure's, as assemble_damping takes).
    void
    check_damping_in_range(const InputFile &input, const Model &model,
                           const std::array<unsigned int, 2> buildings, const LinearSystem &system)
    {
      const bool          structure = system.structure_mass.rows() > 0;
      const SparseMatrix &mass      = structure ? system.structure_mass : system.mass;
      const SparseMatrix &stiffness = structure ? system.structure_stiffness : system.stiffness;
      const BlameOfEntry  term      = [&](const unsigned int b, const int row, const int column) {
        const std::string s = "Building " + std::to_string(b + 1) + "/";
        const double mass_term      = system.rayleigh[b][0] * std::abs(mass.coeff(row, column));
        const double stiffness_term = system.rayleigh[b][1] * std::abs(stiffness.coeff(row, column));
        const double dashpots       = std::abs(system.damping.coeff(row, column)) -
                                mass_term - stiffness_term;
        if (dashpots > std::max(mass_term, stiffness_term)) // NaN (inf - inf): a Rayleigh term
          return s + "Storey damping";
        return s + "Damping/" + (mass_term >= stiffness_term ? "a0" : "a1");
      };
      check_matrix_in_range(input, model, buildings, system.damping, "damping",
                            "a storey dashpot or Rayleigh coefficient (C = a0 M + a1 K)", term);
    }

    /// The modes of one building (`what`) or of the whole model, by the
    /// input's eigensolver; a forced sparse solver that cannot give `n`
    /// modes is bad input.
    Modes
    modes_of(const InputFile &input, const ModalParameters &modal, const SparseMatrix &mass,
             const SparseMatrix &stiffness, const Vector &influence, const unsigned int n,
             const std::string &what)
    {
      if (modal.eigensolver == Eigensolver::sparse && n > max_sparse_modes(mass))
        input.fail("Modal analysis/Eigensolver",
                   "the sparse eigensolver finds at most " +
                     std::to_string(max_sparse_modes(mass)) + " modes of " + what + " (" +
                     std::to_string(mass.rows()) + " equations), " + std::to_string(n) +
                     " are wanted (Output/Number of modes, Damping/Modes); use dense or auto");
      return compute_modes(mass, stiffness, influence, n, modal.eigensolver);
    }

    /// The share of mode `i`'s kinetic energy in vertical motion,
    /// (phi_y^T M phi_y) / (phi^T M phi) with phi_y the mode's uy entries:
    /// 0 for a sway mode of a frame with lumped floor masses, near 1 for a
    /// beam's bending mode.
    double
    vertical_energy_share(const Model &model, const unsigned int b, const SparseMatrix &mass,
                          const Modes &modes, const unsigned int i)
    {
      if (model.dimension == 3) // uy is a horizontal (plan) translation
        return 0;
      const Building &building = model.buildings[b];
      const auto      range    = model.equation_range(b);
      const Vector    phi      = modes.shapes.col(i);
      Vector          vertical = Vector::Zero(phi.size());
      for (unsigned int node = building.first_node; node < building.first_node + building.n_nodes;
           ++node)
        {
          const int equation = model.equation(Model::dof(node, Component::uy));
          if (equation >= int(range[0]) && equation < int(range[1]))
            vertical[equation - range[0]] = phi[equation - range[0]];
        }
      const double total = phi.dot(mass * phi);
      return total > 0 ? vertical.dot(mass * vertical) / total : 0;
    }

    /// Building b's Rayleigh coefficients (a0, a1): none, given, or fitted
    /// to its damping ratio at two of its `modes`.
    std::array<double, 2>
    rayleigh_coefficients_of(const InputFile &input, const Building &building,
                             const unsigned int b, const Modes &modes)
    {
      const RayleighDamping &d = building.damping;
      switch (d.kind)
        {
          case RayleighDamping::Kind::none:
          case RayleighDamping::Kind::modal: // C is modal (assemble_modal_damping)
          case RayleighDamping::Kind::bands:
            return {{0, 0}};
          case RayleighDamping::Kind::coefficients:
            return {{d.a0, d.a1}};
          case RayleighDamping::Kind::modes:
            break;
        }
      const std::string path = "Building " + std::to_string(b + 1) + "/Damping/Modes";
      if (std::max(d.first_mode, d.second_mode) > modes.n_modes())
        throw InputError(input.file, input.line_of(path), path,
                         "building '" + building.name + "' has only " +
                           std::to_string(modes.n_modes()) + " modes");
      return rayleigh_coefficients(d.damping_ratio, modes.omega[d.first_mode - 1],
                                   modes.omega[d.second_mode - 1]);
    }

    /// The entry that sets how many modes building b's modal damping needs.
    std::string
    damped_modes_path(const RayleighDamping &d, const unsigned int b)
    {
      const std::string section = "Building " + std::to_string(b + 1) + "/Damping/";
      return section + (d.kind == RayleighDamping::Kind::modal ? "Modal ratios" : "Damped modes");
    }

    /// A building's damping may not name a mode beyond its equations.
    void
    check_damped_modes(const InputFile &input, const Model &model, const unsigned int b)
    {
      const RayleighDamping &d     = model.buildings[b].damping;
      const auto             range = model.equation_range(b);
      const unsigned int     n     = range[1] - range[0];
      if (d.is_modal() && d.n_modes_needed() > n) // Rayleigh's: rayleigh_coefficients_of
        input.fail(damped_modes_path(d, b),
                   "building '" + model.buildings[b].name + "' has only " + std::to_string(n) +
                     " modes (one per equation), its damping names mode " +
                     std::to_string(d.n_modes_needed()));
    }

    /// "2.5 %" for the ratio 0.025.
    std::string
    percent(const double ratio)
    {
      return rounded(100 * ratio) + " %";
    }
  } // namespace

  std::vector<double>
  modal_damping_ratios(const RayleighDamping &d, const Modes &modes)
  {
    if (d.kind == RayleighDamping::Kind::modal)
      return d.modal_ratios;
    std::vector<double> ratios(d.damped_modes, 0.0);
    for (unsigned int i = 0; i < d.damped_modes; ++i)
      for (const DampingBand &band : d.bands)
        if (modes.frequency(i) >= band.low && modes.frequency(i) < band.high)
          ratios[i] = band.damping_ratio;
    return ratios;
  }

  void
  assemble_modal_damping(Analysis &analysis)
  {
    const Model &model = analysis.model;
    analysis.system.modal_damping = LowRankDamping();
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const RayleighDamping &d = model.buildings[b].damping;
        if (!d.is_modal() || analysis.building_modes[b].n_modes() == 0) // another rank's
          continue;
        const auto   range = model.equation_range(b);
        const Modes &modes = analysis.building_modes[b];
        add_modal_damping(analysis.system.modal_damping, model.n_equations(), range,
                          block(analysis.system.mass, range), modes.shapes, modes.omega,
                          modal_damping_ratios(d, modes));
      }
  }

  std::vector<std::string>
  damping_warnings(const Analysis &analysis)
  {
    const Model             &model = analysis.model;
    std::vector<std::string> warnings;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const RayleighDamping &d       = model.buildings[b].damping;
        const Modes           &modes   = analysis.building_modes[b];
        const std::string      section = "Building " + std::to_string(b + 1) + "/Damping/";
        const std::string      where   = "building '" + model.buildings[b].name + "': ";
        // entries of another Damping/Type: warn_entries_without_effect (model/entry_scope.h)
        if (d.kind == RayleighDamping::Kind::modes && modes.n_modes() > 0) // else another rank's
          {
            const SparseMatrix mass = block(analysis.system.mass, model.equation_range(b));
            for (const unsigned int mode : {d.first_mode, d.second_mode})
              {
                const double share = vertical_energy_share(model, b, mass, modes, mode - 1);
                if (share > 0.5)
                  warnings.push_back(
                    where + section + "Modes fits the damping ratio at mode " +
                    std::to_string(mode) + " (" + rounded(modes.frequency(mode - 1)) +
                    " Hz), a vertical mode (" + percent(share) +
                    " of its kinetic energy in vertical motion): the sway modes that carry "
                    "the horizontal response then get damping ratios other than the one "
                    "intended; fit it at two sway modes (poundfe modal lists the modes "
                    "with their horizontal mass ratios)");
              }
          }
        if (d.kind == RayleighDamping::Kind::coefficients && d.a0 == 0 && d.a1 == 0)
          warnings.push_back(where + section + "a0 and a1 are both 0: the building has no "
                             "Rayleigh damping (Type = none says so; a damping ratio needs "
                             "Type = modes)");
        else if (d.kind == RayleighDamping::Kind::coefficients && d.a1 == 0)
          {
            std::string ratios;
            if (modes.n_modes() > 1)
              ratios = " (here " + percent(d.a0 / (2 * modes.omega.front())) + " at mode 1, " +
                       percent(d.a0 / (2 * modes.omega.back())) + " at mode " +
                       std::to_string(modes.n_modes()) + ")";
            warnings.push_back(where + section + "a1 = 0, mass-proportional damping only: the "
                               "damping ratio a0/(2 omega) falls as the frequency rises" +
                               ratios + ", the higher modes are nearly undamped; give a1 too "
                               "(or Type = modes)");
          }
      }
    return warnings;
  }

  void
  fit_stick_laws(const LinearSystem &system, Model &model)
  {
    // k_s = 1e4 K_ii (automatic): stick deflects 1e-4 of what the structure
    // does under the same force; c_s = 2 sqrt(k_s M_ii), critical for the
    // node's mass on the stick spring
    for (FrictionSurface &surface : model.friction_surfaces)
      {
        FrictionLawParameters &law      = surface.law;
        const int              equation = model.equation(Model::dof(surface.node, Component::ux));
        if (surface.automatic_stick_stiffness)
          law.stick_stiffness = 1e4 * system.stiffness.coeff(equation, equation);
        law.stick_damping = 2 * std::sqrt(law.stick_stiffness * system.mass.coeff(equation, equation));
      }
  }

  namespace
  {
    /// prepare_analysis of the buildings [first, last) of `model`.
    Analysis
    prepare_buildings(const InputFile &input, Model &&built, const ModalParameters &modal,
                      const unsigned int n_modes, const unsigned int n_model_modes,
                      const std::array<unsigned int, 2> buildings)
    {
      Analysis analysis;
      analysis.model           = std::move(built);
      const Model &model       = analysis.model;
      const EquationRange kept = equations_of(model, buildings);
      analysis.system          = assemble_mass_and_stiffness(model, kept);
      LinearSystem &system     = analysis.system;
      check_matrices_in_range(input, model, buildings, system);
      check_stable_under_gravity(input, model, buildings, system);
      set_stick_stiffnesses(input, system, kept, analysis.model);
      if (model.gravity_analysis.enabled)
        {
          if (kept[0] != 0 || kept[1] != model.n_equations())
            input.fail("Model/Gravity analysis/Type",
                       "a gravity analysis needs the whole model on one process "
                       "(not with Time integration/Partition = buildings)");
          set_gravity_state(analysis);
        }
      // the modes of the state the dynamics start from
      const SparseMatrix &modal_stiffness =
        analysis.gravity.active ? analysis.gravity.tangent : system.stiffness;

      std::vector<std::array<double, 2>> coefficients;
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        {
          const Building &building = model.buildings[b];
          const auto      range    = model.equation_range(b);
          check_damped_modes(input, model, b);
          const unsigned wanted = std::max(n_modes, building.damping.n_modes_needed());
          // no modes reported nor needed for damping: no eigenproblem (a
          // large model with given Rayleigh coefficients); none of another
          // rank's building (its rows are empty here)
          const bool ours = b >= buildings[0] && b < buildings[1];
          analysis.building_modes.push_back(
            wanted == 0 || !ours ?
              Modes() :
              modes_of(input, modal, block(system.mass, range), block(modal_stiffness, range),
                       system.influence.segment(range[0], range[1] - range[0]), wanted,
                       "building '" + building.name + "'"));
          coefficients.push_back(
            ours ? rayleigh_coefficients_of(input, building, b, analysis.building_modes.back()) :
                   std::array<double, 2>{{0, 0}});
        }
      assemble_damping(model, coefficients, system);
      check_damping_in_range(input, model, buildings, system);
      assemble_modal_damping(analysis);
      if (n_model_modes > 0)
        analysis.modes = modes_of(input, modal, system.mass, modal_stiffness, system.influence,
                                  n_model_modes, "the model");
      if (model.dimension == 3)
        add_plan_participations(analysis);
      analysis.warnings = analysis.model.warnings; // the builder's, then the damping's
      for (std::string &warning : damping_warnings(analysis))
        analysis.warnings.push_back(std::move(warning));
      return analysis;
    }
  } // namespace

  Analysis
  prepare_analysis(const InputFile &input, const ModelParameters &model_parameters,
                   const ContactParameters &contact, const SpringParameters &springs,
                   const FrictionParameters &friction, const ModalParameters &modal,
                   const unsigned int n_modes)
  {
    Model model = build_model(model_parameters, contact, input, springs, friction);
    const std::array<unsigned int, 2> all{{0, unsigned(model.buildings.size())}};
    return prepare_buildings(input, std::move(model), modal, n_modes, n_modes, all);
  }

  Analysis
  prepare_analysis_of_buildings(const InputFile &input, Model model, const ModalParameters &modal,
                                const std::array<unsigned int, 2> buildings,
                                const unsigned int                n_building_modes)
  {
    AssertThrow(buildings[0] <= buildings[1] && buildings[1] <= model.buildings.size(),
                dealii::ExcMessage("buildings beyond the model's"));
    return prepare_buildings(input, std::move(model), modal, n_building_modes, 0, buildings);
  }
} // namespace poundfe
