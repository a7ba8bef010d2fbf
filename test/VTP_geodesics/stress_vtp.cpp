// vtp_stress: randomized cross-check of VTP (and PVTP) against CGAL::Surface_mesh_shortest_path, and of
// AVTP (PAVTP) and virtual source propagation (VSP, PVSP) against VTP; the paths of every method.
//
//   vtp_stress [--seed S] [--cases N] [--case K] [--min-vertices v] [--max-vertices V]
//              [--sources P] [--methods vtp,pvtp,avtp,pavtp,vsp,pvsp] [--timeout T] [--dump DIR] [--verbose]
//
// Case k of a run seeded with S draws its own mesh and sources from case_seed(S, k), so any case can be
// replayed alone with `--seed S --case k`. The meshes (see vtp_random_meshes.h) are closed surfaces
// (convex hulls of random points on ellipsoids, with radial bumps), open surfaces (the same with a patch
// or scattered faces removed, possibly leaving several components and isolated vertices), and height
// fields over stretched, jittered grids, with or without removed faces. A quarter of the meshes are then
// made degenerate without changing the surface: some edges (a, b) get a new vertex m either on a (a
// zero-length edge and two zero-area faces) or at the midpoint of ab with a zero-area "sliver" (a, b, m)
// glued along ab; CGAL's algorithm (which fails on such meshes) then runs on the same surface without
// the degeneracies (the midpoints split their edges on both sides), and a vertex inserted on a is
// expected at the distance of a. The sources are random
// vertices, boundary vertices, saddle vertices and isolated vertices (of the mesh before the change).
//
// For every source, each method must give the distances of CGAL's exact algorithm (Epick):
//   max |d - d_cgal| <= 1e-12 * (largest finite d_cgal), with the same unreachable (+infinity) vertices,
// no NaN, no negative value, and 0 at the source; PVTP must also equal VTP within the same tolerance.
// The queries are checked against the VTP run from the same source (check_queries()): a distance limit,
// paths (length = distance), two sources (minimum of single runs, labels).
// VSP (one and two virtual sources per vertex) is approximate: it must never be below the VTP distances by
// more than the same tolerance, reach the same vertices, give 0 at the source and no NaN; PVSP on 2 and 3
// threads must give the very same bits as VSP; and its own queries must hold (check_virtual_sources()): a
// distance limit gives distances within it that are never below the exact ones (most often those of the full
// run: the runs where they are not are counted), targets stop the run with the full run's distances, paths
// have the length of the distance, and two sources are never below the exact distance to the source of each
// vertex's label.
// AVTP and PAVTP (windows reset every half mean edge, PAVTP on 2 threads) must never be below VTP by more than
// the tolerance and reach the same vertices.
// Paths, for every method (vtp, pvtp, avtp, pavtp, vsp, pvsp, vsp2, pvsp2; the parallel ones on 2 threads), from
// a run recording them (check_every_path()): the path of every reached vertex starts at the vertex, ends at
// the source and has the length of the vertex's distance within 1e-9 of it, and no path query throws; the
// summary counts, per method, the runs, the paths, the queries that threw, the paths of another length and
// the largest relative difference.
// Any failure is printed with its seed and case (and whether CGAL, run on the midpoint subdivision of the
// mesh, agrees with the method: CGAL itself errs on some meshes); the exit code is then 1. A case that runs longer than
// --timeout seconds (default 120) is reported and ends the program with exit code 3. A crash prints the
// case being run before the signal is handled as usual.
//
// The ctest test `stress_short` runs a few hundred small cases; the long run is
//   vtp_stress --seed 1 --cases 10000 --max-vertices 300

#include "vtp_random_meshes.h"

#include <CGAL/VTP_geodesics.h>
#include <vtp_support/command_line.h>
#include <vtp_support/midpoint_subdivision.h>
#include <vtp_support/shortest_path_reference.h>

#include <CGAL/IO/OFF.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;

