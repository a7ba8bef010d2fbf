// curve_benchmark: the two bars of issue 47 on a mesh, side by side in one run (benchmark/README.md, "Sources that
// are curves"):
//
//   curve_benchmark MESH [--vertices A,B,C,...] [--step H] [--repeats R] [--no-check] [--no-timing] [--dense S]
//
// The curve is the open curve through the vertices A, B, C, ... (indices in the file, as the tools take them;
// default 0,1000,5000), given to add_source_curve(), which joins each two that share no face by the shortest
// geodesic between them.
//
// 1. Between the sampled distances ("check"): the joined curve's polyline is traced as the library joins it
//    (for each two consecutive points, an exact run from the first stopped at the second, and the path back from
//    the second: shortest_path_locations()), sampled every H along its length (default H = the mesh's mean edge
//    length; both ends included, so that every point of the curve is within H/2 along it of a sample), the
//    samples (face locations) are one multi-source run: d_S. The curve's distance d must lie between d_S - H/2
//    and d_S. Printed: the vertices above d_S, those below d_S - H/2 (each beyond 1e-9 of the largest distance),
//    the worst excess on each side relative to the largest distance, and how much of the H/2 slack is used.
// 2. The cost ("timing"): the processor time (std::clock, one thread, Sequential_tag) of compute() from the curve
//    against compute() from vertex A alone, the least of R runs of each (default 3), interleaved; the joining of
//    the curve (add_source_curve(): the runs that find the geodesics between the points) is timed apart, since it
//    is paid once per curve, before compute(). Printed: both times, their ratio (and with the joining), the
//    windows created, and the propagation wall-clock seconds of the statistics.
//
// 3. With --dense S (S >= 2), the joining of a dense curve: the vertices of a path of mesh edges from A to B (breadth
//    first), every S-th (so that consecutive points share no face and each pair is joined by a run), timed as
//    add_source_curve() (the least of R), per pair, against the run from A alone.
//
// Output: one "name value" line per measure.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iostream>
#include <iterator>
#include <limits>
#include <queue>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef vtp_support::Mesh Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;
typedef Mesh::Halfedge_index Halfedge;
typedef std::pair<Face, std::array<double, 3> > Location;
typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
namespace VP = CGAL::VTP_geodesics::parameters;

const double INF = std::numeric_limits<double>::infinity();

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The vertices (with their weights) of the support of a location: weights above 1e-12, renormalised.
std::vector<std::pair<Vertex, double> > support_of(const Mesh& m, const Location& l)
{
  std::vector<std::pair<Vertex, double> > r;
  const Halfedge h = m.halfedge(l.first);
  const Vertex c[3] = { m.source(h), m.target(h), m.target(m.next(h)) };
  double sum = 0.;
  for(int k = 0; k < 3; ++k)
    if(l.second[k] > 1e-12)
    {
      r.push_back(std::make_pair(c[k], l.second[k]));
      sum += l.second[k];
    }
  for(auto& p : r)
    p.second /= sum;
  return r;
}

// The barycentric coordinates in f of the point of support `s` (false if a vertex of `s` is not one of f).
bool in_face(const Mesh& m, Face f, const std::vector<std::pair<Vertex, double> >& s, std::array<double, 3>& w)
{
  const Halfedge h = m.halfedge(f);
  const Vertex c[3] = { m.source(h), m.target(h), m.target(m.next(h)) };
  w = {{ 0., 0., 0. }};
  for(const auto& p : s)
  {
    int k = 0;
    while(k < 3 && c[k] != p.first)
      ++k;
    if(k == 3)
      return false;
    w[k] += p.second;
  }
  return true;
}

Mesh::Point point_of(const Mesh& m, const Location& l)
{
  const Halfedge h = m.halfedge(l.first);
  const Mesh::Point &a = m.point(m.source(h)), &b = m.point(m.target(h)), &c = m.point(m.target(m.next(h)));
  const std::array<double, 3>& w = l.second;
  return Mesh::Point(w[0] * a.x() + w[1] * b.x() + w[2] * c.x(), w[0] * a.y() + w[1] * b.y() + w[2] * c.y(),
                     w[0] * a.z() + w[1] * b.z() + w[2] * c.z());
}

