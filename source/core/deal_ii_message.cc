#include <particulate/core/deal_ii_message.h>

#include <sstream>

namespace particulate {
  namespace core {
    std::string
    one_line_explanation(const dealii::ExceptionBase &exception)
    {
      std::ostringstream info;
      exception.print_info(info);
      std::istringstream words(info.str());
      std::string        text, word;
      while (words >> word)
        text += (text.empty() ? "" : " ") + word;
      return text;
    }
  } // namespace core
} // namespace particulate
