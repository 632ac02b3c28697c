// The fibres of OpenSees's patches and layers (geometry and sources in the
// header; OpenSees's QuadPatch, QuadCell, CircPatch, CircSectionCell,
// StraightReinfLayer, CircReinfLayer) and the parser of their commands.
#include <poundfe/base/exceptions.h>
#include <poundfe/base/input_file.h>
#include <poundfe/base/numbers.h>
#include <poundfe/sections/fibre_generators.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace poundfe
{
  namespace
  {
    [[noreturn]] void
    refuse_fibres(const std::string &problem)
    {
      throw InputError("", 0, "Fibres", problem);
    }

    void
    require_count(const char *what, const unsigned int n)
    {
      if (n < 1)
        refuse_fibres(std::string(what) + " must be at least 1");
    }

    void
    require_positive_length(const char *what, const double value)
    {
      if (!(std::isfinite(value) && value > 0))
        refuse_fibres(std::string(what) + " must be positive (got " + number_text(value) + ")");
    }

    /// A quadrilateral's area (shoelace) and centroid, vertices in order.
    Fibre
    quadrilateral_fibre(const std::array<SectionPoint, 4> &v, const unsigned int material)
    {
      double twice_area = 0, qy = 0, qz = 0;
      for (unsigned int i = 0; i < 4; ++i)
        {
          const SectionPoint &a = v[i], &b = v[(i + 1) % 4];
          const double        cross = a.y * b.z - b.y * a.z;
          twice_area += cross;
          qy += (a.y + b.y) * cross;
          qz += (a.z + b.z) * cross;
        }
      Fibre f;
      f.area     = twice_area / 2;
      f.y        = qy / (3 * twice_area);
      f.z        = qz / (3 * twice_area);
      f.material = material;
      return f;
    }

    /// The bilinear map of the patch at (xi, eta) in [-1, 1]^2.
    SectionPoint
    bilinear_point(const std::array<SectionPoint, 4> &v, const double xi, const double eta)
    {
      const double N[4] = {(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4,
                           (1 + xi) * (1 + eta) / 4, (1 - xi) * (1 + eta) / 4};
      SectionPoint p{0, 0};
      for (unsigned int s = 0; s < 4; ++s)
        {
          p.y += N[s] * v[s].y;
          p.z += N[s] * v[s].z;
        }
      return p;
    }
  } // namespace

  void
  add_quad_patch(FibreGeometry &geometry, const unsigned int material, const unsigned int n_ij,
                 const unsigned int n_jk, const std::array<SectionPoint, 4> &v)
  {
    require_count("a patch's number of subdivisions", n_ij);
    require_count("a patch's number of subdivisions", n_jk);
    if (!(quadrilateral_fibre(v, material).area > 0))
      refuse_fibres("a patch's vertices I J K L must go counter-clockwise round a positive area");
    const double d_xi = 2.0 / n_ij, d_eta = 2.0 / n_jk;
    for (unsigned int j = 0; j < n_jk; ++j)
      for (unsigned int i = 0; i < n_ij; ++i)
        {
          const double xi = -1 + d_xi * i, eta = -1 + d_eta * j;
          const std::array<SectionPoint, 4> cell{
            {bilinear_point(v, xi, eta), bilinear_point(v, xi + d_xi, eta),
             bilinear_point(v, xi + d_xi, eta + d_eta), bilinear_point(v, xi, eta + d_eta)}};
          geometry.fibres.push_back(quadrilateral_fibre(cell, material));
        }
  }

  void
  add_rect_patch(FibreGeometry &geometry, const unsigned int material, const unsigned int n_y,
                 const unsigned int n_z, const SectionPoint i, const SectionPoint j)
  {
    add_quad_patch(geometry, material, n_y, n_z, {{i, SectionPoint{j.y, i.z}, j, SectionPoint{i.y, j.z}}});
  }

  void
  add_circ_patch(FibreGeometry &geometry, const unsigned int material, const unsigned int n_circ,
                 const unsigned int n_rad, const SectionPoint centre, const double inner_radius,
                 const double outer_radius, const double start_angle, const double end_angle)
  {
    require_count("a circular patch's number of sectors", n_circ);
    require_count("a circular patch's number of rings", n_rad);
    if (!(std::isfinite(inner_radius) && inner_radius >= 0 && outer_radius > inner_radius &&
          std::isfinite(outer_radius)))
      refuse_fibres("a circular patch needs 0 <= rInt < rExt");
    if (!(std::isfinite(start_angle) && std::isfinite(end_angle) && end_angle > start_angle))
      refuse_fibres("a circular patch's end angle must exceed its start angle");
    const double pi = std::acos(-1.0);
    const double d_r = (outer_radius - inner_radius) / n_rad;
    const double d_theta = (end_angle - start_angle) * pi / 180 / n_circ;
    const double half = d_theta / 2;
    for (unsigned int j = 0; j < n_rad; ++j)
      {
        const double r1 = inner_radius + d_r * j, r2 = r1 + d_r;
        // sector of r2 minus sector of r1, each at 2 r sin(a) / (3 a)
        const double outer = half * r2 * r2, inner = half * r1 * r1;
        const double area  = outer - inner;
        const double c = (outer * 2 * r2 * std::sin(half) - inner * 2 * r1 * std::sin(half)) /
                         (3 * half * area);
        for (unsigned int i = 0; i < n_circ; ++i)
          {
            const double theta = start_angle * pi / 180 + d_theta * i + half;
            geometry.fibres.push_back(
              {centre.y + c * std::cos(theta), centre.z + c * std::sin(theta), area, material});
          }
      }
  }

  void
  add_straight_layer(FibreGeometry &geometry, const unsigned int material,
                     const unsigned int n_bars, const double bar_area, const SectionPoint start,
                     const SectionPoint end)
  {
    require_count("a layer's number of bars", n_bars);
    require_positive_length("a bar's area", bar_area);
    if (n_bars == 1)
      {
        add_fibre(geometry, material, {(start.y + end.y) / 2, (start.z + end.z) / 2}, bar_area);
        return;
      }
    const double dy = (end.y - start.y) / (n_bars - 1), dz = (end.z - start.z) / (n_bars - 1);
    for (unsigned int i = 0; i < n_bars; ++i)
      add_fibre(geometry, material, {start.y + dy * i, start.z + dz * i}, bar_area);
  }

  void
  add_circ_layer(FibreGeometry &geometry, const unsigned int material, const unsigned int n_bars,
                 const double bar_area, const SectionPoint centre, const double radius,
                 const double start_angle, double end_angle)
  {
    require_count("a layer's number of bars", n_bars);
    require_positive_length("a bar's area", bar_area);
    require_positive_length("a circular layer's radius", radius);
    if (end_angle - start_angle >= 360)
      end_angle = start_angle + 360 - 360.0 / n_bars;
    const double pi    = std::acos(-1.0);
    const double step  = n_bars > 1 ? (end_angle - start_angle) / (n_bars - 1) : 0.0;
    for (unsigned int i = 0; i < n_bars; ++i)
      {
        const double theta = (start_angle + step * i) * pi / 180;
        add_fibre(geometry, material,
                  {centre.y + radius * std::cos(theta), centre.z + radius * std::sin(theta)},
                  bar_area);
      }
  }

  void
  add_fibre(FibreGeometry &geometry, const unsigned int material, const SectionPoint at,
            const double area)
  {
    require_positive_length("a fibre's area", area);
    if (!(std::isfinite(at.y) && std::isfinite(at.z)))
      refuse_fibres("a fibre's position must be finite");
    geometry.fibres.push_back({at.y, at.z, area, material});
  }

  namespace
  {
    /// One command of a fibre text: its words, its number (from 1) and its
    /// text, for messages.
    struct FibreCommand
    {
      std::vector<std::string> words;
      unsigned int             number;
      std::string              text;

      [[noreturn]] void
      refuse(const std::string &problem) const
      {
        refuse_fibres("command " + std::to_string(number) + " '" + text + "': " + problem);
      }

      double
      number_at(const std::size_t k) const
      {
        const auto x = parse_number(words.at(k));
        if (!x)
          refuse("'" + words[k] + "' is not a number");
        return *x;
      }

      unsigned int
      count_at(const std::size_t k) const
      {
        const auto n = parse_count(words.at(k), 1000000);
        if (!n || *n < 1)
          refuse("'" + words[k] + "' is not a count >= 1");
        return *n;
      }

      SectionPoint
      point_at(const std::size_t k) const
      {
        return {number_at(k), number_at(k + 1)};
      }

      void
      expect(const std::size_t n, const std::size_t n_optional, const char *form) const
      {
        if (words.size() != n && words.size() != n + n_optional)
          refuse(std::string("expected '") + form + "'");
      }
    };

    /// The command's fibres, added to `geometry` (form in the header).
    void
    add_fibre_command(FibreGeometry &geometry, const FibreCommand &c)
    {
      const std::string kind = c.words[0] + (c.words.size() > 1 ? " " + c.words[1] : "");
      const auto material = [&](const std::size_t k) { return geometry.material_index(c.words.at(k)); };
      if (kind == "patch quad")
        {
          c.expect(13, 0, "patch quad M nIJ nJK yI zI yJ zJ yK zK yL zL");
          add_quad_patch(geometry, material(2), c.count_at(3), c.count_at(4),
                         {{c.point_at(5), c.point_at(7), c.point_at(9), c.point_at(11)}});
        }
      else if (kind == "patch rect" || kind == "patch rectangular")
        {
          c.expect(9, 0, "patch rect M nY nZ yI zI yJ zJ");
          add_rect_patch(geometry, material(2), c.count_at(3), c.count_at(4), c.point_at(5),
                         c.point_at(7));
        }
      else if (kind == "patch circ")
        {
          c.expect(9, 2, "patch circ M nCirc nRad yc zc rInt rExt [startAngle endAngle]");
          add_circ_patch(geometry, material(2), c.count_at(3), c.count_at(4), c.point_at(5),
                         c.number_at(7), c.number_at(8), c.words.size() > 9 ? c.number_at(9) : 0,
                         c.words.size() > 9 ? c.number_at(10) : 360);
        }
      else if (kind == "layer straight")
        {
          c.expect(9, 0, "layer straight M n A y1 z1 y2 z2");
          add_straight_layer(geometry, material(2), c.count_at(3), c.number_at(4), c.point_at(5),
                             c.point_at(7));
        }
      else if (kind == "layer circ")
        {
          c.expect(8, 2, "layer circ M n A yc zc r [startAngle endAngle]");
          add_circ_layer(geometry, material(2), c.count_at(3), c.number_at(4), c.point_at(5),
                         c.number_at(7), c.words.size() > 8 ? c.number_at(8) : 0,
                         c.words.size() > 8 ? c.number_at(9) : 360);
        }
      else if (c.words[0] == "fiber" || c.words[0] == "fibre")
        {
          c.expect(5, 0, "fiber y z A M");
          add_fibre(geometry, material(4), c.point_at(1), c.number_at(3));
        }
      else
        c.refuse("unknown command (patch quad|rect|circ, layer straight|circ, fiber)");
    }
  } // namespace

  void
  add_fibre_commands(FibreGeometry &geometry, const std::string &text)
  {
    std::string  command;
    unsigned int number = 0;
    std::istringstream in(text);
    while (std::getline(in, command, ';'))
      {
        std::istringstream lines(command);
        for (std::string line; std::getline(lines, line);)
          {
            FibreCommand c{{}, 0, trimmed(line)};
            std::istringstream words(line);
            for (std::string w; words >> w;)
              c.words.push_back(w);
            if (c.words.empty())
              continue;
            c.number = ++number;
            try
              {
                add_fibre_command(geometry, c);
              }
            catch (const InputError &e)
              {
                if (e.parameter() == "Fibres" && e.problem().rfind("command ", 0) == 0)
                  throw;
                c.refuse(e.problem());
              }
          }
      }
  }
} // namespace poundfe
