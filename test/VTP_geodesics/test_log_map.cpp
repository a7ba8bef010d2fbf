// The tangent frame shared by the log map and the straightest geodesics (internal/Tangent_frame.h): on the
// plane, the angles of the edges around an interior vertex (sum 2 pi, scale 1) and a border vertex (scaled
// to pi), the reference of a vertex (source(halfedge(v))) and of a face location (halfedge(f)), 3D
// directions projected.

#include "vtp_test_meshes.h"

#include <CGAL/VTP_geodesics.h>
#include <CGAL/VTP_geodesics/internal/Tangent_frame.h>
#include <CGAL/VTP_geodesics/internal/solver/Mesh_import.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

using namespace vtp_test;
namespace VI = CGAL::VTP_geodesics::internal;

namespace {

typedef VI::Mesh_index<Surface_mesh> Frame_test_index;

struct Frame_test_mesh
{
  Surface_mesh mesh;
  Frame_test_index index;
  explicit Frame_test_mesh(const Polygon_soup& soup) : mesh(to_mesh<Surface_mesh>(soup)), index(mesh)
  {
    VI::import_mesh(index, get(CGAL::vertex_point, mesh), CGAL::VTP_geodesics::Geodesic_traits_3<Kernel>(), 1);
  }
  VI::Index id(Vertex_index v) const { return get(index.vertex_id, v); }
  VI::Vector_3d point(VI::Index i) const
  {
    const Point_3& p = mesh.point(index.vertices[static_cast<std::size_t>(i)]);
    return {p.x(), p.y(), p.z()};
  }
  // the Euclidean direction (in the plane z = 0) of the half-edge h of the arrays
  double direction(VI::Index h) const
  {
    const VI::Vector_3d a = point(index.arrays.source[h]), b = point(index.arrays.target(h));
    return std::atan2(b[1] - a[1], b[0] - a[0]);
  }
};

double angle_difference(double a, double b) { return std::abs(std::remainder(a - b, 2. * PI)); }

TEST(TangentFrame, InteriorVertexOfThePlane)
{
  const int n = 6;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 7);
  Frame_test_mesh m(soup);
  const Vertex_index v(static_cast<Surface_mesh::size_type>(grid_vertex(n, 3, 2)));
  const VI::Index c = m.id(v);
  const VI::Index r = VI::vertex_reference_halfedge(m.index, v);
  ASSERT_NE(r, VI::NO_INDEX);
  // the reference goes from v to source(halfedge(v))
  EXPECT_EQ(m.index.arrays.source[r], c);
  EXPECT_EQ(m.index.arrays.target(r), m.id(source(halfedge(v, m.mesh), m.mesh)));
  VI::Vertex_frame frame;
  ASSERT_TRUE(VI::make_vertex_frame(m.index.arrays, c, r, frame));
  EXPECT_FALSE(frame.border);
  EXPECT_NEAR(frame.angle_sum, 2. * PI, 1e-13);
  EXPECT_NEAR(frame.scale, 1., 1e-13);
  EXPECT_EQ(frame.halfedges.size(), static_cast<std::size_t>(degree(v, m.mesh)));
  const double reference = m.direction(r);
  for(std::size_t i = 0; i < frame.halfedges.size(); ++i)
  {
    const VI::Index h = frame.halfedges[i];
    // counter-clockwise, the Euclidean angle from the reference
    EXPECT_NEAR(angle_difference(frame.phi[i], m.direction(h) - reference), 0., 1e-13);
    EXPECT_EQ(VI::ccw_outgoing(m.index.arrays, h), frame.halfedges[(i + 1) % frame.halfedges.size()]);
    EXPECT_EQ(VI::cw_outgoing(m.index.arrays, frame.halfedges[(i + 1) % frame.halfedges.size()]), h);
    // a direction inside the face of h, there and back
    const double alpha = 0.4 * VI::corner_angle_of(m.index.arrays, h);
    const double theta = frame.theta(h, alpha);
    VI::Index g;
    double beta;
    frame.direction(theta, g, beta);
    EXPECT_EQ(g, h);
    EXPECT_NEAR(beta, alpha, 1e-13);
    // a 3D direction (with a normal component) projected: its Euclidean angle from the reference
    const double e = reference + theta;
    const VI::Vector_3d d{std::cos(e), std::sin(e), 0.7};
    EXPECT_NEAR(angle_difference(VI::vertex_theta_of_3d(m.index.arrays, frame, [&m](VI::Index i) { return m.point(i); }, d),
                                 theta), 0., 1e-12);
  }
}

