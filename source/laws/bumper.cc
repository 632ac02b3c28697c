// A bumper in front of a gap's contact law; equations and sources in
// include/poundfe/laws/bumper.h and doc/theory.md §4.9.
#include <poundfe/base/lean_assert.h>
#include <poundfe/base/numbers.h>
#include <poundfe/laws/bumper.h>
#include <poundfe/laws/contact_law.h>

#include <algorithm>
#include <cmath>

namespace poundfe
{
  namespace
  {
    /// The table's segment holding compression s (s in (0, last point]).
    unsigned int
    segment_of(const std::vector<std::array<double, 2>> &table, const double s)
    {
      unsigned int i = 0;
      while (i + 1 < table.size() && table[i][0] < s)
        ++i;
      return i;
    }

    /// The table's point before segment i: (0, 0) before the first.
    std::array<double, 2>
    start_of(const std::vector<std::array<double, 2>> &table, const unsigned int i)
    {
      return i == 0 ? std::array<double, 2>{{0.0, 0.0}} : table[i - 1];
    }

    /// F_b(s) of the uncrushed bumper, 0 <= s <= t.
    double
    layer_force(const BumperParameters &p, const double s)
    {
      switch (p.law)
        {
          case BumperLaw::linear:
            return p.stiffness * s;
          case BumperLaw::hertz:
            return p.stiffness * s * std::sqrt(s);
          case BumperLaw::table:
            {
              const unsigned int            i = segment_of(p.table, s);
              const std::array<double, 2> a = start_of(p.table, i), &b = p.table[i];
              return a[1] + (b[1] - a[1]) * (s - a[0]) / (b[0] - a[0]);
            }
          case BumperLaw::none:
            break;
        }
      return 0;
    }

    /// int_0^s F_b, 0 <= s <= t.
    double
    layer_energy(const BumperParameters &p, const double s)
    {
      switch (p.law)
        {
          case BumperLaw::linear:
            return 0.5 * p.stiffness * s * s;
          case BumperLaw::hertz:
            return 0.4 * p.stiffness * s * s * std::sqrt(s);
          case BumperLaw::table:
            {
              double                      energy = 0;
              std::array<double, 2>       a{{0.0, 0.0}};
              for (const std::array<double, 2> &b : p.table)
                {
                  const double end = std::min(s, b[0]);
                  if (end <= a[0])
                    break;
                  // trapezoid from a to end on the segment a-b
                  energy += 0.5 * (a[1] + layer_force(p, end)) * (end - a[0]);
                  a = b;
                }
              return energy;
            }
          case BumperLaw::none:
            break;
        }
      return 0;
    }
  } // namespace

  double
  BumperParameters::force(const double compression) const
  {
    return compression > 0 ? layer_force(*this, std::min(compression, thickness)) : 0.0;
  }

  double
  BumperParameters::tangent(const double compression) const
  {
    if (!(compression > 0) || compression >= thickness)
      return 0;
    switch (law)
      {
        case BumperLaw::linear:
          return stiffness;
        case BumperLaw::hertz:
          return 1.5 * stiffness * std::sqrt(compression);
        case BumperLaw::table:
          {
            const unsigned int            i = segment_of(table, compression);
            const std::array<double, 2> a = start_of(table, i), &b = table[i];
            return (b[1] - a[1]) / (b[0] - a[0]);
          }
        case BumperLaw::none:
          break;
      }
    return 0;
  }

  double
  BumperParameters::energy(const double compression) const
  {
    if (!(compression > 0))
      return 0;
    const double s = std::min(compression, thickness);
    return layer_energy(*this, s) + layer_force(*this, s) * (compression - s);
  }

  namespace
  {
    class BumperedContact final : public UniaxialLaw
    {
    public:
      BumperedContact(std::unique_ptr<ContactLaw> structure, const BumperParameters &bumper)
        : structure(std::move(structure))
        , bumper(bumper)
        , face(this->structure->parameters().initial_gap - bumper.thickness)
      {
        reset();
      }

