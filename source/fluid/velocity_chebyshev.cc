#include "velocity_chebyshev.h"

namespace particulate {
  namespace fluid {
    using namespace dealii;

    template <int dim>
    VelocityChebyshev<dim>::VelocityChebyshev(const unsigned int degree,
                                              const IndexSet    &owned_velocity,
                                              const MPI_Comm     communicator,
                                              TimerOutput       &timer)
      : degree(degree)
      , owned_velocity(owned_velocity)
      , communicator(communicator)
      , timer(timer)
    {}



    template <int dim>
    bool
    VelocityChebyshev<dim>::prepare(const VelocityLinearisation &a)
    {
      if (!chebyshev)
        rebuild(a);
      return true; // built from this very matrix
    }



    template <int dim>
    void
    VelocityChebyshev<dim>::rebuild(const VelocityLinearisation &a)
    {
      Assert(a.matrix != nullptr,
             ExcMessage("the Chebyshev polynomial needs the assembled block"));
      TimerOutput::Scope scope(timer, "fluid: velocity Chebyshev setup");
      const auto        &A        = *a.matrix;
      auto               jacobi   = std::make_shared<Jacobi>();
      auto              &diagonal = jacobi->inverse_diagonal;
      diagonal.reinit(owned_velocity, communicator);
      for (const auto row : owned_velocity)
        {
          const double value = A.diag_element(row);
          diagonal(row)      = value != 0. ? 1. / value : 1.;
        }
      diagonal.compress(VectorOperation::insert);
      typename Chebyshev::AdditionalData data;
      data.degree              = degree;
      data.smoothing_range     = 0.;
      data.eig_cg_n_iterations = 12;
      data.preconditioner      = jacobi;
      chebyshev                = std::make_unique<Chebyshev>();
      chebyshev->initialize(A, data);
    }



    template <int dim>
    void
    VelocityChebyshev<dim>::vmult(
      TrilinosWrappers::MPI::Vector       &dst,
      const TrilinosWrappers::MPI::Vector &src) const
    {
      chebyshev->vmult(dst, src);
    }

    template class VelocityChebyshev<2>;
    template class VelocityChebyshev<3>;
  } // namespace fluid
} // namespace particulate