TEST(TangentFrame, BorderVertexScaledToPi)
{
  const int n = 4;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.2, 3);
  Frame_test_mesh m(soup);
  // a vertex inside the bottom side (angle sum pi) and the corner (0, 0) (angle sum pi / 2)
  for(const std::size_t p : {grid_vertex(n, 2, 0), grid_vertex(n, 0, 0)})
  {
    const Vertex_index v(static_cast<Surface_mesh::size_type>(p));
    const VI::Index c = m.id(v);
    VI::Vertex_frame frame;
    ASSERT_TRUE(VI::make_vertex_frame(m.index.arrays, c, VI::vertex_reference_halfedge(m.index, v), frame));
    EXPECT_TRUE(frame.border);
    const double sum = (p == grid_vertex(n, 0, 0)) ? PI / 2. : PI;
    EXPECT_NEAR(frame.angle_sum, sum, 1e-13);
    EXPECT_NEAR(frame.scale, PI / sum, 1e-13);
    // the reference is the border half-edge along +x; the last direction (theta = pi) the other border edge
    EXPECT_EQ(m.index.arrays.opposite[frame.reference()], VI::NO_INDEX);
    EXPECT_NEAR(angle_difference(m.direction(frame.reference()), 0.), 0., 1e-13);
    EXPECT_NEAR(frame.phi.back() * frame.scale, PI, 1e-13);
    for(std::size_t i = 0; i < frame.halfedges.size(); ++i)
      EXPECT_NEAR(frame.phi[i], m.direction(frame.halfedges[i]), 1e-13);
    // directions: into the surface, then outside (clamped to the nearer border edge)
    const auto point = [&m](VI::Index i) { return m.point(i); };
    EXPECT_NEAR(VI::vertex_theta_of_3d(m.index.arrays, frame, point, {std::cos(0.3), std::sin(0.3), 1.}),
                0.3 * frame.scale, 1e-12);
    EXPECT_NEAR(VI::vertex_theta_of_3d(m.index.arrays, frame, point, {1., -0.1, 0.}), 0., 1e-12);
  }
}

TEST(TangentFrame, FaceLocationReference)
{
  const int n = 3;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.25, 5);
  Frame_test_mesh m(soup);
  for(Surface_mesh::Face_index f : faces(m.mesh))
  {
    const VI::Index fi = m.index.face_index(f);
    const VI::Index h = VI::face_reference(fi);
    EXPECT_EQ(m.index.arrays.source[h], m.id(source(halfedge(f, m.mesh), m.mesh)));
    EXPECT_EQ(m.index.arrays.target(h), m.id(target(halfedge(f, m.mesh), m.mesh)));
    // the directions of the face's half-edges in its frame are their Euclidean angles from halfedge(f)
    for(VI::Index k = 0; k < 3; ++k)
    {
      const VI::Index g = 3 * fi + k;
      EXPECT_NEAR(angle_difference(VI::face_theta(m.index.arrays, fi, g, 0.), m.direction(g) - m.direction(h)), 0.,
                  1e-13);
      EXPECT_NEAR(VI::angle_in_halfedge_frame(m.index.arrays, fi, g, VI::face_theta(m.index.arrays, fi, g, 0.25)),
                  0.25, 1e-13);
    }
    const std::array<VI::Vector_3d, 3> corners{m.point(m.index.arrays.source[h]), m.point(m.index.arrays.target(h)),
                                               m.point(m.index.arrays.source[VI::Mesh_arrays::prev(h)])};
    const double e = m.direction(h) + 1.1;
    EXPECT_NEAR(angle_difference(VI::face_theta_of_3d(corners, {std::cos(e), std::sin(e), -2.}), 1.1), 0., 1e-12);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {0., 0., 1.}), CGAL::VTP_geodesics::Invalid_input_error);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {0., 0., 0.}), CGAL::VTP_geodesics::Invalid_input_error);
    EXPECT_THROW(VI::face_theta_of_3d(corners, {std::nan(""), 0., 0.}), CGAL::VTP_geodesics::Invalid_input_error);
  }
}

} // namespace
