// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// vtp_geodesics_cli_check: checks of the content of files written by vtp_geodesics, for the ctest tests of
// cli_tests.cmake (CMake scripts cannot compute). Plain C++, no CGAL: it reads the text files back as a user's
// script would. Exit code 0 if the check passes; else 1 with one line on stderr saying what is wrong.
//
//   nearest DIST LABELS D_0 ... D_k-1
//       DIST, LABELS: a run from sources 0..k-1; D_j: a run from source j alone. DIST is the pointwise minimum of
//       the D_j (to 1e-12 of the largest distance), LABELS[i] is -1 exactly where DIST[i] is inf, and else a
//       source j with D_j[i] = DIST[i] (same tolerance). Every source must label some vertex.
//   limit FULL LIMITED R
//       LIMITED (a run with --max-distance R) equals FULL (the same run without it) where FULL <= R, and is inf
//       where FULL > R (either is accepted within 1e-12 of R); both cases must occur.
//   values A I_0,I_1,... B J_0,J_1,... TOLERANCE
//       line I_k of A and line J_k of B hold the same value: the same text if TOLERANCE is 0, else numbers
//       within TOLERANCE times the largest finite value of B (inf only with inf). The list "all": every line.
//   paths POLYLINES DISTANCES I_0,I_1,... [OBJ]
//       POLYLINES: CGAL's polylines text, one path per line; line I_k of DISTANCES ("all": line k): the distance
//       of path k. Each path's length equals its distance to 1e-12 relative, and a path at distance 0 is one
//       point; with OBJ, that file (v and l lines) holds the same paths, point for point.
//   samples SAMPLES DIST LABELS K FIRST [RADIUS]
//       SAMPLES (--samples-output of --farthest-points K, with --output DIST and --labels LABELS): a '#' header,
//       then "V R" lines; K of them (with RADIUS: up to K, the last radius <= RADIUS and the one before above it),
//       the first one FIRST ("-": any), distinct vertices, radii non-increasing, the last one the largest of DIST;
//       each sample at distance 0 and labelled with its own number; every label in range, -1 exactly where DIST
//       is inf; every sample labels some vertex.
//   plane_query OUTPUT POINTS [limit=R] X_0,Y_0 X_1,Y_1 ...
//       OUTPUT (--query-output of a run on the unit square [0,1]^2 of the plane z = 0, from sources at (X_k, Y_k),
//       labelled k, with --max-distance R if given) has one line "distance label" per line "X Y Z" of POINTS: the
//       point of the square nearest to (X, Y, Z) is (clamp(X), clamp(Y)); its distance is the Euclidean distance
//       to the nearest source, within 1e-9, and the label that source's (either where two are within 1e-6);
//       beyond R, "inf -1" (either within 1e-9 of R). Every source must label some point; with a limit, some
//       point must be beyond it.

#include <algorithm>
#include <array>
#include <cerrno>
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

std::vector<std::string> read_lines(const std::string& file)
{
  std::ifstream in(file);
  if(!in)
    throw Check_failure("cannot open " + file);
  std::vector<std::string> lines;
  std::string line;
  while(std::getline(in, line))
    lines.push_back(line);
  return lines;
}

double to_number(const std::string& text, const std::string& where)
{
  if(text == "inf")
    return infinity;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if(text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(x))
    throw Check_failure(where + ": '" + text + "' is not a number");
  return x;
}

std::vector<double> read_numbers(const std::string& file)
{
  const std::vector<std::string> lines = read_lines(file);
  std::vector<double> r;
  for(std::size_t i = 0; i < lines.size(); ++i)
    r.push_back(to_number(lines[i], file + " line " + std::to_string(i)));
  return r;
}

std::vector<long> read_integers(const std::string& file)
{
  const std::vector<std::string> lines = read_lines(file);
  std::vector<long> r;
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    char* end = nullptr;
    const long x = std::strtol(lines[i].c_str(), &end, 10);
    if(lines[i].empty() || end != lines[i].c_str() + lines[i].size())
      throw Check_failure(file + " line " + std::to_string(i) + ": '" + lines[i] + "' is not an integer");
    r.push_back(x);
  }
  return r;
}

double max_finite(const std::vector<double>& v)
{
  double m = 0.;
  for(double x : v)
    if(std::isfinite(x))
      m = std::max(m, std::abs(x));
  return m;
}

std::vector<std::size_t> index_list(const std::string& s)
{
  std::vector<std::size_t> r;
  if(s == "all")
    return r;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    r.push_back(static_cast<std::size_t>(std::stoul(item)));
  return r;
}

