// curve_heat_comparison: the exact distance from one closed curve along mesh edges, for the side-by-side with the
// signed heat method (issue 47, item 5; doc/VTP_geodesics/source_curves_anchor.txt). The curve file is the one the
// anchor's driver reads (geometry-central's `curve_heat` mode): whitespace-separated 0-based vertex indices, each
// joined to the next by a mesh edge, the last joined to the first (the curve is closed here by repeating the first).
//
//   curve_heat_comparison MESH.off CURVE OUT.txt [signed] [REPEATS] [samples=K] [open]
//
// OUT.txt: a '#' header line, then one distance per vertex in the OFF file's vertex order (ours: negative on the
// left of the curve, left = outward face normal x direction of travel). Timings on stderr, one line:
//   curve_heat_comparison: signed|unsigned nV=.. curve_vertices=.. build_s=.. compute_s=.. propagation_s=..
// build_s: the solver's constructor (the mesh's arrays), once; compute_s: add_source_curve() + compute() (wall),
// propagation_s: statistics().seconds (the propagation alone); with REPEATS > 1 the median of each over the runs.
// open: the curve is not closed (its last vertex is not joined to its first; unsigned only): the smallest cases.
//
// samples=K: a check of the curve run that does not use curve sources: one more run from point sources, K points
// evenly spaced along each edge of the curve (its ends included), gives d_S; the distance d from the curve must lie
// in [d_S - s/2, d_S] (s the largest spacing of the samples along the curve). One more stderr line:
//   curve_heat_comparison: samples=K spacing=s vertices_above_d_S=.. vertices_below_d_S-s/2=.. max_d-d_S=..
//                          max_d_S-d=..
// (above d_S by more than 1e-12 of the largest distance: a distance the curve run missed).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace VP = CGAL::VTP_geodesics::parameters;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4)
  {
    std::cerr << "usage: curve_heat_comparison MESH.off CURVE OUT.txt [signed] [REPEATS]\n";
    return 2;
  }
  bool is_signed = false, is_open = false;
  int repeats = 1, samples = 0;
  for(int i = 4; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "signed")
      is_signed = true;
    else if(a == "open")
      is_open = true;
    else if(a.rfind("samples=", 0) == 0 && std::atoi(a.c_str() + 8) > 0)
      samples = std::atoi(a.c_str() + 8);
    else if(std::atoi(argv[i]) > 0)
      repeats = std::atoi(argv[i]);
    else
    {
      std::cerr << "curve_heat_comparison: unknown argument " << a << "\n";
      return 2;
    }
  }
  Mesh mesh;
  {
    std::ifstream in(argv[1]);
    if(!(in >> mesh) || num_faces(mesh) == 0)
    {
      std::cerr << "curve_heat_comparison: cannot read " << argv[1] << "\n";
      return 1;
    }
  }
  const std::size_t n = num_vertices(mesh);
  std::vector<Vertex> curve;
  {
    std::ifstream in(argv[2]);
    long id = 0;
    while(in >> id)
    {
      if(id < 0 || static_cast<std::size_t>(id) >= n)
      {
        std::cerr << "curve_heat_comparison: vertex " << id << " is not a vertex of the mesh\n";
        return 1;
      }
      curve.push_back(Vertex(static_cast<Mesh::size_type>(id)));
    }
    if(!in.eof() || curve.size() < 2)
    {
      std::cerr << "curve_heat_comparison: " << argv[2] << " is not a list of at least two vertex indices\n";
      return 1;
    }
  }
  if(is_open && is_signed)
  {
    std::cerr << "curve_heat_comparison: signed needs a closed curve here\n";
    return 2;
  }
  // each consecutive pair (and the last with the first) must be a mesh edge, as the anchor's driver requires
  for(std::size_t i = 0; i + (is_open ? 1 : 0) < curve.size(); ++i)
    if(!halfedge(curve[i], curve[(i + 1) % curve.size()], mesh).second)
    {
      std::cerr << "curve_heat_comparison: vertices " << curve[i] << " and " << curve[(i + 1) % curve.size()]
                << " are not joined by an edge\n";
      return 1;
    }
  if(!is_open)
    curve.push_back(curve.front()); // closed

  const double b0 = now();
  CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> solver(mesh);
  const double build_s = now() - b0;
  std::vector<double> d(n);
  auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh));
  std::vector<double> t_compute, t_prop;
  for(int r = 0; r < repeats; ++r)
  {
    const double t0 = now();
    solver.clear_sources();
    solver.add_source_curve(curve);
    if(is_signed)
      solver.compute(dm, VP::signed_distance(true));
    else
      solver.compute(dm);
    t_compute.push_back(now() - t0);
    t_prop.push_back(solver.statistics().seconds);
  }
  std::fprintf(stderr,
               "curve_heat_comparison: %s nV=%zu curve_vertices=%zu build_s=%.6f compute_s=%.6f propagation_s=%.6f "
               "repeats=%d windows_created=%zu\n",
               is_signed ? "signed" : "unsigned", n, curve.size() - (is_open ? 0 : 1), build_s, median(t_compute), median(t_prop),
               repeats, solver.statistics().windows_created);
  if(samples > 0)
  {
    solver.clear_sources();
    double spacing = 0.;
    for(std::size_t i = 0; i + 1 < curve.size(); ++i)
    {
      const auto h = halfedge(curve[i], curve[i + 1], mesh).first; // from curve[i] to curve[i + 1]
      const auto fc = face(h, mesh) != Mesh::null_face() ? face(h, mesh) : face(opposite(h, mesh), mesh);
      spacing = std::max(spacing, std::sqrt(CGAL::squared_distance(mesh.point(curve[i]), mesh.point(curve[i + 1])))
                                      / samples);
      for(int k = 0; k < samples; ++k)
      {
        std::pair<Mesh::Face_index, std::array<double, 3> > loc(fc, {{0., 0., 0.}});
        // the coordinates of source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), as CGAL's face
        // locations
        const auto hf = halfedge(fc, mesh);
        const Vertex corner[3] = {source(hf, mesh), target(hf, mesh), target(next(hf, mesh), mesh)};
        const double t = double(k) / samples;
        for(int c = 0; c < 3; ++c)
          loc.second[c] = corner[c] == curve[i] ? 1. - t : corner[c] == curve[i + 1] ? t : 0.;
        solver.add_source(loc);
      }
    }
    std::vector<double> ds(n);
    solver.compute(boost::make_iterator_property_map(ds.begin(), get(boost::vertex_index, mesh)));
    double scale = 0., worst = 0., gap = 0.;
    std::size_t above = 0, below = 0;
    for(std::size_t v = 0; v < n; ++v)
      scale = std::max(scale, std::abs(d[v]));
    for(std::size_t v = 0; v < n; ++v)
    {
      const double dv = std::abs(d[v]);
      worst = std::max(worst, dv - ds[v]);
      gap = std::max(gap, ds[v] - dv);
      above += dv > ds[v] + 1e-12 * scale;
      below += dv < ds[v] - spacing / 2 - 1e-12 * scale;
    }
    std::fprintf(stderr, "curve_heat_comparison: samples=%d spacing=%.3g vertices_above_d_S=%zu "
                         "vertices_below_d_S-s/2=%zu max_d-d_S=%.3e max_d_S-d=%.3e\n",
                 samples, spacing, above, below, worst, gap);
  }
  std::FILE* f = std::fopen(argv[3], "w");
  if(!f)
  {
    std::cerr << "curve_heat_comparison: cannot write " << argv[3] << "\n";
    return 1;
  }
  std::fprintf(f, "# curve_heat_comparison %s mesh=%s curve=%s (VTP_geodesics, add_source_curve); one distance per "
                  "vertex\n",
               is_signed ? "signed" : "unsigned", argv[1], argv[2]);
  for(double x : d)
    std::fprintf(f, "%.17g\n", x);
  std::fclose(f);
  return 0;
}
