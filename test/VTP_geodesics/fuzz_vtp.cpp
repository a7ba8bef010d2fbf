// vtp_fuzz: libFuzzer target of the VTP_geodesics package (built with the CMake option
// VTP_GEODESICS_BUILD_FUZZER, with Clang and -fsanitize=fuzzer,address,undefined).
//
// Each input is turned into a small triangle mesh and a source vertex:
//   byte 0 (low two bits) chooses the kind of mesh:
//     0, 1  a height field over a grid of up to 6 x 6 cells, vertices jittered by multiples of 1/4 of a
//           cell, heights multiples of 1/4, cells stretched by a power of 2 from 1/8 to 8, diagonals
//           chosen by bits (coincident vertices, collinear and folded triangles happen);
//     2     a polygon soup of up to 24 triangles on up to 12 points with coordinates multiples of 1/2,
//           made a valid triangle mesh as the command-line tool does it (repair_polygon_soup,
//           orient_polygon_soup; see support/include/vtp_support/triangle_mesh_from_soup.h);
//     3     the convex hull of up to 12 such points.
//   the next bytes give the sizes, coordinates and diagonals; the last byte read gives the source.
// Coordinates are quantized to exact binary fractions, so a triangle is either exactly degenerate or far
// from it. (Triangles that are degenerate up to rounding, which decimal coordinates such as 0.05 give,
// are covered by the tests Degenerate.nearly_collinear_* of test_hard_meshes.cpp.)
//
// Checks (any failure prints the mesh and aborts, which libFuzzer reports with the input):
// - no crash, no sanitizer report, no exception other than Invalid_input_error at construction;
// - no NaN, no negative distance, 0 at the source;
// - finite exactly on the connected component of the source;
// - 1-Lipschitz along the edges: |d(u) - d(v)| <= |uv| + 1e-12 * scale, and d(v) >= |sv| - 1e-12 * scale,
//   scale being the largest finite distance;
// - on flat meshes of a convex polygon (no fold; degenerate triangles allowed): the Euclidean distance;
// - on the other meshes without degenerate triangle (CGAL's algorithm fails on those), agreement with
//   CGAL::Surface_mesh_shortest_path: max |d - d_cgal| <= 1e-12 * scale, same unreachable vertices;
//   where CGAL disagrees, CGAL run on the mesh subdivided once or twice (the same surface) must agree,
//   unless VTP gives the length of a straight segment that lies on the surface (CGAL itself errs on some
//   meshes; such cases are printed as notes).
// - the approximations, virtual source propagation (VSP, one and two virtual sources per vertex) and AVTP
//   (windows reset every half mean edge): 0 at the source, no NaN, finite exactly where VTP is, never
//   below VTP's distance by more than 1e-12 * scale (the upper bound), a recorded path from every reached
//   vertex to the source whose length is the distance (1e-9 * scale; checked for VTP too), and for VSP
//   with OpenMP the same bits on 2 and 3 threads (PVSP); from a point inside a face chosen by the input
//   too, against VTP from that point.
// - the paths from every vertex as the source (VTP, AVTP, VSP with one and two virtual sources per vertex):
//   the path of every reached vertex has the length of its distance (1e-9 * scale), no path query throws.
//   (Path defects show from a few sources of a mesh only: this finds them from far fewer inputs.)
// The inputs on which these checks once failed (minimised) are kept in fuzz_corpus/ and replayed by the
// ctest test fuzz_replay (vtp_fuzz_replay, fuzz_replay.cpp: the same checks without libFuzzer, built by
// every build); a new failing input goes there once the defect is fixed (`vtp_fuzz -minimize_crash=1
// -runs=3000 -exact_artifact_path=OUT INPUT` shrinks it first).
// With the environment variable VTP_FUZZ_SKIP_DEGENERATE=1, meshes with a degenerate triangle (zero area
// or zero-length edge) are skipped.
//
// Build and run (see README.md, section Robustness):
//   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
//         -DVTP_GEODESICS_BUILD_FUZZER=ON      (one command)
//   cmake --build build-fuzz --target vtp_fuzz
//   mkdir -p fuzz-corpus && ./build-fuzz/bin/vtp_fuzz fuzz-corpus -max_total_time=600