namespace {

const double TOLERANCE = 1e-12;

struct Settings
{
  std::uint64_t seed = 1;
  std::size_t cases = 100;
  bool single_case = false;
  std::size_t the_case = 0;
  std::size_t min_vertices = 4;
  std::size_t max_vertices = 200;
  std::size_t sources = 2;
  bool vtp = true;
  bool pvtp = false;
  bool avtp = true;
  bool pavtp = false;
  bool vsp = true;
  bool pvsp = false;
  unsigned timeout = 120;
  std::string dump;
  bool verbose = false;
  bool help = false;
};

// ------------------------------------------------------------------------------------------------
// What is running, for the crash and timeout handlers (async-signal-safe: a fixed buffer and write()).
// ------------------------------------------------------------------------------------------------
char current_case[512] = "vtp_stress: (no case running)\n";
struct sigaction previous_actions[NSIG];

void set_current_case(const std::string& s)
{
  const std::size_t n = (std::min)(s.size(), sizeof(current_case) - 2);
  std::memcpy(current_case, s.data(), n);
  current_case[n] = '\n';
  current_case[n + 1] = '\0';
}

void write_current_case(const char* what)
{
  ssize_t ignored = write(2, what, std::strlen(what));
  ignored = write(2, current_case, std::strlen(current_case));
  (void)ignored;
}

void crash_handler(int sig)
{
  write_current_case("vtp_stress: CRASH (signal) while running: ");
  // hand the signal to the previous handler (the default one, or a sanitizer's)
  sigaction(sig, &previous_actions[sig], nullptr);
  raise(sig);
}

void timeout_handler(int)
{
  write_current_case("vtp_stress: TIMEOUT while running: ");
  _exit(3);
}

void install_handlers()
{
  for(int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
  {
    struct sigaction action;
    std::memset(&action, 0, sizeof(action));
    action.sa_handler = crash_handler;
    sigemptyset(&action.sa_mask);
    sigaction(sig, &action, &previous_actions[sig]);
  }
  std::signal(SIGALRM, timeout_handler);
}

// ------------------------------------------------------------------------------------------------
// Cases
// ------------------------------------------------------------------------------------------------
// A vertex m inserted into a mesh without changing its surface: at the position of vertex a (a
// zero-length edge), or at the midpoint of the edge a -> b (the apex of a zero-area sliver).
struct Inserted_vertex
{
  std::size_t m, a, b;
  bool midpoint;
};

struct Case
{
  std::string description;
  Surface_mesh mesh;
  std::vector<std::pair<Vertex_index, std::string> > sources; // vertex and why it was chosen
  // degenerate cases: the mesh before the insertions (CGAL runs on it) and the inserted vertices
  Surface_mesh reference_mesh;
  std::vector<Inserted_vertex> inserted;
};

// Inserts zero-length edges and collinear slivers into `soup` (see the header comment), at edges of
// faces that share no vertex, so that each change is the one described. `reference` (a copy of `soup`
// on entry) gets the same vertices without degeneracy: a midpoint splits the edge on both sides, a vertex
// on a vertex stays isolated (its distance is that of the vertex).
std::vector<Inserted_vertex> insert_degeneracies(Polygon_soup& soup, Polygon_soup& reference, Random& random,
                                                 std::string* what)
{
  std::vector<Inserted_vertex> inserted;
  if(soup.polygons.empty())
    return inserted;
  const std::size_t wanted = random.integer(1, 6);
  std::vector<unsigned char> used(soup.points.size(), 0);
  std::size_t zero_length = 0, slivers = 0;
  for(std::size_t attempt = 0; attempt < 20 * wanted && inserted.size() < wanted; ++attempt)
  {
    const std::vector<std::size_t> t = soup.polygons[random.integer(0, soup.polygons.size() - 1)];
    if(used[t[0]] || used[t[1]] || used[t[2]])
      continue;
    // every face touching the chosen edge must be free too
    const std::size_t k = random.integer(0, 2);
    const std::size_t a = t[k], b = t[(k + 1) % 3];
    std::vector<std::size_t> touched;
    for(const std::vector<std::size_t>& q : soup.polygons)
      if(side_of_edge(q, a, b) < 3)
        touched.insert(touched.end(), q.begin(), q.end());
    if(std::any_of(touched.begin(), touched.end(), [&used](std::size_t v) { return used[v] != 0; }))
      continue;
    for(std::size_t v : touched)
      used[v] = 1;
    const bool midpoint = random.chance(0.5);
    const std::size_t m = midpoint ? insert_sliver(soup, a, b) : split_edge(soup, a, b, soup.points[a]);
    if(midpoint)
      split_edge(reference, a, b, soup.points[m]);
    else
      reference.points.push_back(soup.points[m]);
    used.push_back(1);
    inserted.push_back({m, a, b, midpoint});
    ++(midpoint ? slivers : zero_length);
  }
  *what += ", " + std::to_string(zero_length) + " zero-length edges and " + std::to_string(slivers)
           + " slivers inserted";
  return inserted;
}

// Distances of CGAL's exact algorithm for a case: on the mesh itself, or, for a degenerate case, on the
// mesh without the degeneracies (midpoints are vertices of it; a vertex inserted on a vertex gets the
// distance of that vertex).
std::vector<double> reference_distances(const Case& c, Vertex_index s)
{
  using vtp_support::shortest_path_reference_distances;
  if(c.inserted.empty())
    return shortest_path_reference_distances(c.mesh, s);
  std::vector<double> d = shortest_path_reference_distances(c.reference_mesh, s);
  for(const Inserted_vertex& iv : c.inserted)
    if(!iv.midpoint)
      d[iv.m] = d[iv.a];
  return d;
}

double angle_sum(const Surface_mesh& mesh, Vertex_index v)
{
  double sum = 0.;
  for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
  {
    if(mesh.is_border(h))
      continue;
    const Vector_3 a = mesh.point(mesh.source(h)) - mesh.point(v);
    const Vector_3 b = mesh.point(mesh.target(mesh.next(h))) - mesh.point(v);
    const double c = (a * b) / std::sqrt(a.squared_length() * b.squared_length());
    sum += std::acos((std::max)(-1., (std::min)(1., c)));
  }
  return sum;
}

Case make_case(const Settings& settings, std::size_t index)
{
  Random random(case_seed(settings.seed, index));
  const std::size_t n = random.integer(settings.min_vertices, settings.max_vertices);
  const std::size_t family = random.integer(0, 3);
  Case c;
  std::string what;
  Polygon_soup soup = (family < 2) ? random_closed_surface(n, random, &what) : random_grid(n, random, &what);
  if(family == 1 || family == 3)
  {
    const std::size_t removed = remove_random_faces(soup, random.uniform(0.02, 0.5), random);
    what += ", " + std::to_string(removed) + " faces removed";
  }
  const std::size_t original_vertices = soup.points.size();
  if(random.chance(0.25))
  {
    Polygon_soup reference = soup;
    c.inserted = insert_degeneracies(soup, reference, random, &what);
    c.reference_mesh = to_mesh<Surface_mesh>(reference);
  }
  c.mesh = to_mesh<Surface_mesh>(soup);
  c.description = what + " (" + std::to_string(c.mesh.number_of_vertices()) + " vertices, "
                  + std::to_string(c.mesh.number_of_faces()) + " faces)";

  std::vector<Vertex_index> boundary, isolated;
  Vertex_index saddle = Surface_mesh::null_vertex();
  double largest_angle_sum = 2. * PI + 1e-6;
  for(Vertex_index v : c.mesh.vertices())
  {
    if(std::size_t(v) >= original_vertices)
      continue; // inserted vertices are not sources (CGAL cannot start from them)
    if(c.mesh.is_isolated(v))
      isolated.push_back(v);
    else if(c.mesh.is_border(v))
      boundary.push_back(v);
    else
    {
      const double s = angle_sum(c.mesh, v);
      if(s > largest_angle_sum)
      {
        largest_angle_sum = s;
        saddle = v;
      }
    }
  }
  const std::size_t number_of_sources = random.integer(1, (std::max)(std::size_t(1), settings.sources));
  for(std::size_t k = 0; k < number_of_sources; ++k)
  {
    const double kind = random.uniform();
    if(kind < 0.25 && !boundary.empty())
      c.sources.emplace_back(boundary[random.integer(0, boundary.size() - 1)], "boundary");
    else if(kind < 0.45 && saddle != Surface_mesh::null_vertex())
      c.sources.emplace_back(saddle, "saddle");
    else if(kind < 0.5 && !isolated.empty())
      c.sources.emplace_back(isolated[random.integer(0, isolated.size() - 1)], "isolated");
    else
      c.sources.emplace_back(Vertex_index(static_cast<Surface_mesh::size_type>(random.integer(0, original_vertices - 1))), "random");
  }
  return c;
}

// ------------------------------------------------------------------------------------------------
// Comparison
// ------------------------------------------------------------------------------------------------
struct Difference
{
  double max_abs = 0.;     // over vertices finite in both
  double scale = 0.;       // largest finite expected distance
  std::size_t reachability = 0, invalid = 0, worst = 0;
  bool source_not_zero = false;
  bool ok() const
  {
    return reachability == 0 && invalid == 0 && !source_not_zero && max_abs <= TOLERANCE * scale;
  }
};

// The largest finite entry (0 if none).
double largest_finite(const std::vector<double>& values)
{
  double m = 0.;
  for(double x : values)
    if(std::isfinite(x))
      m = (std::max)(m, x);
  return m;
}

Difference compare(const std::vector<double>& d, const std::vector<double>& expected, std::size_t source)
{
  Difference r;
  r.scale = largest_finite(expected);
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(std::isnan(d[i]) || d[i] < 0.)
    {
      ++r.invalid;
      continue;
    }
    if(std::isfinite(d[i]) != std::isfinite(expected[i]))
    {
      ++r.reachability;
      r.worst = i;
      continue;
    }
    if(std::isfinite(d[i]) && std::abs(d[i] - expected[i]) > r.max_abs)
    {
      r.max_abs = std::abs(d[i] - expected[i]);
      if(r.reachability == 0)
        r.worst = i;
    }
  }
  r.source_not_zero = !(d[source] == 0.);
  return r;
}

void dump_mesh(const Settings& settings, std::size_t index, const Surface_mesh& mesh)
{
  if(settings.dump.empty())
    return;
  const std::string file =
    settings.dump + "/vtp_stress_" + std::to_string(settings.seed) + "_" + std::to_string(index) + ".off";
  std::ofstream out(file);
  out.precision(17);
  if(CGAL::IO::write_OFF(out, mesh))
    std::cout << "  mesh written to " << file << std::endl;
}

// The methods whose every path is checked (check_every_path()), in the order of the summary.
enum Path_method { PATHS_VTP, PATHS_PVTP, PATHS_AVTP, PATHS_PAVTP, PATHS_VSP, PATHS_PVSP, PATHS_VSP2, PATHS_PVSP2,
                   NUMBER_OF_PATH_METHODS };
const char* const path_method_name[NUMBER_OF_PATH_METHODS] = { "vtp", "pvtp", "avtp", "pavtp",
                                                               "vsp", "pvsp", "vsp2", "pvsp2" };
// the reset period of AVTP and PAVTP: half the mean edge (many resets on these small meshes)
const double AVTP_LAMBDA = 0.5;
// a path's length is its vertex's distance within this share of it
const double PATH_TOLERANCE = 1e-9;

struct Path_counts
{
  std::size_t runs = 0, paths = 0, throwing = 0, wrong = 0;
  double worst = 0.;  // the largest |length - d| / d
};

struct Totals
{
  std::size_t cases = 0, sources = 0, comparisons = 0, failures = 0, vertices = 0, query_checks = 0;
  std::size_t vsp_runs = 0, vsp_limit_runs_differing = 0, vsp_limit_differences = 0;
  double worst_vs_cgal = 0., worst_parallel = 0.;
  double vsp_worst_below = 0., vsp_worst_relative = 0.;  // (d_vtp - d_vsp) and |d_vsp - d_vtp| / d_vtp, largest
  std::string vsp_worst_relative_where;                  // the case, source and vertex of the latter
  double cgal_seconds = 0., vtp_seconds = 0., pvtp_seconds = 0., vsp_seconds = 0., avtp_seconds = 0.;
  std::size_t avtp_runs = 0;
  double avtp_worst_below = 0.;  // the largest (d_vtp - d_avtp) / max distance
  std::size_t curve_runs = 0, curve_paths = 0;
  double curve_worst_parallel = 0.;  // the largest |d_pvtp - d_vtp| / max distance from curves
  Path_counts paths[NUMBER_OF_PATH_METHODS];
};

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The options that change the cases drawn, when not the defaults (for the "reproduce with" lines).
std::string size_options(const Settings& settings)
{
  const Settings defaults;
  std::string s;
  if(settings.min_vertices != defaults.min_vertices)
    s += " --min-vertices " + std::to_string(settings.min_vertices);
  if(settings.max_vertices != defaults.max_vertices)
    s += " --max-vertices " + std::to_string(settings.max_vertices);
  if(settings.sources != defaults.sources)
    s += " --sources " + std::to_string(settings.sources);
  return s;
}

// The paths of a few vertices, after a run from s recording them that gave the distances d: from the vertex to
// the source, of the length of its distance within `tolerance`. Returns a description (prefixed by `name`) of
// the first failure, or an empty string.
std::string check_paths(const std::string& name, const Surface_mesh& mesh,
                        Geodesic_distance_solver<Surface_mesh>& solver, Vertex_index s,
                        const std::vector<double>& d, double tolerance)
{
  const std::size_t n = d.size();
  for(std::size_t j = 0; j < 5; ++j)
  {
    const Vertex_index v(static_cast<Surface_mesh::size_type>((std::size_t(s) + 1 + j * (n / 5 + 1)) % n));
    if(!std::isfinite(d[v]))
      continue;
    std::vector<vtp_test::Point_3> path;
    try { solver.shortest_path_points(v, std::back_inserter(path)); }
    catch(const std::exception& e) { return name + "path from vertex " + std::to_string(std::size_t(v)) + ": " + e.what(); }
    double length = 0.;
    for(std::size_t k = 1; k < path.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
    if(path.empty() || path.front() != mesh.point(v) || path.back() != mesh.point(s) || !(std::abs(length - d[v]) <= tolerance))
    {
      std::ostringstream failure;
      failure.precision(17);
      failure << name << "path from vertex " << std::size_t(v) << ": " << path.size() << " points, length " << length
              << ", distance " << d[v];
      return failure.str();
    }
  }
  return std::string();
}

// Every path of the run of method m just made by `solver` from s, recording the paths: the path of every
// reached vertex starts at the vertex, ends at the source and has the length of the vertex's distance d within
// PATH_TOLERANCE * d; no path query throws. Counted in totals.paths[m]. Returns a description of the first
// failure, or an empty string.
std::string check_every_path(Path_method m, const Surface_mesh& mesh, Geodesic_distance_solver<Surface_mesh>& solver,
                             Vertex_index s, Totals& totals)
{
  const std::vector<double> d = solver.distances();
  Path_counts& counts = totals.paths[m];
  ++counts.runs;
  std::ostringstream failure;
  failure.precision(17);
  std::vector<vtp_test::Point_3> path;
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(!std::isfinite(d[i]))
      continue;
    const Vertex_index v(static_cast<Surface_mesh::size_type>(i));
    ++counts.paths;
    path.clear();
    try
    {
      solver.shortest_path_points(v, std::back_inserter(path));
    }
    catch(const std::exception& e)
    {
      ++counts.throwing;
      if(failure.str().empty())
        failure << path_method_name[m] << " path from vertex " << i << " (distance " << d[i] << "): " << e.what();
      continue;
    }
    double length = 0.;
    for(std::size_t k = 1; k < path.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
    const double error = std::abs(length - d[i]);
    if(d[i] > 0.)
      counts.worst = (std::max)(counts.worst, error / d[i]);
    if(path.empty() || path.front() != mesh.point(v) || path.back() != mesh.point(s) || !(error <= PATH_TOLERANCE * d[i]))
    {
      ++counts.wrong;
      if(failure.str().empty())
        failure << path_method_name[m] << " path from vertex " << i << ": " << path.size() << " points, length "
                << length << ", distance " << d[i] << " (relative difference " << error / d[i] << ")";
    }
  }
  return failure.str();
}

// The queries beyond one field, checked against the full run `full` from s (no reference needed): a distance
// limit (the full run inside, +infinity outside), paths (length = distance, from the vertex to the source),
// and two sources, s and s2 (the minimum of the single runs `full` and `second`, labels achieving it). Returns a
// description of the first failure, or an empty string.
std::string check_queries(const Surface_mesh& mesh, Geodesic_distance_solver<Surface_mesh>& solver, Vertex_index s,
                          const std::vector<double>& full, Vertex_index s2, const std::vector<double>& second,
                          Totals& totals)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  const std::size_t n = full.size();
  const double max_d = largest_finite(full);
  const double tolerance = TOLERANCE * (max_d > 0. ? max_d : 1.);
  std::ostringstream failure;
  failure.precision(17);
  // distance limit
  ++totals.query_checks;
  const double R = 0.37 * max_d;
  solver.compute(vtp_test::Discard_map(), s, VP::maximum_distance(R));
  const std::vector<double> limited = solver.distances();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(full[i] <= R - tolerance && !(std::abs(limited[i] - full[i]) <= tolerance))
      failure << "limit " << R << ": vertex " << i << " at " << limited[i] << ", full run " << full[i];
    else if(full[i] > R + tolerance && limited[i] != std::numeric_limits<double>::infinity())
      failure << "limit " << R << ": vertex " << i << " beyond the limit at " << limited[i] << ", full run " << full[i];
    if(!failure.str().empty())
      return failure.str();
  }
  // paths of a few vertices
  ++totals.query_checks;
  solver.compute(vtp_test::Discard_map(), s, VP::record_paths(true));
  std::string path_failure = check_every_path(PATHS_VTP, mesh, solver, s, totals);
  if(path_failure.empty())
    path_failure = check_paths("", mesh, solver, s, full, tolerance);
  if(!path_failure.empty())
    return path_failure;
  // two sources
  ++totals.query_checks;
  std::vector<std::size_t> labels(n);
  solver.compute(vtp_test::Discard_map(), std::vector<Vertex_index>{ s, s2 },
                 VP::nearest_source_map(boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh))));
  const std::vector<double>& both = solver.distances();
  for(std::size_t i = 0; i < n; ++i)
  {
    const double expected = (std::min)(full[i], second[i]);
    const bool reached = std::isfinite(expected);
    if(reached != std::isfinite(both[i]) || (reached && !(std::abs(both[i] - expected) <= tolerance)))
      failure << "two sources: vertex " << i << " at " << both[i] << ", minimum of the single runs " << expected;
    else if(reached && !(labels[i] < 2 && std::abs((labels[i] == 0 ? full[i] : second[i]) - both[i]) <= tolerance))
      failure << "two sources: vertex " << i << " labelled " << labels[i];
    else if(!reached && labels[i] != CGAL::VTP_geodesics::no_source)
      failure << "two sources: unreached vertex " << i << " labelled " << labels[i];
    if(!failure.str().empty())
      return failure.str();
  }
  return std::string();
}

