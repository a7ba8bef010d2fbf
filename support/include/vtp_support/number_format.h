// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_NUMBER_FORMAT_H
#define VTP_SUPPORT_NUMBER_FORMAT_H

// Fast text output of numbers: the shortest decimal text that reads back as exactly the same double
// (std::to_chars), "inf" / "-inf" for infinities and "nan" for NaN.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace vtp_support {

// Room needed by `format_double()`: the longest shortest round-trip text of a double is 24 characters
// ("-2.2250738585072014e-308").
constexpr std::size_t max_double_chars = 32;

// Writes `x` at `p` (at least `max_double_chars` characters of room) and returns the end of the text.
inline char* format_double(char* p, double x)
{
  if(std::isnan(x))
  {
    std::memcpy(p, "nan", 3);
    return p + 3;
  }
  if(std::isinf(x))
  {
    if(x < 0)
      *p++ = '-';
    std::memcpy(p, "inf", 3);
    return p + 3;
  }
  return std::to_chars(p, p + max_double_chars, x).ptr;
}

inline std::string double_to_string(double x)
{
  char buffer[max_double_chars];
  return std::string(buffer, format_double(buffer, x));
}

// One value per line.
inline void write_values_text(std::ostream& os, const std::vector<double>& values)
{
  const std::size_t chunk = 4096;
  std::vector<char> buffer(chunk * (max_double_chars + 1));
  for(std::size_t begin = 0; begin < values.size(); begin += chunk)
  {
    const std::size_t end = (std::min)(values.size(), begin + chunk);
    char* p = buffer.data();
    for(std::size_t i = begin; i < end; ++i)
    {
      p = format_double(p, values[i]);
      *p++ = '\n';
    }
    os.write(buffer.data(), p - buffer.data());
  }
}

} // namespace vtp_support

#endif // VTP_SUPPORT_NUMBER_FORMAT_H
