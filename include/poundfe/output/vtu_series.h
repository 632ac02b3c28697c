// ParaView output: the model as a deal.II Triangulation<1,2> (members and
// storey links are line cells, nodes are vertices) with FESystem(FE_Q(1), 3)
// for (ux, uy, rz); DataOut<1,2> writes one .vtu per frame and a .pvd index.
// Cell data: member end forces in local axes (N, V, M at both ends) or the
// storey shear of a link. deal.II stays inside the implementation.
#ifndef poundfe_output_vtu_series_h
#define poundfe_output_vtu_series_h

#include <poundfe/assembly/linear_system.h>
#include <poundfe/model/model.h>
#include <poundfe/output/observer.h>

#include <memory>
#include <string>

namespace poundfe
{
  class VtuSeries
  {
  public:
    /// Frames go to <directory>/<name>/<name>-NNNNN.vtu, the index to
    /// <directory>/<name>.pvd.
    VtuSeries(const Model &model, const std::string &directory, const std::string &name);
    ~VtuSeries();

    /// One frame; `u` holds the equations' values; `label` is the time or
    /// the mode number shown by ParaView.
    void write(double label, const Vector &u, bool with_forces = true);
    /// Write the .pvd index (atomically).
    void finish();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };

  /// A time history as a VTU series (solution.pvd): a frame every `every` steps.
  class VtuRecorder : public StepObserver
  {
  public:
    VtuRecorder(const Model &model, const std::string &directory, unsigned int every)
      : series(model, directory, "solution")
      , every(every)
    {}
    void
    initialize(const ResponseView &state) override
    {
      next_frame = 0;
      observe_step(state);
    }
    void
    observe_step(const ResponseView &state) override
    {
      if (state.step() != next_frame) // a comparison, not a division, per step
        return;
      next_frame += every;
      series.write(state.time(), state.displacement());
    }
    void finish(const ResponseView &, const RunStatus &) override { series.finish(); }

  private:
    VtuSeries          series;
    const unsigned int every;
    unsigned long      next_frame = 0;
  };
} // namespace poundfe

#endif
