// OpenSees 3.8's Drift and Envelope recorders.
//
// Drift (DriftRecorder.cpp): for each pair (i, j) of nodes whose
// coordinates along perpDirn differ,
//     drift = (u_j[dof] - u_i[dof]) / |x_j[perpDirn] - x_i[perpDirn]|,
// pairs at the same coordinate left out; with none left, no file at all.
//
// EnvelopeNode, EnvelopeElement (EnvelopeNodeRecorder.cpp,
// EnvelopeElementRecorder.cpp): of each value v of a Node or Element
// recorder at the records that are due, three rows
//     min v,  max v,  max |v|,
// updated as OpenSees updates them (the first record sets all three; then a
// value below the least replaces it, else a value above the largest; either
// may raise the magnitude). With -time each value is preceded by the time it
// was reached. The rows are written once, when the recorder finishes; none
// if it never recorded.
#include <poundfe/base/lean_assert.h>
#include <poundfe/opensees/opensees_recorder.h>

#include <cmath>

namespace poundfe
{
  namespace opensees
  {
    DriftRecorder::DriftRecorder(DriftRecorderSpec spec, const Domain &domain)
      : Recorder(spec)
      , dof(spec.dof)
    {
      Assert(spec.i_nodes.size() == spec.j_nodes.size(), dealii::ExcMessage("as many i nodes as j nodes"));
      for (std::size_t k = 0; k < spec.i_nodes.size(); ++k)
        {
          const std::vector<double> &a = domain.node(spec.i_nodes[k]).coordinates,
                                    &b = domain.node(spec.j_nodes[k]).coordinates;
          const unsigned int p = spec.perpendicular;
          if (p < a.size() && p < b.size() && a[p] != b[p])
            {
              pairs.push_back({{spec.i_nodes[k], spec.j_nodes[k]}});
              inverse_lengths.push_back(1.0 / std::fabs(b[p] - a[p]));
            }
        }
    }

    void
    DriftRecorder::record(const Domain &domain)
    {
      if (has_pairs())
        Recorder::record(domain);
    }

    void
    DriftRecorder::write_out()
    {
      if (has_pairs())
        Recorder::write_out();
    }

    void
    DriftRecorder::values(const Domain &domain, std::vector<double> &line)
    {
      for (std::size_t k = 0; k < pairs.size(); ++k)
        {
          const double dx =
            domain.node(pairs[k][1]).disp.at(dof) - domain.node(pairs[k][0]).disp.at(dof);
          line.push_back(dx * inverse_lengths[k]);
        }
    }

    template <typename Values>
    EnvelopeRecorder<Values>::EnvelopeRecorder(typename Values::Spec spec)
      : Values(std::move(spec))
    {}

    template <typename Values>
    void
    EnvelopeRecorder<Values>::record(const Domain &domain)
    {
      if (!this->due(domain.time))
        return;
      current.clear();
      this->values(domain, current);
      const std::size_t n = current.size(), stride = this->time ? 2 : 1, at = stride - 1;
      if (first)
        {
          for (auto &row : rows)
            row.assign(stride * n, domain.time);
          for (std::size_t k = 0; k < n; ++k)
            {
              rows[0][stride * k + at] = rows[1][stride * k + at] = current[k];
              rows[2][stride * k + at] = std::fabs(current[k]);
            }
          first = false;
          return;
        }
      for (std::size_t k = 0; k < n; ++k)
        {
          const double value = current[k];
          const std::size_t i = stride * k + at;
          int extreme = -1; // the row whose value this one replaces
          if (rows[0][i] > value)
            extreme = 0;
          else if (rows[1][i] < value)
            extreme = 1;
          if (extreme < 0)
            continue;
          rows[extreme][i] = value;
          if (this->time)
            rows[extreme][i - 1] = domain.time;
          if (rows[2][i] < std::fabs(value))
            {
              rows[2][i] = std::fabs(value);
              if (this->time)
                rows[2][i - 1] = domain.time;
            }
        }
    }

    template <typename Values>
    void
    EnvelopeRecorder<Values>::write_out()
    {
      if (!first)
        for (const auto &row : rows)
          this->write_line(this->recorded_time, row);
      first = true;
      Values::write_out();
    }

    template class EnvelopeRecorder<NodeRecorder>;
    template class EnvelopeRecorder<ElementRecorder>;
  } // namespace opensees
} // namespace poundfe