      bool set_trial(const double closure, const double rate) override
      {
        const bool ok = structure->set_trial(closure, rate);
        trial.compression = closure - face;
        trial.rate        = rate;
        trial.bumper      = bumper.force(trial.compression);
        if (trial.bumper > 0 && !(committed.bumper > 0)) // onset: the pre-contact rate
          trial.approach_velocity = committed.rate > 0 ? committed.rate : rate;
        else
          trial.approach_velocity = committed.approach_velocity;
        return ok && std::isfinite(trial.bumper);
      }
      double force() const override { return trial.bumper + structure->force(); }
      double tangent() const override
      {
        return bumper.tangent(trial.compression) + structure->tangent();
      }
      double damping_tangent() const override { return structure->damping_tangent(); }
      double stored_energy() const override
      {
        return bumper.energy(trial.compression) + structure->stored_energy();
      }
      /// Penetration beyond the bumper's face (the structure's when t = 0).
      double history_variable() const override { return trial.compression; }
      double initial_stiffness() const override { return 0; }
      bool   is_active() const override { return force() > 0; }
      bool   was_active() const override { return committed.bumper + committed_structure_force > 0; }
      int    phase() const override { return phase_of(structure->is_active(), trial.bumper); }
      int    committed_phase() const override
      {
        return phase_of(structure->was_active(), committed.bumper);
      }
      double contact_duration(const double closing_rate) const override
      {
        if (structure->was_active() || bumper.thickness == 0)
          return structure->contact_duration(closing_rate);
        return bumper_duration(committed.bumper > 0 ? committed.approach_velocity : closing_rate);
      }
      void commit() override
      {
        structure->commit();
        committed                 = trial;
        committed_structure_force = structure->force();
      }
      void revert() override
      {
        structure->revert();
        trial = committed;
      }
      void reset() override
      {
        structure->reset();
        committed                 = State();
        committed.compression     = -face;
        committed_structure_force = 0;
        trial                     = committed;
      }
      std::string failure() const override
      {
        const std::string why = structure->failure();
        return why.empty() ? "the bumper's force is not finite at a compression of " +
                               number_text(trial.compression) + " m" :
                             why;
      }

    private:
      static int phase_of(const bool structure_active, const double bumper_force)
      {
        return structure_active ? structure_contact : (bumper_force > 0 ? bumper_contact : open_gap);
      }

      /// An elastic impact of the effective mass on the bumper alone: a
      /// linear spring of the bumper's (or the table's stiffest) slope, or a
      /// Hertz spring.
      double bumper_duration(const double v0) const
      {
        ContactLawParameters q = structure->parameters();
        q.law                  = bumper.law == BumperLaw::hertz ? "hertz" : "linear";
        q.stiffness            = bumper.stiffness;
        if (bumper.law == BumperLaw::table)
          {
            q.stiffness = 0;
            double a0 = 0, a1 = 0;
            for (const std::array<double, 2> &b : bumper.table)
              {
                q.stiffness = std::max(q.stiffness, (b[1] - a1) / (b[0] - a0));
                a0          = b[0];
                a1          = b[1];
              }
          }
        return q.stiffness > 0 ? elastic_impact_duration(q, std::abs(v0)) : 0.0;
      }

      struct State
      {
        double compression = 0, rate = 0, bumper = 0, approach_velocity = 0;
      };
      std::unique_ptr<ContactLaw> structure;
      BumperParameters            bumper;
      double                      face; // closure at which the bumper is touched: g - t
      State                       committed, trial;
      double                      committed_structure_force = 0;
    };
  } // namespace

  std::unique_ptr<UniaxialLaw>
  make_bumpered_contact(std::unique_ptr<ContactLaw> structure, const BumperParameters &bumper)
  {
    Assert(structure, dealii::ExcMessage("a bumper needs the gap's contact law"));
    return std::make_unique<BumperedContact>(std::move(structure), bumper);
  }
} // namespace poundfe
