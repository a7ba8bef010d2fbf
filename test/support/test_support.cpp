// Tests of the support layer (support/): number formatting, the fast OFF reader (against CGAL's reader), the
// reading of mesh files, the description of the statistics.
//
// Every file these tests write is in VTP_SUPPORT_TEST_TMP_DIR (in the build tree).

#include "vtp_test_files.h"

#include <vtp_support/fast_off_reader.h>
#include <vtp_support/number_format.h>
#include <vtp_support/read_mesh.h>
#include <vtp_support/statistics.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

using vtp_support::Mesh;
using vtp_support::Vertex_index;

using vtp_test_files::write_all;

const std::string mesh_dir = VTP_SUPPORT_TEST_MESH_DIR;

std::string fresh_folder(const std::string& name)
{
  return vtp_test_files::fresh_folder(VTP_SUPPORT_TEST_TMP_DIR, name);
}

// ------------------------------------------------------------------------------------------------
// Number formatting
// ------------------------------------------------------------------------------------------------
TEST(NumberFormat, ShortestTextReadsBackExactly)
{
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> uniform(0., 1.);
  for(int i = 0; i < 100000; ++i)
  {
    const double x = uniform(random) * std::pow(10., static_cast<int>(random() % 40) - 20);
    const std::string text = vtp_support::double_to_string(x);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), x) << text;
  }
  EXPECT_EQ(vtp_support::double_to_string(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(vtp_support::double_to_string(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(vtp_support::double_to_string(0.), "0");
  EXPECT_EQ(vtp_support::double_to_string(1.), "1");
  EXPECT_EQ(vtp_support::double_to_string(0.1), "0.1");
  std::ostringstream os;
  vtp_support::write_values_text(os, { 0., 0.5, std::numeric_limits<double>::infinity() });
  EXPECT_EQ(os.str(), "0\n0.5\ninf\n");
}

// ------------------------------------------------------------------------------------------------
// Fast OFF reader: the same mesh as CGAL's reader, or NOT_HANDLED
// ------------------------------------------------------------------------------------------------
void expect_same_mesh(const Mesh& fast, const Mesh& cgal)
{
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(fast));
  ASSERT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
  ASSERT_EQ(fast.number_of_faces(), cgal.number_of_faces());
  ASSERT_EQ(fast.number_of_edges(), cgal.number_of_edges());
  for(Vertex_index v : cgal.vertices())
  {
    EXPECT_EQ(fast.point(v), cgal.point(v));
    EXPECT_EQ(fast.is_border(v), cgal.is_border(v)) << "vertex " << v;
    EXPECT_EQ(fast.degree(v), cgal.degree(v)) << "vertex " << v;
  }
  std::size_t border_fast = 0, border_cgal = 0;
  for(Mesh::Halfedge_index h : fast.halfedges())
    border_fast += fast.is_border(h) ? 1 : 0;
  for(Mesh::Halfedge_index h : cgal.halfedges())
    border_cgal += cgal.is_border(h) ? 1 : 0;
  EXPECT_EQ(border_fast, border_cgal);
  // Same faces, in the same order, with the same orientation.
  for(Mesh::Face_index f : cgal.faces())
  {
    std::vector<std::size_t> a, b;
    for(Vertex_index v : CGAL::vertices_around_face(fast.halfedge(f), fast))
      a.push_back(std::size_t(v));
    for(Vertex_index v : CGAL::vertices_around_face(cgal.halfedge(f), cgal))
      b.push_back(std::size_t(v));
    ASSERT_EQ(a.size(), 3u);
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    std::rotate(b.begin(), std::min_element(b.begin(), b.end()), b.end());
    EXPECT_EQ(a, b) << "face " << f;
  }
}

TEST(FastOffReader, SameMeshAsCgal)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "mech-holes-shark.off", "knot1.off",
                           "sphere.off", "three_peaks.off" })
  {
    SCOPED_TRACE(name);
    Mesh fast, cgal;
    const vtp_support::Fast_off_result r = vtp_support::read_off_triangle_mesh(mesh_dir + "/" + name, fast);
    ASSERT_EQ(r.status, vtp_support::Fast_off_result::MESH) << r.reason;
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/" + name, cgal));
    expect_same_mesh(fast, cgal);
  }
}

