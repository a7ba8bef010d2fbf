// One vocabulary (issue 46): one location type and one polyline type (Surface_polyline.h) for the solver's
// locations, its shortest paths, straightest geodesics and curves; extra results through named parameters
// (`curves_report` as `statistics`, the trailing report pointer its deprecated alias); one meaning of
// `Voronoi_cell_areas::uncertainty` (a bound of |area - true area|) for both `geodesic_voronoi_cell_areas()`,
// checked on the plane against the cells clipped to the square.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <CGAL/VTP_geodesics.h>
#include <CGAL/VTP_geodesics/Surface_polyline.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

namespace vtp_vocabulary_huge {

// A Surface_mesh that says it has 2^31 vertices (no more memory): the solver numbers vertices with 32 bits (so do
// the vertex indices of Polar_patches) and must refuse it with Invalid_input_error, not wrap around.
struct Huge_mesh : vtp_test::Surface_mesh
{
};

inline std::size_t num_vertices(const Huge_mesh&) { return std::size_t(1) << 31; }

} // namespace vtp_vocabulary_huge

namespace boost {
template <>
struct graph_traits<vtp_vocabulary_huge::Huge_mesh> : graph_traits<vtp_test::Surface_mesh>
{
};
template <class Tag>
struct property_map<vtp_vocabulary_huge::Huge_mesh, Tag> : property_map<vtp_test::Surface_mesh, Tag>
{
};
#define VTP_VOCABULARY_DYNAMIC(TAG)                                                                          \
  template <class T>                                                                                       \
  struct property_map<vtp_vocabulary_huge::Huge_mesh, CGAL::TAG<T> >                                       \
    : property_map<vtp_test::Surface_mesh, CGAL::TAG<T> >                                                  \
  {                                                                                                        \
  };
VTP_VOCABULARY_DYNAMIC(dynamic_vertex_property_t)
VTP_VOCABULARY_DYNAMIC(dynamic_halfedge_property_t)
VTP_VOCABULARY_DYNAMIC(dynamic_face_property_t)
VTP_VOCABULARY_DYNAMIC(dynamic_edge_property_t)
#undef VTP_VOCABULARY_DYNAMIC
} // namespace boost

namespace vtp_vocabulary_huge {
#define VTP_VOCABULARY_DYNAMIC_GET(TAG)                                                                      \
  template <class T>                                                                                       \
  typename boost::property_map<vtp_test::Surface_mesh, CGAL::TAG<T> >::const_type get(const CGAL::TAG<T>& t,  \
                                                                                   const Huge_mesh& m)     \
  {                                                                                                        \
    return get(t, static_cast<const vtp_test::Surface_mesh&>(m));                                          \
  }
VTP_VOCABULARY_DYNAMIC_GET(dynamic_vertex_property_t)
VTP_VOCABULARY_DYNAMIC_GET(dynamic_halfedge_property_t)
VTP_VOCABULARY_DYNAMIC_GET(dynamic_face_property_t)
VTP_VOCABULARY_DYNAMIC_GET(dynamic_edge_property_t)
#undef VTP_VOCABULARY_DYNAMIC_GET
} // namespace vtp_vocabulary_huge

using namespace vtp_test;
namespace VG = CGAL::VTP_geodesics;

