// The parallel (PVTP) and approximate (AVTP, PAVTP) variants against the exact sequential VTP:
//  - PVTP equals VTP (1e-12 relative) on every test mesh for T = 1, 2, 3, 4 (more threads than
//    cores included), and its output for a given T is the same on every run;
//  - approximate distances are never below the exact ones (every reported distance is the length of
//    a real surface path), equal the exact ones when lambda * h exceeds the largest distance, and
//    their error shrinks as lambda grows; PAVTP meets the same invariants and bounds as AVTP.
//  - PVTP and PAVTP match the analytic distances, reach the same vertices as VTP (unreachable ones get
//    +infinity), and need OpenMP; AVTP is never below the exact distance on a planar domain.
// The exact reference is the sequential VTP, itself checked against analytic values and CGAL's
// Surface_mesh_shortest_path by test_exact_distances.cpp.

#include "vtp_test_meshes.h"
#include "vtp_test_utils.h"

#include <vtp_support/midpoint_subdivision.h>


#include <cmath>
#include <string>
#include <vector>

using namespace vtp_test;
using CGAL::VTP_geodesics::Geodesic_distance_solver;
using CGAL::VTP_geodesics::Propagation_statistics;
using CGAL::VTP_geodesics::compute_geodesic_distances;

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

// A thread made late (it sleeps 1 ms before every fifth work item it takes, or the master before every fifth
// round it publishes too, as a thread that the system stops for another process): PVTP and PAVTP give the
// bits and window counts of the runs without it.
TEST(Parallel_variants, a_late_thread_changes_no_bit)
{
  const Surface_mesh mesh = fine_mesh("knot1.off");
  Solver solver(mesh);
  for(int threads : { 2, 3 })
    for(double lambda : { std::numeric_limits<double>::infinity(), 4. })
    {
      Variant o;
      o.number_of_threads = threads;
      o.lambda = lambda;
      Propagation_statistics first;
      const std::vector<double> d0 = run<CGAL::Parallel_tag>(solver, 17, o, &first);
      for(int late : { 0, 1 })
      {
        Propagation_statistics st;
        std::vector<double> d;
        int late_calls = 0;
        // (on a busy machine the master may run every round alone, the team being slower, and the late thread
        // take no item: then the run is done again, up to 20 times, until the delay happens)
        for(int attempt = 0; attempt < 20 && late_calls == 0; ++attempt)
        {
          const vtp_test::Late_thread delay(late);
          d = run<CGAL::Parallel_tag>(solver, 17, o, &st);
          late_calls = delay.calls();
        }
        const std::string what = std::to_string(threads) + " threads, lambda " + std::to_string(lambda)
                                 + ", thread " + std::to_string(late) + " late";
        EXPECT_GT(late_calls, 0) << what;
        EXPECT_GT(st.parallel_rounds, 0u) << what;
        EXPECT_EQ(st.windows_created, first.windows_created) << what;
        EXPECT_EQ(st.windows_propagated, first.windows_propagated) << what;
        std::size_t differences = 0;
        for(std::size_t i = 0; i < d.size(); ++i)
          if(!(d[i] == d0[i]))
            ++differences;
        EXPECT_EQ(differences, 0u) << what;
      }
    }
}

