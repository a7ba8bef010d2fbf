// Tests of the code shared by the command-line tools (support/): safe output files, number formatting, the
// fast OFF reader (against CGAL's reader), the PLY writer (read back with CGAL's PLY reader) and the picture.
//
// Every file these tests write is in VTP_SUPPORT_TEST_TMP_DIR (in the build tree).

#include <vtp_support/distance_ply.h>
#include <vtp_support/fast_off_reader.h>
#include <vtp_support/number_format.h>
#include <vtp_support/output_file.h>
#include <vtp_support/picture.h>
#include <vtp_support/read_mesh.h>

#include <CGAL/IO/OFF.h>
#include <CGAL/IO/read_ply_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using vtp_support::Mesh;
using vtp_support::Point_3;
using vtp_support::Vertex_index;

const std::string tmp_dir = VTP_SUPPORT_TEST_TMP_DIR;
const std::string mesh_dir = VTP_SUPPORT_TEST_MESH_DIR;

std::string read_all(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_all(const std::string& file, const std::string& text)
{
  std::ofstream out(file, std::ios::binary);
  out << text;
}

// Names of the entries of `folder` that start with `prefix`.
std::vector<std::string> entries_starting_with(const std::string& folder, const std::string& prefix)
{
  std::vector<std::string> r;
  DIR* d = ::opendir(folder.c_str());
  if(d == nullptr)
    return r;
  while(dirent* e = ::readdir(d))
  {
    const std::string name = e->d_name;
    if(name.compare(0, prefix.size(), prefix) == 0)
      r.push_back(name);
  }
  ::closedir(d);
  return r;
}

// A fresh folder for one test.
std::string fresh_folder(const std::string& name)
{
  // one folder per test and name: ctest runs the tests of this executable in parallel processes (-j)
  ::mkdir(tmp_dir.c_str(), 0777);
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string folder =
    tmp_dir + "/" + (test ? std::string(test->test_suite_name()) + "." + test->name() + "." : std::string()) + name;
  ::mkdir(folder.c_str(), 0777);
  for(const std::string& e : entries_starting_with(folder, ""))
    if(e != "." && e != "..")
      ::unlink((folder + "/" + e).c_str());
  return folder;
}

bool is_symlink(const std::string& path)
{
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

// ------------------------------------------------------------------------------------------------
// Output files
// ------------------------------------------------------------------------------------------------
TEST(OutputFile, NewRegularFileAppearsOnlyAtCommit)
{
  const std::string folder = fresh_folder("new_file");
  const std::string target = folder + "/out.txt";
  {
    vtp_support::Output_file f(target);
    EXPECT_EQ(f.kind(), vtp_support::Output_file::REPLACED);
    f.stream() << "hello\n";
    f.close();
    EXPECT_NE(::access(target.c_str(), F_OK), 0) << "the target exists before commit()";
    EXPECT_EQ(entries_starting_with(folder, "out.txt.tmp.").size(), 1u);
    f.commit();
  }
  EXPECT_EQ(read_all(target), "hello\n");
  EXPECT_TRUE(entries_starting_with(folder, "out.txt.tmp.").empty());
}

TEST(OutputFile, UncommittedFileLeavesTheTargetAsItWas)
{
  const std::string folder = fresh_folder("uncommitted");
  const std::string target = folder + "/out.txt";
  write_all(target, "old\n");
  {
    vtp_support::Output_file f(target);
    f.stream() << "new, but never committed\n";
  }
  EXPECT_EQ(read_all(target), "old\n");
  EXPECT_TRUE(entries_starting_with(folder, "out.txt.tmp.").empty());
}

TEST(OutputFile, ExistingFileIsReplacedAtomicallyAndKeepsItsMode)
{
  const std::string folder = fresh_folder("existing");
  const std::string target = folder + "/out.txt";
  write_all(target, "old\n");
  ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
  struct stat before, after;
  ASSERT_EQ(::stat(target.c_str(), &before), 0);
  {
    vtp_support::Output_file f(target);
    f.stream() << "new\n";
    f.commit();
  }
  ASSERT_EQ(::stat(target.c_str(), &after), 0);
  EXPECT_EQ(read_all(target), "new\n");
  EXPECT_EQ(after.st_mode & 07777, 0640u);
  EXPECT_NE(before.st_ino, after.st_ino) << "the file was rewritten in place instead of replaced";
}

TEST(OutputFile, SymbolicLinksAreFollowedAndStay)
{
  const std::string folder = fresh_folder("links");
  write_all(folder + "/target.txt", "old\n");
  ASSERT_EQ(::symlink("target.txt", (folder + "/link1").c_str()), 0);   // relative link
  ASSERT_EQ(::symlink((folder + "/link1").c_str(), (folder + "/link2").c_str()), 0); // chain of two
  {
    vtp_support::Output_file f(folder + "/link2");
    EXPECT_EQ(f.kind(), vtp_support::Output_file::REPLACED);
    EXPECT_EQ(f.target(), folder + "/target.txt");
    f.stream() << "new\n";
    f.commit();
  }
  EXPECT_TRUE(is_symlink(folder + "/link1"));
  EXPECT_TRUE(is_symlink(folder + "/link2"));
  EXPECT_FALSE(is_symlink(folder + "/target.txt"));
  EXPECT_EQ(read_all(folder + "/target.txt"), "new\n");
}

TEST(OutputFile, DanglingLinkGetsItsTargetCreated)
{
  const std::string folder = fresh_folder("dangling");
  ASSERT_EQ(::symlink("target.txt", (folder + "/link").c_str()), 0);
  {
    vtp_support::Output_file f(folder + "/link");
    f.stream() << "new\n";
    f.commit();
  }
  EXPECT_TRUE(is_symlink(folder + "/link"));
  EXPECT_EQ(read_all(folder + "/target.txt"), "new\n");
}

TEST(OutputFile, FifoIsWrittenThrough)
{
  const std::string folder = fresh_folder("fifo");
  const std::string fifo = folder + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read_all(fifo); });
  {
    vtp_support::Output_file f(fifo);
    EXPECT_EQ(f.kind(), vtp_support::Output_file::WRITTEN_THROUGH);
    f.stream() << "through the pipe\n";
    f.commit();
  }
  reader.join();
  EXPECT_EQ(received, "through the pipe\n");
  struct stat st;
  ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
  EXPECT_TRUE(entries_starting_with(folder, "fifo.tmp.").empty());
}

