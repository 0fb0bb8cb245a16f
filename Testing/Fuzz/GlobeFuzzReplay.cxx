// A plain driver for a fuzz target (no libFuzzer): calls LLVMFuzzerTestOneInput once for every
// file given, or found (recursively, in name order) in every directory given; names starting
// with '.' and README files are skipped. It exits 1 when an argument does not exist or when no
// file was replayed at all (a corpus that went missing); a finding is a crash, a sanitizer
// report or the test's timeout. `--optional DIR`: a directory that may be missing or empty
// (the crashers of a target that has none).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
bool Skipped(const std::filesystem::path& path)
{
  const std::string name = path.filename().string();
  return name.empty() || name[0] == '.' || name.rfind("README", 0) == 0;
}
} // namespace

int main(int argc, char* argv[])
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  bool ok = true;
  for (int i = 1; i < argc; ++i)
  {
    const bool optional = std::strcmp(argv[i], "--optional") == 0 && i + 1 < argc;
    const fs::path arg = optional ? argv[++i] : argv[i];
    std::error_code ec;
    if (fs::is_directory(arg, ec))
    {
      for (const auto& entry : fs::recursive_directory_iterator(arg, ec))
      {
        if (entry.is_regular_file() && !Skipped(entry.path()))
        {
          files.push_back(entry.path());
        }
      }
    }
    else if (fs::is_regular_file(arg, ec))
    {
      files.push_back(arg);
    }
    else if (!optional)
    {
      std::fprintf(stderr, "error: '%s' is neither a file nor a directory\n", arg.c_str());
      ok = false;
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files)
  {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.eof() && in.fail())
    {
      std::fprintf(stderr, "error: cannot read '%s'\n", file.c_str());
      ok = false;
      continue;
    }
    std::printf("replaying %s (%zu bytes)\n", file.c_str(), bytes.size());
    std::fflush(stdout);
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs replayed\n", files.size());
  if (files.empty())
  {
    std::fprintf(stderr, "error: no input to replay\n");
    ok = false;
  }
  return ok ? 0 : 1;
}