// The halfedge structure built on several threads is the one built on one, halfedge for halfedge (and the
// invalid meshes are found so, with the same reason). Without OpenMP, the number of threads is ignored.
TEST(FastOffReader, SameMeshWithAnyNumberOfThreads)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "mech-holes-shark.off",
                           "degenerate_zero_length_edges.off" })
  {
    SCOPED_TRACE(name);
    Mesh one;
    ASSERT_EQ(vtp_support::read_off_triangle_mesh(mesh_dir + "/" + name, one, 1).status,
              vtp_support::Fast_off_result::MESH);
    for(int threads : { 2, 3, 0 })
    {
      SCOPED_TRACE(threads);
      Mesh many;
      ASSERT_EQ(vtp_support::read_off_triangle_mesh(mesh_dir + "/" + name, many, threads).status,
                vtp_support::Fast_off_result::MESH);
      ASSERT_TRUE(many.is_valid(false)); // (Surface_mesh's check: a file has isolated vertices)
      ASSERT_EQ(many.number_of_halfedges(), one.number_of_halfedges());
      ASSERT_EQ(many.number_of_faces(), one.number_of_faces());
      for(Mesh::Halfedge_index h : one.halfedges())
        ASSERT_TRUE(many.target(h) == one.target(h) && many.next(h) == one.next(h) && many.prev(h) == one.prev(h)
                    && many.face(h) == one.face(h))
          << "halfedge " << h;
      for(Vertex_index v : one.vertices())
        ASSERT_EQ(many.halfedge(v), one.halfedge(v)) << "vertex " << v;
      for(Mesh::Face_index f : one.faces())
        ASSERT_EQ(many.halfedge(f), one.halfedge(f)) << "face " << f;
    }
  }
  const std::string folder = fresh_folder("fast_off_threads");
  const std::pair<const char*, const char*> invalid[] = {
    { "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n3 0 1 2\n3 0 1 3\n", "two faces have the same oriented edge" },
    { "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n", "a vertex is not manifold" },
  };
  int i = 0;
  for(const auto& c : invalid)
  {
    const std::string file = folder + "/invalid" + std::to_string(i++) + ".off";
    write_all(file, c.first);
    for(int threads : { 1, 2 })
    {
      Mesh m;
      const vtp_support::Fast_off_result r = vtp_support::read_off_triangle_mesh(file, m, threads);
      EXPECT_EQ(r.status, vtp_support::Fast_off_result::NOT_HANDLED);
      EXPECT_EQ(r.reason, c.second);
    }
  }
}

TEST(FastOffReader, CommentsBlankLinesAndFaceColours)
{
  const std::string folder = fresh_folder("fast_off");
  const std::string file = folder + "/formatted.off";
  write_all(file, "# a comment\nOFF\n\n# counts\n4 4 0\n0 0 0\n1 0 0 # trailing comment\n\t0 1 0\n0 0 1\r\n"
                  "3 0 2 1 255 0 0\n3 0 1 3\n\n3 1 2 3\n3 0 3 2\n");
  Mesh fast, cgal;
  const vtp_support::Fast_off_result r = vtp_support::read_off_triangle_mesh(file, fast);
  ASSERT_EQ(r.status, vtp_support::Fast_off_result::MESH) << r.reason;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(file, cgal));
  expect_same_mesh(fast, cgal);
}

