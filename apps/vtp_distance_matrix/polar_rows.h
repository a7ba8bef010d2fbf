// vtp_distance_matrix --polar: the rows of polar patches (rho and theta around each source, within the limit).
//
//   compute_polar_rows(input, sources, rows, radius, threads, sink)
// computes, for each row r of `rows`, the polar patch of radius `radius` around the file vertex sources[r] and
// hands it to sink(r, indices, rho, theta) (std::vector of int64 file vertices, ascending, and of double), one
// call at a time, in any order.
//
// The patches go through the library's batch call, Geodesic_distance_solver::compute_each_polar_patch(): one
// local run of the log map per source (stopped at the radius, costing its patch), the rows on `threads` OpenMP
// threads; each row is bit for bit the log map of one run from its source. As in the distance rows
// (vtp_support/distance_rows.h), a file vertex that the repair of the input cut into several mesh vertices is a
// source at all its copies at once (one run with several sources: each vertex's coordinates are relative to its
// nearest copy), a file vertex that the repair removed has only itself in its row (rho 0, theta 0); a file
// vertex with several copies in a row gets the entry of its copy of least rho.

#ifndef VTP_DISTANCE_MATRIX_POLAR_ROWS_H
#define VTP_DISTANCE_MATRIX_POLAR_ROWS_H

#include <vtp_support/methods.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace vtp_matrix {

// Throws whatever the library or the sink threw (once one threw, no new row starts).
template <class Sink>
void compute_polar_rows(const vtp_support::Input_mesh& input, const std::vector<std::int64_t>& sources,
                        const std::vector<std::int64_t>& rows, double radius, int threads, Sink&& sink)
{
  typedef vtp_support::Mesh Mesh;
  typedef vtp_support::Vertex_index Vertex_index;
  typedef CGAL::VTP_geodesics::Geodesic_distance_solver<Mesh> Solver;
  namespace VP = CGAL::VTP_geodesics::parameters;
  if(rows.empty())
    return;
  Solver solver(input.mesh, VP::number_of_threads((std::max)(threads, 1)));
  // the file vertex of each vertex_id() of the solver
  const std::size_t n = solver.number_of_vertices();
  std::vector<std::int64_t> file_of(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t v = static_cast<std::size_t>(solver.vertex_list()[i]);
    file_of[i] = static_cast<std::int64_t>(input.direct ? v : input.file_vertex_of_copy[v]);
  }
  std::vector<std::int64_t> indices;
  std::vector<double> rho, theta;
  std::vector<std::pair<std::int64_t, std::size_t> > entries;  // (file vertex, entry), then deduplicated
  // a patch on the vertices of the file: ascending, one entry per file vertex (its copy of least rho)
  auto to_file = [&](std::size_t count, const auto& vertex_id, const auto& rho_of, const auto& theta_of) {
    entries.clear();
    for(std::size_t e = 0; e < count; ++e)
      entries.push_back(std::make_pair(file_of[vertex_id(e)], e));
    std::sort(entries.begin(), entries.end(), [&](const auto& a, const auto& b) {
      return a.first != b.first ? a.first < b.first : rho_of(a.second) < rho_of(b.second);
    });
    indices.clear();
    rho.clear();
    theta.clear();
    for(std::size_t k = 0; k < entries.size(); ++k)
      if(k == 0 || entries[k].first != entries[k - 1].first)
      {
        indices.push_back(entries[k].first);
        rho.push_back(rho_of(entries[k].second));
        theta.push_back(theta_of(entries[k].second));
      }
  };

  // Rows whose source is one mesh vertex: the batch.
  std::vector<Vertex_index> batch_sources;
  std::vector<std::int64_t> batch_rows, other_rows;
  for(std::int64_t r : rows)
  {
    const std::vector<Vertex_index> copies =
      input.mesh_vertices_of(static_cast<std::size_t>(sources[static_cast<std::size_t>(r)]));
    if(copies.size() == 1 && !input.mesh.is_isolated(copies[0]))
    {
      batch_sources.push_back(copies[0]);
      batch_rows.push_back(r);
    }
    else
      other_rows.push_back(r);
  }
  auto patch_sink = [&](std::size_t i, Vertex_index, const std::vector<std::uint32_t>& v, const std::vector<double>& r,
                        const std::vector<double>& t) {
    to_file(v.size(), [&](std::size_t e) { return static_cast<std::size_t>(v[e]); },
            [&](std::size_t e) { return r[e]; }, [&](std::size_t e) { return t[e]; });
    sink(batch_rows[i], static_cast<const std::vector<std::int64_t>&>(indices),
         static_cast<const std::vector<double>&>(rho), static_cast<const std::vector<double>&>(theta));
  };
  solver.compute_each_polar_patch<vtp_support::Rows_tag>(batch_sources, radius, patch_sink,
                                                         VP::number_of_threads((std::max)(threads, 1)));

  // The other rows (sources cut by the repair, removed by it, or isolated), one run with several sources each.
  std::vector<double> d(input.mesh.number_of_vertices());
  std::vector<std::array<double, 2> > x(input.mesh.number_of_vertices());
  auto dm = boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, input.mesh));
  auto xm = boost::make_iterator_property_map(x.begin(), get(boost::vertex_index, input.mesh));
  const double two_pi = 2. * 3.14159265358979323846;
  for(std::int64_t row : other_rows)
  {
    const std::int64_t source = sources[static_cast<std::size_t>(row)];
    std::vector<Vertex_index> copies = input.mesh_vertices_of(static_cast<std::size_t>(source));
    copies.erase(std::remove_if(copies.begin(), copies.end(), [&](Vertex_index v) { return input.mesh.is_isolated(v); }),
                 copies.end());
    if(copies.empty())
    {
      indices.assign(1, source);
      rho.assign(1, 0.);
      theta.assign(1, 0.);
    }
    else
    {
      solver.compute<CGAL::Sequential_tag>(dm, copies, VP::maximum_distance(radius).log_map(xm));
      std::vector<std::size_t> reached;
      for(std::size_t i = 0; i < n; ++i)
        if(d[static_cast<std::size_t>(solver.vertex_list()[i])] < std::numeric_limits<double>::infinity())
          reached.push_back(i);
      auto vertex = [&](std::size_t e) { return static_cast<std::size_t>(solver.vertex_list()[reached[e]]); };
      to_file(reached.size(), [&](std::size_t e) { return reached[e]; }, [&](std::size_t e) { return d[vertex(e)]; },
              [&](std::size_t e) {
                const std::array<double, 2>& p = x[vertex(e)];
                const double t = std::atan2(p[1], p[0]);
                return t < 0. ? (t + two_pi < two_pi ? t + two_pi : 0.) : t;
              });
    }
    sink(row, static_cast<const std::vector<std::int64_t>&>(indices), static_cast<const std::vector<double>&>(rho),
         static_cast<const std::vector<double>&>(theta));
  }
}

} // namespace vtp_matrix

#endif // VTP_DISTANCE_MATRIX_POLAR_ROWS_H
