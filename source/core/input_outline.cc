#include <particulate/core/input_outline.h>

#include <cstdio>
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

      /**
       * The position of the first byte of @p s that is no text: a control
       * character other than a tab or a carriage return, or a byte outside a
       * well-formed UTF-8 sequence; npos if there is none.
       */
      std::size_t
      first_byte_not_text(const std::string &s)
      {
        for (std::size_t i = 0; i < s.size();)
          {
            const auto   c      = static_cast<unsigned char>(s[i]);
            unsigned int length = c < 0x80                      ? 1 :
                                  (c >> 5) == 0x6 && c >= 0xc2  ? 2 :
                                  (c >> 4) == 0xe               ? 3 :
                                  (c >> 3) == 0x1e && c <= 0xf4 ? 4 :
                                                                  0;
            if (length == 0
                || (length == 1 && c < 0x20 && c != '\t' && c != '\r')
                || c == 0x7f || i + length > s.size())
              return i;
            for (unsigned int k = 1; k < length; ++k)
              if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2)
                return i;
            i += length;
          }
        return std::string::npos;
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
          if (const auto bad = first_byte_not_text(raw);
              bad != std::string::npos)
            {
              char code[8];
              std::snprintf(code,
                            sizeof(code),
                            "0x%02X",
                            static_cast<unsigned char>(raw[bad]));
              fail(filename,
                   line_number,
                   std::string("byte ") + code + " at column "
                     + std::to_string(bad + 1)
                     + " is not text (a control character or no UTF-8). "
                       "A case file is plain text: retype the line in an "
                       "editor.");
            }
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