// A piece of the polyline: a face that holds both ends, their coordinates in it, its length.
struct Piece
{
  Face face;
  std::array<double, 3> a, b;
  double length;
};

// The pieces of the polyline `locs` (consecutive locations share a face).
std::vector<Piece> pieces_of(const Mesh& m, const std::vector<Location>& locs)
{
  std::vector<Piece> r;
  for(std::size_t i = 0; i + 1 < locs.size(); ++i)
  {
    const auto sa = support_of(m, locs[i]), sb = support_of(m, locs[i + 1]);
    Piece p;
    bool found = false;
    for(Face f : CGAL::faces_around_target(m.halfedge(sa[0].first), m))
      if(f != Mesh::null_face() && in_face(m, f, sa, p.a) && in_face(m, f, sb, p.b))
      {
        p.face = f;
        found = true;
        break;
      }
    if(!found)
      throw std::runtime_error("two consecutive points of the traced polyline share no face (point "
                               + std::to_string(i) + ")");
    p.length = std::sqrt(CGAL::squared_distance(point_of(m, locs[i]), point_of(m, locs[i + 1])));
    r.push_back(p);
  }
  return r;
}

// Samples every h along the pieces (arc length 0, h, 2h, ... and the end).
std::vector<Location> sample(const std::vector<Piece>& pieces, double h, double& total_length)
{
  std::vector<Location> r;
  total_length = 0.;
  for(const Piece& p : pieces)
    total_length += p.length;
  double start = 0.;  // arc length at the start of the piece
  std::size_t next = 0;  // index of the next sample: at arc length next * h
  for(const Piece& p : pieces)
  {
    while(next * h <= start + p.length)
    {
      const double t = p.length > 0. ? (std::min)(1., (next * h - start) / p.length) : 0.;
      r.push_back(Location(p.face, {{ (1. - t) * p.a[0] + t * p.b[0], (1. - t) * p.a[1] + t * p.b[1],
                                      (1. - t) * p.a[2] + t * p.b[2] }}));
      ++next;
    }
    start += p.length;
  }
  const Piece& last = pieces.back();
  r.push_back(Location(last.face, last.b));  // the end
  return r;
}

std::vector<std::size_t> parse_list(const std::string& s)
{
  std::vector<std::size_t> r;
  std::stringstream in(s);
  std::string item;
  while(std::getline(in, item, ','))
    r.push_back(static_cast<std::size_t>(std::stoul(item)));
  return r;
}

