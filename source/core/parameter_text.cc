#include <particulate/core/parameter_text.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace particulate {
  namespace core {
    namespace {
      /** 1e-06 -> 1e-6, 2e+21 -> 2e21: the exponent as a person writes it. */
      std::string
      plain_exponent(std::string text)
      {
        const auto e = text.find('e');
        if (e == std::string::npos)
          return text;
        std::string mantissa = text.substr(0, e);
        std::string exponent = text.substr(e + 1);
        const bool  negative = exponent.front() == '-';
        exponent.erase(0, exponent.find_first_not_of("+-0"));
        return mantissa + "e" + (negative ? "-" : "") + exponent;
      }
    } // namespace



    std::string
    number_text(const double value)
    {
      if (value == std::floor(value) && std::abs(value) < 1e15)
        return std::to_string(static_cast<long long>(value));
      // the fewest significant digits that read back as the same double
      for (int digits = 1; digits <= 17; ++digits)
        {
          std::ostringstream text;
          text << std::setprecision(digits) << value;
          if (std::stod(text.str()) == value || digits == 17)
            return plain_exponent(text.str());
        }
      return {};
    }



    std::string
    flag_text(const bool value)
    {
      return value ? "true" : "false";
    }



    std::string
    list_text(const std::vector<unsigned int> &values)
    {
      std::string text;
      for (const unsigned int v : values)
        text += (text.empty() ? "" : ", ") + std::to_string(v);
      return text;
    }
  } // namespace core
} // namespace particulate
