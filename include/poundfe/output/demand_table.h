// Demand tables a loss model reads: pelicun 3's DEMAND sample convention
// (pelicun's file_io.load_data and DemandModel.load_sample), one table per
// building (pelicun assesses one asset at a time):
//   header  ",<event>-<type>-<location>-<direction>", e.g. 1-PID-1-1;
//   row 2   "Units,<unit>,..." in pelicun's unit names (rad, g, m, ea, N, mps);
//   then    one row per realization (a record, a run), its index first.
// The demands of a building with n storeys, along x (direction 1):
//   PFA-0-1 ... PFA-n-1  peak absolute floor acceleration (g; floor 0 the
//                        ground: the PGA);
//   SA_<T>-0-1           Sa(T) of the ground motion (g) when the analysis
//                        scales to it (ida on Sa): what pelicun's collapse
//                        fragility on Sa reads;
//   PID-1-1 ... PID-n-1  peak inter-storey drift ratio (rad);
//   RID-1-1 ... RID-n-1  residual inter-storey drift ratio at the end (rad);
//   PFD-1-1 ... PFD-n-1  peak floor displacement relative to the ground (m)
//   RFD-1-1 ... RFD-n-1  residual floor displacement (m);
//   PRD-n-1              peak roof drift ratio: the roof's peak displacement
//                        over the building's height (rad) (PFD, RFD and PRD
//                        when the analysis traces them: run, not ida);
// and of a 3D model (Model/Dimension = 3) along y (direction 2) and in plan:
//   PFA-0-2 ... PFA-n-2  peak absolute floor acceleration along y (g; floor
//                        0: the PGA along y as applied);
//   PID-1-2 ... PID-n-2  peak inter-storey drift ratio along y (rad);
//   RID-1-2 ... RID-n-2  residual inter-storey drift ratio along y at the
//                        end (rad);
//   PFR-1-0 ... PFR-n-0  peak floor rotation |theta_z| about the vertical
//                        axis (rad; direction 0: pelicun's non-directional);
// and, per gap g touching the building at its floor f, poundfe's own types
// (no pelicun fragility group reads them; PIF is pelicun's wind "Peak
// Internal Force", hence the longer names):
//   NIMP-f-g  impacts (ea), PIMF-f-g  largest impact force (N),
//   PIMV-f-g  largest approach velocity (mps).
// pelicun splits the header at '-': a type holds no '-'.
#ifndef poundfe_output_demand_table_h
#define poundfe_output_demand_table_h

#include <poundfe/integration/impact_log.h>
#include <poundfe/model/model.h>

#include <string>
#include <vector>

namespace poundfe
{
  class Excitation;
  class PeakResponse;

  /// One realization's demands over the whole model: floor arrays indexed as
  /// FloorResponse (building by building, bottom up), gap arrays by gap.
  struct ResponseDemands
  {
    double              pga = 0; // m/s^2 (along x)
    double              pga_y = 0; // m/s^2, along y (3D)
    double              sa  = 0; // g, of the SA_<T> column (when there is one)
    std::vector<double> peak_drift, peak_acceleration, residual_drift; // -, m/s^2, -
    std::vector<double> peak_drift_y, peak_acceleration_y, peak_rotation; // 3D: -, m/s^2, rad
    std::vector<double> residual_drift_y;                             // 3D: -
    std::vector<double> peak_displacement, residual_displacement;     // m; may be empty
    std::vector<double> impacts, impact_force, impact_velocity;       // per gap: -, N, m/s
  };

  /// Per gap of `model`: the impacts, the largest peak force (N) and the
  /// largest approach speed (m/s) of `impacts`, the gaps being the nonlinear
  /// elements first_gap, first_gap + 1, ...
  void gap_demands(const Model &model, const std::vector<Impact> &impacts,
                   unsigned int first_gap, std::vector<double> &count,
                   std::vector<double> &force, std::vector<double> &velocity);

  /// A 3D model's demands along y and in plan from the peaks of a run
  /// (nothing for a 2D model), and the PGA along x and y as applied (the
  /// excitation turned by its incidence angle; 2D: the record's peak).
  void add_plan_demands(const PeakResponse &peaks, const Excitation &excitation,
                        ResponseDemands &demands);

  /// The floor (1 = the first above the ground) of `building` that gap g
  /// touches; 0 when it does not touch it.
  unsigned int gap_floor(const Model &model, unsigned int building, unsigned int g);

  struct DemandColumn
  {
    std::string type, location, direction, unit;
    /// "1-<type>-<location>-<direction>"
    std::string name() const;
  };

  /// A pelicun demand table of one building: its columns and rows.
  class DemandTable
  {
  public:
    /// The columns of `building` (above); PFD, RFD and PRD with
    /// `displacements`; SA_<T> with a `spectral_type` such as "SA_0.63".
    DemandTable(const Model &model, unsigned int building, bool displacements,
                const std::string &spectral_type = "");

    /// A realization's row (the unit conversions of the columns above).
    void add(const ResponseDemands &demands);

    const std::vector<DemandColumn>        &columns() const { return header; }
    const std::vector<std::vector<double>> &rows() const { return values; }
    /// The CSV text: header, units row, one row per realization (0, 1, ...).
    std::string csv() const;

  private:
    const Model               &model;
    unsigned int               building;
    bool                       displacements, spectral, plan; // plan: a 3D model
    std::vector<DemandColumn>  header;
    std::vector<std::vector<double>> values;
  };

  /// "demands_<building>.csv": the file name of a building's table.
  std::string demand_table_file(const Model &model, unsigned int building,
                                const std::string &suffix = "");
} // namespace poundfe

#endif
