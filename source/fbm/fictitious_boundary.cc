#include <particulate/fbm/fictitious_boundary.h>
#include <particulate/geometry/bounding_box.h>
#include <particulate/geometry/cylinder.h>
#include <particulate/geometry/mapped_surface.h>
#include <particulate/geometry/pose.h>
#include <particulate/geometry/sphere.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace particulate {
  namespace fbm {
    using namespace dealii;

    namespace {
      const char *const engine_marks_inside_only
        = "fbm::FictitiousBoundary: the cuda/ containment engine marks the "
          "nodes inside the bodies only ('Covered nodes = inside' in "
          "subsection 'Particles'); use 'Containment backend = cpu' for "
          "'halfway' or 'nearest'.";

      /** A distance map in the layout the cuda/ engine uploads (the fields
       *  of geometry's export; cuda/ does not depend on geometry). */
      cuda::DistanceMapData
      engine_map(const geometry::DistanceMap &map)
      {
        const geometry::DistanceMapData data = map.export_data();
        cuda::DistanceMapData           upload;
        upload.nx = data.nx;
        upload.ny = data.ny;
        upload.nz = data.nz;
        std::copy_n(data.origin, 3, upload.origin);
        std::copy_n(data.spacing, 3, upload.spacing);
        upload.values = data.values;
        return upload;
      }
    } // namespace

    template <int dim>
    FictitiousBoundary<dim>::FictitiousBoundary(
      const fluid::NavierStokes<dim> &flow)
      : flow(flow)
    {}



    template <int dim>
    FictitiousBoundary<dim>::~FictitiousBoundary() = default;



    template <int dim>
    void
    FictitiousBoundary<dim>::set_marking(const Marking m)
    {
      if (engine && m != Marking::inside)
        throw std::invalid_argument(engine_marks_inside_only);
      marking = m;
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::use_containment_engine(const cuda::Backend backend)
    {
      if (marking != Marking::inside)
        throw std::invalid_argument(engine_marks_inside_only);
      engine = std::make_unique<cuda::ContainmentEngine>(backend);
      engine_spheres.clear();
      engine_maps.clear();
    }



    template <int dim>
    std::string
    FictitiousBoundary<dim>::containment_method() const
    {
      return engine ? "cuda/ containment engine on " + engine->device_name() :
                      "hash grid (double precision)";
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::setup()
    {
      const FESystem<dim>      &fe          = flow.get_fe();
      const FiniteElement<dim> &velocity_fe = fe.base_element(0);
      nodes_per_cell_                       = velocity_fe.n_dofs_per_cell();
      const Quadrature<dim> support(velocity_fe.get_unit_support_points());
      FEValues<dim>         fe_values(flow.get_mapping(),
                              fe,
                              support,
                              update_quadrature_points);

      // local_index[k][c]: the cell-local DoF of velocity component c at
      // support point k of the velocity element
      std::vector<std::array<unsigned int, 3>> local_index(nodes_per_cell_);
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto base = fe.system_to_base_index(i);
          if (base.first.first == 0)
            local_index[base.second][base.first.second] = i;
        }

      positions.clear();
      node_dofs.clear();
      cells.clear();
      nodes_of_cells.clear();
      half_spacing.clear();
      std::unordered_map<DofIndex, unsigned int> node_of_dof;
      std::vector<DofIndex> dof_indices(fe.n_dofs_per_cell());
      for (const auto &cell : flow.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned() || cell->is_ghost())
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dof_indices);
            const bool owned = cell->is_locally_owned();
            // Q2 nodes lie half an edge apart; half of that spacing
            const double half_node_spacing
              = 0.25 * cell->minimum_vertex_distance();
            if (owned)
              cells.push_back(cell);
            for (unsigned int k = 0; k < nodes_per_cell_; ++k)
              {
                const DofIndex key = dof_indices[local_index[k][0]];
                auto [it, inserted]
                  = node_of_dof.emplace(key, positions.size());
                if (inserted)
                  {
                    Eigen::Vector3d p = Eigen::Vector3d::Zero();
                    const auto     &q = fe_values.quadrature_point(k);
                    for (unsigned int d = 0; d < dim; ++d)
                      p[d] = q[d];
                    positions.push_back(p);
                    std::array<DofIndex, 3> dofs{{0, 0, 0}};
                    for (unsigned int c = 0; c < dim; ++c)
                      dofs[c] = dof_indices[local_index[k][c]];
                    node_dofs.push_back(dofs);
                    half_spacing.push_back(half_node_spacing);
                  }
                else
                  half_spacing[it->second]
                    = std::min(half_spacing[it->second], half_node_spacing);
                if (owned)
                  nodes_of_cells.push_back(it->second);
              }
          }
      // every marking needs it: `inside` for its rounding tolerance
      make_half_spacing_consistent();
      grid = std::make_unique<geometry::PointHashGrid>(positions);
      node_body.assign(positions.size(), -1);
      positions_float.resize(3 * positions.size());
      for (std::size_t i = 0; i < positions.size(); ++i)
        for (unsigned int d = 0; d < 3; ++d)
          positions_float[3 * i + d] = float(positions[i][d]);
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::make_half_spacing_consistent()
    {
      // A node's spacing is the minimum over the cells around it. The rank
      // owning its DoFs owns one of those cells and has all the others as
      // ghosts, so its value is complete; a node at the edge of another
      // rank's ghost layer may miss cells there. Take the owner's value
      // everywhere, so that every rank marks shared nodes alike.
      const IndexSet &owned = flow.get_dof_handler().locally_owned_dofs();
      auto            owned_spacing = flow.make_owned_vector();
      for (unsigned int i = 0; i < positions.size(); ++i)
        if (owned.is_element(node_dofs[i][0]))
          owned_spacing(node_dofs[i][0]) = half_spacing[i];
      owned_spacing.compress(VectorOperation::insert);
      auto spacing         = flow.make_ghosted_vector();
      spacing              = owned_spacing;
      largest_half_spacing = 0.;
      for (unsigned int i = 0; i < positions.size(); ++i)
        {
          half_spacing[i] = spacing(node_dofs[i][0]);
          largest_half_spacing
            = std::max(largest_half_spacing, half_spacing[i]);
        }
    }



    template <int dim>
    double
    FictitiousBoundary<dim>::reach_fraction() const
    {
      switch (marking)
        {
          case Marking::inside:
            return 0.;
          case Marking::halfway:
            return 0.5;
          case Marking::nearest:
            return 1.;
        }
      return 0.;
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::classify(const std::vector<Body> &bodies)
    {
      if (engine)
        {
          classify_with_engine(bodies);
          return;
        }
      std::fill(node_body.begin(), node_body.end(), -1);
      const double fraction = reach_fraction();
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const rigid::RigidBody &body = *bodies[b].body;
          // the box of the body, enlarged by the marking's reach and
          // slightly against rounding
          const double                reach = fraction * largest_half_spacing;
          const geometry::BoundingBox local_box
            = body.shape().bounding_box().enlarged(
              reach + 1e-9 * body.bounding_radius() + 1e-14);
          const geometry::BoundingBox box
            = geometry::Pose(body.orientation, body.position)
                .to_world(local_box);
          // A node on the surface belongs to the body, whichever side
          // rounding puts it: a mesh adapted to the body carries vertices
          // (and, in 3D, the midpoints of edges along a cylinder's axis)
          // exactly on its surface, and `inside` left each to the sign of
          // a rounding error.
          const double on_surface = 1e-10;
          grid->for_each_in_box(box, [&](const std::size_t i) {
            const double tolerance
              = std::max(fraction, on_surface) * half_spacing[i];
            if (node_body[i] >= 0)
              return;
            // the world box of a turned body holds nodes outside its own
            // box, which are outside it (and beyond a distance map's grid,
            // where its distance is an exact, slower, query)
            const Eigen::Vector3d x = body.to_body(positions[i]);
            if (local_box.contains(x)
                && body.shape().signed_distance(x) <= tolerance)
              node_body[i] = b;
          });
        }
    }



    template <int dim>
    int
    FictitiousBoundary<dim>::engine_shape(const geometry::Shape &shape)
    {
      if (const auto *mesh
          = dynamic_cast<const geometry::MappedSurface *>(&shape))
        {
          const void *key = &mesh->map();
          auto        map
            = std::find_if(engine_maps.begin(),
                           engine_maps.end(),
                           [&](const auto &m) { return m.first == key; });
          if (map == engine_maps.end())
            {
              engine_maps.emplace_back(key,
                                       engine->add_distance_map(
                                         engine_map(mesh->map())));
              map = std::prev(engine_maps.end());
            }
          return map->second;
        }
      double radius = 0.;
      if (shape.kind() == geometry::ShapeKind::sphere)
        radius = static_cast<const geometry::Sphere &>(shape).radius();
      else if (dim == 2 && shape.kind() == geometry::ShapeKind::cylinder)
        radius = static_cast<const geometry::Cylinder &>(shape).radius();
      else
        throw std::invalid_argument(
          "fbm::FictitiousBoundary: the cuda/ containment engine takes "
          "spheres, surface meshes (and disks in 2D) only, not a "
          + shape.name()
          + "; use 'Containment backend = cpu' in subsection 'Particles' for "
            "other shapes.");
      // one uploaded one-sphere set per radius, centred at the body origin
      auto sphere
        = std::find_if(engine_spheres.begin(),
                       engine_spheres.end(),
                       [&](const auto &s) { return s.first == radius; });
      if (sphere == engine_spheres.end())
        {
          cuda::InnerSphereData one;
          one.cx = {0.f};
          one.cy = {0.f};
          one.cz = {0.f};
          one.r  = {float(radius)};
          engine_spheres.emplace_back(radius, engine->add_inner_spheres(one));
          sphere = std::prev(engine_spheres.end());
        }
      return sphere->second;
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::classify_with_engine(
      const std::vector<Body> &bodies)
    {
      std::vector<cuda::BodyInstance> instances(bodies.size());
      for (unsigned int b = 0; b < bodies.size(); ++b)
        {
          const rigid::RigidBody &body = *bodies[b].body;
          instances[b].shape           = engine_shape(body.shape());
          const Eigen::Matrix3d R      = body.orientation.toRotationMatrix();
          for (unsigned int i = 0; i < 3; ++i)
            {
              for (unsigned int j = 0; j < 3; ++j)
                instances[b].R[3 * i + j] = float(R(i, j));
              instances[b].t[i] = float(body.position[i]);
            }
        }
      engine->classify(positions_float.data(),
                       positions.size(),
                       instances.data(),
                       instances.size(),
                       node_body.data(),
                       nullptr);
    }



    template <int dim>
    std::vector<std::pair<typename FictitiousBoundary<dim>::DofIndex, double>>
    FictitiousBoundary<dim>::constraint_values(
      const std::vector<Body> &bodies) const
    {
      std::vector<std::pair<DofIndex, double>> values;
      for (unsigned int i = 0; i < positions.size(); ++i)
        if (node_body[i] >= 0)
          {
            const Eigen::Vector3d u
              = bodies[node_body[i]].body->velocity_at(positions[i]);
            for (unsigned int c = 0; c < dim; ++c)
              values.emplace_back(node_dofs[i][c], u[c]);
          }
      return values;
    }



    template <int dim>
    void
    FictitiousBoundary<dim>::cover_films(const std::vector<Body> &bodies,
                                         const std::vector<int>  &joint_of_body)
    {
      std::map<int, std::vector<unsigned int>> parts_of_joint;
      for (unsigned int b = 0; b < bodies.size(); ++b)
        if (joint_of_body[b] >= 0)
          parts_of_joint[joint_of_body[b]].push_back(b);
      // decided on the marking of classify(), applied afterwards, so that
      // the order of the parts does not matter
      std::vector<std::pair<std::size_t, int>> film;
      for (const auto &[joint, parts] : parts_of_joint)
        {
          // the parts' boxes overlap at the hinges: judge each node once
          std::vector<bool> judged(positions.size(), false);
          for (const unsigned int p : parts)
            {
              const rigid::RigidBody     &body = *bodies[p].body;
              const geometry::BoundingBox local_box
                = body.shape().bounding_box().enlarged(2.
                                                       * largest_half_spacing);
              const geometry::BoundingBox box
                = geometry::Pose(body.orientation, body.position)
                    .to_world(local_box);
              grid->for_each_in_box(box, [&](const std::size_t i) {
                if (node_body[i] >= 0 || judged[i])
                  return;
                judged[i]        = true;
                const int nearer = part_enclosing(bodies, parts, i);
                if (nearer >= 0)
                  film.emplace_back(i, nearer);
              });
            }
        }
      for (const auto &[node, body] : film)
        node_body[node] = body;
    }



    template <int dim>
    int
    FictitiousBoundary<dim>::part_enclosing(
      const std::vector<Body>         &bodies,
      const std::vector<unsigned int> &parts,
      const std::size_t                node) const
    {
      const double spacing  = node_spacing(node);
      unsigned int close    = 0;
      int          nearest  = -1;
      double       shortest = std::numeric_limits<double>::max();
      for (const unsigned int p : parts)
        {
          const rigid::RigidBody &part = *bodies[p].body;
          const double            distance
            = part.shape().signed_distance(part.to_body(positions[node]));
          if (distance < spacing)
            ++close;
          if (distance < shortest)
            {
              shortest = distance;
              nearest  = p;
            }
        }
      return close >= 2 ? nearest : -1;
    }



    template <int dim>
    std::vector<typename FictitiousBoundary<dim>::DofIndex>
    FictitiousBoundary<dim>::joint_dofs(
      const std::vector<int> &joint_of_body) const
    {
      std::vector<DofIndex> dofs;
      const auto            joint = [&](const unsigned int node) {
        return node_body[node] < 0 ? -1 : joint_of_body[node_body[node]];
      };
      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          const unsigned int *nodes = cell_nodes(c);
          bool                meet  = false;
          for (unsigned int a = 0; a < nodes_per_cell_ && !meet; ++a)
            for (unsigned int b = a + 1; b < nodes_per_cell_ && !meet; ++b)
              meet = joint(nodes[a]) >= 0 && joint(nodes[a]) == joint(nodes[b])
                     && node_body[nodes[a]] != node_body[nodes[b]];
          if (!meet)
            continue;
          for (unsigned int a = 0; a < nodes_per_cell_; ++a)
            if (joint(nodes[a]) >= 0)
              for (unsigned int d = 0; d < dim; ++d)
                dofs.push_back(node_dofs[nodes[a]][d]);
        }
      std::sort(dofs.begin(), dofs.end());
      dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
      return dofs;
    }



    template <int dim>
    std::vector<unsigned long>
    FictitiousBoundary<dim>::n_nodes_inside(const unsigned int n_bodies) const
    {
      // count each node once: on the rank that owns its x-velocity DoF
      const IndexSet &owned = flow.get_dof_handler().locally_owned_dofs();
      std::vector<unsigned long> n(n_bodies, 0);
      for (unsigned int i = 0; i < positions.size(); ++i)
        if (node_body[i] >= 0 && owned.is_element(node_dofs[i][0]))
          ++n[node_body[i]];
      Utilities::MPI::sum(n, flow.get_communicator(), n);
      return n;
    }

    template class FictitiousBoundary<2>;
    template class FictitiousBoundary<3>;
  } // namespace fbm
} // namespace particulate