// Virtual source propagation from s against the VTP run `exact` from s (see the header comment); `second`
// is the VTP run from s2, the second source of the two-source check. Returns a description of the first
// failure, or an empty string.
std::string check_virtual_sources(const Settings& settings, const std::string& where, const Surface_mesh& mesh,
                                  Geodesic_distance_solver<Surface_mesh>& solver, Vertex_index s,
                                  const std::vector<double>& exact, Vertex_index s2,
                                  const std::vector<double>& second, Totals& totals)
{
  namespace VP = CGAL::VTP_geodesics::parameters;
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t n = exact.size();
  const double max_d = largest_finite(exact);
  const double tolerance = TOLERANCE * (max_d > 0. ? max_d : 1.);
  std::ostringstream failure;
  failure.precision(17);
  for(int per_vertex = 1; per_vertex <= 2; ++per_vertex)
  {
    const std::string name = per_vertex == 1 ? "vsp" : "vsp2";
    const auto vsp = VP::virtual_sources(true).virtual_sources_per_vertex(per_vertex);
    auto t0 = std::chrono::steady_clock::now();
    solver.compute(vtp_test::Discard_map(), s, vsp);
    totals.vsp_seconds += seconds_since(t0);
    ++totals.vsp_runs;
    const std::vector<double> d = solver.distances();
    if(!(d[std::size_t(s)] == 0.))
      failure << name << ": the source is at " << d[std::size_t(s)];
    for(std::size_t i = 0; i < n && failure.str().empty(); ++i)
    {
      if(std::isnan(d[i]) || d[i] < 0.)
        failure << name << ": vertex " << i << " at " << d[i];
      else if(std::isfinite(d[i]) != std::isfinite(exact[i]))
        failure << name << ": vertex " << i << " at " << d[i] << ", vtp " << exact[i] << " (reachability)";
      else if(std::isfinite(d[i]))
      {
        totals.vsp_worst_below = (std::max)(totals.vsp_worst_below, (exact[i] - d[i]) / (max_d > 0. ? max_d : 1.));
        if(exact[i] > 0. && std::abs(d[i] - exact[i]) / exact[i] > totals.vsp_worst_relative)
        {
          totals.vsp_worst_relative = std::abs(d[i] - exact[i]) / exact[i];
          totals.vsp_worst_relative_where = where + ", " + name + ", vertex " + std::to_string(i) + " at "
                                            + std::to_string(d[i]) + ", vtp " + std::to_string(exact[i]);
        }
        if(d[i] < exact[i] - tolerance)
          failure << name << ": vertex " << i << " at " << d[i] << ", below the exact distance " << exact[i];
      }
    }
    if(!failure.str().empty())
      return failure.str();
    // every path (and a few again, with the tolerance of the distances)
    ++totals.query_checks;
    solver.compute(vtp_test::Discard_map(), s, vsp.record_paths(true));
    std::string path_failure = check_every_path(per_vertex == 1 ? PATHS_VSP : PATHS_VSP2, mesh, solver, s, totals);
    if(path_failure.empty())
      path_failure = check_paths(name + " ", mesh, solver, s, d, tolerance);
    if(!path_failure.empty())
      return path_failure;
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    // (the run on 2 threads records the paths, which must not change its bits, and its paths are checked)
    if(settings.pvsp)
      for(int threads : { 2, 3 })
      {
        t0 = std::chrono::steady_clock::now();
        if(threads == 2)
          solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), s, vsp.number_of_threads(threads).record_paths(true));
        else
          solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), s, vsp.number_of_threads(threads));
        totals.vsp_seconds += seconds_since(t0);
        ++totals.vsp_runs;
        const std::vector<double>& dp = solver.distances();
        for(std::size_t i = 0; i < n; ++i)
          if(!(dp[i] == d[i]))
          {
            failure << "p" << name << " on " << threads << " threads: vertex " << i << " at " << dp[i] << ", " << name
                    << " " << d[i] << " (not the same bits)";
            return failure.str();
          }
        if(threads == 2)
        {
          path_failure = check_every_path(per_vertex == 1 ? PATHS_PVSP : PATHS_PVSP2, mesh, solver, s, totals);
          if(!path_failure.empty())
            return path_failure;
        }
      }
