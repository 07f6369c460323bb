// Small helpers shared by the rigid tests: a checking macro that prints what
// failed and where, and a relative-difference helper.
#ifndef particulate_tests_rigid_test_tools_h
#define particulate_tests_rigid_test_tools_h

#include <cmath>
#include <cstdlib>
#include <iostream>

#define CHECK(cond, msg)                                                \
  do                                                                    \
    {                                                                   \
      if (!(cond))                                                      \
        {                                                               \
          std::cerr << "FAILED " << __FILE__ << ":" << __LINE__ << ": " \
                    << #cond << "\n  " << msg << std::endl;             \
          std::exit(1);                                                 \
        }                                                               \
  } while (false)

inline double
rel_diff(const double a, const double b)
{
  const double s = std::max(std::abs(a), std::abs(b));
  return s > 0. ? std::abs(a - b) / s : 0.;
}

#endif
