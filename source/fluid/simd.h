#ifndef particulate_fluid_simd_h
#define particulate_fluid_simd_h

// Private header of the fluid library: SIMD for the matrix-free operators.
//
// Debian's deal.II 9.4.1 is configured with DEAL_II_VECTORIZATION_WIDTH_IN_BITS
// 0, which compiles the SSE2/AVX/AVX-512 specialisations of VectorizedArray
// out of vectorization.h: the library's own MatrixFree runs one cell per
// instruction. This header switches those specialisations back on for the
// translation units that include it, as wide as the instruction set they are
// compiled for (AVX-512 with the -march=native that CMake adds to them, SSE2
// on plain x86-64), and names the widest array as SimdArray<Number>.
//
// What stays as the library has it: the *default* width of VectorizedArray
// (config.h has already fixed it to one lane through numbers.h), so classes
// compiled into libdeal.ii (MappingQ's internal data, MGTransferMatrixFree)
// keep their layout. Only the explicitly wide types differ, and the
// MatrixFree machinery for them is instantiated in-tree
// (matrix_free_instantiations.cc). doc/performance.md, "SIMD without
// rebuilding deal.II", has the measurements.
//
// It must come before every deal.II header of the translation unit.

#ifdef dealii_vectorization_h
#  error "simd.h must be included before any deal.II header"
#endif

#include <deal.II/base/config.h>

#undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#if defined(__AVX512F__)
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 512
#elif defined(__AVX__)
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 256
#elif defined(__SSE2__)
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 128
#else
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 0
#endif

#include <deal.II/base/vectorization.h>

#include <cstddef>

namespace particulate {
  namespace fluid {
    /** Lanes of the widest SIMD register for @p Number (1 without SIMD). */
    template <typename Number>
    constexpr std::size_t simd_lanes
      = DEAL_II_VECTORIZATION_WIDTH_IN_BITS == 0 ?
          1 :
          DEAL_II_VECTORIZATION_WIDTH_IN_BITS / (8 * sizeof(Number));

    template <typename Number>
    using SimdArray = dealii::VectorizedArray<Number, simd_lanes<Number>>;
  } // namespace fluid
} // namespace particulate

#endif