#else
    (void)settings;
#endif
    if(per_vertex == 2)
      break;
    // a distance limit: within it, never below the exact distance; +infinity beyond. Most often the full
    // run's distances within the limit, but not always (the order of a run is not monotone: see the manual,
    // "Virtual source propagation"): the vertices where the two differ are counted, not failed
    ++totals.query_checks;
    const double R = 0.37 * largest_finite(d);
    solver.compute(vtp_test::Discard_map(), s, vsp.maximum_distance(R));
    const std::vector<double> limited = solver.distances();
    bool differs = false;
    for(std::size_t i = 0; i < n; ++i)
    {
      if(!(limited[i] == inf || (limited[i] <= R && limited[i] >= exact[i] - tolerance)))
      {
        failure << name << " limit " << R << ": vertex " << i << " at " << limited[i] << ", exact " << exact[i];
        return failure.str();
      }
      if(d[i] <= R ? !(limited[i] == d[i]) : !(limited[i] == inf))
      {
        ++totals.vsp_limit_differences;
        differs = true;
      }
    }
    totals.vsp_limit_runs_differing += differs ? 1 : 0;
    // two vertex targets: the full run's distances
    ++totals.query_checks;
    std::vector<Vertex_index> targets;
    for(std::size_t j = 0; j < 2; ++j)
      targets.push_back(Vertex_index(static_cast<Surface_mesh::size_type>((std::size_t(s) + 1 + j * (n / 2)) % n)));
    solver.compute(vtp_test::Discard_map(), s, vsp.targets(targets));
    for(std::size_t j = 0; j < targets.size(); ++j)
      if(!(solver.target_distance(j) == d[std::size_t(targets[j])]))
      {
        failure << name << " target vertex " << std::size_t(targets[j]) << " at " << solver.target_distance(j)
                << ", full run " << d[std::size_t(targets[j])];
        return failure.str();
      }
    // two sources: labels in range, sources at 0 with their own label, never below the exact distance to
    // the labelled source, and reached where one of the sources reaches
    ++totals.query_checks;
    std::vector<std::size_t> labels(n);
    solver.compute(vtp_test::Discard_map(), std::vector<Vertex_index>{ s, s2 },
                   vsp.nearest_source_map(boost::make_iterator_property_map(labels.begin(), get(boost::vertex_index, mesh))));
    const std::vector<double>& both = solver.distances();
    for(std::size_t i = 0; i < n; ++i)
    {
      const bool reached = std::isfinite(exact[i]) || std::isfinite(second[i]);
      if(reached != std::isfinite(both[i]))
        failure << name << " two sources: vertex " << i << " at " << both[i] << ", vtp " << exact[i] << " and " << second[i];
      else if(reached && !(labels[i] < 2 && both[i] >= (labels[i] == 0 ? exact[i] : second[i]) - tolerance))
        failure << name << " two sources: vertex " << i << " at " << both[i] << " labelled " << labels[i] << ", vtp "
                << exact[i] << " and " << second[i];
      else if(!reached && labels[i] != CGAL::VTP_geodesics::no_source)
        failure << name << " two sources: unreached vertex " << i << " labelled " << labels[i];
      if(!failure.str().empty())
        return failure.str();
    }
    if(!(both[std::size_t(s)] == 0.) || !(both[std::size_t(s2)] == 0.) || labels[std::size_t(s)] != 0
       || (s2 != s && labels[std::size_t(s2)] != 1))
    {
      failure << name << " two sources: the sources at " << both[std::size_t(s)] << " and " << both[std::size_t(s2)]
              << ", labelled " << labels[std::size_t(s)] << " and " << labels[std::size_t(s2)];
      return failure.str();
    }
  }
  return std::string();
}

// Runs one case; returns false on a failure (printed).
// A difference in words: its largest value, the vertices reached by one run only, the invalid values.
std::string describe(const Difference& d)
{
  std::ostringstream os;
  os.precision(17);
  os << d.max_abs << " (" << d.reachability << " vertices reached by one run only, " << d.invalid
     << " NaN or negative, worst vertex " << d.worst << ")";
  return os.str();
}

