#ifndef particulate_fbm_fictitious_boundary_h
#define particulate_fbm_fictitious_boundary_h

#include <particulate/cuda/containment_engine.h>
#include <particulate/fluid/navier_stokes.h>
#include <particulate/geometry/point_hash_grid.h>
#include <particulate/rigid/world.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>

#include <Eigen/Core>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The liquid-solid interface of the fictitious boundary method (thesis
     * §5.3.1, §5.4): which Q2 velocity nodes lie inside which body, and the
     * rigid velocity u = U + omega x (x - X) imposed there (eq. 5.9, 5.17).
     *
     * The nodes of this rank's locally relevant cells (owned and ghost) are
     * collected once per mesh into a hash grid (geometry::PointHashGrid), so
     * a classification tests only the nodes in each body's bounding box
     * (§5.4.2). Ghost nodes are classified too: every rank then builds
     * the same constraints for the DoFs it shares, without communication.
     */
    template <int dim>
    class FictitiousBoundary
    {
    public:
      using DofIndex = dealii::types::global_dof_index;

      /** A body as the interface sees it: its pose, velocity and shape. */
      struct Body
      {
        const rigid::RigidBody *body = nullptr;
      };

      /** Which nodes take a body's rigid velocity. */
      enum class Marking
      {
        /// signed distance <= 0 (thesis eq. 5.9): the flow sees the body
        /// shrunk to its innermost nodes, on average by half a node spacing
        inside,
        /// signed distance <= a quarter of the local node spacing: half
        /// the reach of Marking::nearest, between the two bracketing rules
        halfway,
        /// signed distance <= half the local node spacing: the surface
        /// rounded to the nearest node; the body seen enlarged instead
        nearest
      };

      explicit FictitiousBoundary(const fluid::NavierStokes<dim> &flow);
      ~FictitiousBoundary();

      /** Choose the marking (Marking::inside until called). The cuda/
       *  engine supports Marking::inside only. */
      void
      set_marking(Marking m);

      /**
       * Let classify() use the cuda/ library's ContainmentEngine on
       * @p backend (cuda::Backend::cuda: the GPU; cuda::Backend::cpu: its
       * CPU path, the same float arithmetic) instead of the hash grid with
       * the bodies' exact signed distances. The engine sees each body as a
       * one-sphere inner-sphere set of the body's radius: exact for spheres
       * and, in 2D, for disks (their nodes lie in their plane); other
       * shapes are refused. Call before or after setup().
       */
      void
      use_containment_engine(cuda::Backend backend);

      /** "hash grid" or the engine's device name. */
      std::string
      containment_method() const;

      /** Collect the velocity nodes; call again after the mesh changed. */
      void
      setup();

      /**
       * Mark every node by the first body that covers it (signed distance
       * <= 0; <= a quarter or half the local node spacing with
       * Marking::halfway or Marking::nearest), or -1.
       */
      void
      classify(const std::vector<Body> &bodies);

      /**
       * The rigid velocities at the marked nodes, as (DoF, value) pairs for
       * fluid::NavierStokes::set_fictitious_boundary_values().
       */
      std::vector<std::pair<DofIndex, double>>
      constraint_values(const std::vector<Body> &bodies) const;

      /**
       * The velocity DoFs (sorted) of the covered nodes of the owned cells
       * where nodes of two bodies of one joint meet: the parts of an
       * articulated body, @p joint_of_body giving each body's joint (-1:
       * none). Their velocities come from two rigid motions, which no
       * divergence-free flow in the cell takes (fluid::NavierStokes::
       * set_fictitious_boundary_values()).
       */
      std::vector<DofIndex>
      joint_dofs(const std::vector<int> &joint_of_body) const;

      /**
       * After classify(): the free nodes within one node spacing of two
       * bodies of one joint (@p joint_of_body as for joint_dofs()) take
       * the nearer body, so that a film between two parts of an
       * articulated body that is thinner than a cell moves with them
       * ('Films between parts = cover'). The distances are the shapes'
       * signed distances, a node's spacing that of classify().
       */
      void
      cover_films(const std::vector<Body> &bodies,
                  const std::vector<int>  &joint_of_body);

      /** Per body, the number of nodes (all ranks) inside it: a measure
       *  of how well the mesh resolves it. Collective. */
      std::vector<unsigned long>
      n_nodes_inside(const unsigned int n_bodies) const;

      /** The body marking node @p i, or -1. */
      int
      body_of_node(const unsigned int i) const
      {
        return node_body[i];
      }

      /** Locally owned cells, in the order of cell_nodes(). */
      const std::vector<typename dealii::DoFHandler<dim>::active_cell_iterator>
        &
        owned_cells() const
      {
        return cells;
      }

      /** For owned cell @p c, the node of each velocity support point
       *  (nodes_per_cell() entries). */
      const unsigned int *
      cell_nodes(const unsigned int c) const
      {
        return &nodes_of_cells[c * nodes_per_cell_];
      }

      unsigned int
      nodes_per_cell() const
      {
        return nodes_per_cell_;
      }

      /** Number of collected nodes (locally relevant). */
      unsigned int
      n_nodes() const
      {
        return positions.size();
      }

      const Eigen::Vector3d &
      node_position(const unsigned int i) const
      {
        return positions[i];
      }

      /** The distance from node @p i to its nearest neighbour node (the
       *  shortest over the cells around it). */
      double
      node_spacing(const unsigned int i) const
      {
        return 2. * half_spacing[i];
      }

    private:
      /** Of @p parts (bodies of one joint), the one nearest to node
       *  @p node if at least two are within its node spacing, else -1. */
      int
      part_enclosing(const std::vector<Body>         &bodies,
                     const std::vector<unsigned int> &parts,
                     const std::size_t                node) const;

      const fluid::NavierStokes<dim> &flow;
      /// per node its position (z = 0 in 2D) and its dim velocity DoFs
      std::vector<Eigen::Vector3d>             positions;
      std::vector<std::array<DofIndex, 3>>     node_dofs;
      std::unique_ptr<geometry::PointHashGrid> grid;
      std::vector<int>                         node_body;
      Marking                                  marking = Marking::inside;
      /// per node half the local node spacing (a quarter of the shortest
      /// cell edge around it, the same on every rank), and its maximum: the
      /// reach of Marking::halfway and nearest, and the scale of every
      /// marking's rounding tolerance at the surface
      std::vector<double> half_spacing;
      double              largest_half_spacing = 0.;
      /// the engine path: its engine, the node positions as floats, one
      /// uploaded sphere shape per radius and one distance map per mesh
      /// body's map
      std::unique_ptr<cuda::ContainmentEngine>  engine;
      std::vector<float>                        positions_float;
      std::vector<std::pair<double, int>>       engine_spheres;
      std::vector<std::pair<const void *, int>> engine_maps;

      void
      classify_with_engine(const std::vector<Body> &bodies);
      /** The engine's handle of @p shape, uploaded on first use: a mesh
       *  body's distance map, or a one-sphere set for a sphere or a 2D
       *  disk; other shapes throw. */
      int
      engine_shape(const geometry::Shape &shape);
      void
      make_half_spacing_consistent();
      /** How far outside a body a node may lie and still be covered, as a
       *  fraction of its half node spacing: 0, 1/2 or 1. */
      double
      reach_fraction() const;
      std::vector<typename dealii::DoFHandler<dim>::active_cell_iterator> cells;
      std::vector<unsigned int> nodes_of_cells;
      unsigned int              nodes_per_cell_ = 0;
    };
  } // namespace fbm
} // namespace particulate

#endif
