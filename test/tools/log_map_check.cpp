// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// vtp_geodesics_log_map_check: checks of the files of vtp_geodesics --log-map-output ("rho theta via" per vertex
// of the file), for the ctest tests of log_map_tests.cmake. Plain C++, no CGAL: the files are read back as a
// user's script would. Exit code 0 if the check passes; else 1 with one line on stderr saying what is wrong.
//
//   format LOG N [DIST]
//       N lines "rho theta via": rho >= 0 or inf; theta in [0, 2 pi) where rho is finite, "nan" where it is inf;
//       via an integer in [-1, N), -1 where rho is inf, and rho(via) < rho otherwise. With DIST (--output of the
//       same run), rho is the text of its line.
//   plane LOG MESH RX,RY S_0 S_1 ...
//       MESH: an OFF mesh in the plane z = 0 (a convex polygon); S_k: the sources of the run, "V" a vertex or
//       "X,Y" a point; RX,RY: the reference direction of the run. Every vertex has rho = its Euclidean distance to
//       the nearest source and theta = the angle of (vertex - source) minus that of (RX, RY), to 1e-12, via -1
//       (vertices within 1e-9 of two sources are skipped).
//   shift A B ANGLE
//       two runs with different reference directions: the same rho and via, theta of A = theta of B + ANGLE
//       (mod 2 pi, to 1e-12) at every reached vertex that is not a source.
//   strict DEFAULT STRICT
//       the same rho and via; theta equal (1e-9) where via is -1; in STRICT, theta(v) = theta(via(v)) (1e-9);
//       some vertex is behind another, and there the two differ somewhere.
//   limit FULL LIMITED R
//       LIMITED (with --max-distance R) has the lines of FULL where rho <= R and "inf nan -1" where rho > R
//       (either within 1e-12 of R); both occur.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Check_failure : std::runtime_error
{
  explicit Check_failure(const std::string& what) : std::runtime_error(what) {}
};

const double infinity = std::numeric_limits<double>::infinity();
const double two_pi = 6.283185307179586476925286766559;

double number(const std::string& text, const std::string& where)
{
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size())
    throw Check_failure(where + ": '" + text + "' is not a number");
  return x;
}

std::vector<std::string> read_lines(const std::string& file)
{
  std::ifstream in(file);
  if(!in)
    throw Check_failure("cannot open " + file);
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

struct Log_line
{
  std::string rho_text;
  double rho = 0., theta = 0.;
  long long via = -1;
};

std::vector<Log_line> read_log(const std::string& file)
{
  std::vector<Log_line> r;
  const std::vector<std::string> lines = read_lines(file);
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    const std::string where = file + " line " + std::to_string(i);
    std::istringstream is(lines[i]);
    std::string a, b, c, extra;
    if(!(is >> a >> b >> c) || (is >> extra))
      throw Check_failure(where + ": expected three fields 'rho theta via', got '" + lines[i] + "'");
    Log_line l;
    l.rho_text = a;
    l.rho = number(a, where);
    l.theta = number(b, where);
    const double via = number(c, where);
    if(via != std::floor(via) || c.find_first_of(".eE") != std::string::npos)
      throw Check_failure(where + ": via '" + c + "' is not an integer");
    l.via = static_cast<long long>(via);
    r.push_back(l);
  }
  return r;
}

// a - b in (-pi, pi]
double angle_difference(double a, double b)
{
  double d = std::fmod(a - b, two_pi);
  if(d > two_pi / 2.)
    d -= two_pi;
  if(d <= -two_pi / 2.)
    d += two_pi;
  return d;
}

