// The tests' check: reports a failed condition and counts it; a test
// returns EXIT_FAILURE when Failures() is not zero. Header only; not part of
// the library.
#ifndef TyndallTestCheck_h
#define TyndallTestCheck_h

#include <iostream>
#include <string>

namespace tyndall_test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << std::endl;
    ++Failures();
  }
}
}

#endif
