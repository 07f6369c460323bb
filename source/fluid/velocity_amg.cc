#include "velocity_amg.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values_extractors.h>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    VelocityAmg<dim>::VelocityAmg(const LinearSolverParameters &parameters,
                                  const DoFHandler<dim>        &dof_handler,
                                  TimerOutput                  &timer)
      : parameters(parameters)
      , dof_handler(dof_handler)
      , timer(timer)
    {}



    template <int dim>
    bool
    VelocityAmg<dim>::prepare(const VelocityLinearisation &a)
    {
      if (amg)
        return false;
      rebuild(a);
      return true;
    }



    template <int dim>
    void
    VelocityAmg<dim>::rebuild(const VelocityLinearisation &a)
    {
      Assert(a.matrix != nullptr,
             ExcMessage("algebraic multigrid needs the assembled block"));
      TimerOutput::Scope             scope(timer, "fluid: velocity AMG setup");
      std::vector<std::vector<bool>> constant_modes;
      const FEValuesExtractors::Vector velocities(0);
      DoFTools::extract_constant_modes(dof_handler,
                                       dof_handler.get_fe().component_mask(
                                         velocities),
                                       constant_modes);
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.constant_modes        = constant_modes;
      data.elliptic              = parameters.amg_elliptic;
      const std::string smoother = to_string(parameters.amg_smoother);
      data.smoother_type         = smoother.c_str();
      data.higher_order_elements = true;
      data.smoother_sweeps       = parameters.amg_smoother_sweeps;
      data.aggregation_threshold = 0.02;
      amg.reset(); // before the new one: ML asks its matrix when destroyed
      amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      amg->initialize(*a.matrix, data);
      fresh_iterations = 0;
    }



    template <int dim>
    void
    VelocityAmg<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                            const TrilinosWrappers::MPI::Vector &src) const
    {
      amg->vmult(dst, src);
    }



    template <int dim>
    void
    VelocityAmg<dim>::record_solve(const unsigned int iterations,
                                   const bool         fresh)
    {
      if (fresh)
        fresh_iterations = iterations;
      else if (kept_preconditioner_is_worn(iterations, fresh_iterations))
        amg.reset();
    }



    template <int dim>
    std::size_t
    VelocityAmg<dim>::memory_consumption() const
    {
      return amg ? amg->memory_consumption() : 0;
    }

    template class VelocityAmg<2>;
    template class VelocityAmg<3>;
  } // namespace fluid
} // namespace particulate