// The distances d from a curve against ds, those from points sampled on it at most `step` apart (along it): d <= ds
// and d >= ds - step / 2, to TOLERANCE * scale, the same vertices reached. `name` starts the description of the
// first failure (an empty string if none).
std::string check_sampled_bounds(const std::string& name, const std::vector<double>& d, const std::vector<double>& ds,
                                 double step, double scale)
{
  std::ostringstream failure;
  failure.precision(17);
  for(std::size_t i = 0; i < d.size() && failure.str().empty(); ++i)
  {
    if(std::isfinite(d[i]) != std::isfinite(ds[i]) || std::isnan(d[i]))
      failure << name << ": vertex " << i << " at " << d[i] << ", samples " << ds[i];
    else if(std::isfinite(d[i]) && (d[i] > ds[i] + TOLERANCE * scale || d[i] < ds[i] - step / 2. - TOLERANCE * scale))
      failure << name << ": vertex " << i << " at " << d[i] << ", not within [" << ds[i] - step / 2. << ", " << ds[i]
              << "] (the samples every " << step << ")";
  }
  return failure.str();
}

// The paths of five vertices (from vertex `first` on, spread over the mesh) after a run from a curve recording
// them that gave the distances d: each starts at its vertex, has the length of its distance within
// PATH_TOLERANCE, and ends on the curve (the segments `pieces`) within 1e-9 * scale. Counted in totals.curve_paths.
std::string check_curve_paths(const std::string& name, const Surface_mesh& mesh,
                              Geodesic_distance_solver<Surface_mesh>& solver, const std::vector<double>& d,
                              double scale, std::size_t first, const std::vector<vtp_test::Kernel::Segment_3>& pieces,
                              Totals& totals)
{
  const std::size_t n = d.size();
  for(std::size_t j = 0; j < 5; ++j)
  {
    const Vertex_index v(static_cast<Surface_mesh::size_type>((first + j * (n / 5 + 1)) % n));
    if(!std::isfinite(d[v]))
      continue;
    std::vector<vtp_test::Point_3> path;
    try { solver.shortest_path_points(v, std::back_inserter(path)); }
    catch(const std::exception& e) { return name + ": path from vertex " + std::to_string(std::size_t(v)) + ": " + e.what(); }
    double length = 0.;
    for(std::size_t k = 1; k < path.size(); ++k)
      length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
    double off = std::numeric_limits<double>::infinity();  // the end's distance to the curve
    if(!path.empty())
      for(const auto& piece : pieces)
        off = (std::min)(off, std::sqrt(CGAL::squared_distance(path.back(), piece)));
    ++totals.curve_paths;
    if(path.empty() || path.front() != mesh.point(v) || !(std::abs(length - d[v]) <= PATH_TOLERANCE * (d[v] + scale * 1e-3))
       || !(off <= 1e-9 * scale))
    {
      std::ostringstream failure;
      failure.precision(17);
      failure << name << ": path from vertex " << std::size_t(v) << ": " << path.size() << " points, length " << length
              << ", distance " << d[v] << ", its end " << off << " off the curve";
      return failure.str();
    }
  }
  return std::string();
}

// Distances from a curve (add_source_curve): the curve along mesh edges from s to s2 (a path of the edge graph,
// breadth first), against points sampled on it every step (16 per edge; one multi-source run): d <= d_S and
// d >= d_S - step / 2, to TOLERANCE of the largest distance (every point of the curve is within step / 2 of a
// sample along it, and the samples are on it); the same edges as add_source_edges() give the same distances; PVTP
// = VTP; the paths of a few vertices have the length of their distance and end on the curve. Returns a
// description of the first failure, or an empty string.
std::string check_curve(const Surface_mesh& mesh, Geodesic_distance_solver<Surface_mesh>& solver, Vertex_index s,
                        Vertex_index s2, Totals& totals)
{
  if(s == s2 || mesh.halfedge(s) == Surface_mesh::null_halfedge() || mesh.halfedge(s2) == Surface_mesh::null_halfedge())
    return std::string();  // (an isolated vertex: no curve along edges)
  // the path of the edge graph
  std::vector<Surface_mesh::Halfedge_index> from(mesh.number_of_vertices(), Surface_mesh::null_halfedge());
  std::vector<Vertex_index> queue(1, s);
  std::vector<char> seen(mesh.number_of_vertices(), 0);
  seen[s] = 1;
  for(std::size_t i = 0; i < queue.size() && !seen[s2]; ++i)
    for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_source(queue[i], mesh))
    {
      const Vertex_index w = mesh.target(h);
      if(!seen[w])
      {
        seen[w] = 1;
        from[w] = h;
        queue.push_back(w);
      }
    }
  if(!seen[s2])
    return std::string();
  std::vector<Surface_mesh::Halfedge_index> edges;
  for(Vertex_index v = s2; v != s; v = mesh.source(from[v]))
    edges.push_back(from[v]);
  std::reverse(edges.begin(), edges.end());
  std::vector<Vertex_index> curve(1, s);
  for(auto h : edges)
    curve.push_back(mesh.target(h));
  ++totals.curve_runs;
  namespace VP = CGAL::VTP_geodesics::parameters;
  solver.clear_sources();
  solver.add_source_curve(curve);
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), VP::record_paths(true));
  const std::vector<double> d = solver.distances();
  const double scale = (std::max)(largest_finite(d), 1e-300);
  // the samples, as face locations on the edges
  const int per_edge = 16;
  double step = 0.;
  std::vector<std::pair<Surface_mesh::Face_index, std::array<double, 3> > > samples;
  for(auto h : edges)
  {
    auto g = mesh.is_border(h) ? mesh.opposite(h) : h;
    const auto f = mesh.face(g);
    // the barycentric coordinates of source(g) and target(g) in f
    int a = 0, b = 0, k = 0;
    for(auto hh : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    {
      if(mesh.source(hh) == mesh.source(g)) a = k;
      if(mesh.source(hh) == mesh.target(g)) b = k;
      ++k;
    }
    step = (std::max)(step, std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))))
                              / per_edge);
    for(int i = 0; i <= per_edge; ++i)
    {
      std::array<double, 3> bc = { { 0., 0., 0. } };
      bc[static_cast<std::size_t>(a)] = 1. - double(i) / per_edge;
      bc[static_cast<std::size_t>(b)] += double(i) / per_edge;
      samples.emplace_back(f, bc);
    }
  }
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), samples);
  const std::string bounds = check_sampled_bounds("curve", d, solver.distances(), step, scale);
  if(!bounds.empty())
    return bounds;
  // the same edges
  solver.clear_sources();
  solver.add_source_edges(edges);
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map());
  const Difference edges_difference = compare(solver.distances(), d, std::size_t(s));
  if(!edges_difference.ok())
    return "curve: add_source_edges differs from add_source_curve by " + describe(edges_difference);
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  solver.clear_sources();
  solver.add_source_curve(curve);
  solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), VP::number_of_threads(2));
  const Difference parallel = compare(solver.distances(), d, std::size_t(s));
  totals.curve_worst_parallel = (std::max)(totals.curve_worst_parallel, parallel.max_abs / scale);
  if(!parallel.ok())
    return "curve: pvtp differs from vtp by " + describe(parallel);
#endif
  // paths, from the run recording them
  solver.clear_sources();
  solver.add_source_curve(curve);
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), VP::record_paths(true));
  std::vector<vtp_test::Kernel::Segment_3> pieces;
  for(auto h : edges)
    pieces.emplace_back(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
  return check_curve_paths("curve", mesh, solver, d, scale, std::size_t(s) + 1, pieces, totals);
}

