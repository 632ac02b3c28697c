// Rayleigh damping by region of an OpenSees script, with OpenSees 3.8's
// semantics (SRC/domain/region/TclRegionCommands.cpp, MeshRegion.cpp,
// Element::getDamp, Node::getDamp):
//   region tag <-ele tags...> <-eleRange first last> <-eleOnly tags...>
//       <-eleOnlyRange first last> <-node tags...> <-nodeRange first last>
//       <-nodeOnly tags...> <-nodeOnlyRange first last> <-rayleigh aM bK bK0 bKc>
//   setElementRayleighDampingFactors eleTag aM bK bK0 bKc
// -ele's elements bring their nodes into the region, -eleOnly's do not;
// -node's nodes bring the elements whose nodes are all in the region
// (only when no element is given: OpenSees then keeps the elements'
// nodes), -nodeOnly's replace the region's nodes and bring no element.
// Tags that are not in the domain are left out (a listed one with a
// warning). -rayleigh sets, as OpenSees's MeshRegion::
// setRayleighDampingFactors, the factors of the region's elements,
//   C_e = aM M_e + bK K_t + bK0 K_0 + bKc K_c   (Rayleigh-damped elements),
// and the alpha_M of its nodes, C_n = aM M_n, at the time of the command
// (all four zero: nothing, as OpenSees); a later `rayleigh` sets those of
// every element and node then in the domain again (opensees::Domain::
// element_rayleigh; a node or element made after it is undamped).
#include <algorithm>
#include <set>

#include "opensees_tcl.h"

namespace poundfe
{
  namespace opensees_tcl
  {
    namespace
    {
      using opensees::ScriptError;

      /// The objects a region's options name, in OpenSees's terms.
      struct RegionWords
      {
        std::vector<int> elements, nodes;
        bool             has_elements = false, has_nodes = false;
        bool             elements_only = false, nodes_only = false;
        bool             has_rayleigh  = false;
        opensees::RayleighFactors rayleigh;
        /// Tags named one by one (not by a range): a missing one is warned.
        std::set<int> listed_elements, listed_nodes;
      };

      /// first..last in either order (OpenSees swaps them).
      void
      add_range(Words &w, std::vector<int> &tags)
      {
        int first = w.integer("the range's start"), last = w.integer("the range's end");
        if (first > last)
          std::swap(first, last);
        if (static_cast<long>(last) - first > 10000000)
          throw ScriptError("a range of more than 10^7 tags");
        for (int t = first; t <= last; ++t)
          tags.push_back(t);
      }

      void
      read_tags(Words &w, const int region, const std::string &option, std::vector<int> &tags,
                std::set<int> &listed)
      {
        const std::vector<int> given = w.integers("a tag");
        if (given.empty())
          throw ScriptError("region " + std::to_string(region) + ": " + option + ": no tag given");
        tags.insert(tags.end(), given.begin(), given.end());
        listed.insert(given.begin(), given.end());
      }

      RegionWords
      region_words(Words &w, const int tag)
      {
        RegionWords r;
        while (!w.done())
          {
            const std::string option = w.word("an option");
            if (option == "-ele" || option == "-eleOnly")
              read_tags(w, tag, option, r.elements, r.listed_elements);
            else if (option == "-eleRange" || option == "-eleOnlyRange")
              add_range(w, r.elements);
            else if (option == "-node" || option == "-nodeOnly")
              read_tags(w, tag, option, r.nodes, r.listed_nodes);
            else if (option == "-nodeRange" || option == "-nodeOnlyRange")
              add_range(w, r.nodes);
            else if (option == "-rayleigh")
              {
                r.rayleigh.alpha_m          = w.real("aM");
                r.rayleigh.beta_k           = w.real("bK");
                r.rayleigh.beta_k_init      = w.real("bK0");
                r.rayleigh.beta_k_committed = w.real("bKc");
                r.has_rayleigh              = true;
                continue;
              }
            else if (option == "-damp" || option == "getNodeTags" ||
                     option == "getConnectedEleTags" || option == "getEleTags")
              unsupported("region " + option);
            else
              throw ScriptError("region " + std::to_string(tag) + ": '" + option +
                                "' where an option is due");
            const bool elements = option.compare(0, 4, "-ele") == 0;
            (elements ? r.has_elements : r.has_nodes) = true;
            if (option.find("Only") != std::string::npos)
              (elements ? r.elements_only : r.nodes_only) = true;
          }
        return r;
      }