namespace {

typedef VG::Geodesic_distance_solver<Surface_mesh> Vocabulary_solver;
typedef Surface_mesh::Face_index Face_index;

static_assert(std::is_same<Vocabulary_solver::Face_location, VG::Face_location<Face_index> >::value,
              "the solver's location is the package's");
static_assert(std::is_same<VG::Straightest_geodesic<Face_index, Point_3>::Face_location,
                           VG::Face_location<Face_index> >::value,
              "a straightest geodesic's location is the package's");
static_assert(std::is_same<VG::Surface_polyline<Face_index, Point_3>::Face_location,
                           VG::Face_location<Face_index> >::value,
              "a polyline's location is the package's");
static_assert(std::is_base_of<VG::Surface_polyline<Face_index, Point_3>,
                              VG::Straightest_geodesic<Face_index, Point_3> >::value,
              "a straightest geodesic is a surface polyline");
static_assert(std::is_base_of<VG::Surface_polyline<Face_index, Point_3>,
                              VG::Geodesic_curve<Face_index, Point_3> >::value,
              "a curve is a surface polyline");
static_assert(std::is_same<Vocabulary_solver::Polyline, VG::Surface_polyline<Face_index, Point_3> >::value,
              "a shortest path is a surface polyline");

Vertex_index vertex(int nx, int i, int j)
{
  return Vertex_index(static_cast<Surface_mesh::size_type>(grid_vertex(nx, i, j)));
}

// the area of the part of the unit square where (p - a) . (b - a) <= |b - a|^2 / 2 (nearer to a than to b)
double clipped_square_area(const Point_3& a, const Point_3& b)
{
  const double nx = b.x() - a.x(), ny = b.y() - a.y();
  const double c = 0.5 * (nx * (a.x() + b.x()) + ny * (a.y() + b.y()));
  const std::vector<std::array<double, 2> > square = { { { 0., 0. } }, { { 1., 0. } }, { { 1., 1. } }, { { 0., 1. } } };
  std::vector<std::array<double, 2> > kept;
  for(std::size_t i = 0; i < square.size(); ++i)
  {
    const std::array<double, 2>& p = square[i];
    const std::array<double, 2>& q = square[(i + 1) % square.size()];
    const double fp = nx * p[0] + ny * p[1] - c, fq = nx * q[0] + ny * q[1] - c;
    if(fp <= 0.)
      kept.push_back(p);
    if((fp < 0. && fq > 0.) || (fp > 0. && fq < 0.))
    {
      const double t = fp / (fp - fq);
      kept.push_back({ { p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) } });
    }
  }
  double twice = 0.;
  for(std::size_t i = 0; i < kept.size(); ++i)
  {
    const std::array<double, 2>& p = kept[i];
    const std::array<double, 2>& q = kept[(i + 1) % kept.size()];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::abs(twice);
}

} // namespace

// A shortest path as a Surface_polyline: the points and the locations of the two output-iterator forms, bit for
// bit, one location per point, each location's point the point given.
TEST(Vocabulary, ShortestPathIsASurfacePolyline)
{
  const Surface_mesh m = load_mesh("elephant.off");
  Vocabulary_solver s(m);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), Vertex_index(0), VG::parameters::record_paths(true));
  for(Vertex_index v : { Vertex_index(177), Vertex_index(526), Vertex_index(1000), Vertex_index(0) })
  {
    const Vocabulary_solver::Polyline path = s.shortest_path(v);
    std::vector<Point_3> points;
    std::vector<Vocabulary_solver::Face_location> locations;
    s.shortest_path_points(v, std::back_inserter(points));
    s.shortest_path_locations(v, std::back_inserter(locations));
    ASSERT_EQ(path.size(), points.size());
    ASSERT_EQ(path.locations.size(), path.points.size());
    EXPECT_FALSE(path.empty());
    EXPECT_TRUE(path.points == points) << v;
    EXPECT_TRUE(path.locations == locations) << v;
    EXPECT_EQ(path.points.front(), m.point(v));
  }
  // from a face location too
  const Vocabulary_solver::Face_location at(*m.faces().begin(), { { 0.2, 0.3, 0.5 } });
  const Vocabulary_solver::Polyline path = s.shortest_path(at);
  std::vector<Point_3> points;
  s.shortest_path_points(at, std::back_inserter(points));
  EXPECT_TRUE(path.points == points);
  EXPECT_EQ(path.locations.front().first, at.first);
  for(std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(path.locations.front().second[k], at.second[k], 1e-12);
  EXPECT_THROW(s.shortest_path(Vertex_index(static_cast<Surface_mesh::size_type>(m.number_of_vertices()))),
               VG::Invalid_input_error);
}

// A straightest geodesic and a curve are read as Surface_polylines.
TEST(Vocabulary, WalksAndCurvesAreSurfacePolylines)
{
  const int n = 10;
  const Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1.));
  Vocabulary_solver s(m);
  const VG::Surface_polyline<Face_index, Point_3> walk =
    s.straightest_geodesic(vertex(n, 5, 5), std::array<double, 3>{ { 1., 0., 0. } }, 0.3);
  ASSERT_EQ(walk.points.size(), walk.locations.size());
  EXPECT_NEAR(walk.points.back().x(), 0.8, 1e-12);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), vertex(n, 5, 5), VG::parameters::keep_field(true));
  for(const VG::Surface_polyline<Face_index, Point_3>& c : VG::geodesic_isolines(s, { 0.25 }))
  {
    ASSERT_EQ(c.points.size(), c.locations.size());
    for(const Point_3& p : c.points)
      EXPECT_NEAR(std::hypot(p.x() - 0.5, p.y() - 0.5), 0.25, 1e-3 / n + 1e-12);
  }
}

