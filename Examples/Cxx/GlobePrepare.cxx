// GlobePrepare: rewrites a georeferenced raster as a tiled GeoTIFF with reduced-resolution
// levels (vtkGlobeRasterPreparer), the layout vtkGlobePageSource reads page by page.
//
//   GlobePrepare IN OUT [--tile N] [--no-compression]
//
// Progress goes to stderr as a bar; the exit status is 0 on success, 1 on failure, 2 on bad
// arguments.
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGlobeRasterPreparer.h"
#include "vtkNew.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
void Usage()
{
  std::fprintf(stderr,
    "usage: GlobePrepare IN OUT [--tile N] [--no-compression]\n"
    "  IN   a georeferenced raster (GeoTIFF, or an image with a world file)\n"
    "  OUT  the tiled GeoTIFF to write, with reduced-resolution levels down to one tile\n"
    "  --tile N          tile size in texels (multiple of 16, default 256)\n"
    "  --no-compression  store tiles uncompressed (default: deflate)\n");
}

void ShowProgress(vtkObject*, unsigned long, void*, void* callData)
{
  const double progress = *static_cast<double*>(callData);
  const int width = 40;
  const int filled = static_cast<int>(progress * width + 0.5);
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(width - filled), '.');
  std::fprintf(stderr, "\r[%s] %3d%%", bar.c_str(), static_cast<int>(progress * 100.0 + 0.5));
  if (progress >= 1.0)
  {
    std::fprintf(stderr, "\n");
  }
  std::fflush(stderr);
}
} // namespace

int main(int argc, char* argv[])
{
  std::string input, output;
  int tile = 256;
  bool compress = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--tile" && i + 1 < argc)
    {
      char* end = nullptr;
      const long value = std::strtol(argv[++i], &end, 10);
      if (!end || *end || value < 16 || value > 4096)
      {
        std::fprintf(stderr, "GlobePrepare: --tile wants a number in 16..4096\n");
        return 2;
      }
      tile = static_cast<int>(value);
    }
    else if (arg == "--no-compression")
    {
      compress = false;
    }
    else if (arg == "-h" || arg == "--help")
    {
      Usage();
      return 0;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      std::fprintf(stderr, "GlobePrepare: unknown option '%s'\n", arg.c_str());
      Usage();
      return 2;
    }
    else if (input.empty())
    {
      input = arg;
    }
    else if (output.empty())
    {
      output = arg;
    }
    else
    {
      Usage();
      return 2;
    }
  }
  if (input.empty() || output.empty())
  {
    Usage();
    return 2;
  }

  vtkNew<vtkGlobeRasterPreparer> preparer;
  preparer->SetInputFileName(input.c_str());
  preparer->SetFileName(output.c_str());
  preparer->SetTileSize(tile);
  if (!compress)
  {
    preparer->SetCompressionToNone();
  }
  vtkNew<vtkCallbackCommand> progress;
  progress->SetCallback(ShowProgress);
  preparer->AddObserver(vtkCommand::ProgressEvent, progress);

  const auto start = std::chrono::steady_clock::now();
  if (!preparer->Write())
  {
    std::fprintf(stderr, "\nGlobePrepare: %s\n", preparer->GetLastError());
    return 1;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int* size = preparer->GetSize();
  std::printf("%s: %d x %d, %d levels, tiles of %d, %s, %.1f s\n", output.c_str(), size[0],
    size[1], preparer->GetNumberOfLevels(), (tile + 15) / 16 * 16,
    compress ? "deflate" : "uncompressed", seconds);
  return 0;
}
