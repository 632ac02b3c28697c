#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/output/atomic_file.h>
#include <poundfe/output/memory_results.h>
#include <poundfe/output/number_text.h>
#include <poundfe/output/output_directory.h>
#include <poundfe/output/output_queue.h>
#include <poundfe/output/peak_response.h>
#include <poundfe/output/recorders.h>
#include <poundfe/output/section_states.h>
#include <poundfe/elements/member_element.h>
#include <poundfe/output/storey_forces.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  namespace
  {
    struct QuantityInfo
    {
      RecordedQuantity quantity;
      const char      *name; // in `Record`
      const char      *stem; // of its file(s): output/table_writer.h
    };

    const QuantityInfo quantities[] = {
      {RecordedQuantity::floor_displacement, "floor displacement", "floor_displacement"},
      {RecordedQuantity::floor_velocity, "floor velocity", "floor_velocity"},
      {RecordedQuantity::floor_acceleration, "floor acceleration", "floor_acceleration"},
      {RecordedQuantity::drift_ratio, "storey drift ratio", "drift"},
      {RecordedQuantity::storey_shear, "storey shear", "storey_shear"},
      {RecordedQuantity::base_shear, "base shear", "base_shear"},
      {RecordedQuantity::residual_drift, "residual drift", "residual_drift"},
      {RecordedQuantity::member_forces, "member end forces", "member_forces"},
      {RecordedQuantity::hinge_states, "hinge states", "hinges"},
      {RecordedQuantity::gap_states, "gap states", "contact_force"},
      {RecordedQuantity::energy, "energy", "energy"},
      {RecordedQuantity::ground_motion, "ground motion", "ground_motion"},
      {RecordedQuantity::phase_portrait, "phase portrait", "phase_portrait"},
      {RecordedQuantity::corner_acceleration, "corner acceleration", "corner_acceleration"},
      {RecordedQuantity::section_states, "section states", "sections"}};

    const QuantityInfo &
    info(const RecordedQuantity q)
    {
      return quantities[static_cast<unsigned int>(q)];
    }

    std::string
    trim(const std::string &s)
    {
      const auto begin = s.find_first_not_of(" \t");
      if (begin == std::string::npos)
        return "";
      return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
    }

    /// Fills the values of one row from the state.
    using RowFunction = std::function<void(const ResponseView &, std::vector<double> &)>;

    /// A time series: a row (time, values...) every `every` steps.
    class SeriesRecorder : public PeriodicObserver
    {
    public:
      SeriesRecorder(std::unique_ptr<TableWriter> table, const unsigned int every, RowFunction row)
        : PeriodicObserver(every)
        , table(std::move(table))
        , row(std::move(row))
      {}

      void
      write(const ResponseView &state) override
      {
        row(state, values);
        table->add_row(state.time(), values);
      }

      void
      finish(const ResponseView &, const RunStatus &) override
      {
        table->commit();
      }

    private:
      std::unique_ptr<TableWriter> table;
      RowFunction                  row;
      std::vector<double>          values;
    };

    /// The drift ratios at the end of the run (after a failure or an
    /// interruption: at the last step reached).
    class ResidualDriftRecorder : public StepObserver
    {
    public:
      ResidualDriftRecorder(const std::string &directory, const std::string &name,
                            const PeakResponse &peaks, MemoryResults *memory)
        : directory(directory)
        , name(name)
        , peaks(peaks)
        , memory(memory)
      {}
      void observe_step(const ResponseView &) override {}
      void
      finish(const ResponseView &state, const RunStatus &) override
      {
        // 3D: along x, along y and about z (the storey's twist, the floor's
        // rotation), every column named with its direction
        const bool  plan = peaks.floors_y() != nullptr;
        std::string text = plan ? "building,storey,residual_drift_ratio_x,residual_drift_ratio_y,"
                                  "residual_twist_rad,residual_floor_disp_x_m,"
                                  "residual_floor_disp_y_m,residual_floor_rot_z_rad\n" :
                                  "building,storey,residual_drift_ratio,residual_floor_disp_m\n";
        for (unsigned int b = 0; b < state.model.buildings.size(); ++b)
          for (unsigned int f = 0; f < state.model.buildings[b].floors.size(); ++f)
            {
              const unsigned int i = peaks.floors().index(b, f);
              std::ostringstream row;
              row.precision(17);
              row << state.model.buildings[b].name << "," << f + 1 << ","
                  << peaks.floors().drift_ratio()[i] << ",";
              if (plan)
                row << peaks.floors_y()->drift_ratio()[i] << ","
                    << peaks.floors_rz()->drift_ratio()[i] *
                         state.model.buildings[b].floors[f].storey_height
                    << "," << peaks.floors().displacement()[i] << ","
                    << peaks.floors_y()->displacement()[i] << ","
                    << peaks.floors_rz()->displacement()[i] << "\n";
              else
                row << peaks.floors().displacement()[i] << "\n";
              text += row.str();
            }
        write_result_text(memory, directory, name, text);
      }

    private:
      const std::string   directory, name;
      const PeakResponse &peaks;
      MemoryResults      *memory;
    };

    /// Columns and row of a time-series quantity, and what owns each
    /// column in a run partitioned by building (base/rank_merge.h).
    struct Series
    {
      std::vector<std::string> columns;
      RowFunction              row;
      std::vector<ColumnOwner> owners;
    };

    /// `n` columns of each of `entities` of `kind`, entity after entity.
    std::vector<ColumnOwner>
    owners_of(const Owner kind, const std::vector<unsigned int> &entities, const unsigned int n)
    {
      std::vector<ColumnOwner> owners;
      for (const unsigned int i : entities)
        owners.insert(owners.end(), n, ColumnOwner{kind, i});
      return owners;
    }

    /// 0, 1, ..., n - 1.
    std::vector<unsigned int>
    first_integers(const unsigned int n)
    {
      std::vector<unsigned int> all(n);
      std::iota(all.begin(), all.end(), 0u);
      return all;
    }

    /// One column per building: the shear of its first storey; 3D: the base
    /// shears along x and y and the base torque about the first floor's mass
    /// centre at rest (output/storey_forces.h).
    Series
    base_shear_series(const ResponseView &state, const std::shared_ptr<const StoreyForces> &forces)
    {
      const bool               plan = state.model.dimension == 3;
      std::vector<std::string> columns;
      for (const Building &b : state.model.buildings)
        if (plan)
          for (const char *c : {"_base_shear_x_N", "_base_shear_y_N", "_base_torque_N_m"})
            columns.push_back(b.name + c);
        else
          columns.push_back(b.name + "_base_shear_N");
      const unsigned int n_buildings = state.model.buildings.size();
      if (plan)
        return {columns,
                [forces, n_buildings](const ResponseView &s, std::vector<double> &to) {
                  to.resize(3 * n_buildings);
                  for (unsigned int b = 0; b < n_buildings; ++b)
                    {
                      const std::array<double, 3> V =
                        forces->plan_forces(forces->index(b, 0), s.displacement());
                      std::copy(V.begin(), V.end(), to.begin() + 3 * b);
                    }
                },
                owners_of(Owner::building, first_integers(n_buildings), 3)};
      auto shears = std::make_shared<std::vector<double>>();
      return {columns,
              [forces, shears, n_buildings](const ResponseView &s, std::vector<double> &to) {
                forces->storey_shears(s.displacement(), s.velocity(), *shears);
                to.resize(n_buildings);
                for (unsigned int b = 0; b < n_buildings; ++b)
                  to[b] = (*shears)[forces->index(b, 0)];
              },
              owners_of(Owner::building, first_integers(n_buildings), 1)};
    }

    /// A 3D model's storey shears: V_x, V_y and the torque T of every storey
    /// (output/storey_forces.h), each column named with its direction.
    Series
    plan_storey_shear_series(const PeakResponse &peaks,
                             const std::shared_ptr<const StoreyForces> &forces)
    {
      const FloorResponse &floors = peaks.floors();
      const std::array<std::vector<std::string>, 3> names{
        {floors.column_names("storey", "shear_x_N"), floors.column_names("storey", "shear_y_N"),
         floors.column_names("storey", "torque_N_m")}};
      const unsigned int       n = floors.n_floors();
      std::vector<std::string> columns;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int d = 0; d < 3; ++d)
          columns.push_back(names[d][i]);
      return {columns,
              [forces, n](const ResponseView &s, std::vector<double> &to) {
                to.resize(3 * n);
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const std::array<double, 3> V = forces->plan_forces(i, s.displacement());
                    std::copy(V.begin(), V.end(), to.begin() + 3 * i);
                  }
              },
              owners_of(Owner::floor, first_integers(n), 3)};
    }

    /// The twelve local end forces of each requested 3D member.
    Series
    member_force_series_3d(const std::vector<std::string> &labels, const Model &model,
                           const std::shared_ptr<const StoreyForces> &forces)
    {
      std::vector<std::string>  columns;
      std::vector<unsigned int> buildings; // of each member
      for (const std::string &label : labels)
        {
          for (const Member3D &member : model.members_3d)
            if (member.label == label)
              {
                buildings.push_back(member.building);
                break;
              }
          for (const char *end : {"1", "2"})
            for (const auto &[name, unit] : {std::pair{"N", "_N"}, {"Vy", "_N"}, {"Vz", "_N"},
                                             {"T", "_N_m"}, {"My", "_N_m"}, {"Mz", "_N_m"}})
              columns.push_back(label + "_" + name + end + unit);
        }
      return {columns,
              [forces, labels](const ResponseView &s, std::vector<double> &to) {
                to.resize(12 * labels.size());
                for (unsigned int m = 0; m < labels.size(); ++m)
                  {
                    const auto f = forces->member_end_forces_3d(labels[m], s.displacement());
                    std::copy(f.data(), f.data() + 12, to.begin() + 12 * m);
                  }
              },
              owners_of(Owner::building, buildings, 12)};
    }

    /// The six end forces of each requested member (twelve in space); an
    /// unknown label is bad input.
    Series
    member_force_series(const RecorderRequest &request, const Model &model,
                        const std::shared_ptr<const StoreyForces> &forces,
                        const std::string &input_file, const int line)
    {
      for (const std::string &label : request.labels)
        if (!forces->has_member(label))
          throw InputError(input_file, line, "Output/Recorders/Record",
                           "'member end forces of " + label + "': no member is labelled so "
                             "(members are named like A3_C1.2: building, C<storey>.<column line> "
                             "or B<floor>.<bay>; in a 3D frame A_C1.2.1, A_BX1.1.1, A_BY1.1.1: "
                             "storey or floor, x and y line)");
      if (model.dimension == 3)
        return member_force_series_3d(request.labels, model, forces);
      std::vector<std::string>  columns;
      std::vector<unsigned int> buildings; // of each member
      for (const std::string &label : request.labels)
        {
          for (const Member &member : model.members)
            if (member.label == label)
              {
                buildings.push_back(model.nodes[member.nodes[0]].building);
                break;
              }
          for (const char *c : {"_N1_N", "_V1_N", "_M1_N_m", "_N2_N", "_V2_N", "_M2_N_m"})
            columns.push_back(label + c);
        }
      const std::vector<std::string> labels = request.labels;
      return {columns,
              [forces, labels](const ResponseView &s, std::vector<double> &to) {
                to.resize(6 * labels.size());
                for (unsigned int m = 0; m < labels.size(); ++m)
                  {
                    const Vector6 f = forces->member_end_forces(labels[m], s.displacement());
                    for (unsigned int k = 0; k < 6; ++k)
                      to[6 * m + k] = f[k];
                  }
              },
              owners_of(Owner::building, buildings, 6)};
    }

    /// The elements in [first, end) that `labels` name: all without labels;
    /// else each label an element's own, or a building's name for all of
    /// that building's (a gap: either side's). InputError for a label that
    /// is neither, naming the quantity asked for (`quantity`, e.g. "hinge
    /// states"; `what`, e.g. "hinge or Bouc-Wen storey", and `example` say
    /// what was expected).
    std::vector<unsigned int>
    elements_named(const std::vector<std::string> &labels, const Model &model,
                   const NonlinearElements &elements, const unsigned int first,
                   const unsigned int end, const std::function<bool(unsigned int, unsigned int)> &in_building,
                   const std::string &quantity, const std::string &what,
                   const std::string &example, const std::string &input_file, const int line)
    {
      std::vector<unsigned int> chosen;
      if (labels.empty())
        for (unsigned int h = first; h < end; ++h)
          chosen.push_back(h);
      for (const std::string &label : labels)
        {
          const std::size_t n_before = chosen.size();
          for (unsigned int b = 0; b < model.buildings.size(); ++b)
            if (model.buildings[b].name == label)
              for (unsigned int h = first; h < end; ++h)
                if (in_building(h, b))
                  chosen.push_back(h);
          for (unsigned int h = first; h < end; ++h)
            if (elements[h].label == label)
              chosen.push_back(h);
          if (chosen.size() == n_before)
            throw InputError(input_file, line, "Output/Recorders/Record",
                             "'" + quantity + " of " + label + "': no " + what +
                               " is labelled so and no building is " +
                               "named so (labels are like " + example +
                               "; a building's name records all of its)");
        }
      std::sort(chosen.begin(), chosen.end()); // in the model's order, each once
      chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
      return chosen;
    }

    /// Force (moment), deformation (drift, rotation) and z of the hysteretic
    /// elements `chosen`.
    Series
    hinge_state_series(const NonlinearElements &elements, const std::vector<unsigned int> &chosen)
    {
      std::vector<std::string> columns;
      for (const unsigned int h : chosen)
        {
          const bool hinge = elements[h].kind == ElementKind::hinge ||
                             elements[h].kind == ElementKind::member; // end moments
          columns.push_back(elements[h].label + (hinge ? "_moment_N_m" : "_force_N"));
          columns.push_back(elements[h].label + (hinge ? "_rotation_rad" : "_drift_m"));
          columns.push_back(elements[h].label + "_z");
        }
      return {columns,
              [chosen](const ResponseView &s, std::vector<double> &to) {
                to.resize(3 * chosen.size());
                for (unsigned int i = 0; i < chosen.size(); ++i)
                  {
                    if (!s.observes_element(chosen[i]))
                      {
                        to[3 * i] = to[3 * i + 1] = to[3 * i + 2] = 0; // another rank's
                        continue;
                      }
                    const NonlinearElement &e = s.elements[chosen[i]];
                    to[3 * i]     = e.force();
                    to[3 * i + 1] = e.deformation(s.displacement());
                    to[3 * i + 2] = e.history_variable();
                  }
              },
              owners_of(Owner::element, chosen, 3)};
    }

    /// At each integration point of the fibre members `chosen`: N, M, eps0,
    /// kappa and the extreme fibre strains (output/section_limits.h); a
    /// section in space names M and kappa about z and adds My and kappa_y.
    Series
    section_state_series(const NonlinearElements &elements, const std::vector<unsigned int> &chosen)
    {
      std::vector<std::string> columns;
      std::vector<ColumnOwner> owners;
      auto points = std::make_shared<std::vector<std::array<unsigned int, 3>>>(); // element, point, first column
      auto kinds  = std::make_shared<std::vector<std::vector<FibreKind>>>();
      for (const unsigned int h : chosen)
        for (unsigned int i = 0; fibre_section_of(elements[h], i) != nullptr; ++i)
          {
            const FibreSection &section = *fibre_section_of(elements[h], i);
            const bool          space   = section.n_resultants() == 4;
            points->push_back({{h, i, static_cast<unsigned int>(columns.size())}});
            kinds->push_back(fibre_kinds(section.geometry()));
            const std::string at = elements[h].label + "_ip" + std::to_string(i + 1);
            for (const char *c : {"_N_N", space ? "_Mz_N_m" : "_M_N_m", "_eps0",
                                  space ? "_kappa_z_1_m" : "_kappa_1_m", "_concrete_strain",
                                  "_steel_strain_max", "_steel_strain_min"})
              columns.push_back(at + c);
            if (space)
              for (const char *c : {"_My_N_m", "_kappa_y_1_m"})
                columns.push_back(at + c);
            owners.resize(columns.size(), ColumnOwner{Owner::element, h});
          }
      const unsigned int n_columns = columns.size();
      return {columns,
              [points, kinds, n_columns](const ResponseView &s, std::vector<double> &to) {
                to.assign(n_columns, 0); // another rank's: 0
                for (unsigned int p = 0; p < points->size(); ++p)
                  {
                    const auto [h, i, first] = (*points)[p];
                    if (!s.observes_element(h))
                      continue;
                    section_state_values(*fibre_section_of(s.elements[h], i), (*kinds)[p],
                                         &to[first]);
                  }
              },
              owners};
    }

    /// Force and penetration of the gap elements `chosen`.
    Series
    gap_state_series(const NonlinearElements &elements, const std::vector<unsigned int> &chosen)
    {
      std::vector<std::string> columns;
      for (const unsigned int h : chosen)
        {
          columns.push_back(elements[h].label + "_force_N");
          columns.push_back(elements[h].label + "_penetration_m");
        }
      return {columns,
              [chosen](const ResponseView &s, std::vector<double> &to) {
                to.resize(2 * chosen.size());
                for (unsigned int i = 0; i < chosen.size(); ++i)
                  {
                    const bool here = s.observes_element(chosen[i]); // else another rank's
                    to[2 * i]       = here ? s.elements[chosen[i]].force() : 0.0;
                    to[2 * i + 1]   = here ? s.elements[chosen[i]].history_variable() : 0.0;
                  }
              },
              owners_of(Owner::element, chosen, 2)};
    }

    /// u and v of every equation, and the stick/slip phase of each friction element.
    Series
    phase_portrait_series(const ResponseView &state)
    {
      std::vector<std::string> columns;
      for (const std::string &label : equation_labels(state.model))
        {
          // a rotation's unit is rad (the label ends in its component)
          const bool turn = is_rotation(label.substr(label.find('_', label.find("_node")+1) + 1));
          columns.push_back(label + (turn ? "_rad" : "_m"));
          columns.push_back(label + (turn ? "_velocity_rad_s" : "_velocity_m_s"));
        }
      const NonlinearElements  &elements = state.elements;
      std::vector<unsigned int> friction;
      for (unsigned int h = 0; h < elements.size(); ++h)
        if (elements[h].kind == ElementKind::friction)
          {
            friction.push_back(h);
            columns.push_back(elements[h].label + "_phase");
          }
      std::vector<ColumnOwner> owners =
        owners_of(Owner::equation, first_integers(state.model.n_equations()), 2);
      for (const ColumnOwner &e : owners_of(Owner::element, friction, 1))
        owners.push_back(e);
      return {columns,
              [friction](const ResponseView &s, std::vector<double> &to) {
                const Vector &u = s.displacement(), &v = s.velocity();
                to.resize(2 * u.size() + friction.size());
                for (Eigen::Index q = 0; q < u.size(); ++q)
                  {
                    to[2 * q]     = u[q];
                    to[2 * q + 1] = v[q];
                  }
                for (std::size_t i = 0; i < friction.size(); ++i)
                  to[2 * u.size() + i] = s.elements[friction[i]].phase();
              },
              owners};
    }

    /// A 3D model's floor quantity `value` of each floor (or storey), along
    /// x, along y and about z in turn, each column named with its direction
    /// (`suffixes`); `scale_z` multiplies the θz column of floor i (the
    /// storey height for a twist out of FloorResponse's drift ratio).
    Series
    plan_floor_series(const PeakResponse &peaks, const std::string &what,
                      const std::array<std::string, 3> &suffixes,
                      const std::vector<double> &(FloorResponse::*value)() const,
                      const std::vector<double> &scale_z)
    {
      const std::array<const FloorResponse *, 3> floors{
        {&peaks.floors(), peaks.floors_y(), peaks.floors_rz()}};
      std::array<std::vector<std::string>, 3> names;
      for (unsigned int d = 0; d < 3; ++d)
        names[d] = floors[d]->column_names(what, suffixes[d]);
      const unsigned int       n = floors[0]->n_floors();
      std::vector<std::string> columns;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int d = 0; d < 3; ++d)
          columns.push_back(names[d][i]);
      return {columns,
              [floors, value, scale_z, n](const ResponseView &, std::vector<double> &to) {
                to.resize(3 * n);
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int d = 0; d < 3; ++d)
                    to[3 * i + d] = (floors[d]->*value)()[i] * (d == 2 ? scale_z[i] : 1.0);
              },
              owners_of(Owner::floor, first_integers(n), 3)};
    }

    /// A 3D model's floor displacement, velocity, acceleration or drift:
    /// x, y and θz of every floor (the drift: the mass centres' drift ratios
    /// along x and y and the storey's twist θz,i - θz,i-1 in rad), then for
    /// the drift the drift ratios of every slab corner (plan_response.h).
    Series
    plan_series(const RecordedQuantity quantity, const Model &model, const PeakResponse &peaks)
    {
      const std::vector<double> one(peaks.floors().n_floors(), 1.0);
      switch (quantity)
        {
          case RecordedQuantity::floor_displacement:
            return plan_floor_series(peaks, "floor", {{"disp_x_m", "disp_y_m", "rot_z_rad"}},
                                     &FloorResponse::displacement, one);
          case RecordedQuantity::floor_velocity:
            return plan_floor_series(peaks, "floor", {{"vel_x_m_s", "vel_y_m_s", "vel_rz_rad_s"}},
                                     &FloorResponse::velocity, one);
          case RecordedQuantity::floor_acceleration:
            return plan_floor_series(peaks, "floor",
                                     {{"acc_x_m_s2", "acc_y_m_s2", "acc_rz_rad_s2"}},
                                     &FloorResponse::absolute_acceleration, one);
          default:
            break;
        }
      Assert(quantity == RecordedQuantity::drift_ratio, dealii::ExcNotImplemented());
      std::vector<double> heights;
      for (const Building &building : model.buildings)
        for (const Floor &floor : building.floors)
          heights.push_back(floor.storey_height);
      Series centre = plan_floor_series(peaks, "storey",
                                        {{"drift_ratio_x", "drift_ratio_y", "twist_rad"}},
                                        &FloorResponse::drift_ratio, heights);
      const PlanResponse *plan = peaks.plan();
      for (const std::string &name : plan->corner_drift_names())
        centre.columns.push_back(name);
      for (unsigned int b = 0; b < model.buildings.size(); ++b)
        for (const PlanFloor &floor : model.buildings[b].plan)
          centre.owners.insert(centre.owners.end(), 2 * floor.outline.size(),
                               ColumnOwner{Owner::building, b});
      const unsigned int n_centre = 3 * peaks.floors().n_floors();
      return {centre.columns,
              [row = centre.row, plan, n_centre](const ResponseView &s, std::vector<double> &to) {
                row(s, to);
                const std::vector<double> &corners = plan->corner_drift_ratios();
                to.resize(n_centre);
                to.insert(to.end(), corners.begin(), corners.end());
              },
              centre.owners};
    }

    /// A 3D model's ground motion: a_x and a_y as applied (the components
    /// turned by the incidence angle), and a_z with a vertical component.
    Series
    ground_motion_3d_series(const bool vertical)
    {
      std::vector<std::string> columns{"ground_acceleration_x_m_s2", "ground_acceleration_y_m_s2"};
      if (vertical)
        columns.push_back("ground_acceleration_z_m_s2");
      return {columns,
              [vertical](const ResponseView &s, std::vector<double> &to) {
                to = {s.ground_acceleration(), s.ground_acceleration_y()};
                if (vertical)
                  to.push_back(s.ground_acceleration_z());
              },
              {}};
    }

    /// A row function that copies `from`, a vector the peaks keep current
    /// (the recorder reads it after each step, so it refers, not copies).
    auto
    copy_of(const std::vector<double> &from)
    {
      return [&from](const ResponseView &, std::vector<double> &to) { to = from; };
    }

    /// The hinge states of the hinges and Bouc-Wen storeys `request` names.
    Series
    hinge_series_named(const RecorderRequest &request, const ResponseView &state,
                       const PeakResponse &peaks, const std::string &input_file, const int line)
    {
      const NonlinearElements &elements = state.elements;
      const unsigned int       n_hyst   = peaks.n_hysteretic();
      return hinge_state_series(
        elements, elements_named(request.labels, state.model, elements, 0, n_hyst,
                                 [&](const unsigned int h, const unsigned int b) {
                                   return elements[h].building == b;
                                 },
                                 "hinge states", "hinge or Bouc-Wen storey",
                                 "A3_C1.2_bottom, A3_storey1 or in 3D A5_C1.3.2_bottom_z",
                                 input_file, line));
    }

    /// The gap states of the gap elements `request` names: a gap is a
    /// building's if either of its nodes is.
    Series
    gap_series_named(const RecorderRequest &request, const ResponseView &state,
                     const PeakResponse &peaks, const std::string &input_file, const int line)
    {
      // gaps follow the hysteretic elements, in model.gaps order
      const NonlinearElements &elements = state.elements;
      const Model             &model    = state.model;
      const unsigned int       n_hyst   = peaks.n_hysteretic();
      return gap_state_series(
        elements, elements_named(request.labels, model, elements, n_hyst,
                                 n_hyst + peaks.n_gaps(),
                                 [&](const unsigned int h, const unsigned int b) {
                                   const Gap &gap = model.gaps[h - n_hyst];
                                   return (gap.nodes[0] >= 0 && gap.buildings[0] == b) ||
                                          (gap.nodes[1] >= 0 && gap.buildings[1] == b);
                                 },
                                 "gap states", "gap element",
                                 "A3-B2@6.5 or in 3D A5-B5@13.6/1", input_file, line));
    }

    /// The energy balance's terms and its error.
    Series
    energy_series(const Model &model)
    {
      // a column for the foundations' dashpots only when there are
      // some, for the held gravity loads' work only after gravity
      const bool               foundations = !model.foundations.empty();
      const bool               gravity     = model.gravity_analysis.enabled;
      std::vector<std::string> names{"input_J",      "kinetic_J",  "damping_J",
                                     "strain_J",     "hysteretic_J", "contact_J",
                                     "balance_error", "friction_J", "belt_J",
                                     "links_J"};
      if (foundations)
        names.push_back("foundation_J");
      if (gravity)
        names.push_back("constant_load_J");
      return {names,
              [foundations, gravity](const ResponseView &s, std::vector<double> &to) {
                const EnergyBalance e = s.energy();
                to = {e.input,   e.kinetic,          e.damping,  e.strain, e.hysteretic,
                      e.contact, s.max_energy_error(), e.friction, e.belt,   e.links};
                if (foundations)
                  to.push_back(e.foundation);
                if (gravity)
                  to.push_back(e.constant_load);
              },
              {}};
    }

    /// The ground acceleration as applied: its components along x and y in
    /// 3D (`plan`), and the vertical one too when there is one.
    Series
    ground_motion_series(const ResponseView &state, const bool plan)
    {
      if (plan) // every component as applied: along x and y (after the incidence rotation)
        return ground_motion_3d_series(state.has_vertical_ground_motion());
      if (state.has_vertical_ground_motion()) // Components = 3: the vertical one too
        return {{"ground_acceleration_m_s2", "ground_acceleration_z_m_s2"},
                [](const ResponseView &s, std::vector<double> &to) {
                  to = {s.ground_acceleration(), s.ground_acceleration_z()};
                },
                {}};
      return {{"ground_acceleration_m_s2"},
              [](const ResponseView &s, std::vector<double> &to) {
                to.assign(1, s.ground_acceleration());
              },
              {}};
    }

    /// The plan corners' accelerations, x and y of each corner of each floor,
    /// each its building's, as the peaks' plan holds them.
    Series
    corner_acceleration_series(const ResponseView &state, const PeakResponse &peaks)
    {
      const PlanResponse *plan = peaks.plan(); // requests_of refused it in 2D
      std::vector<ColumnOwner> owners; // x and y of each corner of each floor
      for (unsigned int b = 0; b < state.model.buildings.size(); ++b)
        for (const PlanFloor &floor : state.model.buildings[b].plan)
          owners.insert(owners.end(), 2 * floor.outline.size(), ColumnOwner{Owner::building, b});
      return {plan->corner_acceleration_names(), copy_of(plan->corner_accelerations()), owners};
    }

    /// The section states of the fibre members `request` names; those named
    /// that are not fibre members are left out, and none at all is bad input.
    Series
    section_series_named(const RecorderRequest &request, const ResponseView &state,
                         const std::string &input_file, const int line)
    {
      const NonlinearElements  &elements = state.elements;
      std::vector<unsigned int> chosen   = elements_named(
        request.labels, state.model, elements, 0, elements.size(),
        [&](const unsigned int h, const unsigned int b) { return elements[h].building == b; },
        "section states", "fibre member",
        state.model.dimension == 3 ? "A_C1.1.1 or A_BX1.1.1" : "A_C1.1 or A_B2.1", input_file,
        line);
      chosen.erase(std::remove_if(chosen.begin(), chosen.end(),
                                  [&](const unsigned int h) {
                                    return !fibre_section_of(elements[h], 0);
                                  }),
                   chosen.end());
      if (chosen.empty())
        throw InputError(input_file, line, "Output/Recorders/Record",
                         "'section states': no fibre member among those asked for "
                         "(Building <i>/Member model = fibre)");
      return section_state_series(elements, chosen);
    }

    /// The columns and the row function of one recorded quantity (the
    /// owners of its columns: series_of).
    Series
    series_of_quantity(const RecorderRequest &request, const ResponseView &state, const PeakResponse &peaks,
              const std::shared_ptr<const StoreyForces> &forces, const std::string &input_file,
              const int line)
    {
      const FloorResponse &floors = peaks.floors();
      const bool plan = peaks.plan() != nullptr; // a 3D model: x, y and θz
      switch (request.quantity)
        {
          case RecordedQuantity::floor_displacement:
            if (plan)
              return plan_series(request.quantity, state.model, peaks);
            return {floors.column_names("floor", "disp_m"), copy_of(floors.displacement()), {}};
          case RecordedQuantity::floor_velocity:
            if (plan)
              return plan_series(request.quantity, state.model, peaks);
            return {floors.column_names("floor", "vel_m_s"), copy_of(floors.velocity()), {}};
          case RecordedQuantity::floor_acceleration:
            if (plan)
              return plan_series(request.quantity, state.model, peaks);
            return {floors.column_names("floor", "acc_m_s2"), copy_of(floors.absolute_acceleration()), {}};
          case RecordedQuantity::drift_ratio:
            if (plan)
              return plan_series(request.quantity, state.model, peaks);
            return {floors.column_names("storey", "drift_ratio"), copy_of(floors.drift_ratio()), {}};
          case RecordedQuantity::storey_shear:
            if (plan)
              return plan_storey_shear_series(peaks, forces);
            return {floors.column_names("storey", "shear_N"),
                    [forces](const ResponseView &s, std::vector<double> &to) {
                      forces->storey_shears(s.displacement(), s.velocity(), to);
                    }, {}};
          case RecordedQuantity::base_shear:
            return base_shear_series(state, forces);
          case RecordedQuantity::member_forces:
            return member_force_series(request, state.model, forces, input_file, line);
          case RecordedQuantity::hinge_states:
            return hinge_series_named(request, state, peaks, input_file, line);
          case RecordedQuantity::gap_states:
            return gap_series_named(request, state, peaks, input_file, line);
          case RecordedQuantity::energy:
            return energy_series(state.model);
          case RecordedQuantity::ground_motion:
            return ground_motion_series(state, plan);
          case RecordedQuantity::phase_portrait:
            return phase_portrait_series(state);
          case RecordedQuantity::corner_acceleration:
            return corner_acceleration_series(state, peaks);
          case RecordedQuantity::section_states:
            return section_series_named(request, state, input_file, line);
          case RecordedQuantity::residual_drift:
            break; // not a time series
        }
      throw std::logic_error("series_of: not a time series");
    }

    /// series_of_quantity() with the owners of its columns: a floor's (or
    /// storey's) values are its building's, the energy and the ground
    /// motion are alike on every rank.
    Series
    series_of(const RecorderRequest &request, const ResponseView &state, const PeakResponse &peaks,
              const std::shared_ptr<const StoreyForces> &forces, const std::string &input_file,
              const int line)
    {
      Series series = series_of_quantity(request, state, peaks, forces, input_file, line);
      switch (request.quantity)
        {
          case RecordedQuantity::floor_displacement:
          case RecordedQuantity::floor_velocity:
          case RecordedQuantity::floor_acceleration:
          case RecordedQuantity::drift_ratio:
          case RecordedQuantity::storey_shear:
            if (series.owners.empty()) // a 3D model's are its series'
              series.owners = owners_of(Owner::floor, first_integers(peaks.floors().n_floors()), 1);
            break;
          case RecordedQuantity::energy:
          case RecordedQuantity::ground_motion:
            series.owners.assign(series.columns.size(), ColumnOwner{Owner::root, 0});
            break;
          default:
            break; // the series' own
        }
      AssertThrow(series.owners.size() == series.columns.size(),
                  dealii::ExcDimensionMismatch(series.owners.size(), series.columns.size()));
      return series;
    }

    /// The defaults (unless `Default files = false`) with the requests of
    /// `Record` over them. Throws InputError for a quantity the model lacks.
    std::vector<RecorderRequest>
    requests_of(const RecorderParameters &parameters, const std::string &input_file,
                const ResponseView &state, const PeakResponse &peaks)
    {
      const bool has_hysteretic = peaks.n_hysteretic() > 0;
      const bool has_gaps       = peaks.n_gaps() > 0;
      std::vector<RecorderRequest> requests;
      if (parameters.default_files)
        for (const RecordedQuantity q :
             {RecordedQuantity::drift_ratio, RecordedQuantity::floor_acceleration,
              RecordedQuantity::floor_displacement, RecordedQuantity::ground_motion,
              RecordedQuantity::energy, RecordedQuantity::hinge_states, RecordedQuantity::gap_states,
              RecordedQuantity::phase_portrait})
          if ((q != RecordedQuantity::hinge_states || has_hysteretic) &&
              (q != RecordedQuantity::gap_states || has_gaps) &&
              (q != RecordedQuantity::phase_portrait || state.model.n_equations() <= 2))
            requests.push_back({q, {}, -1.0});
      for (const RecorderRequest &r : parameters.requests)
        {
          auto same = std::find_if(requests.begin(), requests.end(),
                                   [&](const RecorderRequest &d) { return d.quantity == r.quantity; });
          if (same != requests.end())
            *same = r; // a request overrides the default of the same quantity
          else
            requests.push_back(r);
          if (r.quantity == RecordedQuantity::corner_acceleration && !peaks.plan())
            throw InputError(input_file, parameters.line, "Output/Recorders/Record",
                             "'corner acceleration': slab corners are those of a 3D model "
                             "(Model/Dimension = 3); use 'floor acceleration'");
          if ((r.quantity == RecordedQuantity::hinge_states && !has_hysteretic) ||
              (r.quantity == RecordedQuantity::gap_states && !has_gaps))
            throw InputError(input_file, parameters.line, "Output/Recorders/Record",
                             std::string("'") + info(r.quantity).name + "': the model has no " +
                               (r.quantity == RecordedQuantity::gap_states ?
                                  "gap elements" : "hinges or Bouc-Wen storeys"));
        }
      return requests;
    }

    /// The files of a quantity: residual drift is a small table, CSV in
    /// either format.
    std::vector<std::string>
    files_of(const RecordedQuantity quantity, const OutputFormat format)
    {
      const char *stem = info(quantity).stem;
      if (quantity == RecordedQuantity::residual_drift)
        return {stem + std::string(".csv")};
      return table_files(format, stem);
    }

    /// Removes what an earlier run's recorders left in `directory` (files of
    /// either format, and temporaries of a killed run) that this run does
    /// not write, so that the directory never mixes two runs' results: a
    /// switch to npy leaves no older CSV behind, and the plots draw only
    /// this run's files.
    void
    remove_stale_files(const std::string &directory, const std::vector<std::string> &files)
    {
      for (const QuantityInfo &q : quantities)
        for (const OutputFormat format : {OutputFormat::csv, OutputFormat::npy})
          for (const std::string &name : files_of(q.quantity, format))
            {
              std::error_code ignored; // most of them do not exist
              if (std::find(files.begin(), files.end(), name) == files.end())
                std::filesystem::remove(directory + "/" + name, ignored);
              std::filesystem::remove(directory + "/" + name + ".tmp", ignored);
            }
    }
  } // namespace

  std::array<const char *, 3>
  node_components(const Model &model, const unsigned int node)
  {
    const Node &n = model.nodes[node];
    if (!n.generalized) // a 2D node, or a 3D floor's diaphragm (mass centre) or joint
      return {{"ux", "uy", "rz"}};
    const bool rocking = std::any_of(model.foundations.begin(), model.foundations.end(),
                                     [&](const Foundation &f) { return f.rocking_node == int(node); });
    if (n.joint_translation_z || rocking) // a 3D joint's other three, a basemat's rocking
      return {{"uz", "rx", "ry"}};
    return {{"hinge_ry", "hinge_rz", "unused"}}; // a 3D hinge: about the member's local y and z
  }

  bool
  is_rotation(const std::string &component)
  {
    return component[0] == 'r' || component.rfind("hinge_r", 0) == 0;
  }

  std::vector<std::string>
  equation_labels(const Model &model)
  {
    std::vector<std::string> labels(model.n_equations());
    for (unsigned int node = 0; node < model.n_nodes(); ++node)
      {
        const std::array<const char *, 3> components = node_components(model, node);
        for (unsigned int c = 0; c < n_dofs_per_node; ++c)
          if (const int q = model.equation(n_dofs_per_node * node + c); q >= 0)
            labels[q] = model.buildings[model.nodes[node].building].name + "_node" +
                        std::to_string(node) + "_" + components[c];
      }
    return labels;
  }

  unsigned int
  steps_per_interval(const double interval, const double dt)
  {
    if (!(interval > 0))
      return 1;
    // clamped, so that an interval far longer than the run cannot overflow
    const double steps = std::min(std::round(interval / dt), 4.0e9);
    return std::max(1u, static_cast<unsigned int>(steps));
  }

  std::vector<std::string>
  recorded_quantity_names()
  {
    std::vector<std::string> names;
    for (const QuantityInfo &q : quantities)
      names.push_back(q.name);
    return names;
  }

  void
  RecorderParameters::declare(dealii::ParameterHandler &prm)
  {
    std::string names;
    for (const QuantityInfo &q : quantities)
      names += std::string(names.empty() ? "" : ", ") + q.name + " (" + q.stem + ".csv)";
    prm.add_parameter("Default files", default_files,
                      "Write the default time series: floor displacement, floor acceleration, "
                      "storey drift ratio, hinge states (with hinges or Bouc-Wen storeys), gap "
                      "states (with gaps), energy, ground motion, every Output interval. Unit: -.");
    prm.add_parameter("Record", record,
                      "Further recorders, separated by ';'. Each is '<quantity> [of <labels>] "
                      "[every <seconds>]'; without 'every', rows come every Output interval "
                      "('every 0': every step). A quantity listed here replaces its default. "
                      "Quantities (files): " + names + ". 'member end forces' needs the members, "
                      "e.g. 'member end forces of A3_C1.1, A3_B2.1' (building, C<storey>.<column "
                      "line> or B<floor>.<bay>; in a 3D frame A_C1.2.1, A_BX1.1.1, A_BY1.1.1: "
                      "storey or floor, x and y line, with N, Vy, Vz, T, My, Mz at each end). "
                      "'hinge states' and 'gap states' record all by "
                      "default, or only those named: 'hinge states of A3_C1.2_bottom, B2' (a "
                      "label, or a building's name for all of its hinges or gaps): for large "
                      "models. Storey and base shear are element forces "
                      "(Rayleigh damping excluded, storey dashpots included). 'corner "
                      "acceleration' (3D models) is the absolute acceleration of every slab "
                      "corner along x and y. 'section states' (fibre members) records at each "
                      "integration point N, M, eps0, kappa and the extreme concrete and steel "
                      "fibre strains, of all fibre members or 'section states of A_C1.1, B' "
                      "(members or buildings). Unit: -.");
  }

  void
  RecorderParameters::finalize(const std::string &file, const int line_of_record,
                               const double interval)
  {
    line            = line_of_record;
    output_interval = interval;
    try
      {
        requests = parse(record);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(file, line, "Output/Recorders/Record", e.what());
      }
  }

  namespace
  {
    /// The recorded quantity of Record's name `name` (std::invalid_argument
    /// with the names known if there is none).
    RecordedQuantity
    quantity_named(const std::string &name)
    {
      for (const QuantityInfo &q : quantities)
        if (name == q.name)
          return q.quantity;
      std::string list;
      for (const QuantityInfo &q : quantities)
        list += (list.empty() ? "" : ", ") + std::string(q.name);
      throw std::invalid_argument("unknown quantity '" + name + "' (one of: " + list + ")");
    }
  } // namespace

  std::vector<RecorderRequest>
  RecorderParameters::parse(const std::string &text)
  {
    std::vector<RecorderRequest> requests;
    std::istringstream           items(text);
    std::string                  item;
    while (std::getline(items, item, ';'))
      {
        item = trim(item);
        if (item.empty() || item == "none")
          continue;
        RecorderRequest request;
        const auto      every = item.rfind(" every ");
        if (every != std::string::npos)
          {
            const std::string value = trim(item.substr(every + 7));
            const std::optional<double> interval = parse_number(value);
            request.interval                     = interval.value_or(-1);
            if (!interval || request.interval < 0 || request.interval > 1e6)
              throw std::invalid_argument("'" + item + "': 'every' needs an interval in s (>= 0), got '" +
                                          value + "'");
            item = trim(item.substr(0, every));
          }
        const auto of = (item + " ").find(" of "); // also a trailing " of" with no list
        const std::string name = trim(of == std::string::npos ? item : item.substr(0, of));
        request.quantity       = quantity_named(name);
        if (of != std::string::npos)
          {
            std::istringstream labels(of + 4 <= item.size() ? item.substr(of + 4) : "");
            std::string        label;
            while (std::getline(labels, label, ','))
              if (!trim(label).empty())
                request.labels.push_back(trim(label));
          }
        const bool needs_labels = request.quantity == RecordedQuantity::member_forces;
        const bool takes_labels = needs_labels ||
                                  request.quantity == RecordedQuantity::hinge_states ||
                                  request.quantity == RecordedQuantity::section_states ||
                                  request.quantity == RecordedQuantity::gap_states;
        if (needs_labels && request.labels.empty())
          throw std::invalid_argument("'" + name + "' needs the members: '" + name +
                                      " of A3_C1.1, A3_B1.1'");
        if (takes_labels && of != std::string::npos && request.labels.empty())
          throw std::invalid_argument("'" + name + " of' needs labels or building names after 'of'");
        if (!takes_labels && of != std::string::npos)
          throw std::invalid_argument("'" + name + "' takes no 'of' list");
        for (const RecorderRequest &r : requests)
          if (r.quantity == request.quantity)
            throw std::invalid_argument("'" + name + "' is recorded twice");
        requests.push_back(request);
      }
    return requests;
  }

  Recorders
  make_recorders(const RecorderParameters &parameters, const std::string &input_file,
                 const ResponseView &state, const PeakResponse &peaks, const double time_step,
                 const std::string &directory, RowSink *ranks, MemoryResults *memory)
  {
    Assert(!ranks || !memory, dealii::ExcNotImplemented());
    const bool writes_files = !memory && (!ranks || ranks->writes_files());
    const std::vector<RecorderRequest> requests = requests_of(parameters, input_file, state, peaks);
    // Every request is checked (series_of throws on an unknown member)
    // before a file or the directory is made: bad input writes nothing.
    auto forces = std::make_shared<const StoreyForces>(state.model, state.elements);
    std::vector<Series> series;
    for (const RecorderRequest &r : requests)
      if (r.quantity != RecordedQuantity::residual_drift)
        series.push_back(series_of(r, state, peaks, forces, input_file, parameters.line));
    if (writes_files)
      prepare_output_directory(directory);
    Recorders recorders;
    for (const RecorderRequest &r : requests)
      for (const std::string &file : files_of(r.quantity, parameters.format))
        recorders.files.push_back(file);
    if (writes_files)
      remove_stale_files(directory, recorders.files); // before this run's temporaries exist

    auto text = std::make_shared<NumberText>(); // shared by the CSV files of the run
    // CSV's text made and written off the stepping thread (output_queue.h);
    // an .npy row is a copy into its buffer already, as cheap as into a block
    const bool queued = writes_files && !series.empty() && parameters.format == OutputFormat::csv;
    const auto queue  = queued ? std::make_shared<OutputQueue>(output_writer_threaded()) : nullptr;
    auto next = series.begin();
    for (const RecorderRequest &r : requests)
      {
        const QuantityInfo &q = info(r.quantity);
        if (r.quantity == RecordedQuantity::residual_drift)
          {
            if (writes_files || memory) // from the merged peaks, at the end
              recorders.observers.push_back(std::make_unique<ResidualDriftRecorder>(
                directory, files_of(r.quantity, parameters.format).front(), peaks, memory));
            continue;
          }
        std::vector<std::string> header{"time_s"};
        header.insert(header.end(), next->columns.begin(), next->columns.end());
        const double       interval = r.interval >= 0 ? r.interval : parameters.output_interval;
        const unsigned int every    = steps_per_interval(interval, time_step);
        recorders.tables.push_back({r.quantity, table_files(parameters.format, q.stem).front(),
                                    static_cast<unsigned int>(header.size()), every});
        std::unique_ptr<TableWriter> table =
          memory       ? memory->table_writer(q.stem, header) :
          writes_files ? queued_table_writer(
                           make_table_writer(parameters.format, directory, q.stem, header, text), queue,
                           header, directory + "/" + recorders.tables.back().file) :
                         nullptr;
        if (ranks)
          table = ranks->merged(std::move(table), std::move(next->owners));
        recorders.observers.push_back(
          std::make_unique<SeriesRecorder>(std::move(table), every, std::move(next->row)));
        ++next;
      }
    return recorders;
  }

  std::string
  large_table_note(const TableShape &table, const unsigned long n_steps, const OutputFormat format)
  {
    const double bytes_per_number = format == OutputFormat::csv ? 21 : 8;
    const double n_rows           = double(n_steps / std::max(table.every, 1u) + 1);
    const double bytes            = bytes_per_number * table.n_columns * n_rows;
    if (bytes <= 1e9)
      return "";
    const std::string name = info(table.quantity).name;
    const bool        named = table.quantity == RecordedQuantity::hinge_states ||
                       table.quantity == RecordedQuantity::gap_states ||
                       table.quantity == RecordedQuantity::section_states;
    std::ostringstream note;
    note << std::fixed;
    note.precision(1);
    note << "poundfe: note: " << table.file << " will be about " << bytes / 1e9 << " GB ("
         << table.n_columns << " columns, " << static_cast<unsigned long>(n_rows)
         << " rows); Output/Recorders/Record = '" << name
         << (named ? " of <labels or buildings>' or '" + name : std::string()) << " every <s>'"
         << " records less\n";
    return note.str();
  }
} // namespace poundfe
