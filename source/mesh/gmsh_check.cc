// The check of a Gmsh .msh text before deal.II reads it (mesh/gmsh_check.h):
// the MSH format of the Gmsh reference manual (C. Geuzaine, J.-F. Remacle,
// "Gmsh Reference Manual", "MSH file format", versions 2.2 and 4.1), read
// token by token as GridIn::read_msh reads it.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/numbers.h>
#include <poundfe/mesh/gmsh_check.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

namespace poundfe
{
  namespace
  {
    constexpr long most_int = INT_MAX; // read_msh reads tags and counts as int

    /// The blank-separated tokens of a .msh text, as `in >> x` reads them,
    /// with their lines; every read names what it expects in the message.
    class MshTokens
    {
    public:
      MshTokens(const std::string &file, const std::string &text)
        : file(file)
        , text(text)
      {}

      /// Throws InputError at `line` of the file.
      [[noreturn]] void
      fail(const int line, const std::string &problem) const
      {
        throw InputError(file, line, "", "Gmsh mesh: " + problem);
      }

      /// The line of the last token read.
      int
      line() const
      {
        return token_line;
      }

      /// The next token; the file ending first is an error naming `what`.
      std::string_view
      next(const std::string &what)
      {
        while (position < text.size() && is_blank(text[position]))
          line_number += text[position++] == '\n' ? 1 : 0;
        if (position == text.size())
          fail(token_line, "the file ends where " + what + " should come"); // after the last token
        const std::size_t start = position;
        while (position < text.size() && !is_blank(text[position]))
          ++position;
        token_line = line_number;
        return std::string_view(text).substr(start, position - start);
      }

      /// The next token, which must be `marker`.
      void
      expect(const std::string &marker)
      {
        const std::string_view token = next(marker);
        if (token != marker)
          fail(token_line, "expected " + marker + ", got '" + shown(token) + "'");
      }

      /// The next token as a whole number in [low, high].
      long
      integer(const std::string &what, const long low, const long high)
      {
        const std::string_view token = next(what);
        long                   value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (error != std::errc() || end != token.data() + token.size() || value < low ||
            value > high)
          fail(token_line, what + ": expected a whole number from " + std::to_string(low) +
                             " to " + std::to_string(high) + ", got '" + shown(token) + "'");
        return value;
      }

      /// A count of items of at least `tokens_each` tokens each: no more
      /// than the rest of the file can hold (a token and a blank each), so
      /// no count allocates or loops beyond the file's size.
      unsigned long
      count(const std::string &what, const unsigned int tokens_each)
      {
        const unsigned long n    = integer("the number of " + what, 0, most_int);
        const unsigned long room = (text.size() - position) / 2;
        if (n * tokens_each > room)
          fail(token_line, std::to_string(n) + " " + what + " announced, but the rest of the "
                             "file holds at most " + std::to_string(room / tokens_each));
        return n;
      }

      /// The next token as a finite number.
      double
      real(const std::string &what)
      {
        const std::string_view      token = next(what);
        const std::optional<double> x     = parse_number(token);
        if (!x)
          fail(token_line, what + ": expected a finite number, got '" + shown(token) + "'");
        return *x;
      }

      /// Every token up to `marker` (a section read_msh skips): it must come.
      void
      skip_to(const std::string &marker)
      {
        while (next(marker) != marker)
          {
          }
      }

    private:
      const std::string &file;
      const std::string &text;
      std::size_t        position    = 0;
      int                line_number = 1;
      int                token_line  = 1;

      static bool
      is_blank(const char c)
      {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
      }

      static std::string
      shown(const std::string_view token)
      {
        return token.size() <= 40 ? std::string(token) : std::string(token.substr(0, 40)) + "...";
      }
    };

    /// A physical tag: the material id members are assigned by (an
    /// unsigned int in deal.II, whose largest value means "none").
    void
    read_physical_tag(MshTokens &in)
    {
      in.integer("a physical tag", 0, most_int);
    }

    /// A 4.1 section's first line: the numbers of blocks and of `item`s
    /// (at least `tokens_each` tokens each), the smallest and largest tag.
    std::pair<unsigned long, unsigned long>
    read_blocks_line(MshTokens &in, const std::string &item, const unsigned int tokens_each)
    {
      const unsigned long n_blocks = in.count(item + " blocks", 4);
      const unsigned long n        = in.count(item + "s", tokens_each);
      in.integer("the smallest " + item + " tag", 0, most_int);
      in.integer("the largest " + item + " tag", 0, most_int);
      return {n_blocks, n};
    }

