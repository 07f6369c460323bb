#include <particulate/core/input_file.h>
#include <particulate/core/input_outline.h>

#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace particulate {
  namespace core {
    namespace {
      using Tree = boost::property_tree::ptree;

      /// The declared parameters as a property tree (deal.II's JSON dump).
      Tree
      declared_tree(const dealii::ParameterHandler &prm)
      {
        std::stringstream json;
        prm.print_parameters(json, dealii::ParameterHandler::JSON);
        Tree tree;
        boost::property_tree::read_json(json, tree);
        return tree;
      }

      bool
      is_entry(const Tree &node)
      {
        return node.find("pattern_description") != node.not_found();
      }

      std::string
      path_string(const std::vector<std::string> &path)
      {
        if (path.empty())
          return "the top level";
        std::string s = "subsection '";
        for (unsigned int i = 0; i < path.size(); ++i)
          s += (i > 0 ? " / " : "") + path[i];
        return s + "'";
      }

      /// Names of children of @p node that are entries (or subsections).
      std::vector<std::string>
      child_names(const Tree &node, const bool entries)
      {
        std::vector<std::string> names;
        for (const auto &child : node)
          if (is_entry(child.second) == entries)
            names.push_back(child.first);
        return names;
      }

      std::string
      suggestion(const std::string              &wrong,
                 const std::vector<std::string> &valid)
      {
        if (valid.empty())
          return " There are none in this place.";
        std::string  best;
        unsigned int best_distance = std::numeric_limits<unsigned int>::max();
        for (const auto &name : valid)
          {
            const unsigned int d = edit_distance(wrong, name);
            if (d < best_distance)
              {
                best_distance = d;
                best          = name;
              }
          }
        // Only propose a name that is plausibly what was meant.
        if (best_distance <= std::max<std::size_t>(3, best.size() / 3))
          return " Did you mean '" + best + "'?";
        std::string list = " Valid names here:";
        for (const auto &name : valid)
          list += " '" + name + "'";
        return list + ".";
      }

      [[noreturn]] void
      fail(const std::string &filename,
           const unsigned int line,
           const std::string &message)
      {
        throw std::runtime_error(filename + ":" + std::to_string(line) + ": "
                                 + message);
      }

      /** Check every name of @p outline against the declared tree. */
      void
      check_names(const Tree &declared, const InputOutline &outline)
      {
        const std::string        &filename = outline.filename();
        std::vector<const Tree *> node_stack{&declared};
        for (const InputOutline::Statement &s : outline.statements())
          {
            const std::vector<std::string> &path = s.path;
            switch (s.keyword)
              {
                case InputOutline::Keyword::subsection:
                  {
                    const Tree &node  = *node_stack.back();
                    const auto  child = node.find(s.name);
                    if (child == node.not_found() || is_entry(child->second))
                      fail(filename,
                           s.line,
                           "unknown subsection '" + s.name + "' in "
                             + path_string(path) + "."
                             + suggestion(s.name, child_names(node, false)));
                    node_stack.push_back(&child->second);
                    break;
                  }
                case InputOutline::Keyword::end:
                  node_stack.pop_back();
                  break;
                case InputOutline::Keyword::set:
                  {
                    const Tree &node  = *node_stack.back();
                    const auto  entry = node.find(s.name);
                    if (entry == node.not_found() || !is_entry(entry->second))
                      fail(filename,
                           s.line,
                           "unknown entry '" + s.name + "' in "
                             + path_string(path) + "."
                             + suggestion(s.name, child_names(node, true)));
                    break;
                  }
                case InputOutline::Keyword::include:
                  break; // deal.II resolves it; the included file is
                         // checked there
              }
          }
      }
    } // namespace



    unsigned int
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> previous(b.size() + 1), current(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        previous[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          current[0] = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const bool same
                = std::tolower(static_cast<unsigned char>(a[i - 1]))
                  == std::tolower(static_cast<unsigned char>(b[j - 1]));
              current[j] = std::min({previous[j] + 1,
                                     current[j - 1] + 1,
                                     previous[j - 1] + (same ? 0 : 1)});
            }
          std::swap(previous, current);
        }
      return previous[b.size()];
    }



    double
    get_positive_double(const dealii::ParameterHandler &prm,
                        const std::string              &name,
                        const std::string              &subsection)
    {
      const double value = prm.get_double(name);
      if (!(value > 0.))
        throw std::runtime_error("The entry '" + name + "' in subsection '"
                                 + subsection
                                 + "' must be larger than zero (it "
                                   "is "
                                 + prm.get(name) + ").");
      return value;
    }



    void
    parse_input_file(dealii::ParameterHandler &prm, const std::string &filename)
    {
      parse_input_file(prm, InputOutline(filename));
    }



    void
    parse_input_file(dealii::ParameterHandler &prm, const InputOutline &outline)
    {
      const std::string &filename = outline.filename();
      check_names(declared_tree(prm), outline);
      try
        {
          prm.parse_input(filename, "", /*skip_undefined=*/false);
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw std::runtime_error("Error in the parameter file '" + filename
                                   + "':\n" + info.str()
                                   + "Correct the value and run again; "
                                     "'particulate --print-parameters' lists "
                                     "every entry with its valid values.");
        }
    }



    namespace {
      std::string
      markdown_escape(const std::string &s)
      {
        std::string out;
        for (const char c : s)
          {
            if (c == '|')
              out += "\\|";
            else if (c == '\n')
              out += ' ';
            else
              out += c;
          }
        return out;
      }

      /// Children of @p node split into entries and subsections, in order.
      std::pair<std::vector<std::pair<std::string, const Tree *>>,
                std::vector<std::pair<std::string, const Tree *>>>
      split_children(const Tree &node)
      {
        std::pair<std::vector<std::pair<std::string, const Tree *>>,
                  std::vector<std::pair<std::string, const Tree *>>>
          result;
        for (const auto &child : node)
          (is_entry(child.second) ? result.first : result.second)
            .emplace_back(child.first, &child.second);
        return result;
      }

      void
      write_markdown_section(const Tree                     &node,
                             const std::vector<std::string> &path,
                             std::ostream                   &out)
      {
        const auto [entries, subsections] = split_children(node);
        if (!entries.empty())
          {
            out << "\n## "
                << (path.empty() ? std::string("Top level") : path_string(path))
                << "\n\n| Entry | Default | Valid values | Meaning |\n"
                << "|---|---|---|---|\n";
            for (const auto &[name, e] : entries)
              out << "| `" << name << "` | `"
                  << markdown_escape(e->get<std::string>("default_value"))
                  << "` | "
                  << markdown_escape(e->get<std::string>("pattern_description"))
                  << " | "
                  << markdown_escape(e->get<std::string>("documentation"))
                  << " |\n";
          }
        for (const auto &[name, child] : subsections)
          {
            auto sub_path = path;
            sub_path.push_back(name);
            write_markdown_section(*child, sub_path, out);
          }
      }

      void
      write_prm_section(const Tree        &node,
                        const unsigned int depth,
                        std::ostream      &out)
      {
        const std::string indent(2 * depth, ' ');
        const auto [entries, subsections] = split_children(node);
        for (const auto &[name, e] : entries)
          {
            out << indent << "# " << e->get<std::string>("documentation")
                << "\n"
                << indent << "# Default: '"
                << e->get<std::string>("default_value")
                << "'  Valid: " << e->get<std::string>("pattern_description")
                << "\n"
                << indent << "set " << name << " = "
                << e->get<std::string>("value") << "\n\n";
          }
        for (const auto &[name, child] : subsections)
          {
            out << indent << "subsection " << name << "\n";
            write_prm_section(*child, depth + 1, out);
            out << indent << "end\n\n";
          }
      }
    } // namespace



    void
    write_parameter_reference(const dealii::ParameterHandler &prm,
                              std::ostream                   &out)
    {
      out << "# Parameter reference\n\n"
          << "Generated from the code by `scripts/generate-parameter-doc.sh` "
             "(`particulate --print-parameters=markdown`); do not edit by "
             "hand. A test fails when this file is stale.\n\n"
          << "Physical quantities are in SI units unless an entry says "
             "otherwise. Every `.prm` file uses the syntax "
             "`subsection Name` ... `set Entry = value` ... `end`.\n";
      write_markdown_section(declared_tree(prm), {}, out);
    }



    void
    write_parameter_listing(const dealii::ParameterHandler &prm,
                            std::ostream                   &out)
    {
      out << "# Particulate parameters: documentation, default and valid "
             "values of every entry.\n# This listing is itself a valid .prm "
             "file holding the current values.\n\n";
      write_prm_section(declared_tree(prm), 0, out);
    }
  } // namespace core
} // namespace particulate
