// Mesh generators of the VTP_geodesics tests.
//
// Every generator returns a polygon soup whose point i becomes vertex i of the mesh built by
// `to_mesh()` (polygon_soup_to_polygon_mesh inserts the points in order), for `Surface_mesh` and
// `Polyhedron_3` alike. The tests compute their analytic distances from the points of the soup.

#ifndef VTP_TEST_MESHES_H
#define VTP_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vtp_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef Surface_mesh::Vertex_index Vertex_index;

// A writable property map that discards what is written (the tests then read the solver's distances()).
typedef CGAL::Constant_property_map<Vertex_index, double> Discard_map;

const double PI = 3.14159265358979323846;

struct Polygon_soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;

  void add_triangle(std::size_t a, std::size_t b, std::size_t c) { polygons.push_back({a, b, c}); }

  // Appends `other` (its indices shifted), optionally translated.
  void append(const Polygon_soup& other, const Vector_3& translation = Vector_3(0, 0, 0))
  {
    const std::size_t offset = points.size();
    for(const Point_3& p : other.points)
      points.push_back(p + translation);
    for(const std::vector<std::size_t>& polygon : other.polygons)
    {
      std::vector<std::size_t> shifted;
      for(std::size_t i : polygon)
        shifted.push_back(i + offset);
      polygons.push_back(shifted);
    }
  }
};

// Builds a mesh of type `Mesh` (Surface_mesh, Polyhedron_3, ...) from the soup; vertex i is point i.
template <class Mesh>
Mesh to_mesh(const Polygon_soup& soup)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  if(num_vertices(mesh) != soup.points.size() || num_faces(mesh) != soup.polygons.size())
    throw std::runtime_error("to_mesh: the soup is not a valid polygon mesh");
  return mesh;
}

// The faces of `mesh` as a soup in a canonical order: points sorted lexicographically, each polygon
// starting at its smallest index (orientation kept), polygons sorted. CGAL::convex_hull_3 builds the
// same hull with vertices and faces in an order that changes from run to run (it depends on memory
// addresses), which would make seeded random meshes and fuzzer inputs irreproducible.
inline Polygon_soup canonical_soup(const Surface_mesh& mesh)
{
  std::vector<Vertex_index> order(mesh.vertices().begin(), mesh.vertices().end());
  std::sort(order.begin(), order.end(),
            [&mesh](Vertex_index a, Vertex_index b) { return mesh.point(a) < mesh.point(b); });
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  Polygon_soup soup;
  for(Vertex_index v : order)
  {
    index[v] = soup.points.size();
    soup.points.push_back(mesh.point(v));
  }
  for(Surface_mesh::Face_index f : mesh.faces())
  {
    std::vector<std::size_t> polygon;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(index[v]);
    std::rotate(polygon.begin(), std::min_element(polygon.begin(), polygon.end()), polygon.end());
    soup.polygons.push_back(polygon);
  }
  std::sort(soup.polygons.begin(), soup.polygons.end());
  return soup;
}

// The side k of triangle t (from t[k] to t[k + 1]) that joins a and b, in either direction; 3 if none.
inline int side_of_edge(const std::vector<std::size_t>& t, std::size_t a, std::size_t b)
{
  for(int k = 0; k < 3; ++k)
    if((t[k] == a && t[(k + 1) % 3] == b) || (t[k] == b && t[(k + 1) % 3] == a))
      return k;
  return 3;
}

// Splits the edge (a, b) of the faces (a, b, c) and (b, a, d) of `soup` at a new vertex m placed at
// `m_position`, into (a, m, c), (m, b, c), (b, m, d), (m, a, d). Returns m.
inline std::size_t split_edge(Polygon_soup& soup, std::size_t a, std::size_t b, const Point_3& m_position)
{
  const std::size_t m = soup.points.size();
  soup.points.push_back(m_position);
  std::vector<std::vector<std::size_t> > out;
  for(const std::vector<std::size_t>& t : soup.polygons)
  {
    const int k = side_of_edge(t, a, b);
    if(k == 3)
    {
      out.push_back(t);
      continue;
    }
    out.push_back({t[k], m, t[(k + 2) % 3]});
    out.push_back({m, t[(k + 1) % 3], t[(k + 2) % 3]});
  }
  soup.polygons = out;
  return m;
}