TEST(FastOffReader, LeavesEverythingElseToCgal)
{
  const std::string folder = fresh_folder("fast_off_other");
  const std::pair<const char*, const char*> cases[] = {
    { "quad", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n" },
    { "coff", "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n" },
    { "repeated_vertex", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n" },
    { "same_oriented_edge", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n3 0 1 2\n3 0 1 3\n" },
    // two triangles sharing only vertex 0
    { "pinched_vertex", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n" },
    { "four_numbers_per_vertex", "OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n" },
  };
  for(const auto& c : cases)
  {
    SCOPED_TRACE(c.first);
    const std::string file = folder + "/" + c.first + ".off";
    write_all(file, c.second);
    Mesh m;
    EXPECT_EQ(vtp_support::read_off_triangle_mesh(file, m).status, vtp_support::Fast_off_result::NOT_HANDLED);
  }
}

TEST(FastOffReader, DefiniteErrors)
{
  const std::string folder = fresh_folder("fast_off_errors");
  const std::pair<const char*, const char*> cases[] = {
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n", "the file ends after 2 of 3 vertices" },
    { "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the file ends after 1 of 2 faces" },
    { "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a non-finite coordinate" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n", "vertex 2 has a non-finite coordinate" },
    { "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "face 0 refers to vertex 3, out of range (there are 3 vertices)" },
    { "OFF\n0 0 0\n", "the mesh has no vertices" },
    { "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "the mesh has no faces" },
  };
  int i = 0;
  for(const auto& c : cases)
  {
    const std::string file = folder + "/case" + std::to_string(i++) + ".off";
    write_all(file, c.first);
    Mesh m;
    try
    {
      vtp_support::read_off_triangle_mesh(file, m);
      ADD_FAILURE() << "no error for: " << c.first;
    }
    catch(const vtp_support::Fast_off_error& e)
    {
      EXPECT_EQ(std::string(e.what()), c.second);
    }
  }
}

// The soup of a valid OFF file (read_off_triangle_soup(), Python's read_mesh()) is the mesh that
// read_off_triangle_mesh() builds: the same points in the same order, face j the triangle that starts at
// source(halfedge(j)); anything else is left to CGAL (the same reason) or is the same error.
TEST(FastOffReader, SoupIsTheMeshOfTheFile)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "mech-holes-shark.off", "knot1.off",
                           "sphere.off", "three_peaks.off", "degenerate_zero_length_edges.off" })
  {
    SCOPED_TRACE(name);
    Mesh mesh;
    ASSERT_EQ(vtp_support::read_off_triangle_mesh(mesh_dir + "/" + name, mesh).status,
              vtp_support::Fast_off_result::MESH);
    for(int threads : { 1, 2 })
    {
      std::vector<double> xyz;
      std::vector<vtp_support::fast_off_detail::Triangle> triangles;
      const vtp_support::Fast_off_result r =
        vtp_support::read_off_triangle_soup(mesh_dir + "/" + name, xyz, triangles, threads);
      ASSERT_EQ(r.status, vtp_support::Fast_off_result::MESH) << r.reason;
      ASSERT_EQ(xyz.size(), 3 * mesh.number_of_vertices());
      ASSERT_EQ(triangles.size(), mesh.number_of_faces());
      for(Vertex_index v : mesh.vertices())
        for(int k = 0; k < 3; ++k)
          ASSERT_EQ(xyz[3 * std::size_t(v) + std::size_t(k)], mesh.point(v)[k]) << "vertex " << v;
      for(Mesh::Face_index f : mesh.faces())
      {
        const Mesh::Halfedge_index h = mesh.halfedge(f);
        const vtp_support::fast_off_detail::Triangle t = { { std::uint32_t(mesh.source(h)), std::uint32_t(mesh.target(h)),
                                                             std::uint32_t(mesh.target(mesh.next(h))) } };
        ASSERT_EQ(triangles[std::size_t(f)], t) << "face " << f;
      }
    }
  }
  const std::string folder = fresh_folder("fast_off_soup");
  const char* const cases[] = {
    "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n",                       // a quad
    "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n",                                // a repeated vertex
    "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n3 0 1 2\n3 0 1 3\n",               // the same oriented edge twice
    "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n",       // a pinched vertex
    "OFF\n3 1 0\n0 0 0\n1 0 0\n",                                                // truncated
    "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",                                // truncated in the faces
    "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n",                              // NaN
    "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1e999 0\n3 0 1 2\n",                            // infinite
    "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",                                // index out of range
  };
  int i = 0;
  for(const char* c : cases)
  {
    SCOPED_TRACE(c);
    const std::string file = folder + "/case" + std::to_string(i++) + ".off";
    write_all(file, c);
    std::string mesh_outcome, soup_outcome;
    try
    {
      Mesh m;
      const vtp_support::Fast_off_result r = vtp_support::read_off_triangle_mesh(file, m, 2);
      mesh_outcome = r.status == vtp_support::Fast_off_result::MESH ? "mesh" : "not handled: " + r.reason;
    }
    catch(const vtp_support::Fast_off_error& e)
    {
      mesh_outcome = std::string("error: ") + e.what();
    }
    try
    {
      std::vector<double> xyz;
      std::vector<vtp_support::fast_off_detail::Triangle> triangles;
      const vtp_support::Fast_off_result r = vtp_support::read_off_triangle_soup(file, xyz, triangles, 2);
      soup_outcome = r.status == vtp_support::Fast_off_result::MESH ? "mesh" : "not handled: " + r.reason;
    }
    catch(const vtp_support::Fast_off_error& e)
    {
      soup_outcome = std::string("error: ") + e.what();
    }
    EXPECT_NE(mesh_outcome, "mesh");
    EXPECT_EQ(soup_outcome, mesh_outcome);
  }
}

// The parse of an OFF file in ranges of lines on several threads has the outcome of a parse line after line (one
// range on one thread): the same points and triangles, or the same reason left to CGAL, or the same error, on
// files of every oddity (comments, blank lines, CRLF, colours after the indices, polygons, trailing lines,
// a last line without newline, errors), whatever the ranges (down to one byte: a range per line) and the threads.
TEST(FastOffReader, RangesOfLinesGiveTheOutcomeOfOneRange)
{
  const std::string folder = fresh_folder("fast_off_ranges");
  const std::vector<std::string> texts = {
    "# a comment\nOFF\n\n# counts\n4 4 0\n0 0 0\n1 0 0 # trailing comment\n\t0 1 0\n0 0 1\r\n"
    "3 0 2 1 255 0 0\n3 0 1 3\n\n3 1 2 3\n3 0 3 2\n",
    "OFF\r\n4 4 0\r\n\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n# c\r\n3 0 2 1\r\n3 0 1 3\r\n3 1 2 3\r\n3 0 3 2",
    "OFF 4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 0.5 0.5 0.5 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\nextra lines\n9 9\n",
    "OFF\n4\n4 0\n  0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
    "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 1 2\n",               // a quad
    "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n4 0 1 2 3\n",               // a quad, last
    "OFF\n3 1 0\n0 0 0 1\n1 0 0\n0 1 0\n3 0 1 2\n",                             // four numbers
    "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n",                                 // two numbers
    "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 x\n3 0 1 2\n",                             // an error, then a reason
    "OFF\n3 1 0\n0 0 0\n1 0 x\n0 1e999 0\n3 0 1 2\n",                           // a reason, then an error
    "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n3 0 1\n",                        // out of range, then short
    "OFF\n3 1 0\n0 0 0\n1 0 0\n",                                               // truncated
    "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n\n# nothing more\n3 0 1 2\n",             // truncated in the faces
    "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",                                        // no faces
    "OFF\n",                                                                     // no counts
    "COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n",
  };
  auto outcome = [](const std::string& file, int threads, std::size_t range_bytes,
                    std::size_t block_bytes = std::size_t(1) << 22) {
    std::vector<double> xyz;
    std::vector<vtp_support::fast_off_detail::Triangle> triangles;
    std::ostringstream os;
    try
    {
      const vtp_support::Fast_off_result r = vtp_support::fast_off_detail::parse_off_triangles(
        file, [&xyz](std::size_t nv) { xyz.resize(3 * nv); },
        [&xyz](std::size_t i, double x, double y, double z) {
          xyz[3 * i] = x;
          xyz[3 * i + 1] = y;
          xyz[3 * i + 2] = z;
        },
        triangles, threads, range_bytes, block_bytes);
      if(r.status != vtp_support::Fast_off_result::MESH)
        return "not handled: " + r.reason;
      for(double x : xyz)
        os << x << ' ';
      for(const auto& t : triangles)
        os << t[0] << ' ' << t[1] << ' ' << t[2] << ", ";
    }
    catch(const vtp_support::Fast_off_error& e)
    {
      return std::string("error: ") + e.what();
    }
    return os.str();
  };
  int i = 0;
  for(const std::string& text : texts)
  {
    SCOPED_TRACE(text);
    const std::string file = folder + "/case" + std::to_string(i++) + ".off";
    write_all(file, text);
    const std::string one = outcome(file, 1, std::size_t(1) << 20);
    for(int threads : { 1, 2, 3 })
      for(std::size_t range_bytes : { 1, 2, 3, 5, 8, 13, 21, 64 })
        for(std::size_t block_bytes : { 48, 64, 100, 4096 })  // blocks of the file, cut after their last newline
          ASSERT_EQ(outcome(file, threads, range_bytes, block_bytes), one)
            << threads << " threads, ranges of " << range_bytes << ", blocks of " << block_bytes;
  }
  // the oddities above as before: the first file is read as CGAL reads it (CommentsBlankLinesAndFaceColours)
  EXPECT_EQ(outcome(folder + "/case1.off", 2, 4), outcome(folder + "/case0.off", 1, std::size_t(1) << 20));
  EXPECT_EQ(outcome(folder + "/case4.off", 2, 4), "not handled: a face is not a triangle");
  EXPECT_EQ(outcome(folder + "/case8.off", 2, 4), "error: vertex 1 has a non-finite coordinate");
  EXPECT_EQ(outcome(folder + "/case9.off", 2, 4), "not handled: unexpected vertex line");
  EXPECT_EQ(outcome(folder + "/case10.off", 2, 4),
            "error: face 0 refers to vertex 7, out of range (there are 3 vertices)");
  EXPECT_EQ(outcome(folder + "/case12.off", 2, 4), "error: the file ends after 1 of 2 faces");
  // a mesh of the data, in ranges of about 1 KB and blocks of 64 KB on 2 threads: the mesh of one range
  for(const char* name : { "elephant.off", "mech-holes-shark.off" })
    EXPECT_EQ(outcome(mesh_dir + "/" + name, 2, 1000, 1 << 16),
              outcome(mesh_dir + "/" + name, 1, std::size_t(1) << 30, std::size_t(1) << 30))
      << name;
  // a line longer than a block is left to CGAL's reader
  EXPECT_EQ(outcome(folder + "/case0.off", 1, 8, 16), "not handled: unexpected header");
  write_all(folder + "/long.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0" + std::string(100, ' ') + "\n3 0 1 2\n");
  EXPECT_EQ(outcome(folder + "/long.off", 2, 8, 64), "not handled: a line is longer than 64 bytes");
}

// The halfedge structure built from the tables of an earlier check of the same triangles (Python's read_mesh(),
// then Solver(V, F)) is the one built with its own check, halfedge for halfedge.
TEST(FastOffReader, MeshFromTheTablesOfAnEarlierCheck)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "mech-holes-shark.off" })
  {
    SCOPED_TRACE(name);
    Mesh checked;
    ASSERT_EQ(vtp_support::read_off_triangle_mesh(mesh_dir + "/" + name, checked, 2).status,
              vtp_support::Fast_off_result::MESH);
    std::vector<double> xyz;
    std::vector<vtp_support::fast_off_detail::Triangle> triangles;
    vtp_support::fast_off_detail::Corner_tables tables;
    ASSERT_EQ(vtp_support::read_off_triangle_soup(mesh_dir + "/" + name, xyz, triangles, 2, &tables).status,
              vtp_support::Fast_off_result::MESH);
    ASSERT_EQ(tables.opposite.size(), 3 * triangles.size());
    Mesh mesh;
    for(std::size_t i = 0; i < xyz.size() / 3; ++i)
      mesh.add_vertex(vtp_support::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]));
    std::string reason;
    ASSERT_TRUE(vtp_support::fast_off_detail::build_triangle_mesh(triangles, mesh, reason, 1, &tables));
    ASSERT_EQ(mesh.number_of_halfedges(), checked.number_of_halfedges());
    for(Mesh::Halfedge_index h : checked.halfedges())
      ASSERT_TRUE(mesh.target(h) == checked.target(h) && mesh.next(h) == checked.next(h)
                  && mesh.prev(h) == checked.prev(h) && mesh.face(h) == checked.face(h))
        << "halfedge " << h;
    for(Vertex_index v : checked.vertices())
      ASSERT_TRUE(mesh.halfedge(v) == checked.halfedge(v) && mesh.point(v) == checked.point(v)) << "vertex " << v;
  }
}

