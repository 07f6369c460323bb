#include <particulate/deformation/laplace_smoothing.h>
#include <particulate/deformation/mesh_deformation.h>
#include <particulate/deformation/pde_deformation.h>

namespace particulate {
  namespace deformation {
    template <int dim>
    std::unique_ptr<MeshDeformation<dim>>
    create_mesh_deformation(const DeformationParameters &p)
    {
      using Method = DeformationParameters::Method;
      SmoothingSettings smoothing;
      smoothing.width            = p.width;
      smoothing.peak_weight      = p.peak_weight;
      smoothing.relaxation       = p.relaxation;
      smoothing.sweeps_per_level = p.sweeps_per_level;
      smoothing.min_quality      = p.min_quality;
      typename PdeDeformation<dim>::Settings pde;
      pde.robust              = p.method == Method::pde_robust;
      pde.width               = p.width;
      pde.smallest_cell_ratio = p.smallest_cell_ratio;
      pde.ode_steps           = p.ode_steps;
      pde.step_ratio          = p.step_ratio;
      switch (p.method)
        {
          case Method::none:
            return nullptr;
          case Method::laplace_kappa:
            return std::make_unique<LaplaceKappa<dim>>(smoothing);
          case Method::laplace_alpha:
            return std::make_unique<LaplaceAlpha<dim>>(smoothing,
                                                       p.projection_range);
          case Method::pde_basic:
          case Method::pde_robust:
            return std::make_unique<PdeDeformation<dim>>(pde);
        }
      return nullptr;
    }

    template std::unique_ptr<MeshDeformation<2>>
    create_mesh_deformation<2>(const DeformationParameters &);
    template std::unique_ptr<MeshDeformation<3>>
    create_mesh_deformation<3>(const DeformationParameters &);
  } // namespace deformation
} // namespace particulate
