#ifndef particulate_fluid_geometric_cell_integrals_h
#define particulate_fluid_geometric_cell_integrals_h

// Private header of the fluid library: one cell's integrals that depend
// only on the mesh, for FlowDiscretisation::assemble_geometric_matrices().

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <array>
#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * On one cell of the Q2^dim x P1disc element:
     *
     *   gradient(a, k) = -(psi_k, d_{c_a} phi_a)    (B^T: velocity row a of
     *                                                component c_a, pressure
     *                                                column k)
     *   mass(k, l)     =  (psi_k, psi_l)            (M_p)
     *   lumped(a)      =  (phi_a, 1)                (row sum of the velocity
     *                                                mass: partition of unity)
     *
     * stored densely over the cell's velocity DoFs a and pressure DoFs k
     * (their cell-local numbers: velocity_dofs(), pressure_dofs()), so that
     * the loops run over contiguous arrays instead of over every DoF of
     * the system with a branch on its component.
     */
    template <int dim>
    class GeometricCellIntegrals
    {
    public:
      explicit GeometricCellIntegrals(const dealii::FESystem<dim> &fe)
      {
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c == dim)
              pressure.push_back(i);
            else
              {
                velocity.push_back(i);
                velocity_component.push_back(c);
              }
          }
        AssertDimension(pressure.size(), n_p);
        gradient_values.resize(velocity.size() * n_p);
        mass_values.resize(n_p * n_p);
        lumped_values.resize(velocity.size());
      }

      /** The integrals on the cell @p fe_values was last reinit'ed on
       *  (values and JxW; gradients too if @p with_gradient). Each entry
       *  is summed over the quadrature points in their order; the loops
       *  run over one shape function's points at a time, which lie
       *  contiguously in FEValues. */
      void
      compute(const dealii::FEValues<dim> &fe_values, const bool with_gradient)
      {
        const unsigned int n_q = fe_values.n_quadrature_points;
        dx.resize(n_q);
        psi.resize(n_q * n_p);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            dx[q] = fe_values.JxW(q);
            for (unsigned int k = 0; k < n_p; ++k)
              psi[q * n_p + k] = fe_values.shape_value(pressure[k], q);
          }
        std::fill(mass_values.begin(), mass_values.end(), 0.);
        for (unsigned int q = 0; q < n_q; ++q)
          for (unsigned int k = 0; k < n_p; ++k)
            for (unsigned int l = 0; l < n_p; ++l)
              mass_values[k * n_p + l]
                += psi[q * n_p + k] * psi[q * n_p + l] * dx[q];
        for (unsigned int a = 0; a < velocity.size(); ++a)
          {
            double lumped = 0.;
            for (unsigned int q = 0; q < n_q; ++q)
              lumped += fe_values.shape_value(velocity[a], q) * dx[q];
            lumped_values[a] = lumped;
            if (with_gradient)
              compute_gradient_row(fe_values, a);
          }
      }

      const std::vector<unsigned int> &
      velocity_dofs() const
      {
        return velocity;
      }
      const std::vector<unsigned int> &
      pressure_dofs() const
      {
        return pressure;
      }
      /** Row @p a of B^T: one entry per pressure DoF. */
      const double *
      gradient_row(const unsigned int a) const
      {
        return &gradient_values[a * n_p];
      }
      /** Row @p k of M_p: one entry per pressure DoF. */
      const double *
      mass_row(const unsigned int k) const
      {
        return &mass_values[k * n_p];
      }
      /** One entry per velocity DoF. */
      const std::vector<double> &
      lumped() const
      {
        return lumped_values;
      }

    private:
      /// pressure DoFs per cell: P1disc
      static constexpr unsigned int n_p = dim + 1;

      void
      compute_gradient_row(const dealii::FEValues<dim> &fe_values,
                           const unsigned int           a)
      {
        // primitive: the gradient of the one nonzero component
        const unsigned int      i = velocity[a], c = velocity_component[a];
        std::array<double, n_p> row{};
        for (unsigned int q = 0; q < dx.size(); ++q)
          {
            const double d_phi = fe_values.shape_grad(i, q)[c];
            for (unsigned int k = 0; k < n_p; ++k)
              row[k] -= psi[q * n_p + k] * d_phi * dx[q];
          }
        std::copy(row.begin(), row.end(), &gradient_values[a * n_p]);
      }

      std::vector<unsigned int> velocity, velocity_component, pressure;
      /// JxW and the pressure shape values, per quadrature point
      std::vector<double> dx, psi;
      std::vector<double> gradient_values, mass_values, lumped_values;
    };
  } // namespace fluid
} // namespace particulate

#endif
