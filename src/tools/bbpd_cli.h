// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   Command-line helpers shared by the BBPD tools: a fatal error that names the
   tool, and strict number parsing for option values.
------------------------------------------------------------------------- */

#ifndef BBPD_CLI_H
#define BBPD_CLI_H

#include <cstdlib>
#include <iostream>
#include <string>

namespace BBPD::cli {

// set by each tool's main() before parsing
inline const char *program = "bbpd";

[[noreturn]] inline void fail(const std::string &msg)
{
  std::cerr << program << ": " << msg << "\n";
  std::exit(1);
}

// the whole of text as a number, or a fatal error naming the option
inline double to_double(const std::string &flag, const char *text)
{
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') fail("bad number '" + std::string(text) + "' for " + flag);
  return v;
}

}    // namespace BBPD::cli

#endif
