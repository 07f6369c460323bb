// The MatrixFree machinery for the SIMD widths of simd.h, instantiated here
// because libdeal.ii (built without SIMD) holds it only for one lane. The
// matrix-free operators (mass_viscous_operator.cc, momentum_operator.cc,
// velocity_multigrid.cc) include only the declarations; this translation
// unit alone pays for deal.II's template definitions.


// simd.h first: it must precede every deal.II header
// clang-format off
#include "simd.h"
// clang-format on

// The evaluation factories dispatch a run-time degree to kernels compiled
// for degrees 1 to this bound. The operators use FEEvaluation with the
// degree fixed at compile time (Q2), which bypasses the factories, so the
// bound only keeps this file's compile time down.
#define FE_EVAL_FACTORY_DEGREE_MAX 2

#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>
// deal.II 9.4 gives the face factory's header the include guard of the cell
// factory's, so it has to be let in by hand.
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>

namespace dealii {
  using particulate::fluid::SimdArray;

#define PARTICULATE_INSTANTIATE_MATRIX_FREE(dim, Number)                       \
  template class MatrixFree<dim, Number, SimdArray<Number>>;                   \
  template void                                                                \
  MatrixFree<dim, Number, SimdArray<Number>>::internal_reinit<double, dim>(    \
    const std::shared_ptr<hp::MappingCollection<dim>> &,                       \
    const std::vector<const DoFHandler<dim, dim> *> &,                         \
    const std::vector<const AffineConstraints<double> *> &,                    \
    const std::vector<IndexSet> &,                                             \
    const std::vector<hp::QCollection<dim>> &,                                 \
    const AdditionalData &);                                                   \
  template void                                                                \
  MatrixFree<dim, Number, SimdArray<Number>>::internal_reinit<float, dim>(     \
    const std::shared_ptr<hp::MappingCollection<dim>> &,                       \
    const std::vector<const DoFHandler<dim, dim> *> &,                         \
    const std::vector<const AffineConstraints<float> *> &,                     \
    const std::vector<IndexSet> &,                                             \
    const std::vector<hp::QCollection<dim>> &,                                 \
    const AdditionalData &);                                                   \
  template void internal::MatrixFreeFunctions::ShapeInfo<                      \
    SimdArray<Number>>::reinit<dim, dim, 1>(const Quadrature<1> &,             \
                                            const FiniteElement<dim, dim> &,   \
                                            unsigned int);                     \
  template void internal::MatrixFreeFunctions::ShapeInfo<                      \
    SimdArray<Number>>::reinit<dim, dim, dim>(const Quadrature<dim> &,         \
                                              const FiniteElement<dim, dim> &, \
                                              unsigned int);                   \
  template struct internal::MatrixFreeFunctions::                              \
    MappingInfo<dim, Number, SimdArray<Number>>;                               \
  template struct internal::FEEvaluationFactory<dim, SimdArray<Number>>;       \
  template struct internal::FEFaceEvaluationFactory<dim, SimdArray<Number>>;   \
  template struct internal::                                                   \
    FEFaceEvaluationGatherFactory<dim, Number, SimdArray<Number>>;             \
  template struct internal::CellwiseInverseMassFactory<dim,                    \
                                                       SimdArray<Number>>;     \
  template struct internal::                                                   \
    FEEvaluationHangingNodesFactory<dim, Number, SimdArray<Number>>;

  template struct internal::MatrixFreeFunctions::ShapeInfo<SimdArray<double>>;
  template struct internal::MatrixFreeFunctions::ShapeInfo<SimdArray<float>>;

  PARTICULATE_INSTANTIATE_MATRIX_FREE(2, double)
  PARTICULATE_INSTANTIATE_MATRIX_FREE(3, double)
  PARTICULATE_INSTANTIATE_MATRIX_FREE(2, float)
  PARTICULATE_INSTANTIATE_MATRIX_FREE(3, float)

#undef PARTICULATE_INSTANTIATE_MATRIX_FREE
} // namespace dealii
