#include <particulate/geometry/geometry_error.h>
#include <particulate/geometry/mass_properties.h>
#include <particulate/geometry/mesh_io.h>
#include <particulate/geometry/triangulated_surface.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <unordered_map>

namespace particulate {
  namespace geometry {

    namespace {
      using Kernel    = CGAL::Exact_predicates_inexact_constructions_kernel;
      using Point     = Kernel::Point_3;
      using CgalMesh  = CGAL::Surface_mesh<Point>;
      using Primitive = CGAL::AABB_face_graph_triangle_primitive<CgalMesh>;
      using Tree      = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
      using Side      = CGAL::Side_of_triangle_mesh<CgalMesh, Kernel>;

      Point
      to_point(const Eigen::Vector3d &p)
      {
        return Point(p[0], p[1], p[2]);
      }

      Eigen::Vector3d
      to_eigen(const Point &p)
      {
        return Eigen::Vector3d(p.x(), p.y(), p.z());
      }
      // Sign and normal from the unsigned query (shared by the single and the
      // batched distance).
      //
      // The side is decided by CGAL's exact Side_of_triangle_mesh, not by the
      // pseudo-normal: the pseudo-normal sign depends on classifying the
      // closest point as lying on a face, an edge or a vertex, which inexact
      // closest-point constructions get wrong near edges shared by nearly
      // coplanar or very thin features (seen on elephant.off: grid signs that
      // changed with the compiler's optimisation level). The exact test is
      // cheap beside the distance query itself.
      double
      signed_from(const Eigen::Vector3d &p,
                  const Eigen::Vector3d &closest,
                  const Eigen::Vector3d &pseudo,
                  const double           d,
                  const double           scale,
                  const bool             inside,
                  Eigen::Vector3d       *normal)
      {
        const Eigen::Vector3d diff = p - closest;
        if (normal)
          {
            // The gradient of the signed distance points from the closest point
            // to p outside, and from p to the closest point inside.
            if (d > 1e-12 * scale)
              *normal = inside ? Eigen::Vector3d(-diff / d) :
                                 Eigen::Vector3d(diff / d);
            else
              *normal = pseudo.normalized();
          }
        return inside ? -d : d;
      }
    } // namespace

    struct TriangulatedSurface::Impl
    {
      TriangleMesh          mesh;
      CgalMesh              sm;
      Tree                  tree;
      std::unique_ptr<Side> side;
      BoundingBox           box;
      MassProperties        mass;

      // Pseudo-normals (Bærentzen-Aanæs): unit face normals, per face the
      // normals of its three edges (sum of the two adjacent face normals; edge
      // e joins corners e and e+1), and angle-weighted vertex normals.
      std::vector<Eigen::Vector3d>                face_normal;
      std::vector<std::array<Eigen::Vector3d, 3>> edge_normal;
      std::vector<Eigen::Vector3d>                vertex_normal;

      // Unsigned distance, closest point and the pseudo-normal of the closest
      // feature.
      using Hit = Tree::Point_and_primitive_id;

      double
      query(const Eigen::Vector3d &p,
            Eigen::Vector3d       &closest,
            Eigen::Vector3d       &pseudo_normal,
            Hit                   *hint = nullptr) const
      {
        const Hit hit = hint ?
                          tree.closest_point_and_primitive(to_point(p), *hint) :
                          tree.closest_point_and_primitive(to_point(p));
        if (hint)
          *hint = hit;
        closest                  = to_eigen(hit.first);
        const std::size_t      f = std::size_t(hit.second);
        const auto            &t = mesh.triangles[f];
        const Eigen::Vector3d &a = mesh.vertices[t[0]],
                              &b = mesh.vertices[t[1]],
                              &c = mesh.vertices[t[2]];
        // Barycentric coordinates of the closest point (Ericson, RTCD 3.4).
        const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = closest - a;
        const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1),
                     d20 = v2.dot(v0), d21 = v2.dot(v1);
        const double den  = d00 * d11 - d01 * d01;
        const double w1   = (d11 * d20 - d01 * d21) / den;
        const double w2   = (d00 * d21 - d01 * d20) / den;
        const double w[3] = {1. - w1 - w2, w1, w2};
        // A closest point within this relative tolerance of an edge or vertex
        // is treated as lying on it; the edge or vertex pseudo-normal then
        // still gives the right sign (it has a positive dot product with the
        // face normal), so the tolerance only needs to be larger than rounding.
        const double tol   = 1e-9;
        int          small = 0, large = 0;
        for (int i = 0; i < 3; ++i)
          {
            if (w[i] < tol)
              ++small;
            if (w[i] > w[large])
              large = i;
          }
        if (small >= 2)
          pseudo_normal = vertex_normal[t[large]];
        else if (small == 1)
          {
            int zero = 0;
            for (int i = 0; i < 3; ++i)
              if (w[i] < tol)
                zero = i;
            // The edge opposite corner `zero` joins corners zero+1 and zero+2.
            pseudo_normal = edge_normal[f][(zero + 1) % 3];
          }
        else
          pseudo_normal = face_normal[f];
        return (p - closest).norm();
      }
    };