// Inserts a zero-area "sliver" at the edge a -> b: its face (a, b, c) becomes (a, m, c), (m, b, c) and the
// sliver (a, b, m), m being the midpoint of ab; the face (b, a, d) stays, glued to the sliver along ab.
// The surface is unchanged. Returns m.
inline std::size_t insert_sliver(Polygon_soup& soup, std::size_t a, std::size_t b)
{
  const std::size_t m = soup.points.size();
  soup.points.push_back(CGAL::midpoint(soup.points[a], soup.points[b]));
  std::vector<std::vector<std::size_t> > out;
  for(const std::vector<std::size_t>& t : soup.polygons)
  {
    const int k = side_of_edge(t, a, b);
    if(k == 3 || t[k] != a)
    {
      out.push_back(t);
      continue;
    }
    const std::size_t c = t[(k + 2) % 3];
    out.push_back({a, m, c});
    out.push_back({m, b, c});
    out.push_back({a, b, m});
  }
  soup.polygons = out;
  return m;
}

// Splits the cell (v00, v10, v11, v01) (counterclockwise) into two triangles; the diagonal alternates
// in a checkerboard pattern so that the mesh has no preferred direction.
inline void add_cell(Polygon_soup& soup, std::size_t v00, std::size_t v10, std::size_t v11, std::size_t v01,
                     bool other_diagonal)
{
  if(!other_diagonal)
  {
    soup.add_triangle(v00, v10, v11);
    soup.add_triangle(v00, v11, v01);
  }
  else
  {
    soup.add_triangle(v00, v10, v01);
    soup.add_triangle(v10, v11, v01);
  }
}

// Uniform number in [-1, 1] from the raw output of mt19937 (which the standard fixes, unlike
// std::uniform_real_distribution), so that the jittered meshes are the same everywhere.
inline double uniform_in_minus_one_one(std::mt19937& generator)
{
  return 2. * (static_cast<double>(generator()) / 4294967295.) - 1.;
}

// Planar grid of (nx+1) x (ny+1) vertices covering the rectangle [0,width] x [0,height] of the plane z = 0;
// vertex (i,j) (column i, row j) has index j*(nx+1)+i. With `jitter` > 0, each interior vertex is moved
// by up to `jitter` cell sizes in x and in y, and each non-corner boundary vertex along its side only,
// so that the domain stays exactly the rectangle (a convex domain: geodesic = Euclidean distance).
inline Polygon_soup planar_grid(int nx, int ny, double width, double height,
                                double jitter = 0., std::uint32_t seed = 1)
{
  Polygon_soup soup;
  std::mt19937 generator(seed);
  const double hx = width / nx, hy = height / ny;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
    {
      double x = (i == nx) ? width : i * hx;
      double y = (j == ny) ? height : j * hy;
      if(jitter > 0.)
      {
        const double dx = jitter * hx * uniform_in_minus_one_one(generator);
        const double dy = jitter * hy * uniform_in_minus_one_one(generator);
        if(i > 0 && i < nx) x += dx;
        if(j > 0 && j < ny) y += dy;
      }
      soup.points.push_back(Point_3(x, y, 0.));
    }
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const std::size_t v00 = std::size_t(j) * (nx + 1) + i;
      add_cell(soup, v00, v00 + 1, v00 + nx + 2, v00 + nx + 1, (i + j) % 2 == 1);
    }
  return soup;
}

inline std::size_t grid_vertex(int nx, int i, int j) { return std::size_t(j) * (nx + 1) + i; }

// True iff every triangle of the planar soup (z = 0) is counterclockwise (checked with exact predicates).
inline bool is_valid_planar_soup(const Polygon_soup& soup)
{
  for(const std::vector<std::size_t>& t : soup.polygons)
  {
    const Point_3 &a = soup.points[t[0]], &b = soup.points[t[1]], &c = soup.points[t[2]];
    if(CGAL::orientation(Point_2(a.x(), a.y()), Point_2(b.x(), b.y()), Point_2(c.x(), c.y())) != CGAL::LEFT_TURN)
      return false;
  }
  return true;
}

// L-shaped planar domain [0,2]x[0,1] U [0,1]x[0,2] (z = 0), with cells of size 1/n: the square (1,2]x(1,2]
// is missing, and (1,1) is a reflex boundary vertex. The grid coordinates are i/n, so that the domain
// boundary lies exactly on the lines x = 0, 1, 2 and y = 0, 1, 2.
inline Polygon_soup l_shape(int n)
{
  Polygon_soup soup;
  std::map<std::pair<int, int>, std::size_t> index;
  for(int j = 0; j <= 2 * n; ++j)
    for(int i = 0; i <= 2 * n; ++i)
      if(!(i > n && j > n))
      {
        index[std::make_pair(i, j)] = soup.points.size();
        soup.points.push_back(Point_3(double(i) / n, double(j) / n, 0.));
      }
  for(int j = 0; j < 2 * n; ++j)
    for(int i = 0; i < 2 * n; ++i)
      if(!(i >= n && j >= n))
        add_cell(soup, index.at({i, j}), index.at({i + 1, j}), index.at({i + 1, j + 1}), index.at({i, j + 1}),
                 (i + j) % 2 == 1);
  return soup;
}