    /// Adds a 4.1 block's `m` items to `given`: more than the `n` announced
    /// is an error (read_msh would write past its array of n).
    void
    add_block(MshTokens &in, const std::string &item, const unsigned long m, unsigned long &given,
              const unsigned long n)
    {
      if ((given += m) > n)
        in.fail(in.line(), "the " + item + " blocks hold more " + item + "s than the " +
                             std::to_string(n) + " announced");
    }

    /// After the last 4.1 block: as many items as announced.
    void
    check_blocks_total(MshTokens &in, const std::string &item, const unsigned long given,
                       const unsigned long n)
    {
      if (given != n)
        in.fail(in.line(), "the " + item + " blocks hold " + std::to_string(given) + " " + item +
                             "s, not the " + std::to_string(n) + " announced");
    }

    /// $MeshFormat ... $EndMeshFormat; returns 22 or 41.
    int
    read_format(MshTokens &in)
    {
      const std::string_view first = in.next("$MeshFormat");
      if (first == "$NOD")
        in.fail(in.line(), "a Gmsh 1 file ($NOD): save it as version 2.2 or 4.1 "
                           "(gmsh -format msh22 or msh41)");
      if (first != "$MeshFormat")
        in.fail(in.line(), "expected $MeshFormat at the start, got '" +
                             std::string(first.substr(0, 40)) + "'");
      const std::string_view version = in.next("the format version");
      int                    format  = 0;
      if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2")
        format = 22;
      else if (version == "4.1")
        format = 41;
      else
        in.fail(in.line(), "format version '" + std::string(version.substr(0, 40)) +
                             "': only 2.2 and 4.1 are read (gmsh -format msh22 or msh41)");
      if (in.integer("the file type (0: ASCII)", 0, 1) != 0)
        in.fail(in.line(), "a binary file (file type 1): save it as ASCII (Mesh.Binary = 0)");
      in.integer("the data size", 8, 8);
      in.expect("$EndMeshFormat");
      return format;
    }

    /// The sections between $EndMeshFormat and $Nodes, $Nodes included:
    /// $PhysicalNames (skipped, as read_msh does) and, in 4.1, $Entities.
    void
    read_sections_before_nodes(MshTokens &in, const int format)
    {
      std::string_view section = in.next("$Nodes");
      if (section == "$PhysicalNames")
        in.skip_to("$EndPhysicalNames"), section = in.next("$Nodes");
      if (section == "$Entities")
        {
          if (format != 41)
            in.fail(in.line(), "an $Entities section in a version 2.2 file");
          const unsigned long n[4] = {in.count("points", 5), in.count("curves", 9),
                                      in.count("surfaces", 9), in.count("volumes", 9)};
          for (unsigned int dim = 0; dim < 4; ++dim)
            for (unsigned long i = 0; i < n[dim]; ++i)
              {
                in.integer("an entity tag", -most_int, most_int);
                for (unsigned int c = 0; c < (dim == 0 ? 3u : 6u); ++c)
                  in.real("a coordinate of an entity");
                // deal.II takes one physical tag per entity
                if (in.integer("the number of physical tags of an entity", 0, 1) == 1)
                  read_physical_tag(in);
                if (dim > 0)
                  for (unsigned long b = in.count("bounding entities", 1); b > 0; --b)
                    in.integer("a bounding entity's tag", -most_int, most_int);
              }
          in.expect("$EndEntities");
          section = in.next("$Nodes");
        }
      if (section == "$PartitionedEntities")
        in.fail(in.line(), "a partitioned mesh: save it unpartitioned");
      if (section != "$Nodes")
        in.fail(in.line(), "expected $Nodes, got '" + std::string(section.substr(0, 40)) + "'");
    }

    /// The next three tokens as a node's coordinates; a second node at the
    /// point of an earlier one is refused: deal.II keeps both, so the
    /// members at one of them are not joined to those at the other (a
    /// member left hanging, a mechanism or a wrong frame).
    void
    read_node_point(MshTokens &in, const long tag, std::map<std::array<double, 3>, long> &points)
    {
      std::array<double, 3> x{};
      for (double &c : x)
        c = in.real("a node coordinate");
      const auto [earlier, is_new] = points.emplace(x, tag);
      if (!is_new)
        in.fail(in.line(), "nodes " + std::to_string(earlier->second) + " and " +
                             std::to_string(tag) + " are at one point (" + number_text(x[0]) +
                             ", " + number_text(x[1]) + ", " + number_text(x[2]) +
                             "): the members at one are not joined to those at the other; "
                             "merge them (Gmsh: Geometry.AutoCoherence, or Coherence Mesh)");
    }

