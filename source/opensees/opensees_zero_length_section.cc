// OpenSees's ZeroLengthSection (element/zeroLength/ZeroLengthSection.cpp,
// OpenSees 3.8): a section between two nodes at one point. With the local
// axes x, z = x × yp, y = z × x, normalised (the rows of T), the
// section's deformations are relative displacements of node j to node i,
//   e = A u,  A = [-A_j  A_j],
// row by resultant: P  = x · Δu (translations), Mz = z · Δθ, My = y · Δθ,
// T = x · Δθ (in 2D, -ndf 3: P = x_X Δu_X + x_Y Δu_Y, Mz = z_Z Δθ);
// resisting force A^T s(e), tangent A^T k_s A. Rayleigh-damped unless
// -doRayleigh 0 (OpenSees's default 1); no mass.
#include <poundfe/opensees/opensees_section_links.h>

#include <Eigen/Geometry>

namespace poundfe
{
  namespace opensees
  {
    namespace
    {
      class ZeroLengthSection : public Element
      {
      public:
        ZeroLengthSection(const int tag, const std::array<int, 2> nodes, Matrix A,
                          std::unique_ptr<SectionLaw> section, const bool rayleigh)
          : Element(tag, {nodes[0], nodes[1]})
          , A(std::move(A))
          , section(std::move(section))
          , rayleigh(rayleigh)
        {
          committed_tangent = tangent();
        }

        unsigned int n_dofs() const override { return A.cols(); }
        bool         rayleigh_damped() const override { return rayleigh; }

        bool
        set_trial(const Vector &u, const Vector &) override
        {
          const Vector e = A * u;
          return section->set_trial(SectionVector(e));
        }
        Vector force() const override { return A.transpose() * section->resultant(); }
        Matrix tangent() const override { return A.transpose() * section->tangent() * A; }
        Matrix
        initial_tangent() const override
        {
          return A.transpose() * section->initial_tangent() * A;
        }
        void        commit() override { section->commit(); }
        void        revert() override { section->revert(); }
        void        reset() override { section->reset(); }
        std::string failure() const override { return section->failure(); }

        /// ZeroLengthSection::setResponse: force (global), basicForce or
        /// localForce (the resultants), deformation or basicDeformation,
        /// section <1> force|deformation.
        std::vector<double>
        response(const std::vector<std::string> &words) const override
        {
          std::vector<std::string> w = words;
          const bool of_section = w.size() >= 2 && w[0] == "section";
          if (of_section)
            w.erase(w.begin(), w.begin() + (w.size() >= 3 && w[1] == "1" ? 2 : 1));
          const std::string what = w.size() == 1 ? w[0] : "";
          const bool        global = what == "force" || what == "forces" ||
                              what == "globalForce" || what == "globalForces";
          if (global && !of_section)
            return Element::response(words);
          if (global || what == "basicForce" || what == "basicForces" ||
              what == "localForce" || what == "localForces")
            return section_values(*section, section->resultant());
          if (what == "deformation" || what == "deformations" || what == "defo" ||
              what == "basicDeformation")
            return section_values(*section, section->deformation());
          return Element::response(words);
        }

      private:
        Matrix                      A; // resultants x DOFs
        std::unique_ptr<SectionLaw> section;
        bool                        rayleigh;
      };

      /// ZeroLengthSection::setUp: the rows x, y, z of direction cosines.
      Eigen::Matrix3d
      local_axes(const int tag, const ZeroLengthSectionData &data)
      {
        const Eigen::Vector3d x(data.x[0], data.x[1], data.x[2]),
          yp(data.y[0], data.y[1], data.y[2]);
        const Eigen::Vector3d z = x.cross(yp), y = z.cross(x);
        if (x.norm() == 0 || y.norm() == 0 || z.norm() == 0)
          throw ScriptError("zeroLengthSection " + std::to_string(tag) +
                            ": -orient vectors are zero or parallel");
        Eigen::Matrix3d T;
        T.row(0) = x / x.norm();
        T.row(1) = y / y.norm();
        T.row(2) = z / z.norm();
        return T;
      }

      /// ZeroLengthSection::setTransformation in poundfe's order of the
      /// resultants (P, Mz[, My, T]).
      Matrix
      section_transformation(const Eigen::Matrix3d &T, const unsigned int n_resultants,
                             const unsigned int ndf)
      {
        Matrix A = Matrix::Zero(n_resultants, 2 * ndf);
        if (ndf == 3)
          {
            A(0, 3) = T(0, 0), A(0, 4) = T(0, 1); // P
            A(1, 5) = T(2, 2);                    // Mz
          }
        else
          {
            A.block(0, 6, 1, 3) = T.row(0); // P
            A.block(1, 9, 1, 3) = T.row(2); // Mz
            A.block(2, 9, 1, 3) = T.row(1); // My
            A.block(3, 9, 1, 3) = T.row(0); // T
          }
        A.leftCols(ndf) = -A.rightCols(ndf);
        return A;
      }
    } // namespace

    std::unique_ptr<Element>
    make_zero_length_section(const Domain &domain, const int tag,
                             const ZeroLengthSectionData &data)
    {
      const std::string name = "zeroLengthSection " + std::to_string(tag);
      const bool        plane = domain.ndm == 2 && domain.ndf == 3;
      if (!plane && !(domain.ndm == 3 && domain.ndf == 6))
        throw ScriptError(name + ": OpenSees's zeroLengthSection takes -ndm 2 -ndf 3 or " +
                          "-ndm 3 -ndf 6 (this model: -ndm " + std::to_string(domain.ndm) +
                          " -ndf " + std::to_string(domain.ndf) + ")");
      const auto it = domain.sections.find(data.section);
      if (it == domain.sections.end())
        throw ScriptError(name + ": no section with tag " + std::to_string(data.section) +
                          " exists");
      const unsigned int n_resultants = plane ? 2 : 4;
      if (it->second->n_resultants() != n_resultants)
        throw ScriptError(name + ": section " + std::to_string(data.section) + " is not a " +
                          (plane ? "plane" : "3D") + " section");
      const Matrix A = section_transformation(local_axes(tag, data), n_resultants, domain.ndf);
      return std::make_unique<ZeroLengthSection>(tag, data.nodes, A, it->second->clone(),
                                                 data.rayleigh);
    }
  } // namespace opensees
} // namespace poundfe