double largest_finite(const std::vector<double>& d)
{
  double r = 0.;
  for(double x : d)
    if(std::isfinite(x))
      r = (std::max)(r, x);
  return r;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2 || std::string(argv[1]) == "--help")
  {
    std::cerr << "usage: curve_benchmark MESH [--vertices A,B,C,...] [--step H] [--repeats R] [--no-check] "
                 "[--no-timing]\n(see the comment at the top of benchmark/VTP_geodesics/curve_benchmark.cpp)\n";
    return 2;
  }
  std::vector<std::size_t> file_vertices = { 0, 1000, 5000 };
  double step = 0.;
  int repeats = 3;
  bool check = true, timing = true;
  int dense = 0;
  for(int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--vertices" && i + 1 < argc)
      file_vertices = parse_list(argv[++i]);
    else if(a == "--step" && i + 1 < argc)
      step = std::atof(argv[++i]);
    else if(a == "--repeats" && i + 1 < argc)
      repeats = (std::max)(1, std::atoi(argv[++i]));
    else if(a == "--no-check")
      check = false;
    else if(a == "--no-timing")
      timing = false;
    else if(a == "--dense" && i + 1 < argc)
      dense = std::atoi(argv[++i]);
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return 2;
    }
  }
  try
  {
    vtp_support::Input_mesh input;
    vtp_support::read_input_mesh(argv[1], input, 1);  // the tools' reader and repair
    const Mesh& mesh = input.mesh;
    Solver solver(mesh);
    std::cout << "mesh " << argv[1] << "\nvertices " << solver.number_of_vertices() << "\nfaces "
              << solver.number_of_faces() << "\nrepaired " << (input.direct ? 0 : 1) << "\n";
    std::vector<Vertex> curve;
    std::cout << "curve_file_vertices";
    for(std::size_t i : file_vertices)
    {
      const std::vector<Vertex> copies = input.mesh_vertices_of(i);
      if(copies.empty())
        throw std::runtime_error("file vertex " + std::to_string(i) + " is not in the mesh");
      curve.push_back(copies[0]);
      std::cout << " " << i;
    }
    std::cout << "\n";
    const double h = step > 0. ? step : solver.mean_edge_length();
    std::cout << "mean_edge_length " << solver.mean_edge_length() << "\nstep_h " << h << "\n";

    if(check)
    {
      // the polyline of the joined curve, as add_source_curve() joins it
      std::vector<Location> polyline;
      for(std::size_t i = 0; i + 1 < curve.size(); ++i)
      {
        solver.compute(CGAL::Constant_property_map<Vertex, double>(0.), curve[i],
                       VP::targets(std::vector<Vertex>(1, curve[i + 1])).record_paths(true));
        std::vector<Location> path;
        solver.shortest_path_locations(curve[i + 1], std::back_inserter(path));  // curve[i+1] ... curve[i]
        std::reverse(path.begin(), path.end());
        polyline.insert(polyline.end(), path.begin() + (polyline.empty() ? 0 : 1), path.end());
      }
      double length = 0.;
      const std::vector<Location> samples = sample(pieces_of(mesh, polyline), h, length);
      std::cout << "curve_polyline_points " << polyline.size() << "\ncurve_length " << length << "\nsamples "
                << samples.size() << "\n";
      solver.compute(CGAL::Constant_property_map<Vertex, double>(0.), samples);
      const std::vector<double> ds = solver.distances();
      solver.clear_sources();
      solver.add_source_curve(curve);
      solver.compute(CGAL::Constant_property_map<Vertex, double>(0.));
      const std::vector<double> d = solver.distances();
      const double largest = largest_finite(ds), tolerance = 1e-9 * largest;
      std::size_t above = 0, below = 0, reached = 0, mismatched_reach = 0;
      double worst_above = -INF, worst_below = -INF, used_slack = 0.;
      for(std::size_t v = 0; v < d.size(); ++v)
      {
        if(!std::isfinite(d[v]) || !std::isfinite(ds[v]))
        {
          mismatched_reach += std::isfinite(d[v]) != std::isfinite(ds[v]);
          continue;
        }
        ++reached;
        worst_above = (std::max)(worst_above, d[v] - ds[v]);
        worst_below = (std::max)(worst_below, ds[v] - h / 2. - d[v]);
        used_slack = (std::max)(used_slack, (ds[v] - d[v]) / (h / 2.));
        above += d[v] > ds[v] + tolerance;
        below += d[v] < ds[v] - h / 2. - tolerance;
      }
      std::cout << "largest_distance " << largest << "\nreached_vertices " << reached
                << "\nvertices_reached_by_one_run_only " << mismatched_reach
                << "\nvertices_above_d_S " << above << "\nvertices_below_d_S_minus_h_over_2 " << below
                << "\nworst_d_minus_d_S_relative " << worst_above / largest
                << "\nworst_d_S_minus_h_over_2_minus_d_relative " << worst_below / largest
                << "\nlargest_d_S_minus_d_over_h_over_2 " << used_slack
                << "\nbar_between_d_S_minus_h_over_2_and_d_S " << (above == 0 && below == 0 && mismatched_reach == 0
                                                                     ? "met" : "FAILED")
                << "\n";
    }

    if(timing)
    {
      // the least of R runs of each, interleaved; one thread, Sequential_tag
      double single_cpu = INF, curve_cpu = INF, join_cpu = INF, single_wall = INF, curve_wall = INF;
      std::size_t single_windows = 0, curve_windows = 0;
      for(int r = 0; r < repeats; ++r)
      {
        solver.clear_sources();
        solver.add_source(curve[0]);
        double c0 = cpu_seconds();
        solver.compute(CGAL::Constant_property_map<Vertex, double>(0.));
        single_cpu = (std::min)(single_cpu, cpu_seconds() - c0);
        single_wall = (std::min)(single_wall, solver.statistics().seconds);
        single_windows = solver.statistics().windows_created;

        solver.clear_sources();
        c0 = cpu_seconds();
        solver.add_source_curve(curve);
        join_cpu = (std::min)(join_cpu, cpu_seconds() - c0);
        c0 = cpu_seconds();
        solver.compute(CGAL::Constant_property_map<Vertex, double>(0.));
        curve_cpu = (std::min)(curve_cpu, cpu_seconds() - c0);
        curve_wall = (std::min)(curve_wall, solver.statistics().seconds);
        curve_windows = solver.statistics().windows_created;
      }
      std::printf("repeats %d\nsingle_vertex_cpu_seconds %.4f\ncurve_cpu_seconds %.4f\n"
                  "curve_join_cpu_seconds %.4f\nratio_curve_vs_single %.3f\nratio_curve_with_join_vs_single %.3f\n"
                  "single_vertex_propagation_wall_seconds %.4f\ncurve_propagation_wall_seconds %.4f\n"
                  "single_vertex_windows_created %zu\ncurve_windows_created %zu\nratio_windows %.3f\n"
                  "bar_at_most_1.5x %s\n",
                  repeats, single_cpu, curve_cpu, join_cpu, curve_cpu / single_cpu, (curve_cpu + join_cpu) / single_cpu,
                  single_wall, curve_wall, single_windows, curve_windows,
                  double(curve_windows) / double(single_windows), curve_cpu / single_cpu <= 1.5 ? "met" : "FAILED");
    }

    if(dense >= 2 && curve.size() >= 2)
    {
      // the path of edges from A to B, breadth first, every dense-th vertex (and B)
      std::vector<Vertex> parent(num_vertices(mesh), Mesh::null_vertex());
      std::queue<Vertex> queue;
      parent[std::size_t(curve[0])] = curve[0];
      queue.push(curve[0]);
      while(!queue.empty())
      {
        const Vertex x = queue.front();
        queue.pop();
        for(Vertex y : CGAL::vertices_around_target(mesh.halfedge(x), mesh))
          if(parent[std::size_t(y)] == Mesh::null_vertex())
          {
            parent[std::size_t(y)] = x;
            queue.push(y);
          }
      }
      if(parent[std::size_t(curve[1])] == Mesh::null_vertex())
        throw std::runtime_error("the first two vertices are not connected");
      std::vector<Vertex> path(1, curve[1]);
      while(path.back() != curve[0])
        path.push_back(parent[std::size_t(path.back())]);
      std::reverse(path.begin(), path.end());
      std::vector<Vertex> points;
      for(std::size_t i = 0; i < path.size(); i += std::size_t(dense))
        points.push_back(path[i]);
      if(points.back() != path.back())
        points.push_back(path.back());
      double join = INF, single = INF;
      for(int r = 0; r < repeats; ++r)
      {
        solver.clear_sources();
        double c0 = cpu_seconds();
        solver.add_source_curve(points);
        join = (std::min)(join, cpu_seconds() - c0);
        solver.clear_sources();
        solver.add_source(curve[0]);
        c0 = cpu_seconds();
        solver.compute(CGAL::Constant_property_map<Vertex, double>(0.));
        single = (std::min)(single, cpu_seconds() - c0);
      }
      std::printf("dense_curve_edges %zu\ndense_curve_points %zu\ndense_curve_join_cpu_seconds %.4f\n"
                  "dense_curve_join_cpu_seconds_per_pair %.6f\ndense_curve_join_vs_single_vertex_run %.3f\n",
                  path.size() - 1, points.size(), join, join / double(points.size() - 1), join / single);
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "curve_benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