void check_format(const std::string& file, std::size_t n, const std::string& dist_file)
{
  const std::vector<Log_line> log = read_log(file);
  if(log.size() != n)
    throw Check_failure(file + " has " + std::to_string(log.size()) + " lines, expected " + std::to_string(n));
  std::vector<std::string> dist;
  if(!dist_file.empty())
    dist = read_lines(dist_file);
  if(!dist_file.empty() && dist.size() != n)
    throw Check_failure(dist_file + " has " + std::to_string(dist.size()) + " lines, expected " + std::to_string(n));
  for(std::size_t i = 0; i < n; ++i)
  {
    const Log_line& l = log[i];
    const std::string where = file + " line " + std::to_string(i);
    if(!(l.rho >= 0.))
      throw Check_failure(where + ": rho is not >= 0");
    if(l.rho < infinity && !(l.theta >= 0. && l.theta < two_pi))
      throw Check_failure(where + ": theta is not in [0, 2 pi)");
    if(l.rho == infinity && (!std::isnan(l.theta) || l.via != -1))
      throw Check_failure(where + ": an unreached vertex must be 'inf nan -1'");
    if(l.via < -1 || l.via >= static_cast<long long>(n))
      throw Check_failure(where + ": via out of range");
    if(l.via >= 0 && !(log[static_cast<std::size_t>(l.via)].rho < l.rho))
      throw Check_failure(where + ": via vertex " + std::to_string(l.via) + " is not nearer to the source");
    if(!dist.empty() && dist[i] != l.rho_text)
      throw Check_failure(where + ": rho '" + l.rho_text + "' is not the distance '" + dist[i] + "' of " + dist_file);
  }
}

std::vector<std::array<double, 2> > read_plane_off(const std::string& file)
{
  std::ifstream in(file);
  std::string word;
  if(!(in >> word) || word != "OFF")
    throw Check_failure(file + " is not an OFF file");
  std::string line;
  std::getline(in, line);
  while(in.peek() == '#' && std::getline(in, line))
  {
  }
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!(in >> nv >> nf >> ne))
    throw Check_failure(file + ": bad OFF header");
  std::vector<std::array<double, 2> > points(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    double z = 0.;
    if(!(in >> points[i][0] >> points[i][1] >> z) || z != 0.)
      throw Check_failure(file + ": vertex " + std::to_string(i) + " is not a point of z = 0");
  }
  return points;
}

void check_plane(const std::string& file, const std::string& mesh, const std::string& reference,
                 const std::vector<std::string>& sources)
{
  const std::vector<Log_line> log = read_log(file);
  const std::vector<std::array<double, 2> > p = read_plane_off(mesh);
  if(log.size() != p.size())
    throw Check_failure(file + " does not have one line per vertex of " + mesh);
  const std::size_t comma = reference.find(',');
  const double ref = std::atan2(number(reference.substr(comma + 1), "RY"), number(reference.substr(0, comma), "RX"));
  std::vector<std::array<double, 2> > s;
  for(const std::string& t : sources)
  {
    const std::size_t c = t.find(',');
    if(c == std::string::npos)
      s.push_back(p.at(static_cast<std::size_t>(number(t, "source"))));
    else
      s.push_back({ { number(t.substr(0, c), "source"), number(t.substr(c + 1), "source") } });
  }
  std::size_t checked = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    double best = infinity, second = infinity;
    std::size_t k = 0;
    for(std::size_t j = 0; j < s.size(); ++j)
    {
      const double d = std::hypot(p[i][0] - s[j][0], p[i][1] - s[j][1]);
      if(d < best)
      {
        second = best;
        best = d;
        k = j;
      }
      else
        second = std::min(second, d);
    }
    if(second - best < 1e-9)
      continue;
    const std::string where = file + " line " + std::to_string(i);
    const Log_line& l = log[i];
    if(!(std::abs(l.rho - best) <= 1e-12))
      throw Check_failure(where + ": rho " + l.rho_text + " is not the Euclidean distance " + std::to_string(best));
    if(l.via != -1)
      throw Check_failure(where + ": via is not -1 on a convex plane");
    if(best > 1e-9)
    {
      const double expected = std::atan2(p[i][1] - s[k][1], p[i][0] - s[k][0]) - ref;
      if(!(std::abs(angle_difference(l.theta, expected)) <= 1e-12))
        throw Check_failure(where + ": theta " + std::to_string(l.theta) + " is not the Euclidean angle "
                            + std::to_string(expected) + " (mod 2 pi)");
    }
    ++checked;
  }
  if(checked < p.size() / 2)
    throw Check_failure(file + ": too few vertices checked");
}

