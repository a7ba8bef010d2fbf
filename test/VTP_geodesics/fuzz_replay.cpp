// vtp_fuzz_replay: runs the checks of the fuzz target (LLVMFuzzerTestOneInput of fuzz_vtp.cpp) on saved
// inputs, without libFuzzer, so that the inputs the fuzzer once failed on are replayed by every build
// (Release and the sanitizer build of CI, with the normal compiler).
//
//   vtp_fuzz_replay FILE_OR_FOLDER...
//
// A folder stands for every regular file in it, in the order of their names. Each input is named on the
// standard output before it runs; a failing check prints the mesh and aborts (as it does under libFuzzer),
// so the last name printed is the failing input. Exit code 0 once every input has run, 2 on a usage error
// (no argument, or a path that cannot be read).
//
// The ctest test `fuzz_replay` runs it on test/VTP_geodesics/fuzz_corpus/, the inputs on which the fuzzer found
// defects (minimised; see the comment at the top of fuzz_vtp.cpp).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  if(argc < 2)
  {
    std::cerr << "usage: vtp_fuzz_replay FILE_OR_FOLDER..." << std::endl;
    return 2;
  }
  std::vector<fs::path> inputs;
  for(int i = 1; i < argc; ++i)
  {
    const fs::path p(argv[i]);
    std::error_code error;
    if(fs::is_directory(p, error))
    {
      std::vector<fs::path> files;
      for(const fs::directory_entry& e : fs::directory_iterator(p))
        if(e.is_regular_file() && e.path().filename().string().front() != '.')
          files.push_back(e.path());
      std::sort(files.begin(), files.end());
      inputs.insert(inputs.end(), files.begin(), files.end());
    }
    else if(fs::is_regular_file(p, error))
      inputs.push_back(p);
    else
    {
      std::cerr << "vtp_fuzz_replay: error: " << p.string() << " is neither a file nor a folder" << std::endl;
      return 2;
    }
  }
  for(const fs::path& p : inputs)
  {
    std::ifstream in(p, std::ios::binary);
    if(!in)
    {
      std::cerr << "vtp_fuzz_replay: error: cannot read " << p.string() << std::endl;
      return 2;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << "vtp_fuzz_replay: " << p.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << "vtp_fuzz_replay: " << inputs.size() << " inputs, every check passed" << std::endl;
  return 0;
}
