#ifndef particulate_tests_performance_machine_measurements_h
#define particulate_tests_performance_machine_measurements_h

// What the benchmarks measure of the machine beside the code: STREAM-like
// bandwidths, the bandwidth a product with the assembled system matrix
// achieves, the peak memory of all ranks.

#include <particulate/fluid/navier_stokes.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <iostream>
#include <vector>

#include <sys/resource.h>

namespace particulate {
  namespace benchmarks {
    using Clock = std::chrono::steady_clock;

    inline double
    seconds_since(const Clock::time_point start)
    {
      return std::chrono::duration<double>(Clock::now() - start).count();
    }

    /** Copy bandwidth of all ranks at once [GB/s, read + write], best of 5. */
    inline double
    stream_copy_bandwidth(MPI_Comm comm)
    {
      const std::size_t   n = std::size_t(1) << 25; // 256 MiB per array
      std::vector<double> a(n, 1.), b(n, 0.);
      double              best = 1e30;
      for (unsigned int repeat = 0; repeat < 5; ++repeat)
        {
          MPI_Barrier(comm);
          const auto start = Clock::now();
          std::copy(a.begin(), a.end(), b.begin());
          MPI_Barrier(comm);
          best      = std::min(best, seconds_since(start));
          a[repeat] = b[n - 1 - repeat]; // keep the copies observable
        }
      const double bytes = 2. * n * sizeof(double)
                           * dealii::Utilities::MPI::n_mpi_processes(comm);
      return bytes / best / 1e9;
    }

    /** Read bandwidth of all ranks at once [GB/s] (a sum over an array),
     *  best of 5: what a matrix-vector product could reach at most. */
    inline double
    stream_read_bandwidth(MPI_Comm comm)
    {
      const std::size_t         n = std::size_t(1) << 26; // 512 MiB
      const std::vector<double> a(n, 1.);
      double                    best = 1e30, sum = 0.;
      for (unsigned int repeat = 0; repeat < 5; ++repeat)
        {
          MPI_Barrier(comm);
          const auto start = Clock::now();
          // eight independent sums, so that the adds do not wait on each
          // other and the loads set the pace
          double partial[8] = {0., 0., 0., 0., 0., 0., 0., 0.};
          for (std::size_t i = 0; i < n; i += 8)
            for (unsigned int j = 0; j < 8; ++j)
              partial[j] += a[i + j];
          for (const double p : partial)
            sum += p;
          MPI_Barrier(comm);
          best = std::min(best, seconds_since(start));
        }
      if (sum != 5. * n) // keeps the sums from being optimised away
        std::cerr << "read bandwidth: wrong sum" << std::endl;
      return double(n) * sizeof(double)
             * dealii::Utilities::MPI::n_mpi_processes(comm) / best / 1e9;
    }

    /** Achieved bandwidth of y = A x with the system matrix [GB/s]; its
     *  values and column indices, all ranks, into @p matrix_bytes. */
    template <int dim>
    double
    matrix_vector_bandwidth(const fluid::NavierStokes<dim> &flow,
                            double                         &matrix_bytes)
    {
      const auto &A = flow.get_system_matrix();
      matrix_bytes  = 0.;
      if (A.n_block_rows() == 0) // 'Velocity operator = matrix-free'
        return 0.;
      auto x       = flow.make_owned_vector();
      auto y       = flow.make_owned_vector();
      x            = 1.;
      double bytes = 0.;
      for (unsigned int i = 0; i < A.n_block_rows(); ++i)
        for (unsigned int j = 0; j < A.n_block_cols(); ++j)
          // values and column indices of all ranks (the count is global);
          // row pointers and the vectors are small against them
          bytes += A.block(i, j).n_nonzero_elements() * (8. + 4.);
      const MPI_Comm comm = flow.get_communicator();
      matrix_bytes        = bytes;
      MPI_Barrier(comm);
      const auto         start       = Clock::now();
      const unsigned int repetitions = 20;
      for (unsigned int r = 0; r < repetitions; ++r)
        A.vmult(y, x);
      MPI_Barrier(comm);
      return repetitions * bytes / seconds_since(start) / 1e9;
    }

    inline double
    peak_resident_bytes(MPI_Comm comm)
    {
      rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      return dealii::Utilities::MPI::sum(1024. * usage.ru_maxrss, comm);
    }

  } // namespace benchmarks
} // namespace particulate

#endif