#include "vtp_test_meshes.h"

#include <CGAL/VTP_geodesics.h>
#include <vtp_support/midpoint_subdivision.h>
#include <vtp_support/shortest_path_reference.h>
#include <vtp_support/triangle_mesh_from_soup.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace vtp_test;

namespace {

const double TOLERANCE = 1e-12;

// Reads the input bytes in order; 0 once they are exhausted.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
  unsigned next() { return m_position < m_size ? m_data[m_position++] : 0u; }
  // an integer in [a, b]
  int in(int a, int b) { return a + int(next() % unsigned(b - a + 1)); }

private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_position = 0;
};

bool skip_degenerate()
{
  static const bool skip = [] {
    const char* v = std::getenv("VTP_FUZZ_SKIP_DEGENERATE");
    return v != nullptr && std::string(v) == "1";
  }();
  return skip;
}

Polygon_soup grid_soup(Bytes& bytes)
{
  const int nx = bytes.in(1, 6), ny = bytes.in(1, 6);
  const double stretch[5] = {1., 2., 0.5, 8., 0.125}; // powers of 2: coordinates stay exact
  const double sx = stretch[bytes.in(0, 4)], sy = stretch[bytes.in(0, 4)];
  Polygon_soup soup;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
    {
      const unsigned b = bytes.next(), c = bytes.next();
      const double x = sx * (i + 0.25 * (int(b % 5) - 2)), y = sy * (j + 0.25 * (int((b / 5) % 5) - 2));
      soup.points.push_back(Point_3(x, y, 0.25 * (int(c % 9) - 4)));
    }
  unsigned diagonals = 0;
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      if((i + j * nx) % 8 == 0)
        diagonals = bytes.next();
      const std::size_t v00 = std::size_t(j) * (nx + 1) + i;
      add_cell(soup, v00, v00 + 1, v00 + nx + 2, v00 + nx + 1, ((diagonals >> ((i + j * nx) % 8)) & 1u) != 0);
    }
  return soup;
}

std::vector<Point_3> quantized_points(Bytes& bytes, int n)
{
  std::vector<Point_3> points;
  for(int i = 0; i < n; ++i)
  {
    const double x = 0.5 * (bytes.in(0, 8) - 4), y = 0.5 * (bytes.in(0, 8) - 4), z = 0.5 * (bytes.in(0, 8) - 4);
    points.push_back(Point_3(x, y, z));
  }
  return points;
}

// Builds the mesh; false if the input makes no mesh (a refusal of the repair is not a failure).
bool make_mesh(Bytes& bytes, Surface_mesh& mesh)
{
  const unsigned kind = bytes.next() % 4;
  if(kind < 2)
  {
    const Polygon_soup soup = grid_soup(bytes);
    mesh = to_mesh<Surface_mesh>(soup);
    return true;
  }
  const int n = bytes.in(4, 12);
  std::vector<Point_3> points = quantized_points(bytes, n);
  if(kind == 3)
  {
    Surface_mesh hull;
    CGAL::convex_hull_3(points.begin(), points.end(), hull);
    if(num_faces(hull) == 0 || !CGAL::is_triangle_mesh(hull))
      return false;
    try
    {
      mesh = to_mesh<Surface_mesh>(canonical_soup(hull)); // the same mesh for the same input, every run
    }
    catch(const std::runtime_error&)
    {
      return false;
    }
    return true;
  }
  std::vector<std::vector<std::size_t> > triangles;
  const int nt = bytes.in(1, 24);
  for(int t = 0; t < nt; ++t)
    triangles.push_back({std::size_t(bytes.in(0, n - 1)), std::size_t(bytes.in(0, n - 1)), std::size_t(bytes.in(0, n - 1))});
  std::vector<std::size_t> copy_begin;
  std::vector<Vertex_index> copies;
  try
  {
    vtp_support::triangle_mesh_from_soup(points, triangles, mesh, copy_begin, copies);
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error&)
  {
    return false;
  }
  // every vertex of the repaired mesh stands for some input point
  std::vector<unsigned char> covered(mesh.number_of_vertices(), 0);
  for(Vertex_index v : copies)
    covered[v] = 1;
  for(unsigned char c : covered)
    if(!c)
    {
      std::cerr << "vtp_fuzz: a vertex of the repaired mesh stands for no input point" << std::endl;
      std::abort();
    }
  return true;
}

