// The parallel (PVTP) and approximate (AVTP, PAVTP) variants against the exact sequential VTP:
//  - PVTP equals VTP (1e-12 relative) on every test mesh for T = 1, 2, 3, 4 (more threads than
//    cores included), and its output for a given T is the same on every run;
//  - approximate distances are never below the exact ones (every reported distance is the length of
//    a real surface path), equal the exact ones when lambda * h exceeds the largest distance, and
//    their error shrinks as lambda grows; PAVTP meets the same invariants and bounds as AVTP.
// The exact reference is the sequential VTP, itself checked against analytic values and CGAL's
// Surface_mesh_shortest_path by the other test files.

#include "vtp_test_utils.h"

#include <vtp_support/midpoint_subdivision.h>

#include <cmath>
#include <string>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Propagation_statistics;

namespace {

typedef Geodesic_distance_solver<Surface_mesh> Solver;

// The parameters the tests below vary.
struct Variant
{
  double lambda = INF;   // window-reset period (infinity: exact)
  int number_of_threads = 0;
};

const char* const all_meshes[] = { "elephant-with-holes.off", "elephant.off", "mushroom.off", "three_peaks.off",
                                   "knot1.off", "mech-holes-shark.off", "sphere.off" };

// Mean over the reached vertices (source excluded) of (d - d_exact) / d_exact.
double mean_relative_error(const std::vector<double>& d, const std::vector<double>& exact)
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

// Largest amount by which d is below the exact distance (0 if never), relative to the largest distance.
double below_exact(const std::vector<double>& d, const std::vector<double>& exact)
{
  double worst = 0.;
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(std::isinf(exact[i]))
    {
      EXPECT_TRUE(std::isinf(d[i])) << "vertex " << i << " is unreachable but got " << d[i];
      continue;
    }
    EXPECT_TRUE(std::isfinite(d[i])) << "vertex " << i << " is reachable but got " << d[i];
    worst = (std::max)(worst, exact[i] - d[i]);
  }
  return worst / max_finite(exact);
}

template <class Tag>
std::vector<double> run(Solver& solver, std::size_t source, const Variant& o,
                        Propagation_statistics* st = nullptr)
{
  solver.template compute<Tag>(Discard_map(), Vertex_index(static_cast<Surface_mesh::size_type>(source)),
                               CGAL::VTP_geodesics::parameters::lambda(o.lambda).number_of_threads(o.number_of_threads));
  if(st != nullptr)
    *st = solver.statistics();
  return solver.distances();
}

