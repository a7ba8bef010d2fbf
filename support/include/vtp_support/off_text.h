// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_OFF_TEXT_H
#define VTP_SUPPORT_OFF_TEXT_H

// The pieces of text of an OFF file as the fast OFF reader (fast_off_reader.h) reads them, each on a line of
// the file in memory, [p, end): blanks, comments, lines with content, numbers (std::from_chars).

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace vtp_support {

namespace fast_off_detail {
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Skips blanks on the current line (not the newline).
inline void skip_blanks(const char*& p, const char* end)
{
  while(p != end && is_blank(*p))
    ++p;
}

// True if only blanks and an optional comment are left on the line; moves past its newline.
inline bool end_of_line(const char*& p, const char* end)
{
  skip_blanks(p, end);
  if(p != end && *p == '#')
    while(p != end && *p != '\n')
      ++p;
  if(p == end)
    return true;
  if(*p != '\n')
    return false;
  ++p;
  return true;
}

// Moves to the start of the next line with content (skipping empty lines and comment lines), or to `end`.
inline void next_content_line(const char*& p, const char* end)
{
  while(p != end)
  {
    skip_blanks(p, end);
    if(p == end || (*p != '\n' && *p != '#'))
      return;
    while(p != end && *p != '\n')
      ++p;
    if(p != end)
      ++p;
  }
}

// The start of the line after the one `p` is in (or `end`).
inline const char* next_line(const char* p, const char* end)
{
  const void* n = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
  return n == nullptr ? end : static_cast<const char*>(n) + 1;
}

// True if the line starting at `p` has content (not blank, not a comment); `p` then points to it.
inline bool content_at(const char*& p, const char* end)
{
  skip_blanks(p, end);
  return p != end && *p != '\n' && *p != '#';
}

enum Number_status { NUMBER_OK, NUMBER_MISSING, NUMBER_OUT_OF_RANGE };

inline Number_status parse_double(const char*& p, const char* end, double& x)
{
  skip_blanks(p, end);
  if(p == end || *p == '\n' || *p == '#' || *p == '+')
    return NUMBER_MISSING;
  const std::from_chars_result r = std::from_chars(p, end, x);
  if(r.ec == std::errc::result_out_of_range)
  {
    // overflow (a non-finite value) or underflow (a tiny value, kept as strtod rounds it)
    const std::string token(p, r.ptr);
    x = std::strtod(token.c_str(), nullptr);
    p = r.ptr;
    return std::isinf(x) ? NUMBER_OUT_OF_RANGE : NUMBER_OK;
  }
  if(r.ec != std::errc() || (r.ptr != end && !is_blank(*r.ptr) && *r.ptr != '\n' && *r.ptr != '#'))
    return NUMBER_MISSING;
  p = r.ptr;
  return NUMBER_OK;
}

inline bool parse_index(const char*& p, const char* end, std::uint64_t& i)
{
  skip_blanks(p, end);
  if(p == end || *p < '0' || *p > '9')
    return false;
  const std::from_chars_result r = std::from_chars(p, end, i);
  if(r.ec != std::errc() || (r.ptr != end && !is_blank(*r.ptr) && *r.ptr != '\n' && *r.ptr != '#'))
    return false;
  p = r.ptr;
  return true;
}

} // namespace fast_off_detail

} // namespace vtp_support

#endif // VTP_SUPPORT_OFF_TEXT_H
