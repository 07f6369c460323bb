#ifndef particulate_fbm_case_file_h
#define particulate_fbm_case_file_h

#include <particulate/fbm/particulate_flow_simulation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace particulate {
  namespace fbm {
    /**
     * Read the case file @p filename into @p prm and the parameters of a
     * run: the particle lists the file holds are declared first, then every
     * entry is parsed and checked against its pattern, then the values and
     * their combinations are checked. @p overrides, if not empty, is parsed
     * after the file (a test shortens a shipped case this way). Nothing is
     * written and no mesh is made.
     * @throw std::runtime_error whose message starts with the file name,
     *   for any entry or combination the run would refuse
     */
    ParticulateFlowParameters
    read_case_file(dealii::ParameterHandler &prm,
                   const std::string        &filename,
                   const std::string        &overrides = "");

    /**
     * The checks of a 'particulate flow' case that concern its particles
     * as a whole: it has at least one, and moving (free or prescribed) ones
     * only with a time-dependent scheme.
     * @throw std::runtime_error naming @p filename and what to change
     */
    void
    check_particles_suit_the_run(const ParticulateFlowParameters &parameters,
                                 const std::string               &filename);

    /**
     * The checks of a case that need its coarse mesh, on every rank of
     * @p comm: the expressions have the dimension's number of components,
     * every boundary id has a condition and is on the mesh, every
     * particle lies inside the mesh's bounding box and on each of its
     * mirror planes, and (check_particles_suit_the_run) a particulate flow
     * has particles it can move. Together with
     * read_case_file() this is what `particulate --validate` does.
     * @throw std::runtime_error naming the file and the entry or particle
     */
    void
    check_case_against_mesh(const ParticulateFlowParameters &parameters,
                            const std::string               &filename,
                            MPI_Comm                         comm);
  } // namespace fbm
} // namespace particulate

#endif
