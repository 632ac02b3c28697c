// Two-node elements of OpenSees scripts beside those of opensees_domain.h:
// zeroLengthSection (a section's resultants between two coincident nodes)
// and corotTruss (a large-displacement truss). Made by the Tcl reader of
// source/commands/opensees_tcl_model.cc; nothing here knows of Tcl.
#ifndef poundfe_opensees_opensees_section_links_h
#define poundfe_opensees_opensees_section_links_h

#include <poundfe/opensees/opensees_domain.h>

#include <array>
#include <memory>
#include <vector>

namespace poundfe
{
  namespace opensees
  {
    /// element zeroLengthSection tag i j secTag <-orient x yp> <-doRayleigh f>
    /// (OpenSees's ZeroLengthSection): the section's deformations the
    /// relative displacements of node j to node i along the local axes
    /// (P along x, Mz about z, My about y, T about x), in 2D (-ndf 3) and
    /// 3D (-ndf 6).
    struct ZeroLengthSectionData
    {
      std::array<int, 2>    nodes{};
      int                   section = 0;
      std::array<double, 3> x{{1, 0, 0}}, y{{0, 1, 0}};
      bool                  rayleigh = false;
    };
    std::unique_ptr<Element> make_zero_length_section(const Domain &domain, int tag,
                                                      const ZeroLengthSectionData &data);

    /// element corotTruss tag i j A matTag <-rho r> <-cMass f> <-doRayleigh f>
    /// (OpenSees's CorotTruss, Crisfield's corotational truss): strain
    /// (L_n - L_0)/L_0 of the current length, force along the current chord.
    std::unique_ptr<Element> make_corot_truss(const Domain &domain, int tag,
                                              std::array<int, 2> nodes, double area,
                                              int material, bool rayleigh);

    /// A section's resultants or deformations in OpenSees's order of its
    /// codes: an Aggregator's in the order the script gave its dofs.
    std::vector<double> section_values(const SectionLaw &section, const SectionVector &values);
  } // namespace opensees
} // namespace poundfe

#endif
