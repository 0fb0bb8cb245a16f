// What the fuzz targets share: quiet VTK and OpenImageIO once, a private temporary directory
// per process, and writing the fuzzer's bytes to files there.
//
// Each target defines LLVMFuzzerTestOneInput. Built with clang and -fsanitize=fuzzer it is a
// libFuzzer program (VTKGLOBE_BUILD_FUZZERS, `bash Utilities/globe.sh fuzz`); built with any
// compiler next to GlobeFuzzReplay.cxx it replays the corpus and crashers as ordinary tests
// (Fuzz.Replay.*). Errors are reported by the classes through vtkErrorMacro and make them
// return false; nothing here aborts on them, so only a crash, a sanitizer report or a hang is
// a finding.
#ifndef GlobeFuzz_h
#define GlobeFuzz_h

#include "vtkObject.h"

#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace GlobeFuzz
{
/// The readers' memory budget in MiB: far below libFuzzer's -rss_limit_mb (2048), so a header
/// declaring a huge raster is refused (vtkGlobeRasterReader::MaximumMemory) and never runs the
/// fuzzer out of memory.
constexpr int MaximumMemoryMiB = 64;

/// Once per process: no error or warning output (thousands of inputs fail on purpose), and
/// OpenImageIO without its thread pool (one input at a time, reproducible).
inline void Setup()
{
  static bool done = false;
  if (!done)
  {
    done = true;
    vtkObject::GlobalWarningDisplayOff();
    OIIO::attribute("threads", 1);
  }
}

/// A directory of this process's own, made on first use (e.g. /tmp/vtkglobe-fuzz-<pid>-<name>):
/// concurrent fuzzers and replays never see each other's files.
inline const std::string& Directory(const char* name)
{
  static std::string dir;
  if (dir.empty())
  {
    std::error_code ec;
    std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec)
    {
      base = "/tmp";
    }
    dir = (base / ("vtkglobe-fuzz-" + std::to_string(getpid()) + "-" + name)).string();
    std::filesystem::remove_all(dir, ec);
    std::filesystem::create_directories(dir, ec);
    // Removed at exit (a libFuzzer run ends with exit()).
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    });
  }
  return dir;
}

/// Writes `size` bytes to `path`; false when the file cannot be written.
inline bool WriteFile(const std::string& path, const uint8_t* data, size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return static_cast<bool>(out);
}

/// Removes what an input left in the directory (its sidecar files included).
inline void Clear(const std::string& dir)
{
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
  {
    std::filesystem::remove(entry.path(), ec);
  }
}
} // namespace GlobeFuzz

#endif
