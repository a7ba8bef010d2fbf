// vtp_benchmark: time, peak memory and accuracy of VTP against CGAL's exact and approximate
// geodesic distance methods.
//
//   vtp_benchmark [--remesh R] [--loop N] [--subdivide N] [--sources K] [--methods vtp,cgal,heat,heat_idt]
//                 [--external NAME=COMMAND] [--csv FILE] [--repeat R] [--save-meshes DIR] MESH...
//
// Realistic large inputs are made with CGAL: isotropic remeshing (--remesh) and Loop subdivision
// (--loop) give saddle vertices almost everywhere, like scans; midpoint subdivision (--subdivide)
// only adds flat vertices and is the easy case for VTP.
//
// Every (mesh, source, method) run happens in a forked child process, so that the peak resident
// memory of each method (ru_maxrss of the child, from wait4) is measured on its own; the child
// sends its timings and its distances back through a pipe. Errors are measured against VTP.
// See readme.txt; the parts of the program are listed in vtp_benchmark.h.

#include "vtp_benchmark.h"

#include <CGAL/assertions_behaviour.h>

#include <vtp_support/shortest_path_reference.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <stdlib.h>       // mkdtemp
#include <unistd.h>       // rmdir

namespace vtp_benchmark {

namespace {

// Round-trip time of a cache line between two threads (they bounce a counter), in nanoseconds; 0 with
// fewer than 2 processors. On a virtual machine it tells where the host placed the virtual processors
// at that moment (seen on the 2-vCPU machine of this project: about 50 ns, or about 330 ns at times),
// which the parallel methods feel (they share data between cores) and the sequential ones do not.
double core_to_core_round_trip_ns()
{
  if(std::thread::hardware_concurrency() < 2)
    return 0.;
  struct alignas(64) Line
  {
    std::atomic<long> value{ 0 };
  } line;
  const long n = 100000;
  auto wait_for = [&line](long v) {
    for(int spins = 0; line.value.load(std::memory_order_acquire) != v;)
      if(++spins > 4096)
        std::this_thread::yield();
  };
  std::thread other([&] {
    for(long i = 0; i < n; ++i)
    {
      wait_for(2 * i + 1);
      line.value.store(2 * i + 2, std::memory_order_release);
    }
  });
  const double t0 = now_seconds();
  for(long i = 0; i < n; ++i)
  {
    line.value.store(2 * i + 1, std::memory_order_release);
    wait_for(2 * i + 2);
  }
  const double t = now_seconds() - t0;
  other.join();
  return t / double(n) * 1e9;
}

int run(int argc, char** argv)
{
  const Arguments args = parse_arguments(argc, argv);
  if(args.help)
  {
    print_usage(std::cout);
    return 0;
  }
  for(const std::string& file : args.meshes)
    if(!std::ifstream(file))
      throw Tool_error("cannot open '" + file + "'");

  std::ofstream csv;
  if(!args.csv.empty())
  {
    csv.open(args.csv);
    if(!csv)
      throw Tool_error("cannot write '" + args.csv + "'");
    csv << csv_columns << '\n';
  }

  // VTP is the reference: it runs first, even when not asked for (then it is not reported).
  std::vector<Method> runs;
  Method reference;
  reference.label = "vtp";
  reference.info = vtp_support::find_method("vtp");
  const bool report_vtp =
    std::any_of(args.methods.begin(), args.methods.end(), [](const Method& m) { return m.label == "vtp"; });
  runs.push_back(reference);
  for(const Method& m : args.methods)
    if(m.label != "vtp")
      runs.push_back(m);

  bool header_printed = false;
  int failures = 0;
  const bool parallel = std::any_of(args.methods.begin(), args.methods.end(),
                                    [](const Method& m) { return m.info != nullptr && m.info->parallel; });
  std::string temporary_folder;  // a generated mesh's OFF file when not saved: external methods, file to answer
  {
    char name[] = "/tmp/vtp_benchmark_XXXXXX";
    if(::mkdtemp(name) == nullptr)
      throw std::runtime_error(std::string("mkdtemp() failed: ") + std::strerror(errno));
    temporary_folder = name;
  }
  for(const std::string& file : args.meshes)
  {
    Mesh mesh;
    Mesh_info info;
    info.label = load_mesh(file, args, mesh);
    info.vertices = mesh.number_of_vertices();
    info.faces = mesh.number_of_faces();
    std::string mesh_file;
    if(!args.save_meshes.empty())
    {
      mesh_file = args.save_meshes + "/" + replace_all(info.label, "/", "_") + ".off";
      write_off(mesh, mesh_file);
    }
    else
    {
      mesh_file = temporary_folder + "/mesh.off";
      write_off(mesh, mesh_file);
    }
    if(!header_printed)
    {
      print_table_header();
      header_printed = true;
    }

    const std::size_t k = (std::min)(args.sources, info.vertices);
    for(std::size_t i = 0; i < k; ++i)
    {
      // Vertex 0 and evenly spaced ids.
      const std::size_t source_id = static_cast<std::size_t>(
        (static_cast<unsigned long long>(i) * info.vertices) / k);
      const Vertex_index source(static_cast<Mesh::size_type>(source_id));
      auto run_method = [&](const Method& m) {
        if(m.kind == Method_kind::EXTERNAL)
          return run_external(mesh_file, source_id, info.vertices, m, temporary_folder + "/distances.txt");
        return run_forked(mesh, source, m, 1);
      };

      const double round_trip_before = parallel ? core_to_core_round_trip_ns() : 0.;
      std::vector<Run_result> results;
      for(const Method& m : runs)
        results.push_back(run_method(m));
      for(int r = 1; r < args.repeat; ++r)
        for(std::size_t j = 0; j < runs.size(); ++j)
        {
          if(!results[j].ok)
            continue;
          const Run_result again = run_method(runs[j]);
          if(!again.ok)
          {
            results[j] = again;
            continue;
          }
          Child_header& h = results[j].header;
          h.seconds = (std::min)(h.seconds, again.header.seconds);
          if(!(h.cpu_seconds <= again.header.cpu_seconds))
            h.cpu_seconds = again.header.cpu_seconds;
          h.preprocessing_seconds = (std::min)(h.preprocessing_seconds, again.header.preprocessing_seconds);
          results[j].peak_rss_mb = (std::max)(results[j].peak_rss_mb, again.peak_rss_mb);
        }
      if(parallel)
        std::printf("# core-to-core round trip: %.0f ns before these runs, %.0f ns after (see --help)\n",
                    round_trip_before, core_to_core_round_trip_ns());

      const Run_result& vtp = results.front();
      if(i == 0 && vtp.ok)
      {
        info.pseudo_source_share = double(vtp.header.pseudo_source_vertices) / double(info.vertices);
        std::printf("# %s: %zu vertices, %zu faces, %llu pseudo-source vertices (saddle or boundary): %.1f%%\n",
                    info.label.c_str(), info.vertices, info.faces,
                    static_cast<unsigned long long>(vtp.header.pseudo_source_vertices),
                    100. * info.pseudo_source_share);
      }
      if(i == 0)
      {
        // the time a user waits, beside the propagation: the same mesh read from its file, checked, preprocessed
        const int threads = default_threads();
        vtp_support::Stage_seconds stages;
        if(file_to_answer(mesh_file, source_id, threads, stages))
          print_file_to_answer(info.label, source_id, threads, stages);
        else
          std::printf("# %s: file to answer: the run failed\n", info.label.c_str());
      }
      const Run_result* cgal = nullptr;
      for(const Run_result& r : results)
        if(r.method.kind == Method_kind::CGAL_SMSP && r.ok)
          cgal = &r;
      for(Run_result& r : results)
      {
        if(!r.ok)
          continue;
        if(vtp.ok && (r.method.kind != Method_kind::EXTERNAL || !r.distances.empty()))
        {
          const vtp_support::Distance_comparison c =
            vtp_support::compare_distances(r.distances, vtp.distances);
          r.max_abs_err = c.max_abs_diff;
          r.max_rel_err = c.max_rel_diff;
          r.mean_rel_err = c.mean_rel_diff;
          r.mean_pointwise_rel_err = c.mean_pointwise_rel_diff;
          r.max_pointwise_rel_err = c.max_pointwise_rel_diff;
          r.mismatched_infinities = c.mismatched_infinities;
          double below = -inf, scale = 0.;
          for(double x : vtp.distances)
            if(std::isfinite(x))
              scale = (std::max)(scale, x);
          for(std::size_t i = 0; i < r.distances.size() && i < vtp.distances.size(); ++i)
            if(std::isfinite(r.distances[i]) && std::isfinite(vtp.distances[i]))
              below = (std::max)(below, vtp.distances[i] - r.distances[i]);
          r.max_below_vtp = scale > 0. ? below / scale : below;
          if(c.mismatched_infinities > 0 && r.status == "ok")
            r.status = "ok (" + std::to_string(c.mismatched_infinities) + " reachability mismatches)";
        }
        if(vtp.ok && r.header.seconds > 0.)
          r.speedup_vs_vtp = vtp.header.seconds / r.header.seconds;
        if(vtp.ok && r.header.cpu_seconds > 0.)
          r.cpu_ratio_vs_vtp = vtp.header.cpu_seconds / r.header.cpu_seconds;
        if(cgal != nullptr && total_seconds(r) > 0.)
          r.speedup_vs_cgal = total_seconds(*cgal) / total_seconds(r);
      }
      // Report in the order of --methods; the reference run is shown only if "vtp" was asked for
      // (or if it failed).
      std::vector<const Run_result*> shown;
      if(!report_vtp && !vtp.ok)
        shown.push_back(&vtp);
      for(const Method& m : args.methods)
        for(const Run_result& r : results)
          if(r.method.label == m.label)
            shown.push_back(&r);
      for(const Run_result* r : shown)
      {
        if(!r->ok)
          ++failures;
        print_table_row(info, source_id, *r);
        if(csv.is_open())
          write_csv_row(csv, info, source_id, *r);
      }
      if(csv.is_open())
      {
        csv.flush();
        if(!csv)
          throw Tool_error("cannot write '" + args.csv + "'");
      }
    }
  }
  if(!temporary_folder.empty())
  {
    std::remove((temporary_folder + "/mesh.off").c_str());
    ::rmdir(temporary_folder.c_str());
  }
  if(failures > 0)
  {
    std::cerr << "vtp_benchmark: " << failures << " run(s) failed (see the status column)" << std::endl;
    return 1;
  }
  return 0;
}

void silent_cgal_handler(const char*, const char*, const char*, int, const char*) {}

} // namespace

} // namespace vtp_benchmark

int main(int argc, char** argv)
{
  // CGAL failures become exceptions reported on one line (or in the status column).
  CGAL::set_error_handler(vtp_benchmark::silent_cgal_handler);
  CGAL::set_warning_handler(vtp_benchmark::silent_cgal_handler);
  try
  {
    return vtp_benchmark::run(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::string message = e.what();
    std::replace(message.begin(), message.end(), '\n', ' ');
    std::cerr << "vtp_benchmark: error: " << message << std::endl;
    return 2;
  }
}
