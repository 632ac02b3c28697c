// The run's report observer (report/run_summary.h): summary.json, impacts.csv
// and the peak profiles; the figures are RunPlots' (report/run_plots.cc).
#include <poundfe/report/run_summary.h>
#include <poundfe/report/run_plots.h>
#include <poundfe/assembly/iterative_solver.h>
#include <poundfe/output/drift_limits.h>
#include <poundfe/output/section_limit_states.h>
#include <poundfe/base/exceptions.h>
#include <poundfe/dynamics/modal_damping_assembly.h>
#include <poundfe/model/parameters.h>
#include <poundfe/output/stick_slip_report.h>
#include <poundfe/output/foundation_report.h>
#include <poundfe/output/link_report.h>
#include <poundfe/output/append_file.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/json_writer.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/response_range.h>
#include <poundfe/output/demand_table.h>
#include <poundfe/output/memory_results.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    /// Keys and units of a hysteretic element: a hinge acts on a rotation
    /// with a moment, a Bouc-Wen storey on a drift with a force.
    struct ElementUnits
    {
      const char *kind, *yield, *peak, *plastic, *force;
    };

    ElementUnits
    units_of(const ElementKind kind)
    {
      switch (kind)
        {
          case ElementKind::hinge:
            return {"hinge", "yield_rotation_rad", "peak_rotation_rad",
                    "peak_plastic_rotation_rad", "peak_moment_N_m"};
          case ElementKind::storey:
            return {"storey", "yield_drift_m", "peak_drift_m", "peak_plastic_drift_m",
                    "peak_force_N"};
          case ElementKind::gap:
            return {"gap", "yield_deformation_m", "peak_penetration_m", "peak_plastic_m",
                    "peak_force_N"};
          case ElementKind::spring:
            return {"spring", "yield_deformation_m", "peak_deformation_m", "peak_plastic_m",
                    "peak_force_N"};
          case ElementKind::friction:
            return {"friction", "yield_deformation_m", "peak_displacement_m", "peak_slip_m",
                    "peak_force_N"};
          case ElementKind::link:
            return {"link", "yield_deformation_m", "peak_deformation_m", "peak_plastic_m",
                    "peak_force_N"};
          case ElementKind::member: // end I's rotation from the chord, its moment
            return {"member", "yield_rotation_rad", "peak_rotation_rad",
                    "peak_plastic_rotation_rad", "peak_moment_N_m"};
          case ElementKind::foundation:
            return {"foundation", "yield_deformation_m", "peak_deformation_m", "peak_plastic_m",
                    "peak_force_N"};
        }
      throw std::logic_error("units_of: unknown element kind");
    }
  } // namespace

  void
  write_modes(JsonWriter &json, const std::string &key, const Modes &modes)
  {
    std::vector<double> f, T;
    for (unsigned int i = 0; i < modes.n_modes(); ++i)
      {
        f.push_back(modes.frequency(i));
        T.push_back(modes.period(i));
      }
    json.begin_object(key)
      .value("frequencies_hz", f)
      .value("periods_s", T)
      .value("participating_mass_ratio_x", modes.participating_mass_ratio);
    if (!modes.participating_mass_ratio_y.empty())
      json.value("participating_mass_ratio_y", modes.participating_mass_ratio_y)
        .value("participating_mass_ratio_rz", modes.participating_mass_ratio_rz);
    json.end_object();
  }

  void
  write_damping(JsonWriter &json, const Analysis &analysis, const unsigned int b)
  {
    const RayleighDamping &d = analysis.model.buildings[b].damping;
    json.value("damping_type", damping_type_names().name(d.kind))
      .value("rayleigh_a0", analysis.system.rayleigh[b][0])
      .value("rayleigh_a1", analysis.system.rayleigh[b][1]);
    if (d.is_modal())
      json.value("modal_damping_ratios", modal_damping_ratios(d, analysis.building_modes[b]));
  }

  void
  write_model(JsonWriter &json, const Analysis &analysis)
  {
    const Model &model = analysis.model;
    json.begin_object("model")
      .value("nodes", model.n_nodes())
      .value("dofs", model.n_dofs())
      .value("equations", model.n_equations())
      .value("members", static_cast<unsigned int>(model.members.size() + model.members_3d.size()))
      .value("storey_links", static_cast<unsigned int>(model.links.size()));
    if (model.dimension == 3) // the storeys of 3D shear buildings
      json.value("resisting_planes", static_cast<unsigned int>(model.plane_links.size()));
    json.value("buildings", static_cast<unsigned int>(model.buildings.size())).end_object();
    write_gravity_state(json, analysis.gravity);
    write_modes(json, "modes", analysis.modes);
  }

  void
  write_gravity_state(JsonWriter &json, const GravityState &gravity)
  {
    if (!gravity.active)
      return;
    json.begin_object("gravity")
      .value("load_steps", gravity.steps)
      .value("iterations", gravity.iterations)
      .value("step_cuts", gravity.cuts)
      .value("peak_displacement_m", gravity.peak_displacement)
      .value("peak_displacement_at", gravity.peak_where)
      .value("base_vertical_reactions_N", gravity.base_reactions)
      .end_object();
  }

  RunSummary::RunSummary(const Analysis &analysis, const RunParameters &parameters,
                         const Excitation &excitation, const PeakResponse &peaks,
                         const ResponseRange &range, const BaseShearPeaks &base_shears,
                         const PlanResponse &plan, const std::string &directory, const bool plots,
                         const std::string &solver, const std::string &tangent_update,
                         std::vector<std::string> files, MemoryResults *memory,
                         const SectionLimitStates *section_limits)
    : analysis(analysis)
    , parameters(parameters)
    , excitation(excitation)
    , peaks(peaks)
    , range(range)
    , directory(directory)
    , plots(plots)
    , solver(solver)
    , tangent_update(tangent_update)
    , files(std::move(files))
    , base_shears(base_shears)
    , plan(plan)
    , memory(memory)
    , section_limits(section_limits)
  {}

  void
  RunSummary::finish(const ResponseView &state, const RunStatus &status)
  {
    // What a file that cannot be written (a full disk) changes in the
    // summary: the status, and the message names the file and the reason.
    RunStatus reported = status;
    auto      attempt  = [&](const auto &write) {
      try
        {
          write();
          return true;
        }
      catch (const OutputError &e)
        {
          if (reported.message.find(e.what()) == std::string::npos)
            reported.message += std::string(reported.message.empty() ? "" : "; ") + e.what();
          reported.kind          = RunStatus::Kind::failed;
          reported.output_failed = true;
          return false;
        }
    };
    // the order of summary.json's `files`: the time series, then these;
    // after a failure of output only those that exist (a file that could not
    // be written is removed, not left incomplete)
    std::vector<std::string> written;
    for (const std::string &file : files)
      if (memory || !status.output_failed || std::filesystem::exists(directory + "/" + file))
        written.push_back(file);
    if (attempt([&]() { write_profiles(); }))
      written.insert(written.end(), {"drift_profile.csv", "acceleration_profile.csv"});
    if (parameters.output.demand_tables)
      {
        std::vector<std::string> tables;
        if (attempt([&]() { tables = write_demand_tables(state); }))
          written.insert(written.end(), tables.begin(), tables.end());
      }
    if (!analysis.model.gaps.empty() && attempt([&]() { write_impacts(state); }))
      written.push_back("impacts.csv");
    if (!analysis.model.friction_surfaces.empty() &&
        attempt([&]() { write_friction_episodes(directory, state, status.end_time, memory); }))
      written.push_back("friction_episodes.csv");
    if (plots && !memory && !reported.output_failed) // before summary.json, which lists them
      for (const std::string &png :
           RunPlots(analysis, parameters, excitation, peaks, base_shears, directory, files)
             .draw(state))
        written.push_back(png);
    written.push_back("summary.json");
    write_json(state, reported, written); // its own failure goes to the caller
  }

  namespace
  {
    /// drift_profile.csv's header: in 3D along x, along y and about z (a
    /// storey's twist); with fibre members each storey's damage state (its
    /// worst member's limit).
    std::string
    drift_profile_header(const bool three_d, const bool damage_states)
    {
      return (three_d ? std::string("building,storey,peak_drift_ratio_x,time_of_peak_x_s,"
                                    "peak_drift_ratio_y,time_of_peak_y_s,peak_twist_rad,"
                                    "time_of_peak_twist_s") :
                        std::string("building,storey,peak_drift_ratio,time_of_peak_s")) +
             (damage_states ? ",damage_state\n" : "\n");
    }

    /// acceleration_profile.csv's header: in 3D along x, along y and about
    /// z (a floor's rotation and angular acceleration), and the floor's
    /// peak resultant displacement.
    std::string
    acceleration_profile_header(const bool three_d)
    {
      return three_d ?
               "building,floor,peak_absolute_acc_x_m_s2,peak_floor_disp_x_m,"
               "peak_absolute_acc_y_m_s2,peak_floor_disp_y_m,peak_angular_acc_rad_s2,"
               "peak_floor_rot_rad,peak_resultant_disp_m\n" :
               "building,floor,peak_absolute_acc_m_s2,peak_floor_disp_m\n";
    }

    /// A profile's row: `name`, then every number in the shortest text that
    /// reads back exactly (std::to_string kept 6 decimals: 3 digits of a
    /// drift ratio); `last` ends the row (a damage state, if any).
    void
    append_profile_row(std::string &text, const std::string &name,
                       const std::initializer_list<double> values,
                       const std::string &last = std::string())
    {
      text += name;
      for (const double *v = values.begin(); v != values.end(); ++v)
        {
          append_number(text, *v);
          if (v + 1 != values.end())
            text += ',';
        }
      text += last + '\n';
    }
  } // namespace

  void
  RunSummary::write_profiles() const
  {
    // 3D: along x, along y and about z (a storey's twist, a floor's rotation
    // and angular acceleration), every column named with its direction, and
    // the floor's peak resultant displacement
    const Model         &model  = analysis.model;
    const FloorResponse &floors = peaks.floors();
    const FloorResponse *y = peaks.floors_y(), *rz = peaks.floors_rz();
    std::string drift = drift_profile_header(y != nullptr, static_cast<bool>(section_limits));
    std::string accel = acceleration_profile_header(y != nullptr);
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      for (unsigned int f = 0; f < model.buildings[b].floors.size(); ++f)
        {
          const unsigned int i    = floors.index(b, f);
          const std::vector<int> damage =
            section_limits ? section_limits->storey_worst_limits(model, b) : std::vector<int>();
          const std::string  name = model.buildings[b].name + "," + std::to_string(f + 1) + ",";
          const std::string damage_column =
            section_limits ? std::string(",") + damage_state_name(damage[f]) : std::string();
          if (!y)
            {
              append_profile_row(drift, name,
                                 {floors.peak_drift_ratio()[i], floors.peak_drift_time()[i]},
                                 damage_column);
              append_profile_row(accel, name,
                                 {floors.peak_acceleration()[i], floors.peak_displacement()[i]});
              continue;
            }
          const double height = model.buildings[b].floors[f].storey_height;
          append_profile_row(drift, name,
                             {floors.peak_drift_ratio()[i], floors.peak_drift_time()[i],
                              y->peak_drift_ratio()[i], y->peak_drift_time()[i],
                              rz->peak_drift_ratio()[i] * height, rz->peak_drift_time()[i]},
                             damage_column);
          append_profile_row(accel, name,
                             {floors.peak_acceleration()[i], floors.peak_displacement()[i],
                              y->peak_acceleration()[i], y->peak_displacement()[i],
                              rz->peak_acceleration()[i], rz->peak_displacement()[i],
                              b < plan.buildings().size() ? // observed
                                plan.buildings()[b].storeys[f].resultant_displacement :
                                0.0});
        }
    write_result_text(memory, directory, "drift_profile.csv", drift);
    write_result_text(memory, directory, "acceleration_profile.csv", accel);
  }

  std::vector<std::string>
  RunSummary::write_demand_tables(const ResponseView &state) const
  {
    const Model         &model  = analysis.model;
    const FloorResponse &floors = peaks.floors();
    ResponseDemands      demands;
    add_plan_demands(peaks, excitation, demands); // the PGA, and a 3D model's y and twist
    demands.peak_drift            = floors.peak_drift_ratio();
    demands.peak_acceleration     = floors.peak_acceleration();
    demands.residual_drift        = floors.drift_ratio(); // at the end of the run
    demands.peak_displacement     = floors.peak_displacement();
    demands.residual_displacement = floors.displacement();
    gap_demands(model, state.impact_log().impacts(), peaks.n_hysteretic(), demands.impacts,
                demands.impact_force, demands.impact_velocity);
    std::vector<std::string> files;
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        DemandTable table(model, b, true);
        table.add(demands);
        files.push_back(demand_table_file(model, b));
        write_result_text(memory, directory, files.back(), table.csv());
      }
    return files;
  }

  void
  RunSummary::write_impacts(const ResponseView &state) const
  {
    const Model       &model = analysis.model;
    const unsigned int first   = peaks.n_hysteretic();
    const bool         bumpers = model.bumper.law != BumperLaw::none;
    std::string csv = "gap,buildings,level_m,start_time_s,max_penetration_time_s,end_time_s,"
                      "approach_velocity_m_s,separation_velocity_m_s,max_penetration_m,"
                      "peak_force_N,impulse_N_s" +
                      std::string(model.dimension == 3 ? ",plan_x_m,plan_y_m,contact,tangential_impulse_N_s" : "") +
                      std::string(bumpers ? ",touched\n" : "\n");
    for (const Impact &impact : state.impact_log().impacts())
      {
        const Gap         &gap = model.gaps[impact.element - first];
        std::ostringstream row;
        row.precision(17); // times to the nanosecond at any length of run
        row << gap.label << "," << model.buildings[gap.buildings[0]].name << "|"
            << (gap.nodes[0] >= 0 && gap.nodes[1] >= 0 ? model.buildings[gap.buildings[1]].name :
                                                         "barrier")
            << "," << gap.level << "," << impact.start_time << "," << impact.max_penetration_time
            << ",";
        if (impact.end_time >= 0)
          row << impact.end_time;
        row << "," << impact.approach_velocity << "," << impact.separation_velocity << ","
            << impact.max_penetration << "," << impact.peak_force << "," << impact.impulse;
        if (model.dimension == 3)
          row << "," << impact.point[0] << "," << impact.point[1] << ","
              << (gap.on_column ? "slab-column" : "slab-slab") << "," << impact.tangential_impulse;
        if (bumpers) // which surface the impact reached
          row << "," << (impact.structure ? (impact.bumper ? "bumper+structure" : "structure") :
                                            "bumper");
        row << "\n";
        csv += row.str();
      }
    write_result_text(memory, directory, "impacts.csv", csv);
  }

  void
  RunSummary::write_json(const ResponseView &state, const RunStatus &status,
                         const std::vector<std::string> &written) const
  {
    // streamed into its file: a large model's is large
    std::unique_ptr<AtomicFile> file =
      memory ? nullptr : std::make_unique<AtomicFile>(directory + "/summary.json");
    JsonWriter json(file.get());
    begin_summary(json, "run", parameters.time_history.input, status.name());
    if (status.kind == RunStatus::Kind::failed)
      json.value("message", status.message);
    std::vector<std::string> warnings = analysis.warnings; // the input's, then the response's
    for (const std::string &warning : range.warnings())
      warnings.push_back(warning);
    json.value("warnings", warnings);
    write_model(json, analysis);
    if (analysis.model.dimension == 3)
      write_ratio_definitions(json);
    const GroundMotion &motion = excitation.ground_motion();
    json.begin_object("ground_motion")
      .value("description", motion.description())
      .value("pga_m_s2", motion.peak())
      .value("pga_g", motion.peak() / standard_gravity)
      .value("duration_s", motion.duration())
      .value("time_step_s", motion.time_step());
    if (analysis.model.dimension == 3) // each component as applied, after the incidence rotation
      {
        const std::array<double, 2> applied = excitation.applied_horizontal_peaks();
        json.value("pga_x_m_s2", applied[0])
          .value("pga_y_m_s2", applied[1])
          .value("pga_x_g", applied[0] / standard_gravity)
          .value("pga_y_g", applied[1] / standard_gravity);
        if (excitation.has_horizontal_pair() && !excitation.second_ground_motion().empty())
          json.value("second_description", excitation.second_ground_motion().description())
            .value("second_pga_m_s2", excitation.second_ground_motion().peak());
      }
    if (excitation.has_vertical()) // Components = 3
      json.value("vertical_description", excitation.vertical_ground_motion().description())
        .value("vertical_pga_m_s2", excitation.vertical_ground_motion().peak());
    json.end_object();
    write_buildings(json);
    if (peaks.n_hysteretic() > 0)
      write_hinges(json, state);
    if (section_limits)
      section_limits->write_json(json, analysis.model);
    if (peaks.n_gaps() > 0)
      write_gaps(json, state);
    write_springs_and_friction(json, state, peaks, status.end_time);
    write_links(json, state, peaks);
    write_foundations(json, state, peaks);
    write_energy_and_newton(json, state);
    write_run(json, status, written);
    json.end_object();
    if (memory)
      return memory->set_text("summary.json", json.str());
    json.finish();
    file->commit();
  }

  namespace
  {
    /// Building b's peak base shear and its time: in 3D along x, along y
    /// and the resultant, each named by its direction; nothing for a run
    /// stopped before its start.
    void
    write_base_shear(JsonWriter &json, const BaseShearPeaks &base_shears, const unsigned int b)
    {
      if (b < base_shears.peak_y().size())
        json.value("peak_base_shear_x_N", base_shears.peak()[b])
          .value("time_of_peak_base_shear_x_s", base_shears.time_of_peak()[b])
          .value("peak_base_shear_y_N", base_shears.peak_y()[b])
          .value("time_of_peak_base_shear_y_s", base_shears.time_of_peak_y()[b])
          .value("peak_base_shear_resultant_N", base_shears.peak_resultant()[b])
          .value("time_of_peak_base_shear_resultant_s", base_shears.time_of_peak_resultant()[b]);
      else if (b < base_shears.peak().size())
        json.value("peak_base_shear_N", base_shears.peak()[b])
          .value("time_of_peak_base_shear_s", base_shears.time_of_peak()[b]);
    }
  } // namespace

  void
  RunSummary::write_buildings(JsonWriter &json) const
  {
    const Model         &model  = analysis.model;
    const FloorResponse &floors = peaks.floors();
    json.begin_array("buildings");
    for (unsigned int b = 0; b < model.buildings.size(); ++b)
      {
        const Building &building = model.buildings[b];
        json.begin_object()
          .value("name", building.name)
          .value("type", building_type_names().name(building.type))
          .value("storeys", static_cast<unsigned int>(building.floors.size()));
        write_damping(json, analysis, b);
        write_modes(json, "modes", analysis.building_modes[b]);
        const unsigned int roof = floors.index(b, building.floors.size() - 1);
        json.value("peak_roof_displacement_m", floors.peak_displacement()[roof]);
        double residual = 0; // the largest residual drift ratio of the building
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          residual = std::max(residual, std::abs(floors.drift_ratio()[floors.index(b, f)]));
        write_base_shear(json, base_shears, b);
        json.value("max_residual_drift_ratio", residual);
        if (model.dimension == 3)
          write_plan_response(json, plan, b);
        json.begin_array("storeys");
        for (unsigned int f = 0; f < building.floors.size(); ++f)
          {
            const unsigned int i = floors.index(b, f);
            json.begin_object()
              .value("storey", f + 1)
              .value("height_m", building.floors[f].storey_height)
              .value("peak_drift_ratio", floors.peak_drift_ratio()[i])
              .value("time_of_peak_drift_s", floors.peak_drift_time()[i])
              .value("residual_drift_ratio", floors.drift_ratio()[i])
              .value("peak_absolute_floor_acceleration_m_s2", floors.peak_acceleration()[i])
              .value("peak_floor_displacement_m", floors.peak_displacement()[i]);
            if (model.dimension == 3)
              write_storey_plan(json, i);
            json.end_object();
          }
        json.end_array();
        write_drift_checks(json, b);
        if (section_limits) // each storey's worst member (theory §13.5)
          {
            std::vector<std::string> states;
            for (const int worst : section_limits->storey_worst_limits(model, b))
              states.push_back(damage_state_name(worst));
            json.value("storey_damage_states", states);
          }
        json.end_object();
      }
    json.end_array();
  }

  void
  RunSummary::write_storey_plan(JsonWriter &json, const unsigned int i) const
  {
    // the keys above are along x; along y and about z with the same peaks
    const FloorResponse &y = *peaks.floors_y(), &rz = *peaks.floors_rz();
    json.value("peak_drift_ratio_y", y.peak_drift_ratio()[i])
      .value("time_of_peak_drift_y_s", y.peak_drift_time()[i])
      .value("residual_drift_ratio_y", y.drift_ratio()[i])
      .value("peak_absolute_floor_acceleration_y_m_s2", y.peak_acceleration()[i])
      .value("peak_floor_displacement_y_m", y.peak_displacement()[i])
      .value("peak_floor_rotation_rad", rz.peak_displacement()[i])
      .value("peak_floor_angular_acceleration_rad_s2", rz.peak_acceleration()[i]);
  }

  void
  RunSummary::write_ratio_definitions(JsonWriter &json) const
  {
    // what each ratio of a 3D run's summary is divided by (the plan ratios
    // are the ones a reader cannot guess); a list of {"key", "divided_by"},
    // so that a key of the summary appears once as a key
    using Ratio = std::pair<const char *, const char *>;
    json.begin_array("ratios");
    for (const auto &[key, definition] :
         {Ratio{"participating_mass_ratio_x", "effective modal mass along x / total mass along x"},
          Ratio{"participating_mass_ratio_y", "effective modal mass along y / total mass along y"},
          Ratio{"participating_mass_ratio_rz",
                "effective modal polar moment about z / total polar moment of the floor masses"},
          Ratio{"peak_drift_ratio", "inter-storey drift of the mass centres along x / storey height"},
          Ratio{"peak_drift_ratio_y", "inter-storey drift of the mass centres along y / storey height"},
          Ratio{"torsional_irregularity_x|y",
                "largest corner drift peak / mean of the largest and smallest corner drift peaks "
                "of the storey along that axis; null along an axis without drift"},
          Ratio{"torsional_irregularity_at_peak_x|y",
                "largest corner drift / mean of the largest and smallest signed corner drifts, at "
                "the instant the largest corner drift peaks; null along an axis without drift"},
          Ratio{"ductility", "peak deformation / yield deformation of the element"},
          Ratio{"max_relative_balance_error",
                "|input - (kinetic + damping + strain + dissipated)| / largest energy term so far"}})
      json.begin_object().value("key", key).value("divided_by", definition).end_object();
    json.end_array();
  }

  void
  RunSummary::write_hinges(JsonWriter &json, const ResponseView &state) const
  {
    const Model       &model        = analysis.model;
    const unsigned int n_hysteretic = peaks.n_hysteretic();
    json.begin_array("hinges");
    for (unsigned int h = 0; h < n_hysteretic; ++h)
      {
        const NonlinearElement &e     = state.elements[h];
        const ElementUnits     units = units_of(e.kind);
        json.begin_object()
          .value("label", e.label)
          .value("kind", units.kind)
          .value("building", model.buildings[e.building].name)
          .value(units.yield, e.yield_deformation())
          .value(units.peak, peaks.peak_deformation()[h])
          .value("time_of_peak_deformation_s", peaks.time_of_peak_deformation()[h])
          .value("ductility", peaks.ductility(h))
          .value(units.plastic, peaks.peak_plastic_deformation()[h])
          .value(units.force, peaks.peak_force()[h])
          .value("dissipated_energy_J", state.dissipated_energy(h))
          .end_object();
      }
    json.end_array();
  }

  namespace
  {
    /// summary.json's `contact` of rigid contact (Contact/Model = nonsmooth):
    /// the model, its scheme and LCP solver, the LCPs' counts (Moreau-Jean's
    /// solves in the run's statistics) and Newton's e of each gap; no law
    /// force parameter, which rigid contact ignores.
    void
    write_rigid_contact(JsonWriter &json, const Model &model, const IterationStatistics &stats,
                        const TimeIntegrationParameters &time_integration)
    {
      const MoreauJeanParameters &moreau_jean = time_integration.moreau_jean;
      const LcpOptions           &lcp         = moreau_jean.lcp;
      const ContactProblemCounts &counts      = stats.contact;
      const bool                  friction    = moreau_jean.friction_coefficient > 0;
      json.begin_object("contact")
        .value("model", "nonsmooth")
        .value("integrator", "Moreau-Jean")
        .value("theta", moreau_jean.theta)
        .value("lcp_solver", lcp_solver_names().name(lcp.solver))
        .value("lcp_tolerance", lcp.tolerance)
        .value("lcp_iteration_limit", lcp.max_iterations)
        .value("friction_coefficient", moreau_jean.friction_coefficient);
      if (friction)
        json.value("friction_solver", friction_solver_names().name(moreau_jean.friction.solver));
      // the step's problems: LCPs, or friction-contact problems with friction
      json.begin_object(friction ? "friction_contact" : "lcp")
        .value("solves", counts.solves)
        .value("max_iterations", counts.max_iterations)
        .value("mean_iterations",
               counts.solves > 0 ? double(counts.iterations) / counts.solves : 0.0)
        .value("max_residual", counts.max_residual)
        .end_object();
      json.begin_array("pairs");
      for (const Gap &gap : model.gaps)
        json.begin_object()
          .value("gap", gap.label)
          .value("coefficient_of_restitution", time_integration.restitution)
          .end_object();
      json.end_array().end_object();
    }
  } // namespace

  void
  RunSummary::write_gaps(JsonWriter &json, const ResponseView &state) const
  {
    const Model       &model        = analysis.model;
    const unsigned int n_hysteretic = peaks.n_hysteretic();
    const unsigned int n_gaps       = peaks.n_gaps();
    const ContactLawParameters &law          = model.contact;
    if (parameters.time_history.time_integration.contact_model == ContactModel::nonsmooth)
      write_rigid_contact(json, model, state.statistics(), parameters.time_history.time_integration);
    else
      {
        json.begin_object("contact").value("law", law.law).value("stiffness", law.stiffness);
        // an undamped law has no damping and no restitution of its own; a
        // given damping parameter owes nothing to the coefficient of restitution
        const ContactDampingFrom from = parameters.contact.damping_from;
        if (contact_law_is_damped(law.law))
          json.value("damping_parameter", law.damping)
            .value("damping_from", contact_damping_from_names().name(from));
        if (contact_law_is_damped(law.law) && from != ContactDampingFrom::given)
          json.value("coefficient_of_restitution", parameters.contact.restitution);
        json.end_object();
      }
    write_bumper(json, state);
    std::vector<unsigned int> count(n_gaps, 0);
    std::vector<double>       peak(n_gaps, 0.0), penetration(n_gaps, 0.0), impulse(n_gaps, 0.0);
    for (const Impact &impact : state.impact_log().impacts())
      {
        const unsigned int g = impact.element - n_hysteretic;
        ++count[g];
        peak[g]        = std::max(peak[g], impact.peak_force);
        penetration[g] = std::max(penetration[g], impact.max_penetration);
        impulse[g] += impact.impulse;
      }
    json.begin_array("gaps");
    for (unsigned int g = 0; g < n_gaps; ++g)
      {
        const Gap &gap = model.gaps[g];
        json.begin_object()
          .value("label", gap.label)
          .value("level_m", gap.level)
          .value("initial_gap_m", gap.initial_gap)
          .value("effective_mass_kg", gap.effective_mass)
          .value("impacts", count[g])
          .value("peak_force_N", peak[g])
          .value("max_penetration_m", penetration[g])
          .value("total_impulse_N_s", impulse[g])
          .value("dissipated_energy_J", state.dissipated_energy(n_hysteretic + g))
          .end_object();
      }
    json.end_array();
  }

  void
  RunSummary::write_energy_and_newton(JsonWriter &json, const ResponseView &state) const
  {
    const EnergyBalance energy = state.energy();
    json.begin_object("energy")
      .value("initial_J", energy.initial)
      .value("input_J", energy.input)
      .value("kinetic_J", energy.kinetic)
      .value("damping_J", energy.damping)
      .value("strain_J", energy.strain)
      .value("hysteretic_J", energy.hysteretic)
      .value("contact_J", energy.contact)
      .value("friction_J", energy.friction)
      .value("links_J", energy.links)
      .value("belt_J", energy.belt);
    if (!analysis.model.foundations.empty())
      json.value("foundation_J", energy.foundation);
    if (analysis.gravity.active) // the gravity loads' work, held from t = 0
      json.value("constant_load_J", energy.constant_load);
    json
      .value("max_relative_balance_error", state.max_energy_error())
      .end_object();
    const IterationStatistics &stats = state.statistics();
    json.begin_object("newton")
      .value("nonlinear_elements", static_cast<unsigned int>(state.elements.size()))
      .value("tangent_update", state.elements.size() > 0 ? tangent_update : "none")
      .value("mean_iterations_per_step",
             stats.steps > 0 ? double(stats.iterations) / stats.steps : 0.0)
      .value("max_iterations_per_step", stats.max_iterations)
      .value("step_cuts", static_cast<unsigned long>(stats.step_cuts))
      .value("event_refinements", static_cast<unsigned long>(stats.event_refinements))
      .value("contact_refinements", static_cast<unsigned long>(stats.contact_refinements))
      .value("accuracy_refinements", static_cast<unsigned long>(stats.accuracy_refinements))
      .value("woodbury_solves", static_cast<unsigned long>(stats.woodbury_solves))
      .value("refactorizations", static_cast<unsigned long>(stats.refactorizations))
      .value("nonlinear_solver", nonlinear_solver_names().name(
                                   parameters.time_history.time_integration.newmark.newton.nonlinear_solver))
      .value("full_newton_retries", static_cast<unsigned long>(stats.full_newton_retries))
      .value("line_searches", static_cast<unsigned long>(stats.line_searches))
      .value("smallest_time_step_s", stats.smallest_time_step)
      .value("steps_including_substeps", static_cast<unsigned long>(stats.steps))
      .end_object();
    if (linear_solver_is_iterative(solver))
      {
        const IterativeSolveCounts &linear = stats.linear;
        json.begin_object("iterative_solver")
          .value("preconditioner_builds", linear.preconditioner_builds)
          .value("rebuilds_for_slow_solves", linear.rebuilds_slow)
          .value("rebuilds_for_failed_solves", linear.rebuilds_failed)
          .value("linear_solves", linear.solves)
          .value("mean_linear_iterations_per_solve",
                 linear.solves > 0 ? double(linear.iterations) / linear.solves : 0.0)
          .value("max_linear_iterations_per_solve", linear.max_iterations)
          .end_object();
      }
  }

  void
  RunSummary::write_run(JsonWriter &json, const RunStatus &status,
                        const std::vector<std::string> &written) const
  {
    const TimeIntegrationParameters &time_integration = parameters.time_history.time_integration;
    const NewmarkParameters         &newmark          = time_integration.newmark;
    json.begin_object("analysis");
    if (time_integration.contact_model == ContactModel::nonsmooth) // rigid contact
      json.value("integrator", "Moreau-Jean")
        .value("theta", time_integration.moreau_jean.theta)
        .value("lcp_solver", lcp_solver_names().name(time_integration.moreau_jean.lcp.solver));
    else
      json.value("integrator", "Newmark").value("gamma", newmark.gamma).value("beta", newmark.beta);
    json.value("time_step_s", newmark.time_step)
      .value("end_time_s", status.end_time)
      .value("steps", status.steps)
      .value("linear_solver", solver)
      .value("wall_time_s", status.wall_time)
      .value("steps_per_second", status.steps / std::max(status.wall_time, 1e-12))
      .end_object();
    json.begin_object("output")
      .value("format", output_format_names().name(parameters.output.recorders.format))
      .value("files", written)
      .end_object();
  }

  std::vector<DriftCheck>
  RunSummary::drift_checks(const unsigned int b) const
  {
    const FloorResponse &floors = peaks.floors();
    std::vector<double>  peak;
    for (unsigned int f = 0; f < analysis.model.buildings[b].floors.size(); ++f)
      peak.push_back(floors.peak_drift_ratio()[floors.index(b, f)]);
    return check_drift_limits(parameters.drift_limits.limits(), peak);
  }

  void
  RunSummary::write_drift_checks(JsonWriter &json, const unsigned int b) const
  {
    if (parameters.drift_limits.limits().empty())
      return; // the summary of a run without limits is unchanged
    json.begin_array("drift_limits");
    for (const DriftCheck &check : drift_checks(b))
      json.begin_object()
        .value("name", check.limit.name)
        .value("drift_ratio_limit", check.limit.drift_ratio)
        .value("peak_drift_ratio", check.peak_drift_ratio)
        .value("storey_of_peak", check.storey_of_peak)
        .value("storeys_exceeding",
               std::vector<double>(check.storeys_exceeding.begin(), check.storeys_exceeding.end()))
        .value("passes", check.passes)
        .end_object();
    json.end_array();
  }
} // namespace poundfe