void same_size(std::size_t a, std::size_t b, const std::string& what)
{
  if(a != b)
    throw Check_failure(what + ": " + std::to_string(a) + " lines against " + std::to_string(b));
}

std::string text(double x)
{
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

void check_nearest(const std::vector<std::string>& args)
{
  if(args.size() < 3)
    throw Check_failure("nearest: expected DIST LABELS D_0 ...");
  const std::vector<double> d = read_numbers(args[0]);
  const std::vector<long> labels = read_integers(args[1]);
  same_size(labels.size(), d.size(), args[1]);
  std::vector<std::vector<double> > single;
  for(std::size_t j = 2; j < args.size(); ++j)
  {
    single.push_back(read_numbers(args[j]));
    same_size(single.back().size(), d.size(), args[j]);
  }
  const double tolerance = 1e-12 * max_finite(d);
  std::vector<std::size_t> count(single.size(), 0);
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    double m = infinity;
    for(const std::vector<double>& s : single)
      m = std::min(m, s[i]);
    const std::string at = "vertex " + std::to_string(i);
    if(std::isinf(m) != std::isinf(d[i]) || (std::isfinite(m) && !(std::abs(m - d[i]) <= tolerance)))
      throw Check_failure(at + ": distance " + text(d[i]) + ", but the minimum of the single-source runs is " + text(m));
    if(std::isinf(d[i]))
    {
      if(labels[i] != -1)
        throw Check_failure(at + ": unreachable, but labelled " + std::to_string(labels[i]));
      continue;
    }
    if(labels[i] < 0 || static_cast<std::size_t>(labels[i]) >= single.size())
      throw Check_failure(at + ": label " + std::to_string(labels[i]) + " is not a source");
    const double by_label = single[static_cast<std::size_t>(labels[i])][i];
    if(!(std::abs(by_label - d[i]) <= tolerance))
      throw Check_failure(at + ": labelled " + std::to_string(labels[i]) + ", at distance " + text(by_label)
                          + " from it, but at " + text(d[i]) + " from the nearest source");
    ++count[static_cast<std::size_t>(labels[i])];
  }
  for(std::size_t j = 0; j < count.size(); ++j)
    if(count[j] == 0)
      throw Check_failure("source " + std::to_string(j) + " labels no vertex");
}

void check_limit(const std::vector<std::string>& args)
{
  if(args.size() != 3)
    throw Check_failure("limit: expected FULL LIMITED R");
  const std::vector<double> full = read_numbers(args[0]);
  const std::vector<double> limited = read_numbers(args[1]);
  same_size(limited.size(), full.size(), args[1]);
  const double r = to_number(args[2], "R");
  const double tolerance = 1e-12 * max_finite(full);
  std::size_t inside = 0, outside = 0;
  for(std::size_t i = 0; i < full.size(); ++i)
  {
    const std::string at = "vertex " + std::to_string(i);
    if(std::abs(full[i] - r) <= tolerance && (std::isinf(limited[i]) || limited[i] == full[i]))
      continue;
    if(full[i] <= r)
    {
      ++inside;
      if(!(std::abs(limited[i] - full[i]) <= tolerance))
        throw Check_failure(at + ": " + text(limited[i]) + " with the limit, " + text(full[i]) + " without");
    }
    else
    {
      ++outside;
      if(!std::isinf(limited[i]))
        throw Check_failure(at + ": beyond the limit (" + text(full[i]) + "), but " + text(limited[i]) + " with it");
    }
  }
  if(inside == 0 || outside == 0)
    throw Check_failure("the limit leaves " + std::to_string(inside) + " vertices inside and " + std::to_string(outside)
                        + " outside: not a test");
}