bool has_degenerate_triangle(const Surface_mesh& mesh)
{
  for(Surface_mesh::Face_index f : faces(mesh))
  {
    const Surface_mesh::Halfedge_index h = mesh.halfedge(f);
    if(CGAL::collinear(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                       mesh.point(mesh.target(mesh.next(h)))))
      return true;
  }
  return false;
}

// True iff the faces of `mesh` form a flat topological disk without fold whose boundary is a convex polygon:
// then the geodesic distance between two of its vertices is their Euclidean distance.
bool is_flat_convex_disk(const Surface_mesh& mesh)
{
  std::vector<Point_3> points;
  for(Vertex_index v : vertices(mesh))
    if(!mesh.is_isolated(v))
      points.push_back(mesh.point(v));
  if(points.size() < 3 || num_faces(mesh) == 0)
    return false;
  // a plane through three non-collinear points, and the coordinate axis it is the least parallel to
  std::size_t a = 1, b = 2;
  while(a < points.size() && points[a] == points[0])
    ++a;
  for(b = a + 1; b < points.size() && CGAL::collinear(points[0], points[a], points[b]); ++b)
  {}
  if(b >= points.size())
    return false;
  for(const Point_3& p : points)
    if(!CGAL::coplanar(points[0], points[a], points[b], p))
      return false;
  const Vector_3 normal = CGAL::cross_product(points[a] - points[0], points[b] - points[0]);
  int axis = 0;
  for(int k = 1; k < 3; ++k)
    if(std::abs(normal[k]) > std::abs(normal[axis]))
      axis = k;
  auto project = [axis](const Point_3& p) {
    return Point_2(p[(axis + 1) % 3], p[(axis + 2) % 3]);
  };
  // no fold: all triangles turn the same way
  CGAL::Orientation orientation = CGAL::COLLINEAR;
  double area = 0.;
  for(Surface_mesh::Face_index f : faces(mesh))
  {
    const Surface_mesh::Halfedge_index h = mesh.halfedge(f);
    const Point_2 p = project(mesh.point(mesh.source(h))), q = project(mesh.point(mesh.target(h))),
                  r = project(mesh.point(mesh.target(mesh.next(h))));
    const CGAL::Orientation o = CGAL::orientation(p, q, r);
    if(o == CGAL::COLLINEAR)
      continue; // a degenerate triangle: zero area, no fold by itself
    if(orientation != CGAL::COLLINEAR && o != orientation)
      return false;
    orientation = o;
    area += std::abs(CGAL::area(p, q, r));
  }
  // a disk: connected, one boundary loop, Euler characteristic 1
  std::size_t border_loops = 0, border_edges = 0;
  Surface_mesh::Halfedge_index first = Surface_mesh::null_halfedge();
  for(Surface_mesh::Halfedge_index h : halfedges(mesh))
    if(mesh.is_border(h))
    {
      ++border_edges;
      first = h;
    }
  if(first == Surface_mesh::null_halfedge())
    return false;
  std::vector<Point_2> loop;
  for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_face(first, mesh))
    loop.push_back(project(mesh.point(mesh.target(h))));
  border_loops = (loop.size() == border_edges) ? 1 : 2;
  const long euler = long(points.size()) - long(num_edges(mesh)) + long(num_faces(mesh));
  if(border_loops != 1 || euler != 1)
    return false;
  // the boundary loop is convex (collinear vertices allowed, but no turning back: a slit would be
  // boundary traversed both ways) and encloses the area of the triangles
  {
    std::vector<Point_2> distinct;
    for(const Point_2& p : loop)
      if(distinct.empty() || p != distinct.back())
        distinct.push_back(p);
    while(distinct.size() > 1 && distinct.back() == distinct.front())
      distinct.pop_back();
    loop.swap(distinct);
  }
  if(loop.size() < 3)
    return false;
  CGAL::Orientation turn = CGAL::COLLINEAR;
  for(std::size_t i = 0; i < loop.size(); ++i)
  {
    const Point_2& p0 = loop[i];
    const Point_2& p1 = loop[(i + 1) % loop.size()];
    const Point_2& p2 = loop[(i + 2) % loop.size()];
    const CGAL::Orientation o = CGAL::orientation(p0, p1, p2);
    if(o == CGAL::COLLINEAR)
    {
      if(!((p1 - p0) * (p2 - p1) > 0.))
        return false;
      continue;
    }
    if(turn != CGAL::COLLINEAR && o != turn)
      return false;
    turn = o;
  }
  if(turn == CGAL::COLLINEAR || !(area > 0.))
    return false;
  // every vertex lies in the polygon (a vertex reached only through zero-area faces may lie outside)
  for(const Point_3& p : points)
    for(std::size_t i = 0; i < loop.size(); ++i)
    {
      const CGAL::Orientation o = CGAL::orientation(loop[i], loop[(i + 1) % loop.size()], project(p));
      if(o != CGAL::COLLINEAR && o != turn)
        return false;
    }
  double loop_area = 0.;
  for(std::size_t i = 1; i + 1 < loop.size(); ++i)
    loop_area += CGAL::area(loop[0], loop[i], loop[i + 1]);
  return std::abs(std::abs(loop_area) - area) <= 1e-12 * area;
}

