#include <particulate/core/input_outline.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace particulate {
  namespace core {
    namespace {
      std::string
      trim(const std::string &s)
      {
        const auto first = s.find_first_not_of(" \t\r");
        if (first == std::string::npos)
          return "";
        const auto last = s.find_last_not_of(" \t\r");
        return s.substr(first, last - first + 1);
      }

      /// Collapse runs of blanks to one, as deal.II does for names.
      std::string
      normalise_name(const std::string &s)
      {
        std::string out;
        bool        blank = false;
        for (const char c : trim(s))
          {
            if (c == ' ' || c == '\t')
              blank = true;
            else
              {
                if (blank && !out.empty())
                  out += ' ';
                out += c;
                blank = false;
              }
          }
        return out;
      }

      [[noreturn]] void
      fail(const std::string &filename,
           const unsigned int line,
           const std::string &message)
      {
        throw std::runtime_error(filename + ":" + std::to_string(line) + ": "
                                 + message);
      }

      std::string
      key(const std::vector<std::string> &path, const std::string &entry)
      {
        return join_path(path) + '\n' + entry;
      }
    } // namespace



    std::string
    join_path(const std::vector<std::string> &path)
    {
      std::string s;
      for (unsigned int i = 0; i < path.size(); ++i)
        s += (i > 0 ? " / " : "") + path[i];
      return s;
    }



    InputOutline::InputOutline(const std::string &filename)
      : file(filename)
    {
      std::ifstream in(filename);
      if (!in)
        throw std::runtime_error("Cannot open the parameter file '" + filename
                                 + "'. Check the path (relative paths are "
                                   "taken from the current directory).");
      std::vector<std::string>  path;
      std::vector<unsigned int> opened_at;
      std::string               raw, line;
      unsigned int              line_number = 0, start_line = 0;
      while (std::getline(in, raw))
        {
          ++line_number;
          if (line.empty())
            start_line = line_number;
          // strip comments, join continuation lines
          const auto hash = raw.find('#');
          if (hash != std::string::npos)
            raw.erase(hash);
          raw = trim(raw);
          if (!raw.empty() && raw.back() == '\\')
            {
              line += raw.substr(0, raw.size() - 1);
              continue;
            }
          line += raw;
          const std::string statement = trim(line);
          line.clear();
          if (statement.empty())
            continue;

          std::istringstream words(statement);
          std::string        keyword, rest;
          words >> keyword;
          std::getline(words, rest);
          if (keyword == "subsection")
            {
              const std::string name = normalise_name(rest);
              list.push_back({start_line, Keyword::subsection, path, name});
              path.push_back(name);
              opened_at.push_back(start_line);
              first_line.emplace(key(path, ""), start_line);
            }
          else if (keyword == "end")
            {
              if (path.empty())
                fail(filename,
                     start_line,
                     "'end' without a matching 'subsection'. Remove it or "
                     "add the missing 'subsection' line.");
              path.pop_back();
              opened_at.pop_back();
              list.push_back({start_line, Keyword::end, path, ""});
            }
          else if (keyword == "set")
            {
              const auto equal = rest.find('=');
              if (equal == std::string::npos)
                fail(filename,
                     start_line,
                     "a 'set' line needs the form 'set Name = value'.");
              const std::string name = normalise_name(rest.substr(0, equal));
              list.push_back({start_line, Keyword::set, path, name});
              first_line.emplace(key(path, name), start_line);
            }
          else if (keyword == "include" || keyword == "INCLUDE")
            list.push_back({start_line, Keyword::include, path, trim(rest)});
          else
            fail(filename,
                 start_line,
                 "cannot read '" + statement
                   + "'. Lines start with 'subsection', 'set', 'end' or "
                     "'#'.");
        }
      if (!path.empty())
        fail(filename,
             opened_at.back(),
             "subsection '" + join_path(path)
               + "' is never closed: add an 'end' line.");
    }



    std::vector<std::string>
    InputOutline::labels(const std::vector<std::string> &path,
                         const std::string              &prefix) const
    {
      std::vector<std::string> found;
      for (const Statement &s : list)
        if (s.keyword == Keyword::subsection && s.path == path
            && s.name.size() > prefix.size() + 1
            && s.name.compare(0, prefix.size() + 1, prefix + " ") == 0)
          {
            const std::string label = s.name.substr(prefix.size() + 1);
            bool              known = false;
            for (const auto &l : found)
              known = known || l == label;
            if (!known)
              found.push_back(label);
          }
      return found;
    }



    std::string
    InputOutline::where(const std::vector<std::string> &path,
                        const std::string              &entry) const
    {
      auto it = first_line.end();
      if (!entry.empty())
        it = first_line.find(key(path, entry));
      if (it == first_line.end())
        it = first_line.find(key(path, ""));
      std::string place = file;
      if (it != first_line.end())
        place += ":" + std::to_string(it->second);
      place += ": subsection '" + join_path(path) + "'";
      if (!entry.empty())
        place += ", entry '" + entry + "'";
      return place;
    }
  } // namespace core
} // namespace particulate