// Distances from a curve through faces: a walk from a face of s across up to 8 faces (a point inside each face,
// joined to a point of the edge to the next one; points drawn from `seed`), as face locations whose consecutive
// points share a face; checked as check_curve() does against points sampled on it (16 per piece), PVTP = VTP, and
// the paths. Returns a description of the first failure, or an empty string.
std::string check_curve_through_faces(const Surface_mesh& mesh, Geodesic_distance_solver<Surface_mesh>& solver,
                                      Vertex_index s, std::uint64_t seed, Totals& totals)
{
  typedef Surface_mesh::Face_index Face_index;
  typedef std::pair<Face_index, std::array<double, 3> > Location;
  if(mesh.halfedge(s) == Surface_mesh::null_halfedge())
    return std::string();
  Surface_mesh::Halfedge_index h = mesh.halfedge(s);
  if(mesh.is_border(h))
    h = mesh.opposite(h);
  if(mesh.is_border(h))
    return std::string();
  vtp_test::Random random(seed);
  auto corner = [&](Face_index f, Vertex_index v) {
    int k = 0;
    for(auto hh : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    {
      if(mesh.source(hh) == v)
        return k;
      ++k;
    }
    return -1;
  };
  auto inside = [&](Face_index f) {
    double a = random.uniform(0.1, 0.8), b = random.uniform(0.1, 0.9) * (1. - a);
    return Location(f, { { a, b, 1. - a - b } });
  };
  auto point_of = [&](const Location& l) {
    int k = 0;
    double x = 0., y = 0., z = 0.;
    for(auto hh : CGAL::halfedges_around_face(mesh.halfedge(l.first), mesh))
    {
      const auto& p = mesh.point(mesh.source(hh));
      const double w = l.second[static_cast<std::size_t>(k++)];
      x += w * p.x();
      y += w * p.y();
      z += w * p.z();
    }
    return vtp_test::Point_3(x, y, z);
  };
  // pieces: pairs of locations in one face
  std::vector<std::pair<Location, Location> > pieces;
  std::vector<Location> curve;
  Face_index f = mesh.face(h);
  Location at = inside(f);
  curve.push_back(at);
  std::vector<Face_index> visited(1, f);
  for(int step = 0; step < 8; ++step)
  {
    // an edge of f to a face not visited yet
    std::vector<Surface_mesh::Halfedge_index> ways;
    for(auto hh : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      if(!mesh.is_border(mesh.opposite(hh))
         && std::find(visited.begin(), visited.end(), mesh.face(mesh.opposite(hh))) == visited.end())
        ways.push_back(hh);
    if(ways.empty())
      break;
    const auto e = ways[random.integer(0, ways.size() - 1)];
    const Face_index g = mesh.face(mesh.opposite(e));
    const double t = random.uniform(0.2, 0.8);
    Location in_f(f, { { 0., 0., 0. } }), in_g(g, { { 0., 0., 0. } });
    in_f.second[static_cast<std::size_t>(corner(f, mesh.source(e)))] = 1. - t;
    in_f.second[static_cast<std::size_t>(corner(f, mesh.target(e)))] = t;
    in_g.second[static_cast<std::size_t>(corner(g, mesh.source(e)))] = 1. - t;
    in_g.second[static_cast<std::size_t>(corner(g, mesh.target(e)))] = t;
    pieces.emplace_back(at, in_f);
    curve.push_back(in_f);
    at = inside(g);
    pieces.emplace_back(in_g, at);
    curve.push_back(at);
    f = g;
    visited.push_back(g);
  }
  if(curve.size() < 2)
    return std::string();
  ++totals.curve_runs;
  namespace VP = CGAL::VTP_geodesics::parameters;
  solver.clear_sources();
  solver.add_source_curve(curve);
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map());
  const std::vector<double> d = solver.distances();
  const double scale = (std::max)(largest_finite(d), 1e-300);
  const int per_piece = 16;
  double step_length = 0.;
  std::vector<Location> samples;
  for(const auto& piece : pieces)
  {
    step_length = (std::max)(step_length, std::sqrt(CGAL::squared_distance(point_of(piece.first), point_of(piece.second)))
                                            / per_piece);
    for(int i = 0; i <= per_piece; ++i)
    {
      const double t = double(i) / per_piece;
      Location l(piece.first.first, { { 0., 0., 0. } });
      for(std::size_t k = 0; k < 3; ++k)
        l.second[k] = (1. - t) * piece.first.second[k] + t * piece.second.second[k];
      samples.push_back(l);
    }
  }
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), samples);
  const std::string bounds = check_sampled_bounds("curve through faces", d, solver.distances(), step_length, scale);
  if(!bounds.empty())
    return bounds;
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), VP::number_of_threads(2));
  const Difference parallel = compare(solver.distances(), d, std::size_t(s));
  totals.curve_worst_parallel = (std::max)(totals.curve_worst_parallel, parallel.max_abs / scale);
  if(parallel.max_abs > TOLERANCE * scale || parallel.reachability != 0)
    return "curve through faces: pvtp differs from vtp by " + describe(parallel);
#endif
  solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), VP::record_paths(true));
  std::vector<vtp_test::Kernel::Segment_3> segments;
  for(const auto& piece : pieces)
    segments.emplace_back(point_of(piece.first), point_of(piece.second));
  return check_curve_paths("curve through faces", mesh, solver, d, scale, std::size_t(s) + 3, segments, totals);
}