    /// $Nodes' content and $EndNodes; returns the node tags.
    std::unordered_set<long>
    read_nodes(MshTokens &in, const int format)
    {
      std::unordered_set<long>              tags;
      std::map<std::array<double, 3>, long> points;
      const auto                            add = [&](const long tag) {
        if (!tags.insert(tag).second)
          in.fail(in.line(), "node " + std::to_string(tag) + " is given twice");
        return tag;
      };
      if (format == 22)
        for (unsigned long n = in.count("nodes", 4); n > 0; --n)
          read_node_point(in, add(in.integer("a node tag", 1, most_int)), points);
      else
        {
          const auto [n_blocks, n] = read_blocks_line(in, "node", 4);
          unsigned long given      = 0;
          for (unsigned long b = 0; b < n_blocks; ++b)
            {
              in.integer("a node block's entity dimension", 0, 3);
              in.integer("a node block's entity tag", -most_int, most_int);
              if (in.integer("a node block's parametric flag", 0, 1) != 0)
                in.fail(in.line(), "parametric nodes: save the mesh without them "
                                   "(Mesh.SaveParametric = 0)");
              const unsigned long m = in.count("nodes of a block", 4);
              add_block(in, "node", m, given, n);
              std::vector<long> block(m);
              for (long &tag : block)
                tag = add(in.integer("a node tag", 1, most_int));
              for (const long tag : block)
                read_node_point(in, tag, points);
            }
          check_blocks_total(in, "node", given, n);
        }
      in.expect("$EndNodes");
      return tags;
    }

    /// The nodes of one element of `type`: a line (1) joins two distinct
    /// nodes of $Nodes, once; a point (15) is one node of $Nodes.
    void
    read_element_nodes(MshTokens &in, const long type, const std::unordered_set<long> &nodes,
                       std::set<std::pair<long, long>> &lines)
    {
      if (type != 1 && type != 15)
        in.fail(in.line(), "element type " + std::to_string(type) +
                             ": a frame mesh holds line elements (type 1) and points (type 15) "
                             "only, not surfaces or volumes");
      std::array<long, 2> node{};
      for (unsigned int i = 0; i < (type == 1 ? 2u : 1u); ++i)
        {
          node[i] = in.integer("a node of an element", 1, most_int);
          if (nodes.count(node[i]) == 0)
            in.fail(in.line(), "an element refers to node " + std::to_string(node[i]) +
                                 ", which $Nodes does not give");
        }
      if (type != 1)
        return;
      const std::string between =
        "nodes " + std::to_string(node[0]) + " and " + std::to_string(node[1]);
      if (node[0] == node[1])
        in.fail(in.line(), "a line element from node " + std::to_string(node[0]) + " to itself");
      if (!lines.insert(std::minmax(node[0], node[1])).second)
        in.fail(in.line(), "the line element between " + between + " is given twice");
    }

    /// $Elements' content and $EndElements.
    void
    read_elements(MshTokens &in, const int format, const std::unordered_set<long> &nodes)
    {
      in.expect("$Elements");
      std::set<std::pair<long, long>> lines;
      if (format == 22)
        for (unsigned long n = in.count("elements", 5); n > 0; --n)
          {
            in.integer("an element tag", 0, most_int);
            const long type = in.integer("an element type", 0, most_int);
            for (unsigned long t = 0, n_tags = in.count("tags of an element", 1); t < n_tags; ++t)
              if (t == 0)
                read_physical_tag(in);
              else
                in.integer("an element's tag", 0, most_int);
            read_element_nodes(in, type, nodes, lines);
          }
      else
        {
          const auto [n_blocks, n] = read_blocks_line(in, "element", 2);
          unsigned long given      = 0;
          for (unsigned long b = 0; b < n_blocks; ++b)
            {
              const long dim = in.integer("an element block's entity dimension", 0, 3);
              in.integer("an element block's entity tag", -most_int, most_int);
              const long type = in.integer("an element block's element type", 0, most_int);
              if ((type == 1 && dim != 1) || (type == 15 && dim != 0))
                in.fail(in.line(), "element type " + std::to_string(type) +
                                     " in a block of entity dimension " + std::to_string(dim));
              const unsigned long m = in.count("elements of a block", 2);
              add_block(in, "element", m, given, n);
              for (unsigned long i = 0; i < m; ++i)
                {
                  in.integer("an element tag", 0, most_int);
                  read_element_nodes(in, type, nodes, lines);
                }
            }
          check_blocks_total(in, "element", given, n);
        }
      in.expect("$EndElements");
      if (lines.empty())
        in.fail(in.line(), "no line elements (type 1)");
    }
  } // namespace

  void
  check_gmsh_text(const std::string &file, const std::string &text)
  {
    MshTokens in(file, text);
    const int format = read_format(in);
    read_sections_before_nodes(in, format);
    const std::unordered_set<long> nodes = read_nodes(in, format);
    read_elements(in, format, nodes);
  }
} // namespace poundfe
