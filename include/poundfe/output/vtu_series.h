// ParaView output: VTK XML unstructured grids (.vtu), one per frame, and a
// .pvd index (Kitware, "VTK File Formats", VTK User's Guide 11th ed., ch. 19:
// XML UnstructuredGrid, PVD collection).
//   Points: one per node (a hinge's member-side node is its joint: they share
//   the translations), plus `n_member_subdivisions` - 1 interior points per
//   frame element and one point per rigid barrier. Point data: the
//   displacement (ux, uy, 0) relative to the ground, for Warp By Vector, and
//   the rotation rz. Inside an element the displacement is the element's own
//   interpolation (axial linear, transverse cubic Hermite:
//   FrameElement::displacement_at), so warped members show their curvature.
//   Cells: each frame element a poly-line through its points; each storey of
//   a shear building a line; each gap a line between its two nodes (or its
//   node and its barrier); each hinge a vertex at its joint.
//   Cell data: kind (0 frame element, 1 storey, 2 gap, 3 hinge), building and
//   member ids (1-based; a member split into several elements keeps one id),
//   member end forces in local axes (N, V, M at both ends; a storey's shear
//   as V; a member on fibre sections's from its element's resisting forces,
//   as the member end forces recorder's, an elastic member's from K u), `force` (storey shear, contact force, hinge moment), `contact`
//   (1 while a gap is closed), `penetration`, the Bouc-Wen variable `z` and
//   the plastic deformation (hinge rotation or storey drift minus force over
//   initial stiffness) of hinges and hysteretic storeys.
//   Members on fibre sections (Member model = fibre) add a vertex cell at
//   each integration point (kind 7; its point shared with the member's own
//   where they coincide), whose cell data `integration_point` (1-based
//   along the member), `section_N`, `section_M`, `axial_strain`,
//   `curvature`, `concrete_strain` (the most compressed concrete fibre),
//   `steel_strain_max` and `steel_strain_min` are the section states
//   recorder's at the same state (output/section_states.h); these arrays
//   are 0 on every other cell and absent from models without fibre members.
// 3D models (Model/Dimension = 3): members, slabs, mass centres, storeys and
// gaps in space, drawn by source/output/vtu_series_3d.cc (doc/theory.md §10).
// Arrays are written in VTK's compressed binary form (zlib, base64), as
// deal.II's DataOut does by default.
// Output/Field format = xdmf writes the same arrays into one HDF5 file (the
// points and cells once, a group per frame) with an XDMF 3 index that
// ParaView's XDMF readers open (source/output/xdmf_series.cc).
// deal.II's DataOut writes every cell's vertices again (duplicated points)
// and interpolates cell data to points; this writer does neither.
#ifndef poundfe_output_vtu_series_h
#define poundfe_output_vtu_series_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/model/model.h>
#include <poundfe/output/observer.h>
#include <poundfe/output/output_parameters.h>

#include <mpi.h>

#include <memory>
#include <string>

namespace poundfe
{
  class NonlinearElements;

  /// What a field frame draws of each nonlinear element at its committed
  /// state, element after element: its kind (fixed), force, history
  /// variable (a gap's penetration, a hinge's z), plastic deformation
  /// (deformation minus force over initial stiffness; 0 without one),
  /// whether it is active, and for a contact in plan whether it is in
  /// reach, its contact point and its force on its first side. After the
  /// n_entries of every element, `values` holds the section state entries
  /// (output/section_states.h: section_state_values, 7 in the plane, 9 in
  /// space) of every integration point of each member on fibre sections,
  /// member after member in the elements' order, and then the global
  /// resisting forces of each such member (6 in the plane, 12 in space), in
  /// the same order (those of an element not observed: 0; a run over ranks has no
  /// fibre members).
  struct ElementFrameStates
  {
    enum Entry : unsigned int
    {
      force,
      history,
      plastic,
      active,
      in_reach,
      point_x,
      point_y,
      force_x,
      force_y,
      n_entries
    };
    /// Of `elements` at displacements `u`; with `observed` (observation by
    /// rank) only those elements h with (*observed)[h], the others' zero.
    void evaluate(const NonlinearElements &elements, const Vector &u,
                  const std::vector<char> *observed = nullptr);
    double operator()(const unsigned int h, const Entry e) const
    {
      return values[n_entries * h + e];
    }

    std::vector<ElementKind> kinds;
    std::vector<double>      values; // n_entries per element, then the sections'
  };

  class VtuSeries
  {
  public:
    /// Interior subdivisions of each frame element in the drawing.
    static constexpr unsigned int n_member_subdivisions = 4;