bool run_case(const Settings& settings, std::size_t index, Totals& totals)
{
  std::ostringstream head;
  head << "seed " << settings.seed << " case " << index;
  set_current_case(head.str() + " (generating the mesh); reproduce with: vtp_stress --seed "
                   + std::to_string(settings.seed) + " --case " + std::to_string(index) + size_options(settings));
  const Case c = make_case(settings, index);
  const std::string reproduce =
    "reproduce with: vtp_stress --seed " + std::to_string(settings.seed) + " --case " + std::to_string(index)
    + size_options(settings);
  if(settings.verbose)
    std::cout << head.str() << ": " << c.description << std::endl;
  const double cgal_before = totals.cgal_seconds, vtp_before = totals.vtp_seconds;
  ++totals.cases;
  totals.vertices += c.mesh.number_of_vertices();

  bool ok = true;
  Geodesic_distance_solver<Surface_mesh> solver(c.mesh);
  for(const auto& source : c.sources)
  {
    const Vertex_index s = source.first;
    const std::string where = head.str() + ", " + c.description + ", source " + std::to_string(std::size_t(s))
                              + " (" + source.second + ")";
    ++totals.sources;
    set_current_case(where + ", CGAL shortest path; " + reproduce);
    auto t0 = std::chrono::steady_clock::now();
    const std::vector<double> reference = reference_distances(c, s);
    totals.cgal_seconds += seconds_since(t0);

    std::vector<double> sequential;
    auto check = [&](const char* method, const std::vector<double>& d, const std::vector<double>& expected,
                     const char* against) {
      ++totals.comparisons;
      const Difference diff = compare(d, expected, std::size_t(s));
      const double relative = diff.scale > 0. ? diff.max_abs / diff.scale : diff.max_abs;
      if(std::string(against) == "CGAL")
        totals.worst_vs_cgal = (std::max)(totals.worst_vs_cgal, relative);
      else
        totals.worst_parallel = (std::max)(totals.worst_parallel, relative);
      if(diff.ok())
        return;
      ok = false;
      std::cout.precision(17);
      std::cout << "vtp_stress: MISMATCH " << where << ": " << method << " vs " << against
                << ": max |d - d_ref| = " << diff.max_abs << " = " << relative << " * max distance "
                << diff.scale << " (tolerance " << TOLERANCE << "), " << diff.reachability
                << " reachability mismatches, " << diff.invalid << " NaN or negative values"
                << (diff.source_not_zero ? ", source distance not 0" : "") << "; worst vertex " << diff.worst
                << ": d = " << d[diff.worst] << ", d_ref = " << expected[diff.worst] << "; " << reproduce
                << std::endl;
      if(std::string(against) == "CGAL" && c.inserted.empty())
      {
        // CGAL itself errs on some meshes: tell whether it agrees on the subdivided mesh (same surface)
        Surface_mesh fine = c.mesh;
        vtp_support::midpoint_subdivide(fine, 1);
        std::vector<double> fine_reference = vtp_support::shortest_path_reference_distances(fine, s);
        fine_reference.resize(reference.size());
        std::cout << "  CGAL on the midpoint-subdivided mesh "
                  << (compare(d, fine_reference, std::size_t(s)).ok() ? "agrees with " : "disagrees with ") << method
                  << std::endl;
      }
    };

    // (VTP runs for PVTP too, which must equal it)
    set_current_case(where + ", vtp; " + reproduce);
    t0 = std::chrono::steady_clock::now();
    solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), s);
    totals.vtp_seconds += seconds_since(t0);
    sequential = solver.distances();
    // the second source of the two-source checks, and its VTP run
    const Vertex_index s2(static_cast<Surface_mesh::size_type>((std::size_t(s) * 7 + 3) % sequential.size()));
    std::vector<double> second;
    if(settings.vtp || settings.vsp)
    {
      set_current_case(where + ", vtp from the second source; " + reproduce);
      solver.compute<CGAL::Sequential_tag>(vtp_test::Discard_map(), s2);
      second = solver.distances();
    }
    if(settings.vtp)
    {
      check("vtp", sequential, reference, "CGAL");
      set_current_case(where + ", queries; " + reproduce);
      const std::string failure = check_queries(c.mesh, solver, s, sequential, s2, second, totals);
      if(!failure.empty())
      {
        ok = false;
        std::cout << "vtp_stress: MISMATCH " << where << ": " << failure << "; " << reproduce << std::endl;
      }
      set_current_case(where + ", curve; " + reproduce);
      std::string curve_failure = check_curve(c.mesh, solver, s, s2, totals);
      if(curve_failure.empty())
        curve_failure = check_curve_through_faces(c.mesh, solver, s, settings.seed * 1000003u + index, totals);
      if(!curve_failure.empty())
      {
        ok = false;
        std::cout << "vtp_stress: MISMATCH " << where << ": " << curve_failure << "; " << reproduce << std::endl;
      }
    }
    if(settings.vsp)
    {
      set_current_case(where + ", vsp; " + reproduce);
      const std::string failure = check_virtual_sources(settings, where, c.mesh, solver, s, sequential, s2, second, totals);
      if(!failure.empty())
      {
        ok = false;
        std::cout << "vtp_stress: MISMATCH " << where << ": " << failure << "; " << reproduce << std::endl;
      }
    }
    auto report = [&](const std::string& failure) {
      if(failure.empty())
        return;
      ok = false;
      std::cout << "vtp_stress: MISMATCH " << where << ": " << failure << "; " << reproduce << std::endl;
    };
    // AVTP (PAVTP): windows reset every AVTP_LAMBDA mean edges; never below VTP, the same vertices reached, and
    // every path of the length of the distance
    auto check_avtp = [&](auto tag, Path_method m) {
      typedef decltype(tag) Tag;
      namespace VP = CGAL::VTP_geodesics::parameters;
      set_current_case(where + ", " + path_method_name[m] + "; " + reproduce);
      t0 = std::chrono::steady_clock::now();
      solver.compute<Tag>(vtp_test::Discard_map(), s, VP::lambda(AVTP_LAMBDA).number_of_threads(2).record_paths(true));
      totals.avtp_seconds += seconds_since(t0);
      ++totals.avtp_runs;
      const std::vector<double>& d = solver.distances();
      const double max_d = largest_finite(sequential);
      std::ostringstream failure;
      failure.precision(17);
      for(std::size_t i = 0; i < d.size() && failure.str().empty(); ++i)
      {
        if(std::isnan(d[i]) || std::isfinite(d[i]) != std::isfinite(sequential[i]))
          failure << path_method_name[m] << ": vertex " << i << " at " << d[i] << ", vtp " << sequential[i];
        else if(std::isfinite(d[i]))
        {
          totals.avtp_worst_below = (std::max)(totals.avtp_worst_below, (sequential[i] - d[i]) / (max_d > 0. ? max_d : 1.));
          if(d[i] < sequential[i] - TOLERANCE * (max_d > 0. ? max_d : 1.))
            failure << path_method_name[m] << ": vertex " << i << " at " << d[i] << ", below the exact distance "
                    << sequential[i];
        }
      }
      report(failure.str().empty() ? check_every_path(m, c.mesh, solver, s, totals) : failure.str());
    };
    if(settings.avtp)
      check_avtp(CGAL::Sequential_tag(), PATHS_AVTP);
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    if(settings.pavtp)
      check_avtp(CGAL::Parallel_tag(), PATHS_PAVTP);
    if(settings.pvtp)
    {
      set_current_case(where + ", pvtp; " + reproduce);
      t0 = std::chrono::steady_clock::now();
      solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), s, CGAL::VTP_geodesics::parameters::number_of_threads(2));
      totals.pvtp_seconds += seconds_since(t0);
      const std::vector<double> parallel = solver.distances();
      check("pvtp", parallel, reference, "CGAL");
      check("pvtp", parallel, sequential, "vtp");
      // its paths, from a run that records them (with the same distances)
      set_current_case(where + ", pvtp paths; " + reproduce);
      solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), s,
                                         CGAL::VTP_geodesics::parameters::number_of_threads(2).record_paths(true));
      check("pvtp (recording paths)", solver.distances(), parallel, "pvtp");
      report(check_every_path(PATHS_PVTP, c.mesh, solver, s, totals));
    }
#endif
  }
  if(settings.verbose)
    std::cout << "  " << c.sources.size() << " sources: CGAL " << totals.cgal_seconds - cgal_before << " s, vtp "
              << totals.vtp_seconds - vtp_before << " s" << std::endl;
  if(!ok)
  {
    ++totals.failures;
    dump_mesh(settings, index, c.mesh);
  }
  set_current_case("(between cases)");
  return ok;
}

// ------------------------------------------------------------------------------------------------
// Command line
// ------------------------------------------------------------------------------------------------
void usage(std::ostream& os)
{
  os << "usage: vtp_stress [--seed S] [--cases N] [--case K] [--min-vertices v] [--max-vertices V]\n"
        "                  [--sources P] [--methods vtp,pvtp,avtp,pavtp,vsp,pvsp] [--timeout T] [--dump DIR]\n"
        "                  [--verbose]\n"
        "\n"
        "Compares VTP (and PVTP) with CGAL::Surface_mesh_shortest_path on random meshes, and checks\n"
        "AVTP and virtual source propagation against VTP (never below it; PVSP on 2 and 3 threads = VSP, bit\n"
        "for bit); the path of every vertex, for every method, has the length of its distance.\n"
        "  --seed S          seed of the run (default 1)\n"
        "  --cases N         number of cases, 0 .. N-1 (default 100)\n"
        "  --case K          run case K only (to replay a failure)\n"
        "  --min-vertices v  smallest number of vertices drawn (default 4)\n"
        "  --max-vertices V  largest number of vertices drawn (default 200)\n"
        "  --sources P       at most P sources per mesh (default 2)\n"
        "  --methods M       comma-separated among vtp, pvtp, avtp, pavtp, vsp, pvsp (default: vtp, avtp and\n"
        "                    vsp, and pvtp, pavtp and pvsp if built with OpenMP; pvsp needs vsp; vsp and pvsp\n"
        "                    check one and two virtual sources per vertex)\n"
        "  --timeout T       seconds allowed per case (default 120; 0: none)\n"
        "  --dump DIR        write the mesh of each failing case to DIR/vtp_stress_<seed>_<case>.off\n"
        "  --verbose         print every case\n"
        "Exit code: 0 if every case agrees, 1 on a mismatch, 2 on a usage error, 3 on a timeout.\n";
}

