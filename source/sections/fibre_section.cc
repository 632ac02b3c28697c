// The fibre section: s = sum sigma_i A_i a_i, k_s = sum E_t,i A_i a_i a_i^T
// with a_i = (1, -y_i[, z_i]) (see the header; Spacone, Filippou & Taucer
// 1996; OpenSees's FiberSection2d/3d).
#include <poundfe/base/exceptions.h>
#include <poundfe/base/lean_assert.h>
#include <poundfe/sections/fibre_section.h>

#include <cmath>
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

    /// a_i . e = e0 - (y - y_ref) e1 [+ (z - z_ref) e2 in space]: fibre f's
    /// strain; the one formula of FibreSection::strain_at and sum_fibres,
    /// so both give the same bits.
    inline double
    strain_of(const Fibre &f, const double y_ref, const double z_ref, const double e0,
              const double e1, const double e2, const bool in_space)
    {
      double strain = e0 - (f.y - y_ref) * e1;
      if (in_space)
        strain += (f.z - z_ref) * e2;
      return strain;
    }

    /// Every fibre's trial state at e and the sums s = sum sigma_i A_i a_i,
    /// k_s = sum E_t,i A_i a_i a_i^T of the m = 2 (plane) or 3 (N, Mz, My in
    /// space) resultants the fibres carry, into the first m entries of s, k;
    /// returns the first fibre that refused its strain, or the number of
    /// fibres. m fixed at compile time: the sums unrolled, in registers.
    template <unsigned int m>
    unsigned int
    sum_fibres(const std::vector<Fibre>                       &fibres,
               const std::vector<std::unique_ptr<UniaxialLaw>> &laws, const double y_ref,
               const double z_ref, const SectionVector &e, SectionVector &s, SectionMatrix &k)
    {
      double       sums[m] = {}, stiffness_sums[m][m] = {};
      const double e0 = e(0), e1 = e(1), e2 = m == 3 ? e(2) : 0.0;
      for (unsigned int i = 0; i < laws.size(); ++i)
        {
          const Fibre &f = fibres[i];
          const double a[3]   = {1, -(f.y - y_ref), f.z - z_ref};
          const double strain = strain_of(f, y_ref, z_ref, e0, e1, e2, m == 3);
          UniaxialLaw &law = *laws[i];
          if (!law.set_trial(strain, 0))
            return i;
          const double force = law.force() * f.area, stiffness = law.tangent() * f.area;
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
      return laws.size();
    }
  } // namespace

  FibreSection::FibreSection(const FibreGeometry &geometry, const unsigned int n_resultants,
                             const double torsional_rigidity, const bool about_centroid)
    : FibreSection(checked_fibre_geometry(geometry), n_resultants, torsional_rigidity,
                   about_centroid ? geometry.centroid_y() : 0.0,
                   about_centroid ? geometry.centroid_z() : 0.0)
  {}

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
    // one law per fibre: each fibre keeps its own history
    laws.reserve(fibres->fibres.size());
    for (const Fibre &f : fibres->fibres)
      laws.push_back(make_material(fibres->materials[f.material].law));
    reset();
    virgin_tangent = trial.tangent;
  }

  double
  FibreSection::strain_at(const unsigned int i, const SectionVector &e) const
  {
    return strain_of(fibres->fibres[i], y_ref, z_ref, e(0), e(1), n == 4 ? e(2) : 0.0, n == 4);
  }

  double
  FibreSection::fibre_strain(const unsigned int i) const
  {
    return strain_at(i, trial.deformation);
  }

  bool
  FibreSection::set_trial(const SectionVector &e)
  {
    Assert(e.size() == n, dealii::ExcDimensionMismatch(e.size(), n));
    trial.deformation = e;
    trial.resultant.setZero();
    trial.tangent.setZero();
    const unsigned int refused =
      n == 4 ?
        sum_fibres<3>(fibres->fibres, laws, y_ref, z_ref, e, trial.resultant, trial.tangent) :
        sum_fibres<2>(fibres->fibres, laws, y_ref, z_ref, e, trial.resultant, trial.tangent);
    if (refused < laws.size())
      {
        failed_fibre = refused;
        return false;
      }
    if (n == 4)
      {
        trial.resultant(3)  = torsional_rigidity * e(3);
        trial.tangent(3, 3) = torsional_rigidity;
      }
    return trial.resultant.allFinite() && trial.tangent.allFinite();
  }

  void
  FibreSection::commit()
  {
    for (const auto &law : laws)
      law->commit();
    committed = trial;
  }

  void
  FibreSection::revert()
  {
    for (const auto &law : laws)
      law->revert();
    trial = committed;
  }

  void
  FibreSection::reset()
  {
    for (const auto &law : laws)
      law->reset();
    trial.deformation = SectionVector::Zero(n);
    trial.resultant   = SectionVector::Zero(n);
    trial.tangent     = SectionMatrix::Zero(n, n);
    // the virgin tangent: each law's initial stiffness at zero strain
    for (unsigned int i = 0; i < laws.size(); ++i)
      {
        const Fibre &f = fibres->fibres[i];
        const double a[3] = {1, -(f.y - y_ref), f.z - z_ref};
        const unsigned int m = n == 4 ? 3 : 2;
        for (unsigned int r = 0; r < m; ++r)
          for (unsigned int c = 0; c < m; ++c)
            trial.tangent(r, c) += laws[i]->initial_stiffness() * f.area * a[r] * a[c];
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
    const Fibre &f = fibres->fibres[failed_fibre];
    std::ostringstream text;
    text.precision(6);
    text << "fibre " << failed_fibre << " at (y, z) = (" << f.y << ", " << f.z << ") m of material '"
         << fibres->materials[f.material].name << "' (" << fibres->materials[f.material].law.material
         << "): " << laws[failed_fibre]->failure();
    return text.str();
  }
} // namespace poundfe
