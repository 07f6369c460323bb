#ifndef particulate_fbm_particle_set_parameters_h
#define particulate_fbm_particle_set_parameters_h

#include <particulate/core/input_outline.h>
#include <particulate/fbm/particle_description.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace particulate {
  namespace fbm {
    /**
     * The list subsections of `Particles` that a case file holds, by label:
     * `Shape <name>`, `Particle <n>`, `Lattice <name>` and `Random fill
     * <name>`. deal.II's ParameterHandler only reads declared subsections,
     * so the labels are read from the file's outline before it is parsed
     * (the way Lethe declares its numbered particle and boundary lists, but
     * without a fixed maximum).
     */
    struct ParticleSetLayout
    {
      std::vector<std::string> shapes;
      std::vector<std::string> particles;
      std::vector<std::string> lattices;
      std::vector<std::string> random_fills;

      /** The labels that @p outline holds. */
      static ParticleSetLayout
      of(const core::InputOutline &outline);

      /** One subsection of each kind, labelled '<name>' or '<n>': what
       *  --print-parameters documents. */
      static ParticleSetLayout
      documentation();
    };

    /**
     * Declare, in the entered subsection `Particles`, the particle file
     * entry and the list subsections of @p layout.
     */
    void
    declare_particle_set(dealii::ParameterHandler &prm,
                         const ParticleSetLayout  &layout);

    /**
     * Read the particles of a @p dim-dimensional run from the entered
     * subsection `Particles`: the `Particle <n>` subsections in the order of
     * n, then the particle file, then each `Lattice` and each `Random fill`
     * in the order of the file. Each names a `Shape <name>` template.
     *
     * @param outline the case file, for the lines that messages name; the
     *   particle file is found relative to its folder
     * @throw std::runtime_error naming the file, line and entry for an
     *   unknown shape name, numbers of the wrong count, particles that are
     *   not numbered 0, 1, 2, ..., a prescribed motion with the wrong
     *   number of components, a hinged part without its hinge or hinged
     *   to a particle that is missing, itself or hinged too, a bad line of the
     * particle file, a generator that cannot place its particles, or two
     * initial particles that overlap
     */
    std::vector<ParticleDescription>
    read_particle_set(dealii::ParameterHandler &prm,
                      const unsigned int        dim,
                      const core::InputOutline &outline);
  } // namespace fbm
} // namespace particulate

#endif