// True iff the segment [p, q] lies on the surface (tested at 1000 points along it): its length is then the
// geodesic distance between p and q (the Euclidean distance is a lower bound).
bool segment_on_surface(const Surface_mesh& mesh, const Point_3& p, const Point_3& q)
{
  const double tolerance = 1e-9 * std::sqrt(CGAL::squared_distance(p, q));
  for(int k = 0; k <= 1000; ++k)
  {
    const Point_3 x = p + (q - p) * (double(k) / 1000.);
    bool on_a_face = false;
    for(Surface_mesh::Face_index f : faces(mesh))
    {
      const Surface_mesh::Halfedge_index h = mesh.halfedge(f);
      const Kernel::Triangle_3 t(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)),
                                 mesh.point(mesh.target(mesh.next(h))));
      if(CGAL::squared_distance(x, t) <= tolerance * tolerance)
      {
        on_a_face = true;
        break;
      }
    }
    if(!on_a_face)
      return false;
  }
  return true;
}

[[noreturn]] void fail(const Surface_mesh& mesh, Vertex_index s, const std::vector<double>& d,
                       const std::vector<double>* reference, const std::string& what)
{
  std::cerr.precision(17);
  std::cerr << "vtp_fuzz: FAILURE: " << what << "\nsource " << std::size_t(s) << "\nmesh:\n";
  CGAL::IO::write_OFF(std::cerr, mesh, CGAL::parameters::stream_precision(17));
  std::cerr << "distances:";
  for(std::size_t i = 0; i < d.size(); ++i)
    std::cerr << ' ' << d[i];
  if(reference != nullptr)
  {
    std::cerr << "\nCGAL:";
    for(double x : *reference)
      std::cerr << ' ' << x;
  }
  std::cerr << std::endl;
  std::abort();
}

double length(const Surface_mesh& mesh, Vertex_index u, Vertex_index v)
{
  return std::sqrt(CGAL::squared_distance(mesh.point(u), mesh.point(v)));
}

typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> Solver;
namespace VP = CGAL::VTP_geodesics::parameters;

// The distances of a run of `solver` from `source` (a vertex or a face location) with the named parameters np.
template <class Source, class NamedParameters>
std::vector<double> run(Solver& solver, const Source& source, const NamedParameters& np)
{
  solver.compute(vtp_test::Discard_map(), source, np);
  return solver.distances();
}

