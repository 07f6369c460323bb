#ifndef particulate_core_input_file_h
#define particulate_core_input_file_h

#include <particulate/core/input_outline.h>

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace particulate {
  namespace core {
    /**
     * Read a `.prm` file into a ParameterHandler whose entries are already
     * declared, with messages a user can act on.
     *
     * Before deal.II parses the file we scan it ourselves: every `subsection`
     * and `set` line is checked against the declared tree, and a name that does
     * not exist is reported with the file, the line, the subsection it was
     * found in and the nearest valid name (by edit distance), e.g.
     *
     *   case.prm:12: unknown entry 'Time stpe' in subsection 'Time'.
     *   Did you mean 'Time step'?
     *
     * Values that do not match their pattern are then caught by deal.II's own
     * parser; we rethrow its explanation without the C++ backtrace.
     *
     * @param prm ParameterHandler with all entries declared.
     * @param filename Path of the parameter file.
     * @throws std::runtime_error with a complete message on any problem
     *   (missing file, unknown subsection or entry, bad value, unbalanced
     *   `end`).
     */
    void
    parse_input_file(dealii::ParameterHandler &prm,
                     const std::string        &filename);

    /** The same for a file whose outline was read already. */
    void
    parse_input_file(dealii::ParameterHandler &prm,
                     const InputOutline       &outline);

    /**
     * The edit (Levenshtein) distance between two strings, ignoring case.
     * Used to suggest the nearest valid parameter name.
     */
    unsigned int
    edit_distance(const std::string &a, const std::string &b);

    /**
     * Write the declared parameters of @p prm as a Markdown reference: one
     * section per subsection, one table row per entry with its default,
     * its pattern and its documentation (which carries the unit).
     */
    void
    write_parameter_reference(const dealii::ParameterHandler &prm,
                              std::ostream                   &out);

    /**
     * Read entry @p name of the current subsection and insist that it is
     * strictly positive (deal.II's Double pattern only has inclusive bounds).
     * @param subsection Name of the current subsection, for the message.
     */
    double
    get_positive_double(const dealii::ParameterHandler &prm,
                        const std::string              &name,
                        const std::string              &subsection);

    /**
     * Write the parameters of @p prm with their current values as a `.prm`
     * file in which every entry is preceded by its documentation, default
     * and valid values. Used by `--print-parameters` and for the
     * `used_parameters.prm` of every run.
     */
    void
    write_parameter_listing(const dealii::ParameterHandler &prm,
                            std::ostream                   &out);
  } // namespace core
} // namespace particulate

#endif