void check_values(const std::vector<std::string>& args)
{
  if(args.size() != 5)
    throw Check_failure("values: expected A I_0,... B J_0,... TOLERANCE");
  const std::vector<std::string> a = read_lines(args[0]), b = read_lines(args[2]);
  std::vector<std::size_t> ia = index_list(args[1]), ib = index_list(args[3]);
  if(ia.empty())
    for(std::size_t i = 0; i < a.size(); ++i)
      ia.push_back(i);
  if(ib.empty())
    for(std::size_t i = 0; i < b.size(); ++i)
      ib.push_back(i);
  same_size(ia.size(), ib.size(), "the line lists");
  const double tolerance = to_number(args[4], "TOLERANCE");
  std::vector<double> bn;
  if(tolerance > 0.)
    bn = read_numbers(args[2]);
  const double scale = tolerance > 0. ? max_finite(bn) : 0.;
  for(std::size_t k = 0; k < ia.size(); ++k)
  {
    if(ia[k] >= a.size() || ib[k] >= b.size())
      throw Check_failure("line " + std::to_string(ia[k]) + " or " + std::to_string(ib[k]) + " does not exist");
    const std::string& x = a[ia[k]];
    const std::string& y = b[ib[k]];
    const std::string at = args[0] + " line " + std::to_string(ia[k]) + " ('" + x + "') and " + args[2] + " line "
                           + std::to_string(ib[k]) + " ('" + y + "')";
    if(tolerance == 0.)
    {
      if(x != y)
        throw Check_failure(at + " differ");
      continue;
    }
    const double u = to_number(x, at), v = to_number(y, at);
    if(std::isinf(u) != std::isinf(v) || (std::isfinite(u) && !(std::abs(u - v) <= tolerance * scale)))
      throw Check_failure(at + " differ by more than " + text(tolerance) + " times " + text(scale));
  }
}

typedef std::vector<std::vector<double> > Path; // points (x, y, z)

std::vector<double> numbers_of_line(const std::string& line, const std::string& where)
{
  std::istringstream in(line);
  std::vector<double> r;
  std::string word;
  while(in >> word)
    r.push_back(to_number(word, where));
  return r;
}

std::vector<Path> read_polylines(const std::string& file)
{
  const std::vector<std::string> lines = read_lines(file);
  std::vector<Path> paths;
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    const std::string where = file + " line " + std::to_string(i);
    const std::vector<double> x = numbers_of_line(lines[i], where);
    if(x.empty() || x[0] < 1. || x[0] != std::floor(x[0]) || x.size() != 1 + 3 * static_cast<std::size_t>(x[0]))
      throw Check_failure(where + ": not 'N x1 y1 z1 ... xN yN zN'");
    Path p;
    for(std::size_t k = 0; k < static_cast<std::size_t>(x[0]); ++k)
      p.push_back({ x[1 + 3 * k], x[2 + 3 * k], x[3 + 3 * k] });
    paths.push_back(p);
  }
  return paths;
}

std::vector<Path> read_obj_lines(const std::string& file)
{
  const std::vector<std::string> lines = read_lines(file);
  std::vector<std::vector<double> > vertices;
  std::vector<Path> paths;
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    const std::string where = file + " line " + std::to_string(i);
    std::istringstream in(lines[i]);
    std::string keyword;
    if(!(in >> keyword) || keyword[0] == '#')
      continue;
    std::string rest;
    std::getline(in, rest);
    const std::vector<double> x = numbers_of_line(rest, where);
    if(keyword == "v")
    {
      if(x.size() != 3)
        throw Check_failure(where + ": a 'v' line without three coordinates");
      vertices.push_back(x);
    }
    else if(keyword == "l")
    {
      if(x.size() < 2)
        throw Check_failure(where + ": an 'l' line with fewer than two vertices");
      Path p;
      for(double k : x)
      {
        if(k != std::floor(k) || k < 1. || k > static_cast<double>(vertices.size()))
          throw Check_failure(where + ": vertex " + text(k) + " does not exist");
        p.push_back(vertices[static_cast<std::size_t>(k) - 1]);
      }
      if(p.size() == 2 && x[0] == x[1]) // a path of one point
        p.pop_back();
      paths.push_back(p);
    }
    else
      throw Check_failure(where + ": unexpected '" + keyword + "'");
  }
  return paths;
}

