#ifndef particulate_core_mesh_size_h
#define particulate_core_mesh_size_h

#include <particulate/core/mesh.h>

namespace particulate {
  namespace core {
    /**
     * The number of cells of the coarse mesh of @p parameters in @p dim
     * dimensions as far as it follows from the entries, without building
     * anything: the product of the subdivisions of a hyper rectangle, of
     * the graded cell counts of a graded rectangle (as graded_cell_sizes()
     * makes them, in closed form). 0 for the meshes whose coarse cells are
     * known only once they are built (ball, channel with cylinder, file).
     */
    double
    coarse_cell_count(const MeshParameters &parameters, const unsigned int dim);

    /**
     * Refuse a mesh of @p coarse_cells cells refined 'Refinements' times
     * whose Q2/P1disc unknowns (about dim 2^dim + dim + 1 per cell) would
     * not fit in deal.II's global DoF index: a case asking for such a mesh
     * would otherwise allocate until the machine runs out of memory.
     * @throw std::runtime_error naming the entries that set the size
     */
    void
    check_mesh_size(const MeshParameters &parameters,
                    const unsigned int    dim,
                    const double          coarse_cells);
  } // namespace core
} // namespace particulate

#endif