// The choice between the team and the master alone (Team_choice, Round_team.h), fed with rounds of known
// work at known times: a team slower than one thread (a busy machine) is left after one probe, a faster one
// is kept (the probes of the other way come less and less often), and the choice follows a change.
TEST(Parallel_variants, the_faster_of_team_and_master_alone_runs_the_rounds)
{
  typedef CGAL::VTP_geodesics::internal::Team_choice Choice;
  typedef Choice::Clock Clock;
  const double window = Choice::window;
  // rounds of 1 unit of work each; `team_rate` and `alone_rate` units per second; returns the share of the
  // rounds run by the team over `seconds`
  auto simulate = [&](Choice& c, Clock::time_point& now, double team_rate, double alone_rate, double seconds) {
    std::size_t team = 0, all = 0;
    const Clock::time_point end = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    while(now < end)
    {
      const bool t = c.team();
      now += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1. / (t ? team_rate : alone_rate)));
      c.record(1., now);
      team += t ? 1 : 0;
      ++all;
    }
    return static_cast<double>(team) / static_cast<double>(all);
  };
  Clock::time_point now = Clock::now();
  Choice c;
  c.reset(now);
  EXPECT_TRUE(c.team());
  const double rate = 1000. / window;  // 1,000 rounds per window
  // the team at 1.5x the master alone: the team runs nearly every round (one probe window in 33 at most, once
  // the stays have grown)
  simulate(c, now, 1.5 * rate, rate, 100 * window);
  EXPECT_GT(simulate(c, now, 1.5 * rate, rate, 330 * window), 0.95);
  // the machine gets busy: the team at 0.6x; a probe finds the master alone faster, which then runs
  simulate(c, now, 0.6 * rate, rate, 80 * window);
  EXPECT_LT(simulate(c, now, 0.6 * rate, rate, 330 * window), 0.05);
  // and idle again: the team comes back
  simulate(c, now, 1.5 * rate, rate, 80 * window);
  EXPECT_GT(simulate(c, now, 1.5 * rate, rate, 330 * window), 0.95);
  // a reset starts with the team
  c.reset(now);
  EXPECT_TRUE(c.team());
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

// ---------------------------------------------------------------------------------------------------
// Parallel (PVTP, PAVTP) and approximate (AVTP) variants: analytic distances, real meshes, unreachable vertices
// ---------------------------------------------------------------------------------------------------

#ifdef CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP

TEST(Parallel, matches_the_analytic_distances)
{
  const int n = 24;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 5u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  for(int threads : {0, 1, 2})
  {
    const std::size_t s = grid_vertex(n, 7, 11);
    std::vector<double> expected(soup.points.size()), d(soup.points.size(), NOT_A_VERTEX);
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      expected[i] = distance(soup.points[s], soup.points[i]);
    solver.compute<CGAL::Parallel_tag>(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)),
                                       Vertex_index(static_cast<Surface_mesh::size_type>(s)),
                                       CGAL::VTP_geodesics::parameters::number_of_threads(threads));
    const Propagation_statistics& st = solver.statistics();
    EXPECT_TRUE(distances_near(d, expected, EXACT_TOLERANCE, "parallel, " + std::to_string(threads) + " threads"));
    EXPECT_EQ(st.method, "pvtp");
    EXPECT_GE(st.threads, 1);
    if(threads > 0)
    {
      EXPECT_LE(st.threads, threads);
    }
  }
}

TEST(Parallel, matches_sequential_on_real_meshes)
{
  for(const char* name : {"elephant-with-holes.off", "knot1.off"})
  {
    const Surface_mesh mesh = load_mesh(name);
    Geodesic_distance_solver<Surface_mesh> solver(mesh);
    for(Vertex_index s : {Vertex_index(0), Vertex_index(static_cast<Surface_mesh::size_type>(num_vertices(mesh) / 2))})
    {
      const std::vector<double> sequential = vtp_distances(mesh, s);
      std::vector<double> parallel(num_vertices(mesh), NOT_A_VERTEX);
      solver.compute<CGAL::Parallel_tag>(boost::make_iterator_property_map(parallel.begin(), get(boost::vertex_index, mesh)), s);
      EXPECT_TRUE(distances_near(parallel, sequential, EXACT_TOLERANCE,
                                 std::string(name) + ", parallel vs sequential, source " + std::to_string(std::size_t(s))));
    }
  }
}