// The options; the help is usage() above.
const vtp_support::Option_table<Settings>& option_table()
{
  typedef const std::string& S;
  using vtp_support::parse_integer;
  const unsigned long long any = std::numeric_limits<std::uint64_t>::max();
  static const vtp_support::Option_table<Settings> table = {
    { "--help", nullptr, nullptr, [](Settings& s, S, S) { s.help = true; } },
    { "--seed", "S", nullptr, [](Settings& s, S n, S v) { s.seed = parse_integer(n, v, 0, any); } },
    { "--cases", "N", nullptr, [](Settings& s, S n, S v) { s.cases = parse_integer(n, v, 0, any); } },
    { "--case", "K", nullptr, [](Settings& s, S n, S v) { s.the_case = parse_integer(n, v, 0, any); s.single_case = true; } },
    { "--min-vertices", "v", nullptr, [](Settings& s, S n, S v) { s.min_vertices = parse_integer(n, v, 0, any); } },
    { "--max-vertices", "V", nullptr, [](Settings& s, S n, S v) { s.max_vertices = parse_integer(n, v, 0, any); } },
    { "--sources", "P", nullptr, [](Settings& s, S n, S v) { s.sources = parse_integer(n, v, 0, any); } },
    { "--timeout", "T", nullptr,
      [](Settings& s, S n, S v) { s.timeout = static_cast<unsigned>(parse_integer(n, v, 0, std::numeric_limits<unsigned>::max())); } },
    { "--dump", "DIR", nullptr, [](Settings& s, S, S v) { s.dump = v; } },
    { "--verbose", nullptr, nullptr, [](Settings& s, S, S) { s.verbose = true; } },
    { "--methods", "M", nullptr,
      [](Settings& s, S, S v) {
        s.vtp = s.pvtp = s.avtp = s.pavtp = s.vsp = s.pvsp = false;
        for(const std::string& m : vtp_support::split(v, ','))
        {
          if(m == "vtp") s.vtp = true;
          else if(m == "avtp") s.avtp = true;
          else if(m == "vsp") s.vsp = true;
          else if(m == "pvtp" || m == "pavtp" || m == "pvsp")
          {
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
            (m == "pvtp" ? s.pvtp : m == "pavtp" ? s.pavtp : s.pvsp) = true;
#else
            throw vtp_support::Tool_error(m + " needs OpenMP, and this program was built without it");
#endif
          }
          else
            throw vtp_support::Tool_error("unknown method '" + m + "' (expected vtp, pvtp, avtp, pavtp, vsp or pvsp)");
        }
        if(s.pvsp && !s.vsp)
          throw vtp_support::Tool_error("pvsp is checked against vsp: list vsp too");
      } },
  };
  return table;
}

Settings parse(int argc, char** argv)
{
  Settings s;
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
  s.pvtp = s.pavtp = s.pvsp = true;
#endif
  vtp_support::parse_command_line(argc, argv, option_table(), s, [](Settings&, const std::string& a) {
    throw vtp_support::Tool_error("unknown argument '" + a + "' (see --help)");
  });
  if(s.help)
  {
    usage(std::cout);
    std::exit(0);
  }
  if(s.min_vertices < 4)
    s.min_vertices = 4;
  if(s.max_vertices < s.min_vertices)
    throw vtp_support::Tool_error("--max-vertices must be >= --min-vertices (and >= 4)");
  if(!s.vtp && !s.pvtp && !s.avtp && !s.pavtp && !s.vsp)
    throw vtp_support::Tool_error("no method selected");
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  Settings settings;
  try
  {
    settings = parse(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "vtp_stress: error: " << e.what() << std::endl;
    return 2;
  }
  install_handlers();

  const auto t0 = std::chrono::steady_clock::now();
  Totals totals;
  const std::size_t first = settings.single_case ? settings.the_case : 0;
  const std::size_t last = settings.single_case ? settings.the_case + 1 : settings.cases;
  for(std::size_t k = first; k < last; ++k)
  {
    alarm(settings.timeout);
    try
    {
      run_case(settings, k, totals);
    }
    catch(const std::exception& e)
    {
      ++totals.failures;
      std::cout << "vtp_stress: EXCEPTION seed " << settings.seed << " case " << k << ": " << e.what()
                << "; reproduce with: vtp_stress --seed " << settings.seed << " --case " << k << size_options(settings)
                << std::endl;
    }
    alarm(0);
    if(!settings.verbose && (k + 1 - first) % 1000 == 0)
      std::cout << "vtp_stress: " << (k + 1 - first) << " cases, " << totals.failures << " failing" << std::endl;
  }
  const double seconds = seconds_since(t0);

  std::cout << "vtp_stress: seed " << settings.seed << ", " << totals.cases << " cases (" << totals.vertices
            << " vertices), " << totals.sources << " sources, " << totals.comparisons << " comparisons, "
            << totals.query_checks << " query checks (limit, targets, paths, two sources), methods"
            << (settings.vtp ? " vtp" : "") << (settings.pvtp ? " pvtp" : "") << (settings.avtp ? " avtp" : "")
            << (settings.pavtp ? " pavtp" : "") << (settings.vsp ? " vsp" : "") << (settings.pvsp ? " pvsp" : "")
            << ": " << totals.failures
            << " failing cases; largest |d - d_cgal| / max distance " << totals.worst_vs_cgal;
  if(settings.pvtp)
    std::cout << ", largest |d_pvtp - d_vtp| / max distance " << totals.worst_parallel;
  if(settings.avtp || settings.pavtp)
    std::cout << "; avtp, pavtp (lambda " << AVTP_LAMBDA << "): " << totals.avtp_runs
              << " runs, largest (d_vtp - d) / max distance " << totals.avtp_worst_below << " (below exact if positive)";
  if(settings.vsp)
    std::cout << "; vsp" << (settings.pvsp ? ", pvsp" : "") << ": " << totals.vsp_runs
              << " runs, largest (d_vtp - d) / max distance " << totals.vsp_worst_below
              << " (below exact if positive), largest |d - d_vtp| / d_vtp " << totals.vsp_worst_relative
              << ", limited runs not equal to the full run within the limit: " << totals.vsp_limit_runs_differing
              << " (" << totals.vsp_limit_differences << " vertices)";
  std::cout << "; " << seconds << " s (CGAL " << totals.cgal_seconds << " s, vtp " << totals.vtp_seconds << " s";
  if(settings.pvtp)
    std::cout << ", pvtp " << totals.pvtp_seconds << " s";
  if(settings.avtp || settings.pavtp)
    std::cout << ", avtp and pavtp " << totals.avtp_seconds << " s";
  if(settings.vsp)
    std::cout << ", vsp " << totals.vsp_seconds << " s";
  std::cout << ")" << std::endl;
  if(settings.vtp)
    std::cout << "vtp_stress: curves along edges and through faces: " << totals.curve_runs << " curves (bounded by their "
              << "samples, those along edges equal to their edges, " << totals.curve_paths << " paths checked), largest |d_pvtp - d_vtp| / max distance "
              << totals.curve_worst_parallel << std::endl;
  // the paths, per method: every reached vertex of every run recording them
  for(int m = 0; m < NUMBER_OF_PATH_METHODS; ++m)
  {
    const Path_counts& p = totals.paths[m];
    if(p.runs == 0)
      continue;
    std::cout << "vtp_stress: paths of " << path_method_name[m] << ": " << p.runs << " runs, " << p.paths << " paths, "
              << p.throwing << " queries throwing, " << p.wrong << " not of the length of the distance (within "
              << PATH_TOLERANCE << " of it), largest |length - d| / d " << p.worst << std::endl;
  }
  if(settings.vsp && !totals.vsp_worst_relative_where.empty())
    std::cout << "vtp_stress: the largest relative error of vsp: " << totals.vsp_worst_relative_where << std::endl;
  return totals.failures == 0 ? 0 : 1;
}