    TriangulatedSurface::TriangulatedSurface(const TriangleMesh &mesh)
      : impl(std::make_unique<Impl>())
    {
      const MeshCheck check = check_surface_mesh(mesh, false);
      if (!check.bounds_a_solid())
        throw GeometryError(
          "TriangulatedSurface: the mesh does not bound a "
          "solid:\n"
          + check.describe()
          + "Read meshes with read_surface_mesh, which checks and "
            "orients them.");
      impl->mesh = mesh;
      impl->mass = compute_mass_properties(mesh); // throws if inward
      impl->box  = mesh.bounding_box();

      auto &sm = impl->sm;
      sm.reserve(mesh.vertices.size(),
                 3 * mesh.triangles.size() / 2,
                 mesh.triangles.size());
      for (const auto &v : mesh.vertices)
        sm.add_vertex(to_point(v));
      for (const auto &t : mesh.triangles)
        sm.add_face(CgalMesh::Vertex_index(t[0]),
                    CgalMesh::Vertex_index(t[1]),
                    CgalMesh::Vertex_index(t[2]));
      impl->tree.insert(faces(sm).first, faces(sm).second, sm);
      impl->tree.build();
      impl->tree.accelerate_distance_queries();
      impl->side = std::make_unique<Side>(impl->tree);
      // Force the lazy search structures now, so later const queries from
      // several threads only read.
      impl->tree.closest_point(to_point(mesh.vertices[0]));

      const std::size_t nt = mesh.triangles.size();
      impl->face_normal.resize(nt);
      impl->edge_normal.resize(nt);
      impl->vertex_normal.assign(mesh.vertices.size(), Eigen::Vector3d::Zero());
      std::unordered_map<std::uint64_t, Eigen::Vector3d> edge_sum;
      auto key = [](int a, int b) {
        if (a > b)
          std::swap(a, b);
        return (static_cast<std::uint64_t>(a) << 32)
               | static_cast<std::uint32_t>(b);
      };
      for (std::size_t f = 0; f < nt; ++f)
        {
          const auto     &t = mesh.triangles[f];
          Eigen::Vector3d n
            = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
          n.normalize();
          impl->face_normal[f] = n;
          for (int e = 0; e < 3; ++e)
            {
              edge_sum[key(t[e], t[(e + 1) % 3])] += n;
              // Angle of the triangle at corner e.
              const Eigen::Vector3d u
                = (mesh.vertices[t[(e + 1) % 3]] - mesh.vertices[t[e]])
                    .normalized();
              const Eigen::Vector3d w
                = (mesh.vertices[t[(e + 2) % 3]] - mesh.vertices[t[e]])
                    .normalized();
              const double angle = std::acos(std::clamp(u.dot(w), -1., 1.));
              impl->vertex_normal[t[e]] += angle * n;
            }
        }
      for (std::size_t f = 0; f < nt; ++f)
        for (int e = 0; e < 3; ++e)
          impl->edge_normal[f][e]
            = edge_sum[key(mesh.triangles[f][e],
                           mesh.triangles[f][(e + 1) % 3])];
    }

    TriangulatedSurface::~TriangulatedSurface() = default;
    TriangulatedSurface::TriangulatedSurface(
      TriangulatedSurface &&) noexcept = default;
    TriangulatedSurface &
    TriangulatedSurface::operator=(TriangulatedSurface &&) noexcept = default;

    double
    TriangulatedSurface::signed_distance(const Eigen::Vector3d &p,
                                         Eigen::Vector3d       *normal) const
    {
      Eigen::Vector3d closest, pseudo;
      const double    d = impl->query(p, closest, pseudo);
      return signed_from(p,
                         closest,
                         pseudo,
                         d,
                         impl->box.extent().norm(),
                         contains(p),
                         normal);
    }


    void
    TriangulatedSurface::signed_distances(
      const std::vector<Eigen::Vector3d> &points,
      std::vector<double>                &distances,
      std::vector<Eigen::Vector3d>       *normals) const
    {
      distances.resize(points.size());
      if (normals)
        normals->resize(points.size());
      if (points.empty())
        return;
      const double scale = impl->box.extent().norm();
      Impl::Hit    hint
        = impl->tree.closest_point_and_primitive(to_point(points[0]));
      Eigen::Vector3d closest, pseudo;
      for (std::size_t i = 0; i < points.size(); ++i)
        {
          const double d = impl->query(points[i], closest, pseudo, &hint);
          distances[i]   = signed_from(points[i],
                                     closest,
                                     pseudo,
                                     d,
                                     scale,
                                     contains(points[i]),
                                     normals ? &(*normals)[i] : nullptr);
        }
    }

    bool
    TriangulatedSurface::contains(const Eigen::Vector3d &p) const
    {
      return (*impl->side)(to_point(p)) != CGAL::ON_UNBOUNDED_SIDE;
    }

    double
    TriangulatedSurface::unsigned_distance(const Eigen::Vector3d &p) const
    {
      return std::sqrt(impl->tree.squared_distance(to_point(p)));
    }

    Eigen::Vector3d
    TriangulatedSurface::closest_point(const Eigen::Vector3d &p) const
    {
      return to_eigen(impl->tree.closest_point(to_point(p)));
    }

    BoundingBox
    TriangulatedSurface::bounding_box() const
    {
      return impl->box;
    }

    double
    TriangulatedSurface::volume() const
    {
      return impl->mass.volume;
    }

    Eigen::Vector3d
    TriangulatedSurface::centroid() const
    {
      return impl->mass.centre;
    }

    Eigen::Matrix3d
    TriangulatedSurface::unit_inertia() const
    {
      return impl->mass.inertia;
    }

    std::vector<Eigen::Vector3d>
    TriangulatedSurface::surface_points() const
    {
      return impl->mesh.vertices;
    }

    const TriangleMesh &
    TriangulatedSurface::mesh() const
    {
      return impl->mesh;
    }



    TriangleMesh
    TriangulatedSurface::surface_mesh() const
    {
      return mesh();
    }

  } // namespace geometry
} // namespace particulate
