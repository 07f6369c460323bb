#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mesh_io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace particulate {
  namespace geometry {

    namespace {
      using Kernel   = CGAL::Exact_predicates_inexact_constructions_kernel;
      using Point    = Kernel::Point_3;
      using CgalMesh = CGAL::Surface_mesh<Point>;

      std::string
      position(const TriangleMesh &m, const int v)
      {
        std::ostringstream s;
        s << v;
        if (v >= 0 && static_cast<std::size_t>(v) < m.vertices.size())
          s << " (" << m.vertices[v][0] << ", " << m.vertices[v][1] << ", "
            << m.vertices[v][2] << ")";
        return s.str();
      }

      std::uint64_t
      edge_key(int a, int b)
      {
        if (a > b)
          std::swap(a, b);
        return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32)
               | static_cast<std::uint32_t>(b);
      }

      /** Per undirected edge: how many triangles use it, and the sum of +1 for
       *  each use in the a<b direction and -1 for each use in the other. */
      struct EdgeUse
      {
        int count          = 0;
        int direction      = 0;
        int first_triangle = -1;
      };

      std::unordered_map<std::uint64_t, EdgeUse>
      edge_uses(const TriangleMesh &m)
      {
        std::unordered_map<std::uint64_t, EdgeUse> edges;
        edges.reserve(3 * m.triangles.size() / 2 + 1);
        for (std::size_t t = 0; t < m.triangles.size(); ++t)
          for (int e = 0; e < 3; ++e)
            {
              const int a = m.triangles[t][e], b = m.triangles[t][(e + 1) % 3];
              auto     &u = edges[edge_key(a, b)];
              if (u.count == 0)
                u.first_triangle = static_cast<int>(t);
              ++u.count;
              u.direction += (a < b) ? 1 : -1;
            }
        return edges;
      }

      CgalMesh
      to_cgal(const TriangleMesh &m)
      {
        CgalMesh sm;
        sm.reserve(m.vertices.size(),
                   3 * m.triangles.size() / 2,
                   m.triangles.size());
        for (const auto &v : m.vertices)
          sm.add_vertex(Point(v[0], v[1], v[2]));
        for (const auto &t : m.triangles)
          {
            const auto f = sm.add_face(CgalMesh::Vertex_index(t[0]),
                                       CgalMesh::Vertex_index(t[1]),
                                       CgalMesh::Vertex_index(t[2]));
            if (f == CgalMesh::null_face())
              throw GeometryError(
                "internal: a checked manifold surface could not be built in CGAL.");
          }
        return sm;
      }

      /** Flip triangles so that each edge is traversed once in each direction,
       *  by a breadth-first walk over edge neighbours. Needs a manifold
       *  surface. Returns false if the surface is not orientable (Möbius,
       *  Klein). */
      bool
      orient_consistently(TriangleMesh &m)
      {
        const std::size_t nt = m.triangles.size();
        std::unordered_map<std::uint64_t, std::array<int, 2>> neighbours;
        neighbours.reserve(3 * nt / 2 + 1);
        for (std::size_t t = 0; t < nt; ++t)
          for (int e = 0; e < 3; ++e)
            {
              auto &n = neighbours
                          .try_emplace(edge_key(m.triangles[t][e],
                                                m.triangles[t][(e + 1) % 3]),
                                       std::array<int, 2>{-1, -1})
                          .first->second;
              (n[0] < 0 ? n[0] : n[1]) = static_cast<int>(t);
            }
        std::vector<char> done(nt, 0);
        std::vector<int>  queue;
        auto              directed = [&](int t, int a, int b) {
          const auto &tri = m.triangles[t];
          for (int e = 0; e < 3; ++e)
            if (tri[e] == a && tri[(e + 1) % 3] == b)
              return true;
          return false;
        };
        for (std::size_t seed = 0; seed < nt; ++seed)
          {
            if (done[seed])
              continue;
            done[seed] = 1;
            queue.assign(1, static_cast<int>(seed));
            while (!queue.empty())
              {
                const int t = queue.back();
                queue.pop_back();
                for (int e = 0; e < 3; ++e)
                  {
                    const int a   = m.triangles[t][e],
                              b   = m.triangles[t][(e + 1) % 3];
                    const auto &n = neighbours[edge_key(a, b)];
                    const int   o = (n[0] == t) ? n[1] : n[0];
                    if (o < 0)
                      continue;
                    // The neighbour must traverse the shared edge as b -> a.
                    const bool agrees = directed(o, b, a);
                    if (done[o])
                      {
                        if (!agrees)
                          return false;
                        continue;
                      }
                    if (!agrees)
                      std::swap(m.triangles[o][1], m.triangles[o][2]);
                    done[o] = 1;
                    queue.push_back(o);
                  }
              }
          }
        return true;
      }

      // CGAL's readers trust the counts in a file: an OFF header or a PLY list
      // claiming 10^9 entries makes them allocate gigabytes before failing. So
      // before handing a file to CGAL we check that every count it declares
      // fits in the bytes that follow, and that an OFF face's vertex indices
      // are those of vertices. Returns an empty string if plausible, else the
      // reason.
      std::string
      implausible_counts(const std::string &path, const std::string &ext)
      {
        std::ifstream     in(path, std::ios::binary);
        const std::string data((std::istreambuf_iterator<char>(in)), {});
        const std::size_t size     = data.size();
        auto              lines_of = [&](std::size_t from) {
          std::vector<std::vector<std::string>> lines;
          std::istringstream                    text(data.substr(from));
          std::string                           line;
          while (std::getline(text, line))
            {
              const auto hash = line.find('#');
              if (hash != std::string::npos)
                line.resize(hash);
              std::istringstream       ls(line);
              std::vector<std::string> tokens;
              for (std::string t; ls >> t;)
                tokens.push_back(t);
              if (!tokens.empty())
                lines.push_back(std::move(tokens));
            }
          return lines;
        };
        // strtold() also reads "nan", which passes every range test below
        // and must not reach a conversion to an integer: not a count.
        auto count = [](const std::string &t, long double &v) {
          char *end = nullptr;
          v         = std::strtold(t.c_str(), &end);
          return end != t.c_str() && *end == '\0' && !std::isnan(v);
        };

        if (ext == ".off")
          {
            if (data.find("BINARY") != std::string::npos
                && data.find("BINARY") < 64)
              return ""; // binary OFF: CGAL checks its reads; counts checked
                         // below
            const auto lines = lines_of(0);
            if (lines.empty())
              return "";
            // The keyword may carry the counts on its own line.
            std::vector<std::string> head(lines[0].begin() + 1, lines[0].end());
            std::size_t              next = 1;
            if (head.empty() && lines.size() > 1)
              head = lines[next++];
            long double nv = 0, nf = 0;
            if (head.size() < 2 || !count(head[0], nv) || !count(head[1], nf))
              return "";
            if (nv < 0 || nf < 0 || nv > size / 6. || nf > size / 4.)
              return "its header declares " + head[0] + " vertices and "
                     + head[1] + " faces, more than the file's "
                     + std::to_string(size) + " bytes can hold";
            // Tokens left in the file from each line on; a face cannot list
            // more vertices than that.
            std::vector<std::size_t> left(lines.size() + 1, 0);
            for (std::size_t l = lines.size(); l-- > 0;)
              left[l] = left[l + 1] + lines[l].size();
            for (std::size_t l = next + static_cast<std::size_t>(nv);
                 l < lines.size()
                 && l < next + static_cast<std::size_t>(nv + nf);
                 ++l)
              {
                long double k = 0;
                if (!count(lines[l][0], k) || k < 0 || k > left[l])
                  return "face line " + std::to_string(l + 1) + " declares "
                         + lines[l][0] + " vertices, more than the file holds";
                // CGAL converts each index, read as a double, to an unsigned
                // integer: a negative or huge one is undefined behaviour there.
                for (std::size_t t = 1; t <= k && t < lines[l].size(); ++t)
                  {
                    long double index = 0;
                    if (count(lines[l][t], index)
                        && !(index >= 0 && index < nv))
                      return "face line " + std::to_string(l + 1)
                             + " refers to vertex " + lines[l][t]
                             + ", but the header declares " + head[0]
                             + " vertices";
                  }
              }
            return "";
          }
        if (ext == ".ply")
          {
            // The header as CGAL reads it: raw lines up to the one whose first
            // word is end_header (no comment stripping, empty lines kept).
            std::vector<std::vector<std::string>> header;
            std::size_t                           body  = 0;
            bool                                  ended = false;
            while (body < size && !ended)
              {
                std::size_t eol = data.find('\n', body);
                eol             = eol == std::string::npos ? size : eol;
                std::istringstream       ls(data.substr(body, eol - body));
                std::vector<std::string> tokens;
                for (std::string t; ls >> t;)
                  tokens.push_back(t);
                body  = eol + 1;
                ended = !tokens.empty() && tokens[0] == "end_header";
                if (tokens.empty())
                  tokens.push_back("");
                header.push_back(std::move(tokens));
              }
            if (!ended)
              return "the PLY header has no end_header line";
            body       = std::min(body, size);
            bool ascii = false, little = true;
            struct Property
            {
              bool        list        = false;
              std::size_t count_bytes = 0, item_bytes = 0;
            };
            struct Element
            {
              long double           n = 0;
              std::vector<Property> properties;
            };
            std::vector<Element> elements;
            auto bytes_of = [](const std::string &t) -> std::size_t {
              if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
                return 1;
              if (t == "short" || t == "ushort" || t == "int16"
                  || t == "uint16")
                return 2;
              if (t == "int" || t == "uint" || t == "float" || t == "int32"
                  || t == "uint32" || t == "float32")
                return 4;
              if (t == "double" || t == "float64")
                return 8;
              return 0;
            };
            // CGAL's PLY reader trusts the header's structure too (a property
            // before any element dereferences an empty list), so check it
            // strictly: signature, format, known types, properties after an
            // element.
            if (header.size() < 3 || header[0][0] != "ply"
                || header[1].size() < 3 || header[1][0] != "format")
              return "the PLY header does not start with 'ply' and a format line";
            if (header[1][1] != "ascii"
                && header[1][1] != "binary_little_endian"
                && header[1][1] != "binary_big_endian")
              return "unknown PLY format '" + header[1][1] + "'";
            ascii  = header[1][1] == "ascii";
            little = header[1][1] != "binary_big_endian";
            for (std::size_t h = 2; h < header.size(); ++h)
              {
                const auto &l = header[h];
                if (l[0] == "end_header")
                  break;
                if (l[0] == "comment" || l[0] == "obj_info")
                  continue;
                if (l[0].empty())
                  return "the PLY header has an empty line";
                if (l[0] == "element")
                  {
                    elements.emplace_back();
                    if (l.size() < 3 || !count(l[2], elements.back().n)
                        || elements.back().n < 0 || elements.back().n > size)
                      return "its header declares "
                             + (l.size() > 2 ? l[2] : std::string("no")) + " "
                             + (l.size() > 1 ? l[1] : std::string(""))
                             + " elements, more than the file's "
                             + std::to_string(size) + " bytes can hold";
                  }
                else if (l[0] == "property")
                  {
                    if (elements.empty())
                      return "a PLY property is declared before any element";
                    Property p;
                    if (l.size() > 1 && l[1] == "list")
                      {
                        p.list        = true;
                        p.count_bytes = l.size() > 4 ? bytes_of(l[2]) : 0;
                        p.item_bytes  = l.size() > 4 ? bytes_of(l[3]) : 0;
                        if (p.count_bytes == 0 || p.item_bytes == 0)
                          return "a PLY list property has an unknown type";
                      }
                    else
                      {
                        p.item_bytes = l.size() > 2 ? bytes_of(l[1]) : 0;
                        if (p.item_bytes == 0)
                          return "a PLY property has an unknown type";
                      }
                    elements.back().properties.push_back(p);
                  }
                else
                  return "unknown PLY header keyword '" + l[0] + "'";
              }
            if (ascii)
              {
                // One element per line; a list count cannot exceed the tokens
                // left on its line.
                const auto  lines = lines_of(body);
                std::size_t l     = 0;
                for (const auto &e : elements)
                  for (long double i = 0; i < e.n && l < lines.size(); ++i, ++l)
                    {
                      std::size_t t = 0;
                      for (const auto &p : e.properties)
                        {
                          if (t >= lines[l].size())
                            break;
                          long double k = 0;
                          if (p.list)
                            {
                              if (!count(lines[l][t], k) || k < 0
                                  || k > lines[l].size() - t - 1)
                                return "line " + std::to_string(l + 1)
                                       + " after the header declares a list of "
                                       + lines[l][t]
                                       + " entries but holds fewer";
                              t += 1 + static_cast<std::size_t>(k);
                            }
                          else
                            ++t;
                        }
                    }
                return "";
              }
            // Binary: walk the elements; every list count must fit in the bytes
            // left.
            std::size_t pos = body;
            for (const auto &e : elements)
              for (long double i = 0; i < e.n; ++i)
                for (const auto &p : e.properties)
                  {
                    if (!p.list)
                      {
                        pos += p.item_bytes;
                        continue;
                      }
                    if (p.count_bytes == 0 || pos + p.count_bytes > size)
                      return "";
                    unsigned long long k = 0;
                    for (std::size_t b = 0; b < p.count_bytes; ++b)
                      {
                        const unsigned char c = static_cast<unsigned char>(
                          data[pos + (little ? b : p.count_bytes - 1 - b)]);
                        k |= static_cast<unsigned long long>(c) << (8 * b);
                      }
                    // A negative signed count reads as huge: refused alike.
                    pos += p.count_bytes;
                    if (p.item_bytes == 0 || k > (size - pos) / p.item_bytes)
                      return "a binary list declares " + std::to_string(k)
                             + " entries, more than the file holds";
                    pos += k * p.item_bytes;
                  }
            return "";
          }
        return "";
      }
    } // namespace

    bool
    MeshCheck::bounds_a_solid() const
    {
      return n_triangles > 0 && invalid_indices == 0 && non_finite_vertices == 0
             && degenerate_triangles == 0 && border_edges == 0
             && non_manifold_edges == 0 && non_manifold_vertices == 0
             && inconsistent_edges == 0 && self_intersecting_pairs == 0;
    }

    std::string
    MeshCheck::describe() const
    {
      std::ostringstream s;
      auto               line = [&](std::size_t n, const char *what) {
        if (n > 0)
          s << what << ": " << n << "\n";
      };
      if (n_triangles == 0)
        s << "empty: no triangles\n";
      line(invalid_indices, "invalid vertex indices");
      line(non_finite_vertices, "vertices with NaN or infinite coordinates");
      line(degenerate_triangles, "degenerate (zero-area) triangles");
      if (border_edges > 0)
        s << "open: " << border_edges << " border edges\n";
      if (non_manifold_edges > 0)
        s << "non-manifold: " << non_manifold_edges
          << " edges shared by more than two triangles\n";
      if (non_manifold_vertices > 0)
        s << "non-manifold: " << non_manifold_vertices
          << " pinched vertices (more than one fan of triangles)\n";
      if (inconsistent_edges > 0)
        s << "inconsistently oriented: " << inconsistent_edges
          << " edges traversed twice in the same direction\n";
      if (self_intersecting_pairs > 0)
        s << self_intersecting_pairs << " self-intersecting triangle pairs\n";
      if (!first_problem.empty() && !bounds_a_solid())
        s << "first problem: " << first_problem << "\n";
      return s.str();
    }

    MeshCheck
    check_surface_mesh(const TriangleMesh &m,
                       const bool          check_self_intersections)
    {
      MeshCheck c;
      c.n_vertices  = m.vertices.size();
      c.n_triangles = m.triangles.size();
      auto note     = [&](const std::string &what) {
        if (c.first_problem.empty())
          c.first_problem = what;
      };

      for (std::size_t v = 0; v < m.vertices.size(); ++v)
        if (!m.vertices[v].allFinite())
          {
            ++c.non_finite_vertices;
            note("vertex " + std::to_string(v) + " is not finite");
          }
      const int nv = static_cast<int>(m.vertices.size());
      for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (const int v : m.triangles[t])
          if (v < 0 || v >= nv)
            {
              ++c.invalid_indices;
              note("triangle " + std::to_string(t) + " uses vertex "
                   + std::to_string(v) + " of " + std::to_string(nv));
            }
      if (c.invalid_indices > 0 || c.non_finite_vertices > 0)
        return c; // nothing else can be trusted

      for (std::size_t t = 0; t < m.triangles.size(); ++t)
        {
          const auto &tri = m.triangles[t];
          const auto &a = m.vertices[tri[0]], &b = m.vertices[tri[1]],
                     &d = m.vertices[tri[2]];
          if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]
              || CGAL::collinear(Point(a[0], a[1], a[2]),
                                 Point(b[0], b[1], b[2]),
                                 Point(d[0], d[1], d[2])))
            {
              ++c.degenerate_triangles;
              note("triangle " + std::to_string(t) + " with vertices "
                   + position(m, tri[0]) + ", " + position(m, tri[1]) + ", "
                   + position(m, tri[2]) + " has zero area");
            }
        }

      for (const auto &[key, use] : edge_uses(m))
        {
          const int a             = static_cast<int>(key >> 32),
                    b             = static_cast<int>(key & 0xffffffffu);
          const std::string where = "edge between vertices " + position(m, a)
                                    + " and " + position(m, b);
          if (use.count == 1)
            {
              ++c.border_edges;
              note("border " + where);
            }
          else if (use.count > 2)
            {
              ++c.non_manifold_edges;
              note(where + " is shared by " + std::to_string(use.count)
                   + " triangles");
            }
          else if (use.direction != 0)
            {
              ++c.inconsistent_edges;
              note(where + " is traversed twice in the same direction");
            }
        }

      // Pinched vertices: the triangles around a vertex must form one fan, i.e.
      // be connected through edges that contain the vertex. Union-find over the
      // corners of each vertex.
      {
        std::vector<std::vector<int>> corners(m.vertices.size());
        for (std::size_t t = 0; t < m.triangles.size(); ++t)
          for (const int v : m.triangles[t])
            corners[v].push_back(static_cast<int>(t));
        std::vector<int> parent;
        for (std::size_t v = 0; v < corners.size(); ++v)
          {
            const auto &ts = corners[v];
            if (ts.size() < 2)
              continue;
            parent.resize(ts.size());
            std::iota(parent.begin(), parent.end(), 0);
            std::function<int(int)> find = [&](int i) {
              return parent[i] == i ? i : parent[i] = find(parent[i]);
            };
            // Map "other vertex of an edge through v" -> first local triangle.
            std::unordered_map<int, int> seen;
            for (std::size_t i = 0; i < ts.size(); ++i)
              for (const int w : m.triangles[ts[i]])
                if (w != static_cast<int>(v))
                  {
                    auto [it, fresh] = seen.emplace(w, static_cast<int>(i));
                    if (!fresh)
                      parent[find(static_cast<int>(i))] = find(it->second);
                  }
            int fans = 0;
            for (std::size_t i = 0; i < ts.size(); ++i)
              fans += (find(static_cast<int>(i)) == static_cast<int>(i));
            if (fans > 1)
              {
                ++c.non_manifold_vertices;
                note("vertex " + position(m, static_cast<int>(v)) + " joins "
                     + std::to_string(fans) + " separate fans of triangles");
              }
          }
      }

      // The intersection test needs a manifold surface (CGAL's halfedge mesh).
      if (check_self_intersections && c.n_triangles > 0 && c.border_edges == 0
          && c.non_manifold_edges == 0 && c.non_manifold_vertices == 0
          && c.degenerate_triangles == 0)
        {
          TriangleMesh oriented = m;
          if (c.inconsistent_edges > 0 && !orient_consistently(oriented))
            return c;
          const CgalMesh sm = to_cgal(oriented);
          std::vector<std::pair<CgalMesh::Face_index, CgalMesh::Face_index>>
            pairs;
          CGAL::Polygon_mesh_processing::self_intersections(sm,
                                                            std::back_inserter(
                                                              pairs));
          c.self_intersecting_pairs    = pairs.size();
          c.self_intersections_checked = true;
          if (!pairs.empty())
            note("triangles " + std::to_string(std::size_t(pairs[0].first))
                 + " and " + std::to_string(std::size_t(pairs[0].second))
                 + " intersect");
        }
      return c;
    }

    TriangleMesh
    read_surface_mesh(const std::string &path, const MeshReadOptions &options)
    {
      const std::string where = "read_surface_mesh('" + path + "')";
      std::error_code   ec;
      if (!std::filesystem::is_regular_file(path, ec))
        throw GeometryError(where
                            + ": no such file. Check the path (relative "
                              "paths are taken from the working directory).");
      const std::string ext = std::filesystem::path(path).extension().string();
      std::string       lower;
      for (char ch : ext)
        lower
          += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (lower != ".off" && lower != ".stl" && lower != ".obj"
          && lower != ".ply")
        throw GeometryError(where + ": unknown extension '" + ext
                            + "'; supported are .off, .stl, .obj and .ply.");

      const std::string implausible = implausible_counts(path, lower);
      if (!implausible.empty())
        throw GeometryError(
          where + ": the file is corrupt or truncated: " + implausible + ".");

      std::vector<Point>                    points;
      std::vector<std::vector<std::size_t>> polygons;
      bool                                  ok = false;
      try
        {
          // CGAL prints parse problems on std::cerr when verbose; we report our
          // own message instead.
          ok = CGAL::IO::read_polygon_soup(path,
                                           points,
                                           polygons,
                                           CGAL::parameters::verbose(false));
        }
      catch (const std::exception &e)
        {
          throw GeometryError(where + ": the file could not be parsed ("
                              + e.what() + "). Is it truncated or not a "
                              + lower + " file?");
        }
      if (!ok)
        throw GeometryError(
          where + ": the file could not be parsed as " + lower
          + " (truncated, or not a " + lower
          + " file?). Open it in a mesh viewer or re-export it.");
      if (polygons.empty())
        throw GeometryError(where
                            + ": the file holds no faces (empty mesh); a "
                              "closed triangulated surface is required.");

      // Triangles (fans for larger polygons), then drop unused vertices.
      TriangleMesh mesh;
      mesh.vertices.reserve(points.size());
      for (const auto &p : points)
        mesh.vertices.emplace_back(p.x(), p.y(), p.z());
      for (std::size_t f = 0; f < polygons.size(); ++f)
        {
          const auto &poly = polygons[f];
          if (poly.size() < 3)
            throw GeometryError(where + ": face " + std::to_string(f) + " has "
                                + std::to_string(poly.size())
                                + " vertices; faces need at least three.");
          for (const auto v : poly)
            if (v >= points.size())
              throw GeometryError(
                where + ": face " + std::to_string(f) + " uses vertex "
                + std::to_string(v) + " but the file has only "
                + std::to_string(points.size()) + " vertices.");
          for (std::size_t k = 1; k + 1 < poly.size(); ++k)
            mesh.triangles.push_back({static_cast<int>(poly[0]),
                                      static_cast<int>(poly[k]),
                                      static_cast<int>(poly[k + 1])});
        }
      {
        std::vector<int>             new_id(mesh.vertices.size(), -1);
        std::vector<Eigen::Vector3d> used;
        for (auto &t : mesh.triangles)
          for (int &v : t)
            {
              if (new_id[v] < 0)
                {
                  new_id[v] = static_cast<int>(used.size());
                  used.push_back(mesh.vertices[v]);
                }
              v = new_id[v];
            }
        mesh.vertices = std::move(used);
      }

      MeshCheck check
        = check_surface_mesh(mesh, options.check_self_intersections);
      if (check.inconsistent_edges > 0 && options.orient)
        {
          // Flipped triangles alone are repairable; other defects are not.
          MeshCheck others          = check;
          others.inconsistent_edges = 0;
          if (others.bounds_a_solid())
            {
              if (!orient_consistently(mesh))
                throw GeometryError(
                  where
                  + ": the surface is not orientable (like a "
                    "Klein bottle); it cannot bound a solid.");
              check = others;
            }
        }
      if (!check.bounds_a_solid())
        throw GeometryError(
          where + ": the surface does not bound a solid:\n" + check.describe()
          + "Repair it (e.g. with CGAL's Polygon Mesh Processing "
            "or MeshLab) and try again.");

      if (options.orient)
        {
          CgalMesh sm = to_cgal(mesh);
          // Handles nested components (cavities) correctly, unlike flipping on
          // the sign of the enclosed volume alone.
          CGAL::Polygon_mesh_processing::orient_to_bound_a_volume(sm);
          for (const auto f : sm.faces())
            {
              auto &tri = mesh.triangles[std::size_t(f)];
              int   k   = 0;
              for (const auto v :
                   CGAL::vertices_around_face(sm.halfedge(f), sm))
                tri[k++] = static_cast<int>(std::size_t(v));
            }
        }
      return mesh;
    }

    void
    write_surface_mesh(const std::string &path, const TriangleMesh &mesh)
    {
      std::vector<Point>                    points;
      std::vector<std::vector<std::size_t>> polygons;
      for (const auto &v : mesh.vertices)
        points.emplace_back(v[0], v[1], v[2]);
      for (const auto &t : mesh.triangles)
        polygons.push_back(
          {std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
      bool ok = false;
      try
        {
          ok = CGAL::IO::write_polygon_soup(path,
                                            points,
                                            polygons,
                                            CGAL::parameters::stream_precision(
                                              17));
        }
      catch (const std::exception &)
        {
          ok = false;
        }
      if (!ok)
        throw GeometryError(
          "write_surface_mesh('" + path
          + "'): could not write the file (check the folder "
            "exists and the extension is .off/.stl/.obj/.ply).");
    }

  } // namespace geometry
} // namespace particulate