      /// The region's elements and nodes as OpenSees's MeshRegion holds them.
      std::pair<std::set<int>, std::set<int>>
      region_members(Session &s, const RegionWords &r, const int tag)
      {
        const opensees::Domain &d = s.domain;
        const std::string       name = "region " + std::to_string(tag);
        std::set<int>           elements, nodes;
        for (const int e : r.elements)
          if (d.elements.count(e))
            elements.insert(e);
          else if (r.listed_elements.count(e))
            s.warnings << "WARNING " << name << ": element " << e
                       << " does not exist: left out\n";
        if (r.has_elements && !r.elements_only)
          for (const int e : elements)
            for (const int n : d.elements.at(e)->node_tags)
              nodes.insert(n);
        if (!r.has_nodes)
          return {elements, nodes};
        std::set<int> given;
        for (const int n : r.nodes)
          if (d.nodes.count(n))
            given.insert(n);
          else if (r.listed_nodes.count(n))
            s.warnings << "WARNING " << name << ": node " << n << " does not exist: left out\n";
        if (r.nodes_only)
          return {elements, given};
        if (r.has_elements)
          {
            s.warnings << "WARNING region - both elements & nodes set, ONLY set using elements\n";
            return {elements, nodes};
          }
        for (const auto &[e, element] : d.elements)
          if (std::all_of(element->node_tags.begin(), element->node_tags.end(),
                          [&](const int n) { return given.count(n) > 0; }))
            elements.insert(e);
        return {elements, given};
      }

      void
      set_element_factors(opensees::Domain &d, const int element,
                          const opensees::RayleighFactors &factors)
      {
        d.element_rayleigh[element] = factors;
        // OpenSees's K_c starts as the element's tangent now (Element::
        // setRayleighDampingFactors)
        if (factors.beta_k_committed != 0)
          d.elements.at(element)->committed_tangent = d.elements.at(element)->tangent();
        d.changed = true;
      }

      void
      region(Session &s, Words &w)
      {
        if (s.domain.ndf == 0)
          throw ScriptError("no model yet: the script must call 'model basic -ndm N' first");
        const int         tag = w.integer("the region's tag");
        const RegionWords r   = region_words(w, tag);
        opensees::Domain &d   = s.domain;
        if (std::find(d.regions.begin(), d.regions.end(), tag) != d.regions.end())
          throw ScriptError("region " + std::to_string(tag) + " exists already");
        d.regions.push_back(tag);
        const auto &f = r.rayleigh;
        if (!r.has_rayleigh || !has_factors(f))
          return; // OpenSees sets no factor then
        const auto [elements, nodes] = region_members(s, r, tag);
        for (const int e : elements)
          set_element_factors(d, e, f);
        for (const int n : nodes)
          d.node_alpha_m[n] = f.alpha_m;
        d.changed = true; // the analysis takes the masses' damping anew
      }

      void
      element_factors(Session &s, Words &w)
      {
        if (s.domain.ndf == 0)
          throw ScriptError("no model yet: the script must call 'model basic -ndm N' first");
        const int tag = w.integer("the element's tag");
        if (!s.domain.elements.count(tag))
          throw ScriptError("element " + std::to_string(tag) + " does not exist");
        opensees::RayleighFactors f;
        f.alpha_m          = w.real("alphaM");
        f.beta_k           = w.real("betaK");
        f.beta_k_init      = w.real("betaK0");
        f.beta_k_committed = w.real("betaKc");
        if (!w.done())
          throw ScriptError("'" + w.peek() + "' after betaKc");
        set_element_factors(s.domain, tag, f);
      }
    } // namespace

    void
    define_region_commands(Tcl_Interp *interp, Session &session)
    {
      define(interp, session, "region", region);
      define(interp, session, "setElementRayleighDampingFactors", element_factors);
    }
  } // namespace opensees_tcl
} // namespace poundfe