// The stages from the file to the answer: each named once, in seconds but the ratio; the time in no named stage
// and the ratio follow from the others; the JSON has every name once.
TEST(Statistics, StagesAddUp)
{
  vtp_support::Stage_seconds s;
  s.read = 0.5;
  s.repair = 0.25;
  s.preprocessing = 1.;
  s.propagation = 8.;
  s.write = 0.125;
  s.total = 10.;
  EXPECT_EQ(s.other(), 0.125);
  EXPECT_EQ(s.outside_propagation_ratio(), 0.25);
  std::vector<std::string> names;
  double sum = 0.;
  vtp_support::for_each_stage(s, [&](const char* name, double value, vtp_support::Statistic_unit unit) {
    names.push_back(name);
    const std::string n = name;
    if(unit == vtp_support::Statistic_unit::seconds)
    {
      EXPECT_EQ(n.substr(n.size() - 8), "_seconds");
      if(n != "total_seconds")
        sum += value;
    }
    else
      EXPECT_EQ(n, "outside_propagation_ratio");
  });
  EXPECT_EQ(sum, s.total);
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  EXPECT_EQ(names.size(), 8u);
  std::ostringstream os;
  vtp_support::write_stages_json(os, s);
  for(const std::string& n : names)
    EXPECT_NE(os.str().find("\"" + n + "\": "), std::string::npos) << n;
  EXPECT_NE(os.str().find("\"outside_propagation_ratio\": 0.25"), std::string::npos);
  // a total below the sum of the stages (clocks read at other moments): nothing negative
  s.total = 9.;
  EXPECT_EQ(s.other(), 0.);
}