// The report of the curves comes back through the named parameter `curves_report`, as through the deprecated
// trailing pointer; the named parameter wins when both are given.
TEST(Vocabulary, CurvesReportIsANamedParameter)
{
  const Surface_mesh m = load_mesh("elephant.off");
  Vocabulary_solver s(m);
  s.compute(CGAL::Constant_property_map<Vertex_index, double>(), std::vector<Vertex_index>{ Vertex_index(0), Vertex_index(2000) },
            VG::parameters::keep_field(true));
  VG::Geodesic_curves_report named, trailing, unused;
  const auto a = VG::geodesic_cell_borders(s, VG::parameters::curves_report(named));
  const auto b = VG::geodesic_cell_borders(s, VG::parameters::default_values(), &trailing);
  EXPECT_GT(named.points, 0u);
  EXPECT_EQ(named.points, trailing.points);
  EXPECT_EQ(named.undecided, trailing.undecided);
  EXPECT_EQ(named.edge_fallbacks, trailing.edge_fallbacks);
  EXPECT_EQ(named.junction_fallbacks, trailing.junction_fallbacks);
  EXPECT_EQ(a.size(), b.size());
  double largest = 0.;
  for(double x : s.distances())
    largest = std::isfinite(x) ? (std::max)(largest, x) : largest;
  VG::Geodesic_curves_report both;
  VG::geodesic_isolines(s, { 0.3 * largest }, VG::parameters::chord_tolerance(1e-3).curves_report(both).exact_refinement(1),
                        &unused);
  EXPECT_GT(both.points, 0u);
  EXPECT_TRUE(std::isfinite(both.residual));
  EXPECT_EQ(unused.points, 0u);
  EXPECT_TRUE(std::isnan(unused.residual));
}

// `uncertainty[i]` bounds |areas[i] - the true area| for both functions, here on the unit square with two sources
// whose bisector is slanted (so that faces are split): the true cells are the square clipped by the bisector.
TEST(Vocabulary, VoronoiUncertaintyIsABoundForBothFunctions)
{
  const int n = 20;
  Surface_mesh m = to_mesh<Surface_mesh>(planar_grid(n, n, 1., 1.));
  Vocabulary_solver s(m);
  const std::vector<Vertex_index> two = { vertex(n, 5, 6), vertex(n, 14, 11) };
  auto labels = m.add_property_map<Vertex_index, std::size_t>("v:vocabulary_label", VG::no_source).first;
  auto distances = m.add_property_map<Vertex_index, double>("v:vocabulary_distance", 0.).first;
  s.compute(distances, two, VG::parameters::nearest_source_map(labels).keep_field(true));
  const double truth0 = clipped_square_area(m.point(two[0]), m.point(two[1]));
  const double truth[2] = { truth0, 1. - truth0 };

  const VG::Voronoi_cell_areas from_field = VG::geodesic_voronoi_cell_areas(s);
  std::vector<std::size_t> l;
  std::vector<double> d;
  for(Vertex_index v : vertices(m))
  {
    l.push_back(labels[v]);
    d.push_back(distances[v]);
  }
  const VG::Voronoi_cell_areas from_labels = VG::geodesic_voronoi_cell_areas(m, 2, l, d);
  for(const VG::Voronoi_cell_areas* r : { &from_field, &from_labels })
  {
    ASSERT_EQ(r->areas.size(), 2u);
    ASSERT_EQ(r->uncertainty.size(), 2u);
    for(std::size_t i = 0; i < 2; ++i)
    {
      EXPECT_GT(r->uncertainty[i], 0.);
      EXPECT_LE(std::abs(r->areas[i] - truth[i]), r->uncertainty[i] + 1e-12)
        << (r == &from_field ? "field" : "labels") << ", cell " << i;
    }
  }
  // the field's borders are exact here: its bound is far tighter than that of the split faces
  EXPECT_LT(from_field.uncertainty[0], from_labels.uncertainty[0]);
}

// 32-bit vertex indices (the solver's arrays, Polar_patches::vertices): a mesh of 2^31 vertices or more is refused
// at construction with a clear Invalid_input_error (the number of entries of polar patches is a std::size_t: it
// has no such bound).
TEST(Vocabulary, MoreThan2To31VerticesIsAClearError)
{
  vtp_vocabulary_huge::Huge_mesh m;
  static_cast<Surface_mesh&>(m) = to_mesh<Surface_mesh>(planar_grid(2, 2, 1., 1.));
  try
  {
    VG::Geodesic_distance_solver<vtp_vocabulary_huge::Huge_mesh> s(m, get(CGAL::vertex_point, m));
    FAIL() << "no error for 2^31 vertices";
  }
  catch(const VG::Invalid_input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("the mesh is too large (more than 2147483647 vertices"), std::string::npos)
      << e.what();
  }
  static_assert(std::is_same<decltype(VG::Polar_patches().offsets)::value_type, std::size_t>::value,
                "the entries of polar patches are counted with std::size_t");
}