TEST(OutputFile, DevicesAndStandardOutputAreWrittenThrough)
{
  {
    vtp_support::Output_file f("/dev/null");
    EXPECT_EQ(f.kind(), vtp_support::Output_file::WRITTEN_THROUGH);
    f.stream() << "nothing\n";
    f.commit();
  }
  struct stat st;
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  for(const char* name : { "-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1" })
  {
    vtp_support::Output_file f(name);
    EXPECT_TRUE(f.writes_to_stdout()) << name;
    f.commit();
  }
  EXPECT_TRUE(is_symlink("/dev/stdout"));
  {
    vtp_support::Output_file f("/dev/stderr");
    EXPECT_EQ(f.descriptor(), 2);
  }
}

TEST(OutputFile, FoldersAndMissingFoldersAreErrors)
{
  const std::string folder = fresh_folder("errors");
  EXPECT_THROW(vtp_support::Output_file f(folder), vtp_support::Output_error);
  EXPECT_THROW(vtp_support::Output_file f(folder + "/no_such_folder/out.txt"), vtp_support::Output_error);
  EXPECT_THROW(vtp_support::Output_file f(""), vtp_support::Output_error);
}

TEST(OutputFile, WriteErrorsAreReported)
{
  struct stat st;
  if(::stat("/dev/full", &st) != 0)
    GTEST_SKIP() << "no /dev/full";
  vtp_support::Output_file f("/dev/full");
  f.stream() << std::string(1 << 21, 'x');
  EXPECT_THROW(f.close(), vtp_support::Output_error);
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

// ------------------------------------------------------------------------------------------------
// PLY output, read back with CGAL's PLY reader
// ------------------------------------------------------------------------------------------------
void check_ply_round_trip(const std::string& mesh_file, bool with_labels)
{
  vtp_support::Input_mesh input;
  vtp_support::read_input_mesh(mesh_file, input);
  std::vector<double> distances(input.file_vertices);
  std::vector<int> labels(input.file_vertices);
  for(std::size_t i = 0; i < distances.size(); ++i)
  {
    distances[i] = 0.001 * static_cast<double>(i) + 1. / 3.;
    labels[i] = static_cast<int>(i % 3);
  }
  distances.back() = std::numeric_limits<double>::infinity();

  const std::string file = fresh_folder("ply") + "/out.ply";
  {
    vtp_support::Output_file f(file);
    vtp_support::write_distance_ply(f.stream(), input, distances, with_labels ? &labels : nullptr, 1., "test");
    f.commit();
  }
  // Faces, as a polygon soup (a repaired input is written as read, and may not be a valid mesh).
  {
    std::vector<Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(in, points, polygons));
    ASSERT_EQ(points.size(), input.file_vertices);
    ASSERT_EQ(polygons.size(), input.file_faces);
    for(std::size_t f = 0; f < polygons.size(); ++f)
    {
      std::vector<std::size_t> expected;
      if(input.direct)
        for(Vertex_index v : CGAL::vertices_around_face(input.mesh.halfedge(Mesh::Face_index(
                                                          static_cast<Mesh::size_type>(f))), input.mesh))
          expected.push_back(std::size_t(v));
      else
        expected = input.file_polygons[f];
      std::vector<std::size_t> written = polygons[f];
      if(input.direct) // the same cycle (the file's, for the fast OFF reader), from any vertex
      {
        std::rotate(written.begin(), std::min_element(written.begin(), written.end()), written.end());
        std::rotate(expected.begin(), std::min_element(expected.begin(), expected.end()), expected.end());
      }
      EXPECT_EQ(written, expected) << "face " << f;
    }
    for(std::size_t i = 0; i < points.size(); ++i)
      EXPECT_EQ(points[i], input.direct ? input.mesh.point(Vertex_index(static_cast<Mesh::size_type>(i)))
                                        : input.file_points[i]);
  }
  // Vertex properties.
  typedef std::tuple<Point_3, double, int, unsigned char, unsigned char, unsigned char> Row;
  std::vector<Row> rows;
  {
    std::ifstream in(file, std::ios::binary);
    using CGAL::IO::PLY_property;
    if(with_labels)
      ASSERT_TRUE(CGAL::IO::read_PLY_with_properties(
        in, std::back_inserter(rows),
        CGAL::IO::make_ply_point_reader(CGAL::Nth_of_tuple_property_map<0, Row>()),
        std::make_pair(CGAL::Nth_of_tuple_property_map<1, Row>(), PLY_property<double>("distance")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<2, Row>(), PLY_property<int>("source")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<3, Row>(), PLY_property<unsigned char>("red")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<4, Row>(), PLY_property<unsigned char>("green")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<5, Row>(), PLY_property<unsigned char>("blue"))));
    else
      ASSERT_TRUE(CGAL::IO::read_PLY_with_properties(
        in, std::back_inserter(rows),
        CGAL::IO::make_ply_point_reader(CGAL::Nth_of_tuple_property_map<0, Row>()),
        std::make_pair(CGAL::Nth_of_tuple_property_map<1, Row>(), PLY_property<double>("distance")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<3, Row>(), PLY_property<unsigned char>("red")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<4, Row>(), PLY_property<unsigned char>("green")),
        std::make_pair(CGAL::Nth_of_tuple_property_map<5, Row>(), PLY_property<unsigned char>("blue"))));
  }
  ASSERT_EQ(rows.size(), distances.size());
  for(std::size_t i = 0; i < distances.size(); ++i)
  {
    EXPECT_EQ(std::get<1>(rows[i]), distances[i]);
    if(with_labels)
    {
      EXPECT_EQ(std::get<2>(rows[i]), labels[i]);
    }
    const vtp_support::Rgb c = vtp_support::colour_of_distance(distances[i], 1.);
    EXPECT_EQ(std::get<3>(rows[i]), c.r);
    EXPECT_EQ(std::get<4>(rows[i]), c.g);
    EXPECT_EQ(std::get<5>(rows[i]), c.b);
  }
  // Unreachable: grey.
  EXPECT_EQ(std::get<3>(rows.back()), vtp_support::unreachable_colour().r);
  // The file also opens as a mesh with a `distance` property when it is one.
  if(input.direct)
  {
    Mesh back;
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(CGAL::IO::read_PLY(in, back));
    auto d = back.property_map<Vertex_index, double>("v:distance");
    ASSERT_TRUE(d.second);
    EXPECT_EQ(d.first[Vertex_index(1)], distances[1]);
  }
}

