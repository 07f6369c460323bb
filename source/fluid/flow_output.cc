#include <particulate/fluid/flow_output.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <cmath>
#include <fstream>

namespace particulate {
  namespace fluid {
    using namespace dealii;

    namespace {
      /** Vorticity curl u: a scalar in 2D, a vector in 3D. */
      template <int dim>
      class Vorticity : public DataPostprocessor<dim>
      {
      public:
        void
        evaluate_vector_field(
          const DataPostprocessorInputs::Vector<dim> &inputs,
          std::vector<Vector<double>>                &computed) const override
        {
          for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
            {
              const auto &g = inputs.solution_gradients[q];
              if constexpr (dim == 2)
                computed[q](0) = g[1][0] - g[0][1];
              else
                {
                  computed[q](0) = g[2][1] - g[1][2];
                  computed[q](1) = g[0][2] - g[2][0];
                  computed[q](2) = g[1][0] - g[0][1];
                }
            }
        }
        std::vector<std::string>
        get_names() const override
        {
          return std::vector<std::string>(dim == 2 ? 1 : dim, "vorticity");
        }
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          return std::vector<
            DataComponentInterpretation::DataComponentInterpretation>(
            dim == 2 ? 1 : dim,
            dim == 2 ?
              DataComponentInterpretation::component_is_scalar :
              DataComponentInterpretation::component_is_part_of_vector);
        }
        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_gradients;
        }
      };

      /** The shear rate g = sqrt(2 D:D) and the viscosity mu(g) of a
       *  generalized-Newtonian fluid. */
      template <int dim>
      class ShearRateAndViscosity : public DataPostprocessor<dim>
      {
      public:
        explicit ShearRateAndViscosity(const ViscosityModel &model)
          : model(model)
        {}

        void
        evaluate_vector_field(
          const DataPostprocessorInputs::Vector<dim> &inputs,
          std::vector<Vector<double>>                &computed) const override
        {
          for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
            {
              Tensor<2, dim> grad;
              for (unsigned int d = 0; d < dim; ++d)
                grad[d] = inputs.solution_gradients[q][d];
              const SymmetricTensor<2, dim> D          = symmetrize(grad);
              const double                  shear_rate = std::sqrt(2. * D * D);
              computed[q](0)                           = shear_rate;
              computed[q](1) = model.viscosity(shear_rate);
            }
        }
        std::vector<std::string>
        get_names() const override
        {
          return {"shear_rate", "viscosity"};
        }
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          return std::vector<
            DataComponentInterpretation::DataComponentInterpretation>(
            2,
            DataComponentInterpretation::component_is_scalar);
        }
        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_gradients;
        }

      private:
        const ViscosityModel &model;
      };
    } // namespace



    template <int dim>
    FlowOutput<dim>::FlowOutput(const std::string &directory,
                                const std::string &basename)
      : directory(directory)
      , basename(basename)
    {}



    template <int dim>
    void
    FlowOutput<dim>::write(const NavierStokes<dim> &flow,
                           const unsigned int       step,
                           const double             time)
    {
      std::vector<std::string> names(dim, "velocity");
      names.emplace_back("pressure");
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
        interpretation(
          dim,
          DataComponentInterpretation::component_is_part_of_vector);
      interpretation.push_back(
        DataComponentInterpretation::component_is_scalar);

      DataOut<dim> data_out;
      data_out.attach_dof_handler(flow.get_dof_handler());
      data_out.add_data_vector(flow.get_solution(),
                               names,
                               DataOut<dim>::type_dof_data,
                               interpretation);
      // the vorticity postprocessor sees only the velocity components
      Vorticity<dim> vorticity;
      data_out.add_data_vector(flow.get_solution(), vorticity);
      const ShearRateAndViscosity<dim> rheology(flow.get_viscosity_model());
      if (flow.get_viscosity_model().depends_on_shear_rate())
        data_out.add_data_vector(flow.get_solution(), rheology);

      Vector<float> rank(
        flow.get_dof_handler().get_triangulation().n_active_cells());
      rank = Utilities::MPI::this_mpi_process(flow.get_communicator());
      data_out.add_data_vector(rank, "rank");

      DataOutBase::VtkFlags flags;
      flags.write_higher_order_cells = true;
      flags.time                     = time;
      data_out.set_flags(flags);
      data_out.build_patches(flow.get_mapping(),
                             2,
                             DataOut<dim>::curved_inner_cells);

      const std::string pvtu
        = data_out.write_vtu_with_pvtu_record(directory + "/",
                                              basename,
                                              step,
                                              flow.get_communicator(),
                                              5);
      records.emplace_back(time, pvtu);
      if (Utilities::MPI::this_mpi_process(flow.get_communicator()) == 0)
        {
          std::ofstream pvd(directory + "/" + basename + ".pvd");
          DataOutBase::write_pvd_record(pvd, records);
        }
    }

    template class FlowOutput<2>;
    template class FlowOutput<3>;
  } // namespace fluid
} // namespace particulate