void check_shift(const std::string& a_file, const std::string& b_file, double angle)
{
  const std::vector<Log_line> a = read_log(a_file), b = read_log(b_file);
  if(a.size() != b.size())
    throw Check_failure(a_file + " and " + b_file + " do not have the same number of lines");
  std::size_t checked = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    const std::string where = a_file + " line " + std::to_string(i);
    if(a[i].rho_text != b[i].rho_text || a[i].via != b[i].via)
      throw Check_failure(where + ": rho or via differ from " + b_file);
    if(a[i].rho > 0. && a[i].rho < infinity)
    {
      if(!(std::abs(angle_difference(a[i].theta, b[i].theta + angle)) <= 1e-12))
        throw Check_failure(where + ": theta " + std::to_string(a[i].theta) + " is not " + std::to_string(b[i].theta)
                            + " + " + std::to_string(angle));
      ++checked;
    }
  }
  if(checked == 0)
    throw Check_failure(a_file + ": no vertex reached");
}

void check_strict(const std::string& default_file, const std::string& strict_file)
{
  const std::vector<Log_line> d = read_log(default_file), s = read_log(strict_file);
  if(d.size() != s.size())
    throw Check_failure(default_file + " and " + strict_file + " do not have the same number of lines");
  std::size_t behind = 0, differ = 0;
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    const std::string where = strict_file + " line " + std::to_string(i);
    if(d[i].rho_text != s[i].rho_text || d[i].via != s[i].via)
      throw Check_failure(where + ": rho or via differ from " + default_file);
    if(!(d[i].rho < infinity))
      continue;
    if(s[i].via < 0)
    {
      if(!(std::abs(angle_difference(d[i].theta, s[i].theta)) <= 1e-9))
        throw Check_failure(where + ": theta differs from the default's, and the geodesic passes through no vertex");
      continue;
    }
    ++behind;
    const double t = s[static_cast<std::size_t>(s[i].via)].theta;
    if(!(std::abs(angle_difference(s[i].theta, t)) <= 1e-9))
      throw Check_failure(where + ": strict theta is not the theta of its via vertex " + std::to_string(s[i].via));
    differ += std::abs(angle_difference(d[i].theta, s[i].theta)) > 1e-6;
  }
  if(behind == 0 || differ == 0)
    throw Check_failure(strict_file + ": no vertex behind another (or the default equals the strict everywhere)");
}

void check_limit(const std::string& full_file, const std::string& limited_file, double r)
{
  const std::vector<Log_line> f = read_log(full_file), l = read_log(limited_file);
  const std::vector<std::string> fl = read_lines(full_file), ll = read_lines(limited_file);
  if(f.size() != l.size())
    throw Check_failure(full_file + " and " + limited_file + " do not have the same number of lines");
  std::size_t inside = 0, outside = 0;
  for(std::size_t i = 0; i < f.size(); ++i)
  {
    const std::string where = limited_file + " line " + std::to_string(i);
    if(std::abs(f[i].rho - r) <= 1e-12 * (1. + r))
      continue;
    if(f[i].rho <= r)
    {
      if(fl[i] != ll[i])
        throw Check_failure(where + ": '" + ll[i] + "' is not the full run's '" + fl[i] + "'");
      ++inside;
    }
    else
    {
      if(ll[i] != "inf nan -1")
        throw Check_failure(where + ": '" + ll[i] + "' beyond the limit, expected 'inf nan -1'");
      ++outside;
    }
  }
  if(inside == 0 || outside == 0)
    throw Check_failure(limited_file + ": the limit does not split the vertices");
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::vector<std::string> a(argv + 1, argv + argc);
    if(a.size() >= 3 && a[0] == "format")
      check_format(a[1], static_cast<std::size_t>(number(a[2], "N")), a.size() > 3 ? a[3] : std::string());
    else if(a.size() >= 5 && a[0] == "plane")
      check_plane(a[1], a[2], a[3], std::vector<std::string>(a.begin() + 4, a.end()));
    else if(a.size() == 4 && a[0] == "shift")
      check_shift(a[1], a[2], number(a[3], "ANGLE"));
    else if(a.size() == 3 && a[0] == "strict")
      check_strict(a[1], a[2]);
    else if(a.size() == 4 && a[0] == "limit")
      check_limit(a[1], a[2], number(a[3], "R"));
    else
      throw Check_failure("usage: vtp_geodesics_log_map_check format|plane|shift|strict|limit ... (see the source)");
  }
  catch(const std::exception& e)
  {
    std::cerr << "vtp_geodesics_log_map_check: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
