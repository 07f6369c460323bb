#ifndef particulate_fluid_velocity_jacobian_kernel_h
#define particulate_fluid_velocity_jacobian_kernel_h

// Private header of the fluid library: the velocity-velocity block of one
// cell's Newton Jacobian, computed as small matrix products.

#include <vector>

namespace particulate {
  namespace fluid {
    /**
     * The velocity block of a Q2^dim cell's Jacobian, for trial phi_b e_d
     * and test phi_a e_c (phi: the n_s scalar Q2 functions):
     *
     *   J(c, d)[a][b] = sum_q  delta_cd [ m_q phi_a phi_b
     *                                     + phi_a (beta_q . grad phi_b)
     *                                     + nu_q grad phi_a . grad phi_b ]
     *                        + nu_q d_d phi_a d_c phi_b
     *                        + N_q(c, d) phi_a phi_b
     *
     * with quadrature weights folded into m_q (mass), nu_q (viscosity),
     * beta_q (advecting velocity) and N_q (Newton term rho d_d u_c).
     *
     * Every block is a product sum_k left_k[a] right_k[b] over a list of
     * k = (quadrature point, feature) pairs: the left features are phi and
     * its dim derivatives, the right ones the same functions weighted for
     * the block. The products run on register tiles of three test
     * functions times all trial functions, with the sum over k innermost,
     * so that the block's entries stay in registers instead of being
     * loaded and stored once per quadrature point (the outer-product form
     * this replaces was bound by those loads and stores; doc/performance.md,
     * "Assembling the Jacobian").
     */
    template <int dim>
    class VelocityJacobianKernel
    {
    public:
      /// scalar Q2 functions per cell
      static constexpr unsigned int n_s = dim == 2 ? 9 : 27;
      /// a block's row length in memory: n_s rounded up to a multiple of
      /// 8, the doubles of the widest SIMD register (AVX-512)
      static constexpr unsigned int stride = dim == 2 ? 16 : 32;

      explicit VelocityJacobianKernel(unsigned int n_quadrature_points);

      /**
       * Data of quadrature point q: values phi[b] and derivatives
       * gradient[e][b] of the scalar functions, and the weights m_q,
       * nu_q, beta_q (dim values) and N_q (dim * dim, row c, column d).
       */
      void
      set_quadrature_point(unsigned int         q,
                           const double        *phi,
                           const double *const *gradient,
                           double               mass,
                           double               viscosity,
                           const double        *advection,
                           const double        *newton);

      /** The blocks from the data of every quadrature point. */
      void
      compute();

      double
      operator()(const unsigned int c,
                 const unsigned int d,
                 const unsigned int a,
                 const unsigned int b) const
      {
        return blocks[((c * dim + d) * n_s + a) * stride + b];
      }

    private:
      static constexpr unsigned int n_features = dim + 1;
      unsigned int                  n_q;
      /// phi and its derivatives by test function: [a][q][feature]
      std::vector<double> left;
      /// phi and two of its derivatives, [d][a][q][2]: (phi, d_d phi)
      std::vector<double> left_off_diagonal;
      /// phi and its derivatives by quadrature point: [q][feature][stride]
      std::vector<double> right_functions;
      /// m_q, nu_q, beta_q, N_q per quadrature point
      std::vector<double> weights;
      /// the right features of one block, [k][stride]
      std::vector<double> right;
      std::vector<double> blocks;
    };
  } // namespace fluid
} // namespace particulate

#endif