// The checks of the approximations, VSP and AVTP (see the comment at the top), from `source`, whose exact
// distances (VTP) are `exact`.
template <class Source>
void check_approximations(const Surface_mesh& mesh, Vertex_index s, const Source& source,
                           const std::vector<double>& exact, double tolerance, const std::string& from)
{
  double scale = 0.;
  for(double x : exact)
    if(std::isfinite(x))
      scale = (std::max)(scale, x);
  // 1 and 2: VSP with one or two virtual sources per vertex; 0: AVTP with windows reset every half mean
  // edge; -1: VTP itself (its paths)
  for(int per_vertex : {1, 2, 0, -1})
  {
    const std::string what = from + ", "
                             + (per_vertex == 0  ? std::string("AVTP (lambda 0.5)")
                                : per_vertex < 0 ? std::string("VTP")
                                                 : std::to_string(per_vertex) + " virtual source(s) per vertex")
                             + ": ";
    Solver solver(mesh);
    const std::vector<double> d =
        per_vertex == 0  ? run(solver, source, VP::lambda(0.5).record_paths(true))
        : per_vertex < 0 ? run(solver, source, VP::record_paths(true))
                         : run(solver, source, VP::virtual_sources(true).virtual_sources_per_vertex(per_vertex).record_paths(true));
    if(d.size() != exact.size())
      fail(mesh, s, d, &exact, what + "not one distance per vertex");
    for(std::size_t i = 0; i < d.size(); ++i)
    {
      const std::string at = " at vertex " + std::to_string(i) + " (VTP in the second list)";
      if(std::isnan(d[i]) || d[i] < 0.)
        fail(mesh, s, d, &exact, what + "NaN or negative distance" + at);
      if(std::isfinite(d[i]) != std::isfinite(exact[i]))
        fail(mesh, s, d, &exact, what + "finite where VTP is not, or the other way" + at);
      if(std::isfinite(d[i]) && d[i] < exact[i] - tolerance)
        fail(mesh, s, d, &exact, what + "below the exact distance" + at);
      if(std::isfinite(d[i]) && exact[i] == 0. && d[i] != 0.)
        fail(mesh, s, d, &exact, what + "not 0 at the source" + at);
      if(!std::isfinite(d[i]))
        continue;
      const Vertex_index v(static_cast<Surface_mesh::size_type>(i));
      std::vector<Point_3> path;
      try
      {
        solver.shortest_path_points(v, std::back_inserter(path));
      }
      catch(const std::exception& e)
      {
        fail(mesh, s, d, &exact, what + "no path: " + e.what() + at);
      }
      double path_length = 0.;
      for(std::size_t k = 1; k < path.size(); ++k)
        path_length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
      if(path.empty() || path.front() != mesh.point(v) || std::abs(path_length - d[i]) > 1e-9 * (std::max)(scale, 1e-300))
        fail(mesh, s, d, &exact, what + "the path does not start at the vertex or its length " + std::to_string(path_length)
                                     + " is not the distance" + at);
    }
#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
    for(int threads : {2, 3})
    {
      if(per_vertex <= 0)
        break;
      std::vector<double> dp(d.size());
      solver.compute<CGAL::Parallel_tag>(vtp_test::Discard_map(), source,
                                         VP::virtual_sources(true).virtual_sources_per_vertex(per_vertex)
                                           .number_of_threads(threads));
      dp = solver.distances();
      for(std::size_t i = 0; i < d.size(); ++i)
        if(!(dp[i] == d[i]) && !(std::isinf(dp[i]) && std::isinf(d[i])))
          fail(mesh, s, dp, &d, what + "PVSP on " + std::to_string(threads)
                                  + " threads (first list) differs from VSP (second) at vertex " + std::to_string(i));
    }
#endif
  }
}

