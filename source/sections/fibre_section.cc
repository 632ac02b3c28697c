// The fibre section: s = sum sigma_i A_i a_i, k_s = sum E_t,i A_i a_i a_i^T
// with a_i = (1, -y_i[, z_i]) (see the header; Spacone, Filippou & Taucer
// 1996; OpenSees's FiberSection2d/3d).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/lean_assert.h>
#include <poundfe/laws/concrete02.h>
#include <poundfe/laws/steel02.h>
#include <poundfe/sections/fibre_section.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace poundfe
{
  MaterialRole
  SectionMaterial::role() const
  {
    const std::string &m = law.material;
    if (m == "Concrete01" || m == "Concrete02")
      return MaterialRole::concrete;
    if (m == "Steel01" || m == "Steel02" || m == "ElasticPP")
      return MaterialRole::steel;
    return MaterialRole::other;
  }

  unsigned int
  FibreGeometry::material_index(const std::string &name) const
  {
    for (unsigned int i = 0; i < materials.size(); ++i)
      if (materials[i].name == name)
        return i;
    std::string known;
    for (const SectionMaterial &m : materials)
      known += (known.empty() ? "" : ", ") + m.name;
    throw InputError("", 0, "Material",
                     "no material '" + name + "' in the section (given: " +
                       (known.empty() ? "none" : known) + ")");
  }

  unsigned int
  FibreGeometry::add_material(const SectionMaterial &material)
  {
    for (const SectionMaterial &m : materials)
      if (m.name == material.name)
        throw InputError("", 0, "Material", "material '" + material.name + "' given twice");
    materials.push_back(material);
    return materials.size() - 1;
  }

  double
  FibreGeometry::area() const
  {
    double a = 0;
    for (const Fibre &f : fibres)
      a += f.area;
    return a;
  }

  double
  FibreGeometry::centroid_y() const
  {
    double q = 0;
    for (const Fibre &f : fibres)
      q += f.y * f.area;
    return q / area();
  }

  double
  FibreGeometry::centroid_z() const
  {
    double q = 0;
    for (const Fibre &f : fibres)
      q += f.z * f.area;
    return q / area();
  }

  namespace
  {
    std::shared_ptr<const FibreGeometry>
    checked_fibre_geometry(const FibreGeometry &geometry)
    {
      if (geometry.fibres.empty())
        throw InputError("", 0, "Fibres", "the section has no fibres");
      for (unsigned int i = 0; i < geometry.fibres.size(); ++i)
        {
          const Fibre &f = geometry.fibres[i];
          if (!(std::isfinite(f.y) && std::isfinite(f.z) && std::isfinite(f.area) && f.area > 0))
            throw InputError("", 0, "Fibres",
                             "fibre " + std::to_string(i) + " has area " +
                               std::to_string(f.area) + " (each must be positive)");
          if (f.material >= geometry.materials.size())
            throw InputError("", 0, "Fibres", "fibre " + std::to_string(i) + " has no material");
        }
      return std::make_shared<const FibreGeometry>(geometry);
    }

    /// a_i . e = e0 - dy e1 [+ dz e2 in space], dy = y - y_ref, dz = z -
    /// z_ref: a fibre's strain; the one formula of FibreSection::strain_at
    /// and the section's trial, so both give the same bits.
    inline double
    strain_of(const double dy, const double dz, const double e0, const double e1,
              const double e2, const bool in_space)
    {
      double strain = e0 - dy * e1;
      if (in_space)
        strain += dz * e2;
      return strain;
    }
  } // namespace

  namespace internal
  {
    /// Consecutive fibres first, ..., first + n - 1 of one material: their
    /// states, evaluated together.
    class FibreRun
    {
    public:
      FibreRun(const unsigned int first, const unsigned int n)
        : first(first)
        , n(n)
      {}
      virtual ~FibreRun() = default;
      /// Each fibre's trial state at strains[k]: its stress and tangent into
      /// stresses[k], tangents[k] (k < n).
      virtual void set_trials(const double *strains, double *stresses, double *tangents) = 0;
      virtual void commit() = 0;
      virtual void revert() = 0;
      virtual void reset() = 0;
      /// Fibre first + k's trial stress, and why its law refused its strain.
      virtual double      stress(unsigned int k) const = 0;
      virtual std::string failure(unsigned int k) const = 0;
      /// The law of fibre first + k's material, for its constants.
      virtual const UniaxialLaw &material(unsigned int k) const = 0;

      const unsigned int first, n;
    };

    /// A run of a material whose fibres' states are one typed array each
    /// (committed, trial), evaluated by the material's trial_state: no
    /// virtual call per fibre. The material's one law holds its constants.
    /// Material: a UniaxialMaterial<State> whose trial_state(from, last,
    /// strain) is what its set_trial computes, and which befriends the run.
    template <class Material, class State>
    class TypedFibreRun final : public FibreRun
    {
    public:
      TypedFibreRun(const unsigned int first, const unsigned int n,
                    std::unique_ptr<UniaxialLaw> material_law)
        : FibreRun(first, n)
        , law(std::move(material_law))
        , typed(static_cast<const Material &>(*law))
      {
        reset();
      }
      void set_trials(const double *strains, double *stresses, double *tangents) override
      {
        for (unsigned int k = 0; k < n; ++k)
          {
            // trial[k] is the last trial until replaced (Concrete02's dead band)
            trial[k]    = typed.trial_state(committed[k], trial[k], strains[k]);
            stresses[k] = trial[k].stress;
            tangents[k] = trial[k].tangent;
          }
      }
      void   commit() override { committed = trial; }
      void   revert() override { trial = committed; }
      void   reset() override { committed = trial = std::vector<State>(n, typed.virgin()); }
      double stress(const unsigned int k) const override { return trial[k].stress; }
      std::string failure(const unsigned int k) const override
      {
        // the material's own words, of a law in fibre k's trial state
        Material fibre = typed;
        fibre.trial    = trial[k];
        return fibre.failure();
      }
      const UniaxialLaw &material(unsigned int) const override { return *law; }

    private:
      std::unique_ptr<UniaxialLaw> law;
      const Material              &typed;
      std::vector<State>           committed, trial;
    };

    /// A run of any other material: one law per fibre.
    class LawFibreRun final : public FibreRun
    {
    public:
      LawFibreRun(const unsigned int first, std::vector<std::unique_ptr<UniaxialLaw>> fibre_laws)
        : FibreRun(first, fibre_laws.size())
        , laws(std::move(fibre_laws))
      {}
      void set_trials(const double *strains, double *stresses, double *tangents) override
      {
        for (unsigned int k = 0; k < n; ++k)
          {
            // a refused strain shows as a stress or tangent that is not
            // finite: the section looks no further than its sums
            if (laws[k]->set_trial(strains[k], 0))
              {
                stresses[k] = laws[k]->force();
                tangents[k] = laws[k]->tangent();
              }
            else
              stresses[k] = tangents[k] = std::numeric_limits<double>::quiet_NaN();
          }
      }
      void commit() override
      {
        for (const auto &law : laws)
          law->commit();
      }
      void revert() override
      {
        for (const auto &law : laws)
          law->revert();
      }
      void reset() override
      {
        for (const auto &law : laws)
          law->reset();
      }
      double      stress(const unsigned int k) const override { return laws[k]->force(); }
      std::string failure(const unsigned int k) const override { return laws[k]->failure(); }
      const UniaxialLaw &material(const unsigned int k) const override { return *laws[k]; }

    private:
      std::vector<std::unique_ptr<UniaxialLaw>> laws;
    };

    /// A section's fibres: a_i's entries dy = y - y_ref, dz = z - z_ref and
    /// the areas (structure of arrays, in the fibres' order), the last
    /// trial's strains, stresses and tangents, and the runs that hold the
    /// states.
    struct FibreStates
    {
      std::vector<double>                    dy, dz, area, strain, stress, tangent;
      std::vector<std::unique_ptr<FibreRun>> runs;
      /// The run of fibre i.
      const FibreRun &run_of(unsigned int i) const;
    };

    const FibreRun &
    FibreStates::run_of(const unsigned int i) const
    {
      const auto after = std::upper_bound(runs.begin(), runs.end(), i,
                                          [](const unsigned int j, const auto &run) {
                                            return j < run->first;
                                          });
      return **(after - 1);
    }

    namespace
    {
      /// The run of fibres first, ..., first + n - 1, all of `material`.
      std::unique_ptr<FibreRun>
      make_run(const MaterialParameters &material, const unsigned int first, const unsigned int n)
      {
        std::unique_ptr<UniaxialLaw> law = make_material(material);
        if (dynamic_cast<const Concrete02 *>(law.get()))
          return std::make_unique<TypedFibreRun<Concrete02, Concrete02State>>(first, n,
                                                                              std::move(law));
        if (dynamic_cast<const Steel02 *>(law.get()))
          return std::make_unique<TypedFibreRun<Steel02, Steel02State>>(first, n, std::move(law));
        std::vector<std::unique_ptr<UniaxialLaw>> laws;
        laws.push_back(std::move(law));
        while (laws.size() < n) // each fibre keeps its own history
          laws.push_back(make_material(material));
        return std::make_unique<LawFibreRun>(first, std::move(laws));
      }

      std::unique_ptr<FibreStates>
      make_fibre_states(const FibreGeometry &g, const double y_ref, const double z_ref)
      {
        auto               states = std::make_unique<FibreStates>();
        const unsigned int n      = g.fibres.size();
        for (const Fibre &f : g.fibres)
          {
            states->dy.push_back(f.y - y_ref);
            states->dz.push_back(f.z - z_ref);
            states->area.push_back(f.area);
          }
        states->strain.assign(n, 0.0);
        states->stress.assign(n, 0.0);
        states->tangent.assign(n, 0.0);
        for (unsigned int first = 0, end = 0; first < n; first = end)
          {
            end = first + 1;
            while (end < n && g.fibres[end].material == g.fibres[first].material)
              ++end;
            states->runs.push_back(
              make_run(g.materials[g.fibres[first].material].law, first, end - first));
          }
        return states;
      }

      /// The sums s = sum sigma_i A_i a_i, k_s = sum E_t,i A_i a_i a_i^T of
      /// the m = 2 (plane) or 3 (N, Mz, My in space) resultants the fibres
      /// carry, over the fibres in their order, into the first m entries of
      /// s, k. m fixed at compile time: the sums unrolled, in registers.
      template <unsigned int m>
      void
      sum_fibres(const FibreStates &fibres, SectionVector &s, SectionMatrix &k)
      {
        double sums[m] = {}, stiffness_sums[m][m] = {};
        for (unsigned int i = 0; i < fibres.area.size(); ++i)
          {
            const double a[3]  = {1, -fibres.dy[i], fibres.dz[i]};
            const double force = fibres.stress[i] * fibres.area[i],
                         stiffness = fibres.tangent[i] * fibres.area[i];
            for (unsigned int r = 0; r < m; ++r)
              {
                sums[r] += force * a[r];
                for (unsigned int c = 0; c < m; ++c)
                  stiffness_sums[r][c] += stiffness * a[r] * a[c];
              }
          }
        for (unsigned int r = 0; r < m; ++r)
          {
            s(r) = sums[r];
            for (unsigned int c = 0; c < m; ++c)
              k(r, c) = stiffness_sums[r][c];
          }
      }
    } // namespace
  } // namespace internal

  FibreSection::FibreSection(const FibreGeometry &geometry, const unsigned int n_resultants,
                             const double torsional_rigidity, const bool about_centroid)
    : FibreSection(checked_fibre_geometry(geometry), n_resultants, torsional_rigidity,
                   about_centroid ? geometry.centroid_y() : 0.0,
                   about_centroid ? geometry.centroid_z() : 0.0)
  {}

  FibreSection::FibreSection(FibreSection &&) noexcept = default;
  FibreSection::~FibreSection()                        = default;

  FibreSection::FibreSection(std::shared_ptr<const FibreGeometry> geometry,
                             const unsigned int n_resultants, const double torsional_rigidity,
                             const double y_ref, const double z_ref)
    : fibres(std::move(geometry))
    , n(n_resultants)
    , torsional_rigidity(torsional_rigidity)
    , y_ref(y_ref)
    , z_ref(z_ref)
  {
    if (n != 2 && n != 4)
      throw std::logic_error("a fibre section has 2 or 4 resultants");
    if (n == 4 && !(std::isfinite(torsional_rigidity) && torsional_rigidity > 0))
      throw InputError("", 0, "GJ", "a section in space needs a positive torsional rigidity");
    states = internal::make_fibre_states(*fibres, y_ref, z_ref);
    reset();
    virgin_tangent = trial.tangent;
  }

  double
  FibreSection::strain_at(const unsigned int i, const SectionVector &e) const
  {
    return strain_of(states->dy[i], states->dz[i], e(0), e(1), n == 4 ? e(2) : 0.0, n == 4);
  }

  double
  FibreSection::fibre_strain(const unsigned int i) const
  {
    return strain_at(i, trial.deformation);
  }

  double
  FibreSection::fibre_stress(const unsigned int i) const
  {
    const internal::FibreRun &run = states->run_of(i);
    return run.stress(i - run.first);
  }

  const UniaxialLaw &
  FibreSection::fibre_material(const unsigned int i) const
  {
    const internal::FibreRun &run = states->run_of(i);
    return run.material(i - run.first);
  }

  bool
  FibreSection::set_trial(const SectionVector &e)
  {
    Assert(e.size() == n, dealii::ExcDimensionMismatch(e.size(), n));
    trial.deformation = e;
    trial.resultant.setZero();
    trial.tangent.setZero();
    internal::FibreStates &f = *states;
    const unsigned int     n_fibres = f.area.size();
    const double           e0 = e(0), e1 = e(1), e2 = n == 4 ? e(2) : 0.0;
    bool strains_finite = true; // a law refuses a strain that is not finite
    for (unsigned int i = 0; i < n_fibres; ++i)
      {
        f.strain[i] = strain_of(f.dy[i], f.dz[i], e0, e1, e2, n == 4);
        strains_finite &= std::isfinite(f.strain[i]);
      }
    for (const auto &run : f.runs)
      run->set_trials(&f.strain[run->first], &f.stress[run->first], &f.tangent[run->first]);
    if (n == 4)
      internal::sum_fibres<3>(f, trial.resultant, trial.tangent);
    else
      internal::sum_fibres<2>(f, trial.resultant, trial.tangent);
    if (!(strains_finite && trial.resultant.allFinite() && trial.tangent.allFinite()))
      {
        // the first fibre whose law refused its strain, if one did
        for (failed_fibre = 0; failed_fibre < n_fibres; ++failed_fibre)
          if (!(std::isfinite(f.strain[failed_fibre]) && std::isfinite(f.stress[failed_fibre]) &&
                std::isfinite(f.tangent[failed_fibre])))
            break;
        failed_fibre = std::min(failed_fibre, n_fibres - 1);
        return false;
      }
    if (n == 4)
      {
        trial.resultant(3)  = torsional_rigidity * e(3);
        trial.tangent(3, 3) = torsional_rigidity;
      }
    return std::isfinite(trial.resultant(n - 1));
  }

  void
  FibreSection::commit()
  {
    for (const auto &run : states->runs)
      run->commit();
    committed = trial;
  }

  void
  FibreSection::revert()
  {
    for (const auto &run : states->runs)
      run->revert();
    trial = committed;
  }

  void
  FibreSection::reset()
  {
    for (const auto &run : states->runs)
      run->reset();
    trial.deformation = SectionVector::Zero(n);
    trial.resultant   = SectionVector::Zero(n);
    trial.tangent     = SectionMatrix::Zero(n, n);
    // the virgin tangent: each law's initial stiffness at zero strain
    const unsigned int m = n == 4 ? 3 : 2;
    for (unsigned int i = 0; i < states->area.size(); ++i)
      {
        const double a[3] = {1, -states->dy[i], states->dz[i]};
        const double stiffness = fibre_material(i).initial_stiffness() * states->area[i];
        for (unsigned int r = 0; r < m; ++r)
          for (unsigned int c = 0; c < m; ++c)
            trial.tangent(r, c) += stiffness * a[r] * a[c];
      }
    if (n == 4)
      trial.tangent(3, 3) = torsional_rigidity;
    committed = trial;
  }

  std::unique_ptr<SectionLaw>
  FibreSection::clone() const
  {
    return std::unique_ptr<SectionLaw>(
      new FibreSection(fibres, n, torsional_rigidity, y_ref, z_ref));
  }

  std::string
  FibreSection::failure() const
  {
    const Fibre              &f   = fibres->fibres[failed_fibre];
    const internal::FibreRun &run = states->run_of(failed_fibre);
    std::ostringstream        text;
    text.precision(6);
    text << "fibre " << failed_fibre << " at (y, z) = (" << f.y << ", " << f.z << ") m of material '"
         << fibres->materials[f.material].name << "' (" << fibres->materials[f.material].law.material
         << "): " << run.failure(failed_fibre - run.first);
    return text.str();
  }
} // namespace poundfe