TEST(ReadInputMesh, TinyValuesUnderflowLikeCgal)
{
  const std::string folder = fresh_folder("underflow");
  const std::string file = folder + "/tiny.off";
  write_all(file, "OFF\n3 1 0\n0 0 0\n1e-320 0 0\n0 1e-400 1\n3 0 1 2\n");
  Mesh m;
  ASSERT_EQ(vtp_support::read_off_triangle_mesh(file, m).status, vtp_support::Fast_off_result::MESH);
  EXPECT_EQ(m.point(Vertex_index(1)).x(), 1e-320);
  EXPECT_EQ(m.point(Vertex_index(2)).y(), 0.);
}

// A vertex line that CGAL's reader refuses is named by its line of the file (from 1) and its vertex (from 0), as CGAL
// reads an OFF file: counts on the header's line or after it, comment lines and blank lines skipped, a comment after
// the numbers ignored, numbers after the third ignored, four numbers needed in 4OFF; other refusals keep the generic
// message.
TEST(ReadInputMesh, MalformedOffVertexLineNamesItsLine)
{
  const std::string folder = fresh_folder("vertex_lines");
  auto error_of = [&](const std::string& name, const std::string& text) {
    write_all(folder + "/" + name, text);
    vtp_support::Input_mesh input;
    try
    {
      vtp_support::read_input_mesh(folder + "/" + name, input);
    }
    catch(const vtp_support::Input_error& e)
    {
      const std::string what = e.what();
      return what.substr(what.find("': ") + 3);
    }
    return std::string("read");
  };
  const std::string faces = "3 0 1 2\n3 0 2 3\n";
  EXPECT_EQ(error_of("a.off", "OFF 4 2 0\n0 0 0\n1 0 0\n0 1\n0 0 1\n" + faces),
            "line 4: vertex 2 has 2 coordinates (expected 3)");
  EXPECT_EQ(error_of("b.off", "# c\nOFF\n\n4 2 0\n# c\n0 0 0 # c\n\n1 0 0 7 8\n0 1 0\n  1e0 x 1\n" + faces),
            "line 10: vertex 3 has an invalid coordinate 'x'");
  EXPECT_EQ(error_of("c.off", "OFF\r\n4 2 0\r\n0 0 0\r\n1 0 # 0\r\n0 1 0\r\n0 0 1\r\n" + faces),
            "line 4: vertex 1 has 2 coordinates (expected 3)");
  EXPECT_EQ(error_of("d.off", "4OFF\n4 2 0\n0 0 0 1\n1 0 0 1\n0 1 0\n0 0 1 1\n" + faces),
            "line 5: vertex 2 has 3 coordinates (expected 4)");
  EXPECT_EQ(error_of("e.off", "OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n" + faces),
            "vertex 2 has a non-finite coordinate");                         // the fast reader's, unchanged
  EXPECT_EQ(error_of("f.off", "OFF\n4 2 0\n0 0 0\n1 0 0 \n0 1 0 a\n0 0 1\n" + faces), "read");
  EXPECT_EQ(error_of("g.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n" + faces), "invalid or unsupported mesh data");
}