TEST(DistancePly, RoundTripThroughCgalReader)
{
  check_ply_round_trip(mesh_dir + "/elephant.off", false);
  check_ply_round_trip(mesh_dir + "/elephant.off", true);
}

TEST(DistancePly, RepairedInputIsWrittenAsRead)
{
  // Two tetrahedra sharing vertex 0, plus an isolated vertex: repaired (vertex 0 duplicated) for the
  // computation, written back with the 8 vertices and 8 faces of the file.
  check_ply_round_trip(VTP_SUPPORT_TEST_CLI_DATA_DIR "/nonmanifold_vertex.off", true);
}

// ------------------------------------------------------------------------------------------------
// Picture
// ------------------------------------------------------------------------------------------------
struct Rendered
{
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
  std::size_t count(bool (*pred)(const unsigned char*)) const
  {
    std::size_t n = 0;
    for(std::size_t i = 0; i + 2 < pixels.size(); i += 3)
      n += pred(&pixels[i]) ? 1 : 0;
    return n;
  }
};

Rendered render(const Mesh& m, const std::vector<double>& values, int isolines, bool marker,
               const std::vector<std::array<double, 3> >& polyline = std::vector<std::array<double, 3> >())
{
  vtp_support::Picture_options o;
  o.isolines = isolines;
  vtp_support::Distance_picture picture(o);
  double max_value = 0.;
  for(double v : values)
    if(std::isfinite(v))
      max_value = std::max(max_value, v);
  picture.set_mesh(
    m.number_of_vertices(),
    [&m](std::size_t i) {
      const Point_3& p = m.point(Vertex_index(static_cast<Mesh::size_type>(i)));
      return std::array<double, 3>{ { p.x(), p.y(), p.z() } };
    },
    m.number_of_faces(),
    [&m](std::size_t f) {
      const Mesh::Halfedge_index h = m.halfedge(Mesh::Face_index(static_cast<Mesh::size_type>(f)));
      return std::array<std::uint32_t, 3>{ { std::uint32_t(m.source(h)), std::uint32_t(m.target(h)),
                                             std::uint32_t(m.target(m.next(h))) } };
    },
    values, max_value);
  if(marker)
  {
    const Point_3& p = m.point(Vertex_index(0));
    picture.add_marker({ { p.x(), p.y(), p.z() } });
  }
  if(!polyline.empty())
    picture.add_polyline(polyline);
  picture.render();
  Rendered r;
  r.width = picture.width();
  r.height = picture.height();
  r.pixels = picture.pixels();
  return r;
}

