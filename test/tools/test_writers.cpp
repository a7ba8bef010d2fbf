// Tests of the file writers of vtp_geodesics (apps/vtp_geodesics, library vtp_geodesics_writers): safe output
// files, the PLY writer (read back with CGAL's PLY reader) and the picture.
//
// Every file these tests write is in VTP_WRITERS_TEST_TMP_DIR (in the build tree).

#include "vtp_test_files.h"

#include "colour_map.h"
#include "distance_ply.h"
#include "output_file.h"
#include "picture.h"

#include <vtp_support/read_mesh.h>

#include <CGAL/IO/read_ply_points.h>
#include <CGAL/property_map.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace {

using vtp_support::Mesh;
using vtp_support::Point_3;
using vtp_support::Vertex_index;
using vtp_test_files::entries_starting_with;
using vtp_test_files::is_symlink;
using vtp_test_files::read_all;
using vtp_test_files::write_all;
namespace app = vtp_geodesics_app;

const std::string mesh_dir = VTP_WRITERS_TEST_MESH_DIR;

std::string fresh_folder(const std::string& name)
{
  return vtp_test_files::fresh_folder(VTP_WRITERS_TEST_TMP_DIR, name);
}

// ------------------------------------------------------------------------------------------------
// Output files
// ------------------------------------------------------------------------------------------------
TEST(OutputFile, NewRegularFileAppearsOnlyAtCommit)
{
  const std::string folder = fresh_folder("new_file");
  const std::string target = folder + "/out.txt";
  {
    app::Output_file f(target);
    EXPECT_EQ(f.kind(), app::Output_file::REPLACED);
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
    app::Output_file f(target);
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
    app::Output_file f(target);
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
    app::Output_file f(folder + "/link2");
    EXPECT_EQ(f.kind(), app::Output_file::REPLACED);
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
    app::Output_file f(folder + "/link");
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
    app::Output_file f(fifo);
    EXPECT_EQ(f.kind(), app::Output_file::WRITTEN_THROUGH);
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
    app::Output_file f("/dev/null");
    EXPECT_EQ(f.kind(), app::Output_file::WRITTEN_THROUGH);
    f.stream() << "nothing\n";
    f.commit();
  }
  struct stat st;
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  for(const char* name : { "-", "/dev/stdout", "/dev/fd/1", "/proc/self/fd/1" })
  {
    app::Output_file f(name);
    EXPECT_TRUE(f.writes_to_stdout()) << name;
    f.commit();
  }
  EXPECT_TRUE(is_symlink("/dev/stdout"));
  {
    app::Output_file f("/dev/stderr");
    EXPECT_EQ(f.descriptor(), 2);
  }
}

TEST(OutputFile, FoldersAndMissingFoldersAreErrors)
{
  const std::string folder = fresh_folder("errors");
  EXPECT_THROW(app::Output_file f(folder), app::Output_error);
  EXPECT_THROW(app::Output_file f(folder + "/no_such_folder/out.txt"), app::Output_error);
  EXPECT_THROW(app::Output_file f(""), app::Output_error);
}

TEST(OutputFile, WriteErrorsAreReported)
{
  struct stat st;
  if(::stat("/dev/full", &st) != 0)
    GTEST_SKIP() << "no /dev/full";
  app::Output_file f("/dev/full");
  f.stream() << std::string(1 << 21, 'x');
  EXPECT_THROW(f.close(), app::Output_error);
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
    app::Output_file f(file);
    app::write_distance_ply(f.stream(), input, distances, with_labels ? &labels : nullptr, 1., "test");
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
    const app::Rgb c = app::colour_of_distance(distances[i], 1.);
    EXPECT_EQ(std::get<3>(rows[i]), c.r);
    EXPECT_EQ(std::get<4>(rows[i]), c.g);
    EXPECT_EQ(std::get<5>(rows[i]), c.b);
  }
  // Unreachable: grey.
  EXPECT_EQ(std::get<3>(rows.back()), app::unreachable_colour().r);
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
  check_ply_round_trip(VTP_WRITERS_TEST_CLI_DATA_DIR "/nonmanifold_vertex.off", true);
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

typedef std::vector<std::vector<std::array<double, 3> > > Curves;

Rendered render(const Mesh& m, const std::vector<double>& values, int isolines, bool marker,
               const std::vector<std::array<double, 3> >& polyline = std::vector<std::array<double, 3> >(),
               const Curves* curves = nullptr)
{
  app::Picture_options o;
  o.isolines = isolines;
  app::Distance_picture picture(o);
  if(curves != nullptr)
    picture.set_curves(*curves);
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

// A field that grows along x, from 1 at vertex 0.
std::vector<double> linear_values(const Mesh& m)
{
  std::vector<double> values(m.number_of_vertices());
  for(Vertex_index v : m.vertices())
    values[std::size_t(v)] = m.point(v).x() - m.point(Vertex_index(0)).x() + 1.;
  return values;
}

TEST(Picture, DrawsTheFieldIsolinesAndMarkers)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/elephant.off", m));
  const std::vector<double> values = linear_values(m);
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

TEST(Picture, GivenCurvesReplaceTheInterpolatedIsolines)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(mesh_dir + "/elephant.off", m));
  const std::vector<double> values = linear_values(m);
  const Rendered plain = render(m, values, 0, false);
  // no curves given: no isolines drawn on the mesh, whatever the number asked for (the colour bar, right of the
  // mesh, has its ticks)
  const Curves none;
  const Rendered without = render(m, values, 10, false, {}, &none);
  ASSERT_EQ(without.width, plain.width);
  std::size_t differ = 0;
  for(std::size_t y = 0; y < std::size_t(plain.height); ++y)
    for(std::size_t x = 0; x + 200 < std::size_t(plain.width); ++x)
      for(std::size_t k = 0; k < 3; ++k)
        differ += without.pixels[3 * (y * plain.width + x) + k] != plain.pixels[3 * (y * plain.width + x) + k];
  EXPECT_EQ(differ, 0u);
  // a curve along the edges of the first faces (on the surface): dark pixels, the same picture every time
  Curves along(1);
  for(Mesh::Face_index f : m.faces())
  {
    if(along[0].size() > 300)
      break;
    const Point_3& p = m.point(m.source(m.halfedge(f)));
    along[0].push_back({ { p.x(), p.y(), p.z() } });
  }
  const Rendered with = render(m, values, 10, false, {}, &along);
  EXPECT_GT(with.count(is_dark), plain.count(is_dark) + 100);
  EXPECT_EQ(render(m, values, 10, false, {}, &along).pixels, with.pixels);
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
  EXPECT_DOUBLE_EQ(app::picture_detail::isoline_step(0.973, 10), 0.1);
  EXPECT_DOUBLE_EQ(app::picture_detail::isoline_step(1.8, 10), 0.2);
  EXPECT_DOUBLE_EQ(app::picture_detail::isoline_step(230., 10), 25.);
  EXPECT_EQ(app::picture_detail::isoline_step(1., 0), 0.);
  EXPECT_EQ(app::picture_detail::label_text(0.25, 0.25), "0.25");
  EXPECT_EQ(app::picture_detail::label_text(30., 10.), "30");
}

} // namespace
