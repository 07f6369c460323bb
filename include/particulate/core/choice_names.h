#ifndef particulate_core_choice_names_h
#define particulate_core_choice_names_h

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace particulate {
  namespace core {
    /**
     * The names a case file uses for the values of an enum that a parameter
     * selects, in the order its selection pattern lists them. A parameter
     * struct holds the enum; its declaration writes the default with
     * name_of() and the pattern with selection_of(), its parse() reads the
     * value back with choice_named(), so a choice is compared as an enum
     * everywhere and spelt in one table.
     */
    template <typename Choice>
    using ChoiceNames = std::vector<std::pair<Choice, std::string>>;

    /** The choice named @p name (a value its selection pattern accepted). */
    template <typename Choice>
    Choice
    choice_named(const ChoiceNames<Choice> &names, const std::string &name)
    {
      for (const auto &[choice, text] : names)
        if (text == name)
          return choice;
      throw std::logic_error("'" + name + "' passed a selection pattern");
    }

    /** The name of @p choice in a case file. */
    template <typename Choice>
    std::string
    name_of(const ChoiceNames<Choice> &names, const Choice choice)
    {
      for (const auto &[c, text] : names)
        if (c == choice)
          return text;
      throw std::logic_error("a choice without a name");
    }

    /** The names joined by '|', the argument of Patterns::Selection. */
    template <typename Choice>
    std::string
    selection_of(const ChoiceNames<Choice> &names)
    {
      std::string pattern;
      for (std::size_t i = 0; i < names.size(); ++i)
        pattern += (i > 0 ? "|" : "") + names[i].second;
      return pattern;
    }
  } // namespace core
} // namespace particulate

#endif