// Lateral surface of a prism over the regular `sides`-gon of circumradius `radius`, between the heights
// 0 and `height`, with `bands` bands of quads (so bands+1 rings), each quad split into two triangles.
// Vertex (k, r) (corner k of the polygon, ring r) has index r*sides + k. Open (two boundary loops).
inline Polygon_soup open_prism(int sides, int bands, double radius, double height)
{
  Polygon_soup soup;
  for(int r = 0; r <= bands; ++r)
    for(int k = 0; k < sides; ++k)
    {
      const double angle = 2. * PI * k / sides;
      soup.points.push_back(Point_3(radius * std::cos(angle), radius * std::sin(angle), height * r / bands));
    }
  for(int r = 0; r < bands; ++r)
    for(int k = 0; k < sides; ++k)
    {
      const std::size_t k1 = (k + 1) % sides;
      add_cell(soup, std::size_t(r) * sides + k, std::size_t(r) * sides + k1,
               std::size_t(r + 1) * sides + k1, std::size_t(r + 1) * sides + k, (r + k) % 2 == 1);
    }
  return soup;
}

// Surface of the unit cube [0,1]^3, each face cut into an n x n grid of cells (two triangles each),
// outward oriented. The lattice point (a,b,c) (a,b,c in 0..n) is the point (a/n, b/n, c/n).
// `lattice` receives the lattice coordinates of each vertex.
inline Polygon_soup subdivided_cube(int n, std::vector<std::array<int, 3> >* lattice = nullptr)
{
  Polygon_soup soup;
  std::map<std::array<int, 3>, std::size_t> index;
  auto vertex = [&](const std::array<int, 3>& c) -> std::size_t {
    auto it = index.find(c);
    if(it != index.end())
      return it->second;
    const std::size_t id = soup.points.size();
    index[c] = id;
    soup.points.push_back(Point_3(double(c[0]) / n, double(c[1]) / n, double(c[2]) / n));
    if(lattice != nullptr)
      lattice->push_back(c);
    return id;
  };
  for(int axis = 0; axis < 3; ++axis)
  {
    // (u, w, axis) is a direct frame: e_u x e_w = e_axis
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for(int side = 0; side <= n; side += n)
      for(int q = 0; q < n; ++q)
        for(int p = 0; p < n; ++p)
        {
          std::array<std::array<int, 3>, 4> corners;
          const int du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
          for(int k = 0; k < 4; ++k)
          {
            corners[k][axis] = side;
            corners[k][u] = p + du[k];
            corners[k][w] = q + dw[k];
          }
          std::size_t v[4];
          for(int k = 0; k < 4; ++k)
            v[k] = vertex(corners[k]);
          if(side == n) // counterclockwise around +e_axis: outward
            add_cell(soup, v[0], v[1], v[2], v[3], (p + q) % 2 == 1);
          else          // outward is -e_axis: reverse
            add_cell(soup, v[0], v[3], v[2], v[1], (p + q) % 2 == 1);
        }
  }
  return soup;
}

// Regular tetrahedron with the vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) (edge length 2 sqrt(2)),
// outward oriented.
inline Polygon_soup regular_tetrahedron()
{
  Polygon_soup soup;
  soup.points = {Point_3(1, 1, 1), Point_3(1, -1, -1), Point_3(-1, 1, -1), Point_3(-1, -1, 1)};
  const std::size_t faces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for(const auto& f : faces)
  {
    const Point_3 &a = soup.points[f[0]], &b = soup.points[f[1]], &c = soup.points[f[2]];
    // the centroid is the origin: outward iff the normal points away from it
    if(CGAL::cross_product(b - a, c - a) * (a - CGAL::ORIGIN) > 0)
      soup.add_triangle(f[0], f[1], f[2]);
    else
      soup.add_triangle(f[0], f[2], f[1]);
  }
  return soup;
}

// A planar grid of quads (not a triangle mesh).
inline Polygon_soup quad_grid(int n)
{
  Polygon_soup soup;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      soup.points.push_back(Point_3(i, j, 0));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const std::size_t v00 = std::size_t(j) * (n + 1) + i;
      soup.polygons.push_back({v00, v00 + 1, v00 + n + 2, v00 + n + 1});
    }
  return soup;
}

} // namespace vtp_test

#endif // VTP_TEST_MESHES_H