// The paths from every vertex as the source (see the comment at the top): for VTP, AVTP (lambda 0.5) and VSP with
// one and two virtual sources per vertex, the path of every reached vertex starts at it and has the length of
// its distance (1e-9 * scale), and no path query throws.
void check_paths_from_every_vertex(const Surface_mesh& mesh)
{
  Solver solver(mesh);
  for(Vertex_index s : vertices(mesh))
    for(int method = 0; method < 4; ++method)
    {
      const std::string what = std::string("paths from every vertex, ")
                               + (method == 0 ? "VTP" : method == 1 ? "AVTP (lambda 0.5)"
                                                      : std::to_string(method - 1) + " virtual source(s) per vertex")
                               + ", from vertex " + std::to_string(std::size_t(s)) + ": ";
      const std::vector<double> d =
          method == 0   ? run(solver, s, VP::record_paths(true))
          : method == 1 ? run(solver, s, VP::lambda(0.5).record_paths(true))
                        : run(solver, s, VP::virtual_sources(true).virtual_sources_per_vertex(method - 1).record_paths(true));
      double scale = 0.;
      for(double x : d)
        if(std::isfinite(x))
          scale = (std::max)(scale, x);
      std::vector<Point_3> path;
      for(Vertex_index v : vertices(mesh))
      {
        if(!std::isfinite(d[v]))
          continue;
        const std::string at = "vertex " + std::to_string(std::size_t(v));
        path.clear();
        try
        {
          solver.shortest_path_points(v, std::back_inserter(path));
        }
        catch(const std::exception& e)
        {
          fail(mesh, s, d, nullptr, what + "no path: " + e.what() + " at " + at);
        }
        double path_length = 0.;
        for(std::size_t k = 1; k < path.size(); ++k)
          path_length += std::sqrt(CGAL::squared_distance(path[k - 1], path[k]));
        if(path.empty() || path.front() != mesh.point(v) || std::abs(path_length - d[v]) > 1e-9 * (std::max)(scale, 1e-300))
          fail(mesh, s, d, nullptr, what + "the path does not start at the vertex or its length " + std::to_string(path_length)
                                      + " is not the distance at " + at);
      }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes bytes(data, size);
  Surface_mesh mesh;
  if(!make_mesh(bytes, mesh) || mesh.number_of_vertices() == 0)
    return 0;
  const bool degenerate = has_degenerate_triangle(mesh);
  if(degenerate && skip_degenerate())
    return 0;
  const std::size_t nv = mesh.number_of_vertices();
  const Vertex_index s(static_cast<Surface_mesh::size_type>(bytes.next() % nv));

  std::vector<double> d;
  try
  {
    CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> solver(mesh);
    solver.compute(vtp_test::Discard_map(), s);
    d = solver.distances();
  }
  catch(const CGAL::VTP_geodesics::Invalid_input_error& e)
  {
    fail(mesh, s, d, nullptr, std::string("valid mesh refused: ") + e.what());
  }

  // reachability by a search over the edges
  std::vector<unsigned char> reached(nv, 0);
  std::vector<Vertex_index> stack(1, s);
  reached[s] = 1;
  while(!stack.empty())
  {
    const Vertex_index v = stack.back();
    stack.pop_back();
    if(mesh.is_isolated(v))
      continue;
    for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
      if(!reached[mesh.source(h)])
      {
        reached[mesh.source(h)] = 1;
        stack.push_back(mesh.source(h));
      }
  }

  double scale = 0.;
  for(double x : d)
    if(std::isfinite(x))
      scale = (std::max)(scale, x);
  const double tolerance = TOLERANCE * (std::max)(scale, 1e-300);
  if(!(d[s] == 0.))
    fail(mesh, s, d, nullptr, "the source is not at distance 0");
  for(Vertex_index v : vertices(mesh))
  {
    if(std::isnan(d[v]) || d[v] < 0.)
      fail(mesh, s, d, nullptr, "NaN or negative distance at vertex " + std::to_string(std::size_t(v)));
    if(std::isfinite(d[v]) != bool(reached[v]))
      fail(mesh, s, d, nullptr, "vertex " + std::to_string(std::size_t(v)) + " is " + (reached[v] ? "" : "not ")
                                  + "in the component of the source, but its distance is " + std::to_string(d[v]));
    if(std::isfinite(d[v]) && d[v] < length(mesh, s, v) - tolerance)
      fail(mesh, s, d, nullptr, "distance below the Euclidean distance at vertex " + std::to_string(std::size_t(v)));
  }
  for(Surface_mesh::Edge_index e : edges(mesh))
  {
    const Vertex_index u = mesh.vertex(e, 0), v = mesh.vertex(e, 1);
    if(std::isfinite(d[u]) && std::abs(d[u] - d[v]) > length(mesh, u, v) + tolerance)
      fail(mesh, s, d, nullptr,
           "not 1-Lipschitz along the edge (" + std::to_string(std::size_t(u)) + ", " + std::to_string(std::size_t(v)) + ")");
  }

  if(!mesh.is_isolated(s) && is_flat_convex_disk(mesh))
  {
    for(Vertex_index v : vertices(mesh))
      if(!mesh.is_isolated(v) && std::abs(d[v] - length(mesh, s, v)) > tolerance)
        fail(mesh, s, d, nullptr, "flat convex mesh: not the Euclidean distance at vertex " + std::to_string(std::size_t(v)));
  }
  else if(!degenerate)
  {
    // CGAL's algorithm itself errs on some meshes (e.g. a flat grid of 5 x 3 squares, all diagonals alike,
    // where it misses the straight path between opposite corners). Where it disagrees, it is run again
    // on the 1-to-4 midpoint subdivision of the mesh, then on the subdivision of that (the same surface,
    // the original vertices first); and a vertex where VTP gives the length of a straight segment lying
    // on the surface is right whatever CGAL says.
    auto agrees = [&](const std::vector<double>& reference, std::size_t i) {
      return std::isfinite(reference[i]) == std::isfinite(d[i])
             && !(std::isfinite(d[i]) && std::abs(d[i] - reference[i]) > tolerance);
    };
    const std::vector<double> reference = vtp_support::shortest_path_reference_distances(mesh, s);
    std::vector<double> fine[2]; // CGAL on the mesh subdivided once and twice
    auto cgal_on_subdivided = [&](int levels) -> const std::vector<double>& {
      std::vector<double>& r = fine[levels - 1];
      if(r.empty())
      {
        Surface_mesh subdivided = mesh;
        vtp_support::midpoint_subdivide(subdivided, levels);
        r = vtp_support::shortest_path_reference_distances(subdivided, s);
        r.resize(nv);
      }
      return r;
    };
    for(std::size_t i = 0; i < nv; ++i)
    {
      if(agrees(reference, i))
        continue;
      const Vertex_index v(static_cast<Surface_mesh::size_type>(i));
      std::string why;
      if(agrees(cgal_on_subdivided(1), i))
        why = "CGAL on the subdivided mesh agrees with VTP";
      else if(agrees(cgal_on_subdivided(2), i))
        why = "CGAL on the mesh subdivided twice agrees with VTP";
      else if(std::isfinite(d[i]) && std::abs(d[i] - length(mesh, s, v)) <= tolerance
              && segment_on_surface(mesh, mesh.point(s), mesh.point(v)))
        why = "VTP gives the length of a straight segment on the surface";
      else
        fail(mesh, s, d, &reference, "differs from CGAL at vertex " + std::to_string(i) + ", also on the subdivided meshes");
      static std::size_t notes = 0;
      if(notes++ < 20)
        std::cerr << "vtp_fuzz: note: VTP differs from CGAL at vertex " << i << " (" << d[i] << " vs "
                  << reference[i] << "): " << why << std::endl;
    }
  }

  // the approximations, from the source vertex and from a point inside a face; the paths from every vertex
  check_approximations(mesh, s, s, d, tolerance, "from the vertex");
  check_paths_from_every_vertex(mesh);
  if(num_faces(mesh) > 0)
  {
    const unsigned a = 1u + bytes.next() % 8u, b = 1u + bytes.next() % 8u, f = bytes.next() % num_faces(mesh);
    const Solver::Face_location point(Surface_mesh::Face_index(static_cast<Surface_mesh::size_type>(f)),
                                      {{a / 18., b / 18., 1. - (a + b) / 18.}});
    Solver solver(mesh);
    solver.compute(vtp_test::Discard_map(), point);
    const std::vector<double> exact = solver.distances();
    double point_scale = 0.;
    for(double x : exact)
      if(std::isfinite(x))
        point_scale = (std::max)(point_scale, x);
    check_approximations(mesh, s, point, exact, TOLERANCE * (std::max)(point_scale, 1e-300),
                          "from a point in face " + std::to_string(f));
  }
  return 0;
}
