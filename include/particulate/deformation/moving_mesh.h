#ifndef particulate_deformation_moving_mesh_h
#define particulate_deformation_moving_mesh_h

#include <particulate/core/mesh.h>
#include <particulate/deformation/deformation_parameters.h>
#include <particulate/deformation/mesh_deformation.h>

#include <deal.II/grid/tria.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace particulate {
  namespace deformation {
    template <int dim>
    class VertexHierarchy;

    /**
     * A flow mesh that follows moving bodies (thesis §6.3): every rank holds
     * the whole refinement hierarchy of the case's mesh; each time step
     * regularises it and adapts it to the bodies' new positions with the
     * method of subsection `Mesh deformation`, and copies the vertex
     * positions into the distributed mesh of the flow solver, cell by cell
     * (matched by CellId).
     *
     * The thesis regularises by a few plain Laplacian sweeps before each
     * re-adaptation. Measured on the oscillating cylinder (test
     * deformation_moving_mesh), four sweeps per level leave the mesh
     * depending on the path the body took: after a quarter period and back,
     * vertices stood 0.17 m (13 fine cells) from where the same body
     * position had put them. So the regularisation goes to its limit: every
     * adaptation starts from the undeformed mesh (on the generated
     * tensor-product meshes exactly where plain smoothing converges to),
     * and the mesh is a function of where the bodies are.
     */
    template <int dim>
    class MovingMesh
    {
    public:
      /** Builds the hierarchy from @p mesh (as core::create_mesh() does).
       *  Throws std::invalid_argument for `Method = none` unless the mesh
       *  carries the neighbourhoods of the bodies (then it is the
       *  undeformed mesh, carried). */
      MovingMesh(const core::MeshParameters  &mesh,
                 const DeformationParameters &parameters);
      ~MovingMesh();

      /**
       * Adapt the undeformed mesh to the surfaces that @p distance
       * describes. Throws DeformationError (mesh unchanged) when the method
       * refuses.
       */
      DeformationReport
      adapt(const DistanceField<dim> &distance);

      /**
       * Follow the bodies to where @p distance puts them now. With `Moving
       * bodies = re-adapt`, adapt() (readapted set in the report). With
       * `carry surface vertices`, LaplaceAlpha::carry() moves the vertices
       * on a surface by @p body_displacement (the displacement over the
       * step of the body nearest to a point) and smooths the rest. With
       * `carry neighbourhood`, every vertex moves by a share of
       * @p body_displacement: all of it within `Carried zone width` of the
       * surface, none beyond `Carried zone fade` more (see
       * carried_share()). Either carrying mode calls adapt() only when
       * that leaves a cell worse than `Re-adaptation quality` or
       * `Re-adaptation aspect ratio` (and than the last fresh adaptation's
       * worst cell), or a surface vertex could not follow. Throws
       * DeformationError (mesh unchanged) when a fresh adaptation is refused
       * or the move would leave a cell inverted.
       *
       * With `carry neighbourhood`, no method and @p previous (the bodies
       * where the step starts, where the mesh was carried to before), a
       * fresh start is made there and then carried over the step like any
       * other: fresh_start_vertices() holds the fresh mesh, onto which the
       * flow is carried before the step's ALE motion, so that the covered
       * nodes move with their body in this step too. When that carry alone
       * bends a cell below `Re-adaptation quality`, the fresh start is
       * made where the bodies are now instead (fresh_start_vertices()
       * empty).
       */
      DeformationReport
      follow(
        const DistanceField<dim> &distance,
        const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
                                 &body_displacement,
        const DistanceField<dim> *previous = nullptr);

      /** The fresh start of the last follow() where the bodies were before
       *  the step (see follow()); empty when there was none. */
      const std::vector<dealii::Point<dim>> &
      fresh_start_vertices() const
      {
        return fresh_start;
      }

      /**
       * Give every cell of @p tria (a partition of the same mesh, e.g. a
       * parallel::fullydistributed::Triangulation made by
       * core::create_mesh()) the vertex positions of its twin here.
       */
      void
      copy_vertices_to(dealii::Triangulation<dim> &tria) const;

      /** The same with the vertices at @p positions (indexed like the
       *  hierarchy's), e.g. fresh_start_vertices(). */
      void
      copy_vertices_to(dealii::Triangulation<dim>            &tria,
                       const std::vector<dealii::Point<dim>> &positions) const;

      /** The hierarchy with its current vertex positions. */
      const dealii::Triangulation<dim> &
      hierarchy() const
      {
        return mesh;
      }

      /** True unless `Moving bodies = re-adapt`: the mesh moves gradually
       *  with the bodies, except when follow() adapts afresh. */
      bool
      carries_mesh() const
      {
        return following != DeformationParameters::Following::readapt;
      }

      /** The method's name for the log. */
      std::string
      method_name() const
      {
        return method ? method->name() : std::string("none");
      }

      /**
       * `carry neighbourhood`: the share of its body's displacement that a
       * vertex at signed distance @p d from the surface takes: 1 up to
       * `Carried zone width`, then a smoothstep 1 - 3t^2 + 2t^3 (t the
       * fraction of `Carried zone fade` crossed) down to 0, so that the
       * mesh velocity is continuous with a continuous gradient.
       */
      double
      carried_share(const double d) const;

      /** Checkpoints: the vertex positions and the vertices on a surface
       *  (binary). */
      void
      save(std::ostream &out) const;
      /** Reads what save() wrote; throws std::runtime_error when the vertex
       *  count differs. */
      void
      load(std::istream &in);

    private:
      /** `carry neighbourhood`'s move of every vertex (see follow()). */
      DeformationReport
      carry_neighbourhood(
        const DistanceField<dim> &distance,
        const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
          &body_displacement);
      /** Put the vertices back at @p before and throw DeformationError:
       *  a move left a cell inverted (@p min_scaled_jacobian <= 0). */
      [[noreturn]] void
      refuse_inverted_mesh(const std::vector<dealii::Point<dim>> &before,
                           const double min_scaled_jacobian);
      /** Whether a carried mesh stays within `Re-adaptation quality` and
       *  `Re-adaptation aspect ratio` (or the last fresh start's worst). */
      bool
      keeps_quality(const DeformationReport &report) const;
      /** `carry neighbourhood`'s fresh start about the bodies @p at: the
       *  undeformed mesh, each body's zone realigned to where it lies on
       *  the carried mesh @p carried_positions, with the lattice shift
       *  chosen for the end of the @p step it is about to be carried by
       *  (realigned_zones()). */
      DeformationReport
      restart_carried_zones(
        const std::vector<dealii::Point<dim>> &carried_positions,
        const DistanceField<dim>              &at,
        const std::function<dealii::Tensor<1, dim>(const dealii::Point<dim> &)>
          &step
        = {});

      dealii::Triangulation<dim>            mesh;
      std::unique_ptr<MeshDeformation<dim>> method;
      DeformationParameters::Following      following;
      double                                readaptation_quality;
      double                                readaptation_aspect_ratio;
      double                                carried_zone_width;
      double                                carried_zone_fade;
      /// carry_neighbourhood: the mesh's levels, edges and boundary
      /// planes, which carrying does not change (built at the first carry)
      std::unique_ptr<const VertexHierarchy<dim>> carried_hierarchy;
      /// the vertex positions as the case's mesh made them
      std::vector<dealii::Point<dim>> undeformed;
      /// carry_surface: the vertices Laplace-alpha put onto a surface,
      /// and the worst cell of the last fresh adaptation
      std::vector<bool> on_surface;
      double            fresh_min_quality      = 1.;
      double            fresh_max_aspect_ratio = 1.;
      /// see fresh_start_vertices()
      std::vector<dealii::Point<dim>> fresh_start;
    };
  } // namespace deformation
} // namespace particulate

#endif
