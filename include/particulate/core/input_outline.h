#ifndef particulate_core_input_outline_h
#define particulate_core_input_outline_h

#include <map>
#include <string>
#include <vector>

namespace particulate {
  namespace core {
    /**
     * The statements of a `.prm` file with the lines they stand on, read
     * without any declared parameters: what a file holds and where.
     *
     * Two things need this before, or beside, deal.II's ParameterHandler:
     * - lists a user writes as numbered or named subsections (`subsection
     *   Particle 3`, `subsection Shape ball`) must be declared before the
     *   file is parsed, so their names are read from the outline first;
     * - a value that is valid for its pattern but wrong for the case (two
     *   particles overlapping) is reported with the line it was set on.
     *
     * Comments, continuation lines and blanks are handled as deal.II does.
     * `include` lines are recorded but not followed.
     */
    class InputOutline
    {
    public:
      /** What a statement does. */
      enum class Keyword
      {
        subsection,
        end,
        set,
        include
      };

      /** One statement: its first line, keyword, subsection and name. */
      struct Statement
      {
        unsigned int line;
        Keyword      keyword;
        /// the subsections it stands in, outermost first
        std::vector<std::string> path;
        /// the subsection's or entry's name (blanks collapsed, as deal.II
        /// reads it), or the included file
        std::string name;
      };

      /**
       * Read @p filename.
       * @throw std::runtime_error with the file and line for a file that
       *   cannot be opened, a line that is no statement, an 'end' without
       *   subsection, a 'set' without '=' and a subsection never closed
       */
      explicit InputOutline(const std::string &filename);

      const std::string &
      filename() const
      {
        return file;
      }

      const std::vector<Statement> &
      statements() const
      {
        return list;
      }

      /**
       * The subsections directly inside @p path whose names are @p prefix
       * followed by a blank and a label, e.g. the labels {"0", "1"} of
       * `subsection Particle 0` and `subsection Particle 1` for the prefix
       * "Particle". In the order of the file, each once.
       */
      std::vector<std::string>
      labels(const std::vector<std::string> &path,
             const std::string              &prefix) const;

      /**
       * Where entry @p entry of subsection @p path is set, for messages:
       * "case.prm:12: subsection 'A / B', entry 'E'". Without @p entry, or
       * when the file does not set it, the line that opens the subsection
       * is given (no line if the file has no such subsection).
       */
      std::string
      where(const std::vector<std::string> &path,
            const std::string              &entry = "") const;

    private:
      std::string                         file;
      std::vector<Statement>              list;
      std::map<std::string, unsigned int> first_line;
    };

    /** 'A / B' for the path {A, B}. */
    std::string
    join_path(const std::vector<std::string> &path);
  } // namespace core
} // namespace particulate

#endif