void check_paths(const std::vector<std::string>& args)
{
  if(args.size() != 3 && args.size() != 4)
    throw Check_failure("paths: expected POLYLINES DISTANCES I_0,... [OBJ]");
  const std::vector<Path> paths = read_polylines(args[0]);
  const std::vector<double> all_distances = read_numbers(args[1]);
  std::vector<std::size_t> lines = index_list(args[2]);
  if(lines.empty())
    for(std::size_t i = 0; i < all_distances.size(); ++i)
      lines.push_back(i);
  std::vector<double> distances;
  for(std::size_t i : lines)
  {
    if(i >= all_distances.size())
      throw Check_failure(args[1] + " has no line " + std::to_string(i));
    distances.push_back(all_distances[i]);
  }
  same_size(paths.size(), distances.size(), args[0] + " (paths) and the distances");
  if(paths.empty())
    throw Check_failure("no path: not a test");
  for(std::size_t k = 0; k < paths.size(); ++k)
  {
    double length = 0.;
    for(std::size_t i = 0; i + 1 < paths[k].size(); ++i)
    {
      const double dx = paths[k][i + 1][0] - paths[k][i][0], dy = paths[k][i + 1][1] - paths[k][i][1],
                   dz = paths[k][i + 1][2] - paths[k][i][2];
      length += std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    if(!std::isfinite(distances[k]) || !(std::abs(length - distances[k]) <= 1e-12 * distances[k]))
      throw Check_failure("path " + std::to_string(k) + " (" + std::to_string(paths[k].size()) + " points) has length "
                          + text(length) + ", its distance is " + text(distances[k]));
    if((distances[k] == 0.) != (paths[k].size() == 1))
      throw Check_failure("path " + std::to_string(k) + " has " + std::to_string(paths[k].size())
                          + " points at distance " + text(distances[k]) + " (one point exactly at distance 0)");
  }
  if(args.size() == 4)
  {
    const std::vector<Path> obj = read_obj_lines(args[3]);
    if(obj != paths)
      throw Check_failure(args[3] + " does not hold the paths of " + args[0]);
  }
}

void check_samples(const std::vector<std::string>& args)
{
  if(args.size() != 5 && args.size() != 6)
    throw Check_failure("samples: expected SAMPLES DIST LABELS K FIRST [RADIUS]");
  std::vector<std::string> lines = read_lines(args[0]);
  if(lines.empty() || lines[0].empty() || lines[0][0] != '#')
    throw Check_failure(args[0] + ": no '#' header line");
  lines.erase(lines.begin());
  const std::vector<double> d = read_numbers(args[1]);
  const std::vector<long> labels = read_integers(args[2]);
  same_size(d.size(), labels.size(), args[1] + " and " + args[2]);
  const std::size_t k = static_cast<std::size_t>(std::stoul(args[3]));
  std::vector<std::size_t> samples;
  std::vector<double> radii;
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    std::istringstream in(lines[i]);
    std::string v, r, rest;
    if(!(in >> v >> r) || (in >> rest))
      throw Check_failure(args[0] + " line " + std::to_string(i + 1) + ": '" + lines[i] + "' is not 'V R'");
    samples.push_back(static_cast<std::size_t>(std::stoul(v)));
    radii.push_back(to_number(r, args[0] + " line " + std::to_string(i + 1)));
    if(samples.back() >= d.size())
      throw Check_failure("sample " + v + " is not a vertex");
  }
  if(args.size() == 6)
  {
    const double radius = to_number(args[5], "RADIUS");
    if(samples.empty() || samples.size() > k || !(radii.back() <= radius)
       || (samples.size() > 1 && !(radii[radii.size() - 2] > radius)))
      throw Check_failure(std::to_string(samples.size()) + " samples do not stop at the first radius <= " + args[5]);
  }
  else if(samples.size() != k)
    throw Check_failure(std::to_string(samples.size()) + " samples, expected " + args[3]);
  if(args[4] != "-" && samples[0] != static_cast<std::size_t>(std::stoul(args[4])))
    throw Check_failure("the first sample is " + std::to_string(samples[0]) + ", expected " + args[4]);
  double largest = 0.;
  for(double x : d)
    largest = std::max(largest, x);
  if(!(radii.back() == largest || std::abs(radii.back() - largest) <= 1e-12 * largest))
    throw Check_failure("the last radius " + text(radii.back()) + " is not the largest distance " + text(largest));
  std::vector<std::size_t> cell_size(samples.size(), 0);
  for(std::size_t i = 0; i < samples.size(); ++i)
  {
    if(i > 0 && !(radii[i] <= radii[i - 1]))
      throw Check_failure("radius " + std::to_string(i) + " (" + text(radii[i]) + ") is above the one before");
    for(std::size_t j = 0; j < i; ++j)
      if(samples[j] == samples[i])
        throw Check_failure("vertex " + std::to_string(samples[i]) + " is sampled twice");
    if(d[samples[i]] != 0. || labels[samples[i]] != static_cast<long>(i))
      throw Check_failure("sample " + std::to_string(i) + " (vertex " + std::to_string(samples[i]) + ") is at distance "
                          + text(d[samples[i]]) + " with label " + std::to_string(labels[samples[i]]));
  }
  for(std::size_t v = 0; v < d.size(); ++v)
  {
    if((labels[v] == -1) != std::isinf(d[v]) || labels[v] < -1 || labels[v] >= static_cast<long>(samples.size()))
      throw Check_failure("vertex " + std::to_string(v) + ": label " + std::to_string(labels[v]) + " at distance "
                          + text(d[v]));
    if(labels[v] >= 0)
      ++cell_size[static_cast<std::size_t>(labels[v])];
  }
  for(std::size_t i = 0; i < samples.size(); ++i)
    if(cell_size[i] == 0)
      throw Check_failure("sample " + std::to_string(i) + " labels no vertex");
}

