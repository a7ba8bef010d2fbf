// Random meshes of the VTP_geodesics stress program (stress_vtp.cpp): closed surfaces (convex hulls of
// random points on perturbed spheres, pushed in and out radially), open surfaces (the same with faces
// removed, keeping a valid mesh), and grids with noisy heights and anisotropic stretching.
//
// Everything is drawn from a std::mt19937_64 through `Random` (the standard fixes mt19937_64's output
// but not that of its distributions), so that a (seed, case) pair gives the same mesh everywhere.

#ifndef VTP_RANDOM_MESHES_H
#define VTP_RANDOM_MESHES_H

#include "vtp_test_meshes.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vtp_test {

class Random
{
public:
  explicit Random(std::uint64_t seed) : m_generator(seed) {}

  // uniform in [0, 1)
  double uniform() { return static_cast<double>(m_generator() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // uniform integer in [a, b]
  std::size_t integer(std::size_t a, std::size_t b)
  {
    return a + static_cast<std::size_t>(m_generator() % static_cast<std::uint64_t>(b - a + 1));
  }
  bool chance(double p) { return uniform() < p; }
  // standard normal deviate (Box-Muller)
  double normal()
  {
    const double u = 1. - uniform(); // (0, 1]
    const double v = uniform();
    return std::sqrt(-2. * std::log(u)) * std::cos(2. * PI * v);
  }

private:
  std::mt19937_64 m_generator;
};

// Seed of case `index` of a run seeded with `seed` (SplitMix64 of both), so that every case can be
// reproduced on its own.
inline std::uint64_t case_seed(std::uint64_t seed, std::uint64_t index)
{
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ULL + index + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// Removes about `fraction` of the faces of `soup` (a valid polygon mesh), keeping a valid polygon mesh:
// the faces are taken in the order in which a random patch grows (or in random order, for scattered
// holes), and a face is skipped if removing it would leave one of its vertices with two separate fans
// of faces. Vertices left in no face stay in the soup (isolated vertices). Returns the number of faces
// removed.
inline std::size_t remove_random_faces(Polygon_soup& soup, double fraction, Random& random)
{
  const std::size_t nf = soup.polygons.size();
  const std::size_t target = (std::min)(nf, std::size_t(fraction * double(nf)));
  std::vector<std::vector<std::size_t> > faces_of(soup.points.size());
  for(std::size_t f = 0; f < nf; ++f)
    for(std::size_t v : soup.polygons[f])
      faces_of[v].push_back(f);
  std::vector<unsigned char> removed(nf, 0);

  // Number of edges at `v` with exactly one remaining face once `f` is removed too: a vertex of a
  // manifold mesh keeps one fan (or none) iff at most two such edges remain.
  auto border_edges_without = [&](std::size_t v, std::size_t f) {
    std::vector<std::pair<std::size_t, int> > edge_faces; // (other end, number of faces)
    for(std::size_t g : faces_of[v])
    {
      if(removed[g] || g == f)
        continue;
      const std::vector<std::size_t>& p = soup.polygons[g];
      for(std::size_t k = 0; k < p.size(); ++k)
        if(p[k] == v)
          for(std::size_t u : {p[(k + 1) % p.size()], p[(k + p.size() - 1) % p.size()]})
          {
            auto it = std::find_if(edge_faces.begin(), edge_faces.end(),
                                   [u](const std::pair<std::size_t, int>& e) { return e.first == u; });
            if(it == edge_faces.end())
              edge_faces.emplace_back(u, 1);
            else
              ++it->second;
          }
    }
    return std::count_if(edge_faces.begin(), edge_faces.end(),
                         [](const std::pair<std::size_t, int>& e) { return e.second == 1; });
  };

  // candidate order
  std::vector<std::size_t> order;
  if(random.chance(0.5))
  {
    std::vector<unsigned char> seen(nf, 0);
    std::vector<std::size_t> front(1, random.integer(0, nf - 1));
    seen[front[0]] = 1;
    while(!front.empty())
    {
      const std::size_t k = random.integer(0, front.size() - 1);
      const std::size_t f = front[k];
      front[k] = front.back();
      front.pop_back();
      order.push_back(f);
      for(std::size_t v : soup.polygons[f])
        for(std::size_t g : faces_of[v])
          if(!seen[g])
          {
            seen[g] = 1;
            front.push_back(g);
          }
    }
  }
  else
  {
    order.resize(nf);
    for(std::size_t f = 0; f < nf; ++f)
      order[f] = f;
    for(std::size_t f = nf; f > 1; --f)
      std::swap(order[f - 1], order[random.integer(0, f - 1)]);
  }

  std::size_t count = 0;
  for(std::size_t f : order)
  {
    if(count >= target)
      break;
    bool keeps_manifold = true;
    for(std::size_t v : soup.polygons[f])
      if(border_edges_without(v, f) > 2)
        keeps_manifold = false;
    if(keeps_manifold)
    {
      removed[f] = 1;
      ++count;
    }
  }
  std::vector<std::vector<std::size_t> > kept;
  for(std::size_t f = 0; f < nf; ++f)
    if(!removed[f])
      kept.push_back(soup.polygons[f]);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(kept))
    return 0; // not expected; keep the mesh as it was
  soup.polygons.swap(kept);
  return count;
}

// Closed surface: the convex hull of about `n` random points on an ellipsoid with random axes, then
// each vertex moved along its ray from the center by a random factor in [1 - bump, 1 + bump] (the
// surface stays star-shaped, so embedded, but gets saddle vertices).
inline Polygon_soup random_closed_surface(std::size_t n, Random& random, std::string* description = nullptr)
{
  const double axes[3] = {random.uniform(0.3, 3.), random.uniform(0.3, 3.), random.uniform(0.3, 3.)};
  const double bump = random.chance(0.3) ? 0. : random.uniform(0., 0.35);
  std::vector<Point_3> points;
  while(points.size() < (std::max)(n, std::size_t(4)))
  {
    const double x = random.normal(), y = random.normal(), z = random.normal();
    const double r = std::sqrt(x * x + y * y + z * z);
    if(r > 1e-6) // a uniform direction
      points.push_back(Point_3(axes[0] * x / r, axes[1] * y / r, axes[2] * z / r));
  }
  Surface_mesh hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  Polygon_soup soup = canonical_soup(hull); // reproducible order (see canonical_soup())
  for(Point_3& p : soup.points)
  {
    const double f = 1. + bump * random.uniform(-1., 1.);
    p = Point_3(f * p.x(), f * p.y(), f * p.z());
  }
  if(description != nullptr)
    *description = "closed hull of " + std::to_string(points.size()) + " points on an ellipsoid (axes "
                   + std::to_string(axes[0]) + ", " + std::to_string(axes[1]) + ", " + std::to_string(axes[2])
                   + "), radial bumps " + std::to_string(bump);
  return soup;
}

// Height field over a grid of about `n` vertices: cells stretched by up to 30 in one direction, vertices
// jittered in the plane, random diagonals, heights from a few random waves plus noise.
inline Polygon_soup random_grid(std::size_t n, Random& random, std::string* description = nullptr)
{
  const double aspect = std::exp(random.uniform(-std::log(30.), std::log(30.)));
  const std::size_t nx = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(n)) * random.uniform(0.4, 1.6)));
  const std::size_t rows = n / (nx + 1);
  const std::size_t ny = rows > 2 ? rows - 1 : 1;
  const double hx = 1., hy = aspect;
  const double jitter = random.chance(0.3) ? 0. : random.uniform(0., 0.3);
  const double noise = random.chance(0.2) ? 0. : random.uniform(0., 0.5);
  const double amplitude = random.uniform(0., 2.) * double((std::max)(nx, ny)) * (std::min)(hx, hy) / 4.;
  double wave[3][4];
  for(auto& w : wave)
  {
    w[0] = random.uniform(-1., 1.) * amplitude;                 // amplitude
    w[1] = random.uniform(0., 3.) / (double(nx) * hx);          // frequency in x
    w[2] = random.uniform(0., 3.) / (double(ny) * hy);          // frequency in y
    w[3] = random.uniform(0., 2. * PI);                         // phase
  }
  Polygon_soup soup;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
    {
      const double x = hx * (double(i) + jitter * random.uniform(-1., 1.));
      const double y = hy * (double(j) + jitter * random.uniform(-1., 1.));
      double z = noise * (std::min)(hx, hy) * random.uniform(-1., 1.);
      for(const auto& w : wave)
        z += w[0] * std::sin(2. * PI * (w[1] * x + w[2] * y) + w[3]);
      soup.points.push_back(Point_3(x, y, z));
    }
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i)
    {
      const std::size_t v00 = j * (nx + 1) + i;
      add_cell(soup, v00, v00 + 1, v00 + nx + 2, v00 + nx + 1, random.chance(0.5));
    }
  if(description != nullptr)
    *description = "grid " + std::to_string(nx) + " x " + std::to_string(ny) + ", aspect " + std::to_string(aspect)
                   + ", jitter " + std::to_string(jitter) + ", noise " + std::to_string(noise) + ", waves "
                   + std::to_string(amplitude);
  return soup;
}

} // namespace vtp_test

#endif // VTP_RANDOM_MESHES_H