// The correspondence of the file's vertices and the mesh's, both ways: two tetrahedra sharing vertex 0 (cut
// apart by the repair into two copies), and vertex 7 in no face (removed).
TEST(ReadInputMesh, FileAndMeshVerticesBothWays)
{
  vtp_support::Input_mesh input;
  vtp_support::read_input_mesh(VTP_SUPPORT_TEST_CLI_DATA_DIR "/nonmanifold_vertex.off", input);
  ASSERT_FALSE(input.direct);
  ASSERT_EQ(input.file_vertices, 8u);
  EXPECT_EQ(input.mesh_vertices_of(0).size(), 2u);
  EXPECT_TRUE(input.mesh_vertices_of(7).empty());
  std::vector<int> seen(input.mesh.number_of_vertices(), 0);
  for(std::size_t i = 0; i < input.file_vertices; ++i)
    for(Vertex_index v : input.mesh_vertices_of(i))
    {
      EXPECT_EQ(input.file_vertex_of(v), i);
      ++seen[std::size_t(v)];
    }
  for(int n : seen)
    EXPECT_EQ(n, 1);
  // values of the mesh reported on the file: the smallest of the copies, +inf without copy
  std::vector<double> per_mesh_vertex(input.mesh.number_of_vertices());
  for(Vertex_index v : input.mesh.vertices())
    per_mesh_vertex[std::size_t(v)] = static_cast<double>(std::size_t(v));
  const std::vector<double> on_file = input.on_file_vertices(std::move(per_mesh_vertex));
  EXPECT_EQ(on_file[0], static_cast<double>(std::size_t(input.mesh_vertices_of(0).front())));
  EXPECT_EQ(on_file[7], std::numeric_limits<double>::infinity());
}

} // namespace