void check_plane_query(const std::vector<std::string>& args)
{
  if(args.size() < 3)
    throw Check_failure("plane_query: expected OUTPUT POINTS [limit=R] X_0,Y_0 ...");
  const std::vector<std::string> out = read_lines(args[0]);
  const std::vector<std::string> points = read_lines(args[1]);
  same_size(out.size(), points.size(), args[0] + " and " + args[1]);
  std::size_t first_source = 2;
  double limit = infinity;
  if(args[2].compare(0, 6, "limit=") == 0)
  {
    limit = to_number(args[2].substr(6), "R");
    ++first_source;
  }
  std::vector<std::array<double, 2> > sources;
  for(std::size_t k = first_source; k < args.size(); ++k)
  {
    const std::size_t comma = args[k].find(',');
    if(comma == std::string::npos)
      throw Check_failure("source '" + args[k] + "' is not X,Y");
    sources.push_back({ { to_number(args[k].substr(0, comma), "X"), to_number(args[k].substr(comma + 1), "Y") } });
  }
  if(sources.empty())
    throw Check_failure("plane_query: no source");
  std::vector<std::size_t> count(sources.size(), 0);
  std::size_t beyond = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const std::string at = args[0] + " line " + std::to_string(i + 1) + " ('" + out[i] + "')";
    const std::vector<double> p = numbers_of_line(points[i], args[1] + " line " + std::to_string(i + 1));
    if(p.size() != 3)
      throw Check_failure(args[1] + " line " + std::to_string(i + 1) + ": not 'X Y Z'");
    const double x = std::min(1., std::max(0., p[0])), y = std::min(1., std::max(0., p[1]));
    std::vector<double> d;
    for(const std::array<double, 2>& s : sources)
      d.push_back(std::hypot(x - s[0], y - s[1]));
    const std::size_t nearest = static_cast<std::size_t>(std::min_element(d.begin(), d.end()) - d.begin());
    std::istringstream in(out[i]);
    std::string distance_text, rest;
    long label = 0;
    if(!(in >> distance_text >> label) || (in >> rest))
      throw Check_failure(at + ": not 'distance label'");
    const double distance = to_number(distance_text, at);
    if(std::abs(d[nearest] - limit) <= 1e-9)
      continue;
    if(d[nearest] > limit)
    {
      ++beyond;
      if(!std::isinf(distance) || label != -1)
        throw Check_failure(at + ": beyond the limit (" + text(d[nearest]) + "), expected 'inf -1'");
      continue;
    }
    if(!(std::abs(distance - d[nearest]) <= 1e-9))
      throw Check_failure(at + ": the distance of (" + text(x) + ", " + text(y) + ") is " + text(d[nearest]));
    if(label < 0 || static_cast<std::size_t>(label) >= sources.size()
       || !(d[static_cast<std::size_t>(label)] <= d[nearest] + 1e-6))
      throw Check_failure(at + ": the nearest source of (" + text(x) + ", " + text(y) + ") is "
                          + std::to_string(nearest));
    ++count[static_cast<std::size_t>(label)];
  }
  for(std::size_t k = 0; k < count.size(); ++k)
    if(count[k] == 0)
      throw Check_failure("source " + std::to_string(k) + " labels no point: not a test");
  if(limit < infinity && beyond == 0)
    throw Check_failure("no point beyond the limit: not a test");
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: vtp_geodesics_cli_check nearest|limit|values|paths|samples|plane_query ARGUMENTS... (see cli_check.cpp)\n";
    return 2;
  }
  const std::string mode = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try
  {
    if(mode == "nearest")
      check_nearest(args);
    else if(mode == "limit")
      check_limit(args);
    else if(mode == "values")
      check_values(args);
    else if(mode == "paths")
      check_paths(args);
    else if(mode == "samples")
      check_samples(args);
    else if(mode == "plane_query")
      check_plane_query(args);
    else
      throw Check_failure("unknown check '" + mode + "'");
  }
  catch(const std::exception& e)
  {
    std::cerr << "check " << mode << " failed: " << e.what() << std::endl;
    return 1;
  }
  std::cout << "check " << mode << ": passed" << std::endl;
  return 0;
}
