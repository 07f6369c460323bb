#ifndef particulate_deformation_pde_deformation_h
#define particulate_deformation_pde_deformation_h

#include <particulate/deformation/mesh_deformation.h>

#include <deal.II/base/point.h>

#include <functional>
#include <vector>

namespace particulate {
  namespace deformation {
    /**
     * The PDE-based deformation method of Grajewski (thesis §5.6): a map
     * Psi of the domain onto itself whose Jacobian turns the present cell
     * sizes g_0 into the sizes a monitor f asks for, g_0 |J Psi| = f(Psi)
     * (eq. 5.19). One basic step (Algorithm 10): normalise f and g_0 (eq.
     * 5.20) into the reciprocal densities f~ = c_f / f and g~ = c_g / g_0,
     * solve the Neumann problem -div grad v = f~ - g~ (eq. 5.21) with Q1
     * elements, recover grad v at the vertices, and move every vertex along
     * the ODE x' = grad v / (t f~ + (1-t) g~) from t = 0 to 1 (eq.
     * 5.22-5.23, classical Runge-Kutta), locating it in the mesh with a
     * PointLocator. The robust method (Algorithm 11) reaches f through
     * blended monitors f_s = s f + (1-s) g_0 (eq. 5.25), each step a basic
     * step from the mesh the previous one left.
     *
     * Boundary vertices slide along flat boundaries. If a step would tangle
     * the mesh, the mesh is left as it was and DeformationError says how
     * many cells would have inverted.
     */
    template <int dim>
    class PdeDeformation : public MeshDeformation<dim>
    {
    public:
      struct Settings
      {
        bool         robust = true;
        double       width  = 0.1; ///< [m] monitor ramp, see deform()
        double       smallest_cell_ratio = 0.1; ///< epsilon
        unsigned int ode_steps           = 20;
        double       step_ratio          = 2.; ///< robust: gamma_0
      };

      explicit PdeDeformation(const Settings &settings);

      /**
       * Adapt to the monitor f(x) = min{1, max{|d(x)| / width, epsilon}}
       * with d the signed distance to the nearest surface: cells shrink to
       * epsilon times the far-field size at the surfaces (the test monitor
       * of eq. 5.24 is this for the circle of radius 0.25).
       */
      DeformationReport
      deform(dealii::Triangulation<dim> &tria,
             const DistanceField<dim>   &distance) const override;

      /**
       * Adapt the active cells of @p tria to the relative target cell size
       * @p monitor (a positive function of the position).
       */
      DeformationReport
      deform_to_monitor(
        dealii::Triangulation<dim>                              &tria,
        const std::function<double(const dealii::Point<dim> &)> &monitor) const;

      std::string
      name() const override;

      /**
       * The robust method's blending parameters s_1 < ... < s_n = 1 for a
       * largest ratio @p extreme_ratio between the normalised monitor and
       * area function: the blended target at that point changes by the
       * same factor, at most `step_ratio`, in every step.
       */
      std::vector<double>
      blending_parameters(const double extreme_ratio) const;

    private:
      /**
       * One basic step from the present mesh to @p target (evaluated at the
       * vertices). Returns the new vertex positions.
       */
      std::vector<dealii::Point<dim>>
      basic_step(const dealii::Triangulation<dim> &tria,
                 const std::vector<double>        &target_at_vertices,
                 DeformationReport                &report) const;

      Settings settings;
    };
  } // namespace deformation
} // namespace particulate

#endif
