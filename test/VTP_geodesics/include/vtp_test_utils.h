// Helpers of the VTP_geodesics tests: data files, running the solver on a Surface_mesh, comparing
// distance vectors with a relative tolerance, and finding boundary and saddle vertices.

#ifndef VTP_TEST_UTILS_H
#define VTP_TEST_UTILS_H

#include "vtp_test_meshes.h"

#include <CGAL/VTP_geodesics.h>
#include <CGAL/VTP_geodesics/internal/parallel/Round_team.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#ifndef VTP_TEST_DATA_DIR
#define VTP_TEST_DATA_DIR "data"
#endif

namespace vtp_test {

const double INF = std::numeric_limits<double>::infinity();
const double NOT_A_VERTEX = std::numeric_limits<double>::quiet_NaN();

// Relative tolerance of the exact algorithm: |d - d_expected| <= EXACT_TOLERANCE * max finite d_expected.
const double EXACT_TOLERANCE = 1e-12;

inline std::string data_file(const std::string& name) { return std::string(VTP_TEST_DATA_DIR) + "/" + name; }

// Reads a triangle mesh of the test data folder (throws if it cannot, so that the test fails loudly).
inline Surface_mesh load_mesh(const std::string& name)
{
  Surface_mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data_file(name), mesh) || num_vertices(mesh) == 0)
    throw std::runtime_error("cannot read the test mesh " + data_file(name));
  if(!CGAL::is_triangle_mesh(mesh))
    throw std::runtime_error("the test mesh " + name + " is not a triangle mesh");
  return mesh;
}