    /// vtu: frames go to <directory>/<name>/<name>-NNNNN.vtu, the index to
    /// <directory>/<name>.pvd; xdmf: to <directory>/<name>.h5 (HDF5), the
    /// index to <directory>/<name>.xdmf (source/output/xdmf_series.cc).
    VtuSeries(const Model &model, const std::string &directory, const std::string &name,
              FieldFormat format = FieldFormat::vtu);
    /// The ranks of a partitioned run writing one HDF5 file and its XDMF
    /// index together. Each rank gives write() its own values and NaN
    /// where it has none (equations it neither owns nor ghosts, elements it
    /// does not observe). At the first frame the ranks agree whose each
    /// point and cell is: the lowest rank that draws it without a NaN (from
    /// zeros where it has values, so that the values cannot move a row).
    /// This needs every row to hold an array that passes a NaN through from
    /// each value the row depends on: true of the displacements and forces
    /// drawn; not of a comparison (`contact` is 1 for NaN), which a row must
    /// never hold alone.
    /// Each rank then writes its rows, rank 0 the rest. write() and
    /// finish() are collective; write_mode() is not for this series.
    VtuSeries(const Model &model, const std::string &directory, const std::string &name,
              MPI_Comm communicator);
    ~VtuSeries();

    /// A frame of a time history: `u` holds the equations' values; the
    /// member end forces from u, the gaps', hinges' and storeys' states from
    /// `elements` (their committed state).
    void write(double time, const Vector &u, const NonlinearElements &elements);
    /// The same with the elements' states given (observation by rank:
    /// merged from the ranks that observe them).
    void write(double time, const Vector &u, const ElementFrameStates &states);
    /// A mode shape, scaled so that its largest translation is
    /// `mode_amplitude` of the model's largest dimension (the factor is in
    /// the file's field data `scale`, with `mode`, `frequency_Hz` and
    /// `period_s`); no forces or states.
    void write_mode(unsigned int mode, double frequency, const Vector &shape);
    /// Write the .pvd index (atomically); xdmf: close the .h5 and write
    /// the .xdmf (both atomically; the ranks' file: rank 0 renames it and
    /// writes the index).
    void finish();

    static constexpr double mode_amplitude = 0.05;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };

  /// When a time history's field series adds a frame at an impact's peak:
  /// at the step where the gaps' total |force| stops rising (it rose or
  /// held to it and falls at the next step), unless that step has its
  /// regular frame. The peak is known one step late, so the step that may
  /// be one is held. One rule for the whole-model recorder and the
  /// recorder of a run partitioned by building, so both write the same
  /// frames.
  class ImpactPeakRule
  {
  public:
    /// At a step whose gaps' total |force| is `force`: whether the step
    /// held last was an impact's peak (its frame is due now).
    bool
    held_was_peak(const double force) const
    {
      return candidate && held_force >= force_before && force < held_force;
    }
    /// Then, with whether this step has its regular frame: whether this
    /// step must be held (it may be a peak).
    bool
    hold(const double force, const bool regular)
    {
      force_before = held_force;
      held_force   = force;
      candidate    = force > 0 && !regular;
      return candidate;
    }

  private:
    double held_force = 0, force_before = 0;
    bool   candidate  = false; // in contact and without a regular frame
  };

  /// The gaps' total |force| of `elements`, in the elements' order (the
  /// order fixes the rounding, alike in a whole-model and a partitioned run).
  double
  total_gap_force(const NonlinearElements &elements);

  /// A time history as a field series (solution.pvd, or solution.xdmf and
  /// solution.h5): a frame every `every` steps and, with `impact_peaks` and
  /// gap elements, a frame at the peak of each impact, where the impact is strongest: the
  /// step at which the gaps' total |force| stops rising (it rose or held to
  /// it and falls at the next step), unless that step has its regular frame.
  /// A regular interval alone would show an impact of a few steps at a
  /// random phase, or not at all. The peak is known one step late: the
  /// step's displacements and element states are held until the next.
  class VtuRecorder : public StepObserver
  {
  public:
    VtuRecorder(const Model &model, const std::string &directory, unsigned int every,
                FieldFormat format = FieldFormat::vtu, bool impact_peaks = false)
      : every(every)
      , impact_peaks(impact_peaks)
      , series(model, directory, "solution", format)
    {}
    void initialize(const ResponseView &state) override;
    void observe_step(const ResponseView &state) override;
    void finish(const ResponseView &, const RunStatus &) override { series.finish(); }

  private:
    const unsigned int every;
    const bool         impact_peaks; // Output/VTU impact peaks
    unsigned long      next = 0;
    VtuSeries          series;
    ImpactPeakRule     peaks;
    /// The last step, while it may be an impact's peak.
    struct HeldStep
    {
      double             time = 0;
      Vector             u;
      ElementFrameStates states;
    } held;
  };
} // namespace poundfe

#endif
