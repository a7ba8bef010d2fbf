// Helpers of the tests that write files (test/support, test/tools): reading and writing whole files, a fresh
// folder per test, the entries of a folder.

#ifndef VTP_TEST_FILES_H
#define VTP_TEST_FILES_H

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vtp_test_files {

inline std::string read_all(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_all(const std::string& file, const std::string& text)
{
  std::ofstream out(file, std::ios::binary);
  out << text;
}

// Names of the entries of `folder` that start with `prefix`.
inline std::vector<std::string> entries_starting_with(const std::string& folder, const std::string& prefix)
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

// A fresh (empty) folder `name` for the current test, in `tmp_dir`.
inline std::string fresh_folder(const std::string& tmp_dir, const std::string& name)
{
  // one folder per test and name: ctest runs the tests of an executable in parallel processes (-j)
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

inline bool is_symlink(const std::string& path)
{
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

} // namespace vtp_test_files

#endif // VTP_TEST_FILES_H