// Size of a vector indexed by the vertex indices of `mesh` (removed vertices included).
inline std::size_t index_range(const Surface_mesh& mesh)
{
  return static_cast<std::size_t>(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
}

// Runs the solver from `source` (a vertex, a face location, or a range of either) with the named
// parameters `np` and returns the distances indexed by vertex index, written through the public output
// property map. Entries of removed vertices (and of vertices the solver did not write) are NaN.
template <class ConcurrencyTag = CGAL::Sequential_tag, class Sources,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<double>
vtp_distances(const Surface_mesh& mesh, const Sources& source, const NamedParameters& np = CGAL::parameters::default_values(),
              CGAL::VTP_geodesics::Propagation_statistics* statistics = nullptr)
{
  std::vector<double> distances(index_range(mesh), NOT_A_VERTEX);
  CGAL::VTP_geodesics::Geodesic_distance_solver<Surface_mesh> solver(mesh);
  solver.template compute<ConcurrencyTag>(
    boost::make_iterator_property_map(distances.begin(), get(boost::vertex_index, mesh)), source, np);
  if(statistics != nullptr)
    *statistics = solver.statistics();
  return distances;
}

// Mean over the reached vertices (source excluded) of (d - d_exact) / d_exact.
inline double mean_relative_error(const std::vector<double>& d, const std::vector<double>& exact)
{
  double sum = 0.;
  std::size_t n = 0;
  for(std::size_t i = 0; i < d.size(); ++i)
    if(exact[i] > 0. && std::isfinite(exact[i]))
    {
      sum += (d[i] - exact[i]) / exact[i];
      ++n;
    }
  return n > 0 ? sum / double(n) : 0.;
}

// Largest finite entry (0 if none).
inline double max_finite(const std::vector<double>& values)
{
  double m = 0.;
  for(double x : values)
    if(std::isfinite(x))
      m = (std::max)(m, x);
  return m;
}

// Compares two results for exact equality (+infinity included), reporting the first difference.
inline ::testing::AssertionResult identical(const std::vector<double>& a, const std::vector<double>& b)
{
  if(a.size() != b.size())
    return ::testing::AssertionFailure() << "sizes differ: " << a.size() << " and " << b.size();
  for(std::size_t i = 0; i < a.size(); ++i)
    if(!(a[i] == b[i]))
      return ::testing::AssertionFailure() << "first difference at vertex " << i << ": " << a[i] << " and " << b[i];
  return ::testing::AssertionSuccess();
}

// Compares `actual` with `expected` entry by entry. Entries where `expected` is NaN are not vertices and
// are skipped; where `expected` is +infinity, `actual` must be +infinity; elsewhere `actual` must be
// finite with |actual - expected| <= relative_tolerance * (largest finite expected value).
// Prints the largest relative difference found (also on success, to show the margin).
inline ::testing::AssertionResult
distances_near(const std::vector<double>& actual, const std::vector<double>& expected, double relative_tolerance,
               const std::string& what = "")
{
  if(actual.size() != expected.size())
    return ::testing::AssertionFailure() << what << ": " << actual.size() << " distances, expected "
                                         << expected.size();
  double scale = max_finite(expected);
  if(!(scale > 0.))
    scale = 1.;
  const double tolerance = relative_tolerance * scale;
  std::size_t compared = 0, failures = 0, worst = 0;
  double worst_error = -1.;
  std::ostringstream details;
  details.precision(17);
  for(std::size_t i = 0; i < expected.size(); ++i)
  {
    const double e = expected[i], a = actual[i];
    if(std::isnan(e))
      continue;
    ++compared;
    double error;
    if(std::isinf(e))
      error = (a == e) ? 0. : INF;
    else
      error = std::isfinite(a) ? std::abs(a - e) : INF;
    if(!(error <= tolerance))
    {
      if(failures < 5)
        details << "\n  vertex " << i << ": got " << a << ", expected " << e;
      ++failures;
    }
    if(!(error <= worst_error))
    {
      worst_error = error;
      worst = i;
    }
  }
  std::cout << "  [" << what << "] " << compared << " vertices, max |d - d_expected| / max_d = "
            << (worst_error / scale) << " (tolerance " << relative_tolerance << ")" << std::endl;
  if(failures == 0)
    return ::testing::AssertionSuccess();
  std::ostringstream message;
  message.precision(17);
  message << what << ": " << failures << " of " << compared << " vertices off by more than " << relative_tolerance
          << " * " << scale << "; worst: vertex " << worst << ", got " << actual[worst] << ", expected "
          << expected[worst] << " (relative error " << worst_error / scale << ")" << details.str();
  return ::testing::AssertionFailure() << message.str();
}

// Sum of the corner angles at `v`.
inline double angle_sum(const Surface_mesh& mesh, Vertex_index v)
{
  double sum = 0.;
  for(Surface_mesh::Halfedge_index h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
  {
    if(mesh.is_border(h))
      continue;
    const Point_3& p = mesh.point(v);
    const Vector_3 a = mesh.point(mesh.source(h)) - p;
    const Vector_3 b = mesh.point(mesh.target(mesh.next(h))) - p;
    const double c = (a * b) / std::sqrt(a.squared_length() * b.squared_length());
    sum += std::acos((std::max)(-1., (std::min)(1., c)));
  }
  return sum;
}

// The interior vertex of largest angle sum, if that sum exceeds 2 pi (a saddle vertex); else null_vertex().
inline Vertex_index strongest_saddle_vertex(const Surface_mesh& mesh)
{
  Vertex_index best = Surface_mesh::null_vertex();
  double best_sum = 2. * PI + 1e-6;
  for(Vertex_index v : vertices(mesh))
  {
    if(mesh.is_isolated(v) || mesh.is_border(v))
      continue;
    const double s = angle_sum(mesh, v);
    if(s > best_sum)
    {
      best_sum = s;
      best = v;
    }
  }
  return best;
}

// The first vertex (in index order) on the boundary, or null_vertex().
inline Vertex_index first_boundary_vertex(const Surface_mesh& mesh)
{
  for(Vertex_index v : vertices(mesh))
    if(!mesh.is_isolated(v) && mesh.is_border(v))
      return v;
  return Surface_mesh::null_vertex();
}

// The vertex whose point is exactly `p`, or null_vertex().
template <class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor find_vertex(const Mesh& mesh, const Point_3& p)
{
  for(auto v : vertices(mesh))
    if(get(CGAL::vertex_point, mesh, v) == p)
      return v;
  return boost::graph_traits<Mesh>::null_vertex();
}

// The polygon soup of the live elements of `mesh` (removed ones skipped); the live vertices keep their
// relative order. `new_index` (if given) receives, per vertex index of `mesh`, the index of the vertex in
// the soup (std::size_t(-1) for removed vertices).
inline Polygon_soup to_soup(const Surface_mesh& mesh, std::vector<std::size_t>* new_index = nullptr)
{
  Polygon_soup soup;
  std::vector<std::size_t> index(index_range(mesh), std::size_t(-1));
  for(Vertex_index v : vertices(mesh))
  {
    index[v] = soup.points.size();
    soup.points.push_back(mesh.point(v));
  }
  for(Surface_mesh::Face_index f : faces(mesh))
  {
    std::vector<std::size_t> polygon;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(index[v]);
    soup.polygons.push_back(polygon);
  }
  if(new_index != nullptr)
    *new_index = index;
  return soup;
}

// Euclidean distance between two points.
inline double distance(const Point_3& a, const Point_3& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

// The length of a polyline.
inline double polyline_length(const std::vector<Point_3>& p)
{
  double l = 0.;
  for(std::size_t i = 1; i < p.size(); ++i)
    l += distance(p[i - 1], p[i]);
  return l;
}

// A point of a face given by barycentric coordinates with respect to the vertices of the face (starting
// at the source of its half-edge).
inline Point_3 point_of(const Surface_mesh& mesh,
                        const std::pair<Surface_mesh::Face_index, std::array<double, 3> >& location)
{
  const Surface_mesh::Halfedge_index h = mesh.halfedge(location.first);
  const Point_3& a = mesh.point(mesh.source(h));
  const Point_3& b = mesh.point(mesh.target(h));
  const Point_3& c = mesh.point(mesh.target(mesh.next(h)));
  const std::array<double, 3>& w = location.second;
  return Point_3(w[0] * a.x() + w[1] * b.x() + w[2] * c.x(), w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                 w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
}

// The elephant of the test data (read once).
inline const Surface_mesh& elephant()
{
  static const Surface_mesh mesh = load_mesh("elephant.off");
  return mesh;
}

// A method of the tests that run several: its name, whether it runs with CGAL::Parallel_tag, and its
// lambda (infinity for the exact methods).
struct Method
{
  const char* name;
  bool parallel;
  double lambda;
};

// While it lives, thread `late` of the parallel teams (PVTP, PAVTP, PVSP) is made late, as a thread that the
// system stops for another process: it sleeps 1 ms before every fifth work item it takes, and, if it is the
// master, before every fifth round it publishes too (through round_team_test_hook()). calls(): the calls of
// the hook by that thread since the object was made (a test checks the delay did happen).
class Late_thread
{
public:
  explicit Late_thread(int late)
  {
    thread() = late;
    count() = 0;
    CGAL::VTP_geodesics::internal::round_team_test_hook() = &hook;
  }
  ~Late_thread()
  {
    CGAL::VTP_geodesics::internal::round_team_test_hook() = nullptr;
    thread() = -100;
  }
  Late_thread(const Late_thread&) = delete;
  Late_thread& operator=(const Late_thread&) = delete;

  int calls() const { return count().load(); }

private:
  static std::atomic<int>& thread()
  {
    static std::atomic<int> t{ -100 };
    return t;
  }
  static std::atomic<int>& count()
  {
    static std::atomic<int> c{ 0 };
    return c;
  }
  static void hook(int t)
  {
    const int late = thread().load();
    if((t == late || t == -1 - late) && ++count() % 5 == 0)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
};

} // namespace vtp_test

#endif // VTP_TEST_UTILS_H