bool is_white(const unsigned char* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; }
bool is_dark(const unsigned char* p) { return p[0] < 40 && p[1] < 40 && p[2] < 40; }
bool is_marker_red(const unsigned char* p) { return p[0] > 150 && p[1] < 60 && p[2] < 60; }
bool is_grey(const unsigned char* p)
{
  return p[0] != 255 && std::abs(int(p[0]) - int(p[1])) < 4 && std::abs(int(p[1]) - int(p[2])) < 4 && p[0] > 40;
}

TEST(Picture, DrawsTheFieldIsolinesAndMarkers)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/elephant.off", m));
  std::vector<double> values(m.number_of_vertices());
  for(Vertex_index v : m.vertices())
    values[std::size_t(v)] = m.point(v).x() - m.point(Vertex_index(0)).x() + 1.;
  const Rendered plain = render(m, values, 0, false);
  const Rendered lines = render(m, values, 10, false);
  const Rendered marked = render(m, values, 10, true);
  ASSERT_GT(plain.width, 300);
  ASSERT_GT(plain.height, 300);
  const std::size_t total = std::size_t(plain.width) * plain.height;
  // The mesh covers a good part of the picture, and nothing in it is grey (every value is finite).
  EXPECT_GT(total - plain.count(is_white), total / 5);
  EXPECT_LT(plain.count(is_grey), total / 200);
  // Isolines add dark pixels; the marker adds red ones.
  EXPECT_GT(lines.count(is_dark), plain.count(is_dark) + 500);
  EXPECT_GT(marked.count(is_marker_red), lines.count(is_marker_red) + 50);
}

TEST(Picture, DrawsPolylines)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/elephant.off", m));
  std::vector<double> values(m.number_of_vertices(), 1.);
  // A path along vertices 0, 1, 2, ... (a polyline on or through the surface).
  std::vector<std::array<double, 3> > path;
  for(std::size_t i = 0; i < 200; ++i)
  {
    const Point_3& p = m.point(Vertex_index(static_cast<Mesh::size_type>(i)));
    path.push_back({ { p.x(), p.y(), p.z() } });
  }
  const Rendered without = render(m, values, 0, false);
  const Rendered with = render(m, values, 0, false, path);
  EXPECT_GT(with.count(is_marker_red), without.count(is_marker_red) + 100);
}

TEST(Picture, UnreachableIsGreyAndViewFitsTheMesh)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/elephant.off", m));
  const std::vector<double> values(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  const Rendered r = render(m, values, 10, false);
  const std::size_t drawn = std::size_t(r.width) * r.height - r.count(is_white);
  EXPECT_GT(r.count(is_grey), drawn / 2);
  // The mesh touches neither the top nor the bottom rows (margins): the view fits the whole mesh.
  for(int x = 0; x < r.width; ++x)
  {
    EXPECT_TRUE(is_white(&r.pixels[3 * std::size_t(x)]));
    EXPECT_TRUE(is_white(&r.pixels[3 * (std::size_t(r.height - 1) * r.width + x)]));
  }
}

TEST(Picture, RoundIsolineSteps)
{
  EXPECT_DOUBLE_EQ(vtp_support::picture_detail::isoline_step(0.973, 10), 0.1);
  EXPECT_DOUBLE_EQ(vtp_support::picture_detail::isoline_step(1.8, 10), 0.2);
  EXPECT_DOUBLE_EQ(vtp_support::picture_detail::isoline_step(230., 10), 25.);
  EXPECT_EQ(vtp_support::picture_detail::isoline_step(1., 0), 0.);
  EXPECT_EQ(vtp_support::picture_detail::label_text(0.25, 0.25), "0.25");
  EXPECT_EQ(vtp_support::picture_detail::label_text(30., 10.), "30");
}

} // namespace