TEST(Parallel, unreachable_vertices)
{
  Polygon_soup soup = planar_grid(6, 6, 1., 1.);
  soup.append(regular_tetrahedron(), Vector_3(10, 0, 0));
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  std::vector<double> d(num_vertices(mesh), NOT_A_VERTEX);
  Propagation_statistics st;
  compute_geodesic_distances<CGAL::Parallel_tag>(
    mesh, boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)), Vertex_index(0),
    CGAL::VTP_geodesics::parameters::statistics(st));
  for(std::size_t i = 0; i < 49; ++i)
    EXPECT_NEAR(d[i], distance(soup.points[0], soup.points[i]), EXACT_TOLERANCE * std::sqrt(2.));
  for(std::size_t i = 49; i < 53; ++i)
    EXPECT_EQ(d[i], INF);
  EXPECT_EQ(st.reached_vertices, 49u);
}

// PAVTP: same lower bound as AVTP below (every distance is the length of a real path).
TEST(Parallel, approximate_never_below_the_exact_distance)
{
  const int n = 24;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 12u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const std::size_t s = grid_vertex(n, 20, 5);
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  const double lambda = 1.;
  std::vector<double> d(soup.points.size(), NOT_A_VERTEX);
  solver.compute<CGAL::Parallel_tag>(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)),
                                     Vertex_index(static_cast<Surface_mesh::size_type>(s)),
                                     CGAL::VTP_geodesics::parameters::lambda(lambda));
  const Propagation_statistics& st = solver.statistics();
  EXPECT_EQ(st.method, "pavtp");
  EXPECT_EQ(st.reached_vertices, soup.points.size());
  double below = 0.;
  for(std::size_t i = 0; i < soup.points.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(d[i])) << "vertex " << i;
    below = (std::max)(below, distance(soup.points[s], soup.points[i]) - d[i]);
  }
  EXPECT_LE(below, EXACT_TOLERANCE * std::sqrt(2.));
  ASSERT_GT(st.max_distance, 5. * lambda * solver.mean_edge_length());
  EXPECT_GT(st.resets, 0u);
}

#else

TEST(Parallel, requires_openmp)
{
  GTEST_SKIP() << "CGAL::VTP_geodesics_OpenMP_support is not available: the parallel variant is not tested";
}

#endif // CGAL_VTP_GEODESICS_LINKED_WITH_OPENMP

// The approximate variant drops windows, so each of its distances is the length of some path on the
// surface: never below the exact geodesic distance. On a convex planar domain that is the Euclidean one.
TEST(Approximate, never_below_the_exact_distance)
{
  const int n = 24;
  const Polygon_soup soup = planar_grid(n, n, 1., 1., 0.3, 11u);
  const Surface_mesh mesh = to_mesh<Surface_mesh>(soup);
  const std::size_t s = grid_vertex(n, 2, 3);
  Geodesic_distance_solver<Surface_mesh> solver(mesh);
  for(double lambda : {0.5, 1., 3.})
  {
    std::vector<double> d(soup.points.size(), NOT_A_VERTEX);
    solver.compute(boost::make_iterator_property_map(d.begin(), get(boost::vertex_index, mesh)),
                   Vertex_index(static_cast<Surface_mesh::size_type>(s)), CGAL::VTP_geodesics::parameters::lambda(lambda));
    const Propagation_statistics& st = solver.statistics();
    EXPECT_EQ(st.method, "avtp");
    EXPECT_EQ(st.reached_vertices, soup.points.size());
    EXPECT_EQ(d[s], 0.);
    double below = 0.;
    for(std::size_t i = 0; i < soup.points.size(); ++i)
    {
      ASSERT_TRUE(std::isfinite(d[i])) << "vertex " << i;
      below = (std::max)(below, distance(soup.points[s], soup.points[i]) - d[i]);
    }
    EXPECT_LE(below, EXACT_TOLERANCE * std::sqrt(2.)) << "lambda = " << lambda;
    // the propagation radius (about 1.3) is many times lambda * h (h is about 0.05): windows were reset
    ASSERT_GT(st.max_distance, 5. * lambda * solver.mean_edge_length());
    EXPECT_GT(st.resets, 0u) << "lambda = " << lambda;
  }
}
