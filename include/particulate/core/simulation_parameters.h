#ifndef particulate_core_simulation_parameters_h
#define particulate_core_simulation_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <string>

namespace particulate {
  namespace core {
    /** subsection `Simulation`: what to run and in which dimension. */
    struct SimulationParameters
    {
      /** What the run simulates. */
      enum class Type
      {
        fluid,            ///< incompressible flow with body-fitted obstacles
        particulate_flow, ///< particles in the flow (fictitious boundaries)
        rigid_bodies      ///< the particles alone, without a fluid
      };
      Type         type      = Type::fluid;
      unsigned int dimension = 2;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /** subsection `Time`: the time-stepping scheme and the time step. */
    struct TimeParameters
    {
      /**
       * The one-step schemes of thesis §5.3.2. `steady` solves the stationary
       * problem with one nonlinear solve.
       */
      enum class Scheme
      {
        steady,
        backward_euler,
        crank_nicolson,
        fractional_step_theta
      };
      Scheme scheme            = Scheme::fractional_step_theta;
      double time_step         = 0.01; ///< [s]
      double end_time          = 1.0;  ///< [s]
      bool   adaptive          = false;
      double cfl_target        = 1.0;
      double minimum_time_step = 1e-6; ///< [s]
      double maximum_time_step = 1.0;  ///< [s]

      /**
       * The step after one of size @p dt that had the CFL number @p cfl:
       * aimed at cfl_target, changed by at most 20 %, within the minimum
       * and maximum time step. Only meaningful when `adaptive` is set.
       */
      double
      next_time_step(const double dt, const double cfl) const;

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };

    /** subsection `Output`: where and how often results are written. */
    struct OutputParameters
    {
      /** How a particulate run writes its particles' series. */
      enum class ParticleFiles
      {
        automatic,     ///< each particle's own up to 100 particles
        each_particle, ///< `particle_<i>.dat`, a surface series per body
        shared         ///< `particles.dat`, all surfaces in one file
      };

      std::string   directory = "output";
      unsigned int  interval  = 1; ///< write VTU every this many time steps
      bool          write_vtu = true;
      ParticleFiles particle_files = ParticleFiles::automatic;

      /** Whether a run with @p n_particles writes shared particle files. */
      bool
      shares_particle_files(const std::size_t n_particles) const
      {
        return particle_files == ParticleFiles::shared
               || (particle_files == ParticleFiles::automatic
                   && n_particles > 100);
      }

      static void
      declare(dealii::ParameterHandler &prm);
      void
      parse(dealii::ParameterHandler &prm);
    };
  } // namespace core
} // namespace particulate

#endif
