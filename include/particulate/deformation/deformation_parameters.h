#ifndef particulate_deformation_deformation_parameters_h
#define particulate_deformation_deformation_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <vector>

namespace particulate {
  namespace deformation {
    /** subsection `Mesh deformation`: which method moves the vertices, and
     *  how strongly. */
    struct DeformationParameters
    {
      enum class Method
      {
        none,
        laplace_kappa, ///< weighted Laplacian smoothing (eq. 5.27, Alg. 12)
        laplace_alpha, ///< surface projection plus smoothing (§5.7)
        pde_basic,     ///< basic deformation method (Algorithm 10)
        pde_robust     ///< robust deformation method (Algorithm 11)
      };
      Method method = Method::none;
      /// distance from the surfaces over which the mesh is refined [m]
      double width = 0.1;
      /// Laplace-kappa: smoother weight at the surface (1 far away)
      double peak_weight = 8.;
      /// relaxation omega of eq. 5.27
      double relaxation = 0.5;
      /// smoothing sweeps per level, coarse to fine (the last entry
      /// repeats for finer levels)
      std::vector<unsigned int> sweeps_per_level{4};
      /// PDE methods: smallest over largest target cell size (epsilon)
      double smallest_cell_ratio = 0.1;
      /// PDE methods: Runge-Kutta steps of the vertex ODE (eq. 5.22)
      unsigned int ode_steps = 20;
      /// robust method: largest change of the target size per step
      double step_ratio = 2.;
      /// Laplace-alpha: project a vertex (any level) whose distance to a
      /// surface is below this fraction of its shortest edge
      double projection_range = 0.45;
      /// no cell may end below this scaled Jacobian (or below its value
      /// before the move, if that was lower)
      double min_quality = 0.2;

      /** How a mesh follows moving bodies (deformation::MovingMesh). */
      enum class Following
      {
        /// adapt the undeformed mesh afresh every step
        readapt,
        /// laplace-alpha: carry the surface vertices with their body,
        /// smooth the rest; adapt afresh only when the quality demands
        carry_surface,
        /// any method (also none): move the vertices near a body rigidly
        /// with it, fading out farther away; adapt afresh only when the
        /// quality demands
        carry_neighbourhood
      };
      Following following = Following::readapt;
      /// carry_surface: adapt afresh when the smallest scaled Jacobian
      /// falls below this (and below that of the last fresh adaptation)
      double readaptation_quality = 0.3;
      /// carry_surface: adapt afresh when the largest aspect ratio exceeds
      /// this (and that of the last fresh adaptation)
      double readaptation_aspect_ratio = 20.;
      /// carry_neighbourhood: vertices closer than this to a body's
      /// surface move rigidly with it [m]
      double carried_zone_width = 0.01;
      /// carry_neighbourhood: beyond that, the displacement falls to zero
      /// over this distance [m]
      double carried_zone_fade = 0.05;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };
  } // namespace deformation
} // namespace particulate

#endif