// A mesh whose geodesic radius is many mean edge lengths, so that many resets happen.
Surface_mesh fine_mesh(const char* name)
{
  Surface_mesh mesh = load_mesh(name);
  vtp_support::midpoint_subdivide(mesh, 1);
  return mesh;
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// Approximate, sequential scheduling (AVTP)
// ---------------------------------------------------------------------------------------------------

TEST(Approximate_variants, never_below_exact_and_error_shrinks_with_lambda)
{
  for(const char* name : { "elephant.off", "knot1.off", "three_peaks.off" })
  {
    const Surface_mesh mesh = fine_mesh(name);
    Solver solver(mesh);
    const std::vector<double> exact = run<CGAL::Sequential_tag>(solver, 0, Variant());
    std::vector<double> errors;
    for(double lambda : { 2., 8., 32. })
    {
      Variant o;
      o.lambda = lambda;
      Propagation_statistics st;
      const std::vector<double> d = run<CGAL::Sequential_tag>(solver, 0, o, &st);
      EXPECT_EQ(st.method, "avtp");
      EXPECT_GT(st.resets, 0u) << name << ", lambda " << lambda;
      EXPECT_LE(below_exact(d, exact), EXACT_TOLERANCE) << name << ", lambda " << lambda;
      errors.push_back(mean_relative_error(d, exact));
    }
    std::cout << "  [" << name << " x4] mean relative error, lambda 2 / 8 / 32: " << errors[0] << " / "
              << errors[1] << " / " << errors[2] << std::endl;
    EXPECT_GT(errors[0], errors[1]) << name;
    EXPECT_GT(errors[1], errors[2]) << name;
    EXPECT_GT(errors[2], 0.) << name;
    // lambda = 8: about 0.1% on these meshes (the package's recommended value)
    EXPECT_LT(errors[1], 2.5e-3) << name;
  }
}

TEST(Approximate_variants, equal_exact_when_lambda_h_exceeds_the_largest_distance)
{
  for(const char* name : { "elephant-with-holes.off", "mushroom.off", "knot1.off" })
  {
    const Surface_mesh mesh = load_mesh(name);
    Solver solver(mesh);
    Propagation_statistics st;
    const std::vector<double> exact = run<CGAL::Sequential_tag>(solver, 5, Variant(), &st);
    Variant o;
    o.lambda = 1.01 * st.max_distance / solver.mean_edge_length();
    Propagation_statistics sa;
    const std::vector<double> d = run<CGAL::Sequential_tag>(solver, 5, o, &sa);
    EXPECT_EQ(sa.resets, 0u);
    EXPECT_TRUE(distances_near(d, exact, EXACT_TOLERANCE, std::string(name) + ", AVTP with lambda h > max distance"));
  }
}

// ---------------------------------------------------------------------------------------------------
// Parallel scheduling (PVTP, PAVTP)
// ---------------------------------------------------------------------------------------------------

#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP

TEST(Parallel_variants, pvtp_equals_vtp_on_every_test_mesh_for_1_to_4_threads)
{
  for(const char* name : all_meshes)
  {
    const Surface_mesh mesh = load_mesh(name);
    Solver solver(mesh);
    for(std::size_t source : { std::size_t(0), std::size_t(num_vertices(mesh) / 3) })
    {
      Propagation_statistics vs;
      const std::vector<double> exact = run<CGAL::Sequential_tag>(solver, source, Variant(), &vs);
      for(int threads : { 1, 2, 3, 4 })
      {
        Variant o;
        o.number_of_threads = threads;
        Propagation_statistics ps;
        const std::vector<double> d = run<CGAL::Parallel_tag>(solver, source, o, &ps);
        EXPECT_EQ(ps.method, "pvtp");
        EXPECT_EQ(ps.threads, threads);
        EXPECT_EQ(ps.reached_vertices, vs.reached_vertices);
        EXPECT_TRUE(distances_near(d, exact, EXACT_TOLERANCE,
                                   std::string(name) + ", source " + std::to_string(source) + ", " +
                                     std::to_string(threads) + " threads"));
      }
    }
  }
}

TEST(Parallel_variants, output_does_not_depend_on_thread_timing)
{
  // Bitwise-identical distances and identical window counts over repeated runs, for each T.
  const Surface_mesh mesh = fine_mesh("knot1.off");
  Solver solver(mesh);
  for(int threads : { 2, 3, 4 })
    for(double lambda : { std::numeric_limits<double>::infinity(), 4. })
    {
      Variant o;
      o.number_of_threads = threads;
      o.lambda = lambda;
      Propagation_statistics first;
      const std::vector<double> d0 = run<CGAL::Parallel_tag>(solver, 17, o, &first);
      for(int repeat = 0; repeat < 3; ++repeat)
      {
        Propagation_statistics st;
        const std::vector<double> d = run<CGAL::Parallel_tag>(solver, 17, o, &st);
        EXPECT_EQ(st.windows_created, first.windows_created) << threads << " threads, lambda " << lambda;
        EXPECT_EQ(st.windows_propagated, first.windows_propagated) << threads << " threads, lambda " << lambda;
        std::size_t differences = 0;
        for(std::size_t i = 0; i < d.size(); ++i)
          if(!(d[i] == d0[i]))
            ++differences;
        EXPECT_EQ(differences, 0u) << threads << " threads, lambda " << lambda << ", repeat " << repeat;
      }
    }
}

TEST(Parallel_variants, pavtp_meets_the_avtp_invariants)
{
  for(const char* name : { "elephant.off", "knot1.off", "three_peaks.off" })
  {
    const Surface_mesh mesh = fine_mesh(name);
    Solver solver(mesh);
    Propagation_statistics vs;
    const std::vector<double> exact = run<CGAL::Sequential_tag>(solver, 0, Variant(), &vs);
    for(int threads : { 1, 2, 4 })
    {
      std::vector<double> errors;
      for(double lambda : { 2., 8., 32. })
      {
        Variant o;
        o.lambda = lambda;
        o.number_of_threads = threads;
        Propagation_statistics st;
        const std::vector<double> d = run<CGAL::Parallel_tag>(solver, 0, o, &st);
        EXPECT_EQ(st.method, "pavtp");
        EXPECT_GT(st.resets, 0u);
        EXPECT_LE(below_exact(d, exact), EXACT_TOLERANCE) << name << ", " << threads << " threads, lambda " << lambda;
        errors.push_back(mean_relative_error(d, exact));
      }
      std::cout << "  [" << name << " x4, " << threads << " threads] PAVTP mean relative error, lambda 2 / 8 / 32: "
                << errors[0] << " / " << errors[1] << " / " << errors[2] << std::endl;
      EXPECT_GT(errors[0], errors[2]) << name << ", " << threads << " threads";
      EXPECT_GE(errors[1], errors[2]) << name << ", " << threads << " threads";
      EXPECT_LT(errors[1], 2.5e-3) << name << ", " << threads << " threads";
      // lambda h above the largest distance: exact
      Variant o;
      o.number_of_threads = threads;
      o.lambda = 1.01 * vs.max_distance / solver.mean_edge_length();
      const std::vector<double> d = run<CGAL::Parallel_tag>(solver, 0, o);
      EXPECT_TRUE(distances_near(d, exact, EXACT_TOLERANCE, std::string(name) + ", PAVTP with lambda h > max distance"));
    }
  }
}

// A reset deletes the windows waiting near the wavefront: in the parallel scheduling, the lists queued
// by a selection must be propagated before it happens, or some vertices are never reached (found on a
// mesh of 2.5M vertices, where a selection takes many vertices). Many resets (small lambda) on a mesh
// large enough for big selections, several thread counts: every reachable vertex is reached.
TEST(Parallel_variants, pavtp_reaches_every_reachable_vertex)
{
  Surface_mesh mesh = load_mesh("elephant.off");
  vtp_support::midpoint_subdivide(mesh, 2);
  Solver solver(mesh);
  Propagation_statistics vs;
  const std::vector<double> exact = run<CGAL::Sequential_tag>(solver, 0, Variant(), &vs);
  for(int threads : { 2, 3, 4 })
    for(double lambda : { 1., 2., 4. })
    {
      Variant o;
      o.lambda = lambda;
      o.number_of_threads = threads;
      Propagation_statistics st;
      const std::vector<double> d = run<CGAL::Parallel_tag>(solver, 0, o, &st);
      EXPECT_GT(st.resets, 10u);
      EXPECT_EQ(st.reached_vertices, vs.reached_vertices) << threads << " threads, lambda " << lambda;
      EXPECT_LE(below_exact(d, exact), EXACT_TOLERANCE) << threads << " threads, lambda " << lambda;
    }
}

#endif // CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP
