// GlobeMakePlanet: the streaming benchmark's data, made reproducibly from Data/ (nothing
// downloaded, nothing committed): a global height raster and a global RGB image of
// WIDTH x WIDTH/2 posts (default 43200 x 21600, 30 arc-seconds), each the bilinear
// upsampling of the repository's 2-degree relief / Blue Marble image plus deterministic
// fractal detail (value noise, octaves from a 1-degree wavelength halving while it stays at
// least 2 posts long, 8 at most: 6 at W = 43200, the finest 3.75 posts), written as plain
// striped TIFFs with world files and then prepared (tiled, MIP-mapped) with
// vtkGlobeRasterPreparer. The plain files are removed afterwards.
//
//   GlobeMakePlanet DATA_DIR OUT_DIR [--width 43200] [--keep-plain]
// (WIDTH even, at least 360.) Each file is prepared under a temporary name and renamed when
// complete: an interrupted run leaves no file that looks finished.
//
// Writes OUT_DIR/planet_heights_<W>.tif (float, metres) and OUT_DIR/planet_imagery_<W>.tif
// (RGB): 3.7 GB and 2.8 GB at full resolution before their levels (a third more with them).
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobeLayer.h"
#include "vtkGlobeRasterPreparer.h"
#include "vtkNew.h"
#include "vtkDataArray.h"

#include <tiffio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace
{
// Deterministic lattice value noise in [-1, 1], smoothly interpolated.
double Hash(int64_t x, int64_t y, int octave)
{
  uint64_t h = static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
    static_cast<uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^ static_cast<uint64_t>(octave) * 0x165667B19E3779F9ull;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return static_cast<double>(h & 0xFFFFFF) / 8388607.5 - 1.0;
}

double Noise(double x, double y, int octave, int64_t period)
{
  const double fx = std::floor(x), fy = std::floor(y);
  const double tx = x - fx, ty = y - fy;
  const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
  const int64_t ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  auto at = [&](int64_t i, int64_t j) { return Hash(((i % period) + period) % period, j, octave); };
  return (1 - sy) * ((1 - sx) * at(ix, iy) + sx * at(ix + 1, iy)) +
    sy * ((1 - sx) * at(ix, iy + 1) + sx * at(ix + 1, iy + 1));
}

// Fractal detail at post (x, y) of a W-wide global grid: wavelengths from 1 degree halving
// to 2 posts (8 at most), amplitude halving with them; wraps east-west.
double Fractal(double x, double y, int W)
{
  double sum = 0.0, amplitude = 1.0;
  double cells = 360.0; // lattice cells around the globe: 1 degree first
  for (int octave = 0; octave < 8 && cells <= W / 2.0; ++octave)
  {
    const double scale = cells / W;
    sum += amplitude * Noise(x * scale, y * scale, octave, static_cast<int64_t>(cells));
    amplitude *= 0.5;
    cells *= 2.0;
  }
  return sum;
}

// Bilinear sample (wrapping east-west) of a north-up raster of w x h x c at the centre of
// post (x, y) of a W x H grid.
double Sample(vtkDataArray* data, int w, int h, int component, double x, double y, int W, int H)
{
  const double u = (x + 0.5) / W * w - 0.5, v = (y + 0.5) / H * h - 0.5;
  const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
  const double fu = u - i, fv = v - j;
  auto at = [&](int ii, int jj) {
    ii = ((ii % w) + w) % w;
    jj = std::clamp(jj, 0, h - 1);
    return data->GetComponent(static_cast<vtkIdType>(jj) * w + ii, component);
  };
  return (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i + 1, j)) + fv * ((1 - fu) * at(i, j + 1) + fu * at(i + 1, j + 1));
}

// Writes rows of a plain striped TIFF; row(y, buffer) fills one row; rows are made on all
// cores in blocks.
bool WritePlain(const std::string& path, int W, int H, int channels, bool floats,
  const std::function<void(int, unsigned char*)>& row)
{
  TIFF* tif = TIFFOpen(path.c_str(), "w8"); // BigTIFF: over 4 GB with some rasters
  if (!tif)
  {
    return false;
  }
  TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, W);
  TIFFSetField(tif, TIFFTAG_IMAGELENGTH, H);
  TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, channels);
  TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, floats ? 32 : 8);
  TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, floats ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
  TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, channels == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 1);
  const size_t rowBytes = static_cast<size_t>(W) * channels * (floats ? 4 : 1);
  const int block = 64;
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<unsigned char> rows(rowBytes * block);
  bool ok = true;
  for (int y0 = 0; y0 < H && ok; y0 += block)
  {
    const int n = std::min(block, H - y0);
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t)
    {
      pool.emplace_back([&, t] {
        for (int k = static_cast<int>(t); k < n; k += static_cast<int>(threads))
        {
          row(y0 + k, rows.data() + rowBytes * k);
        }
      });
    }
    for (auto& p : pool)
    {
      p.join();
    }
    for (int k = 0; k < n && ok; ++k)
    {
      ok = TIFFWriteScanline(tif, rows.data() + rowBytes * k, y0 + k, 0) == 1;
    }
    if ((y0 / block) % 64 == 0)
    {
      std::printf("\r  %s: %5.1f %%", std::filesystem::path(path).filename().c_str(), 100.0 * y0 / H);
      std::fflush(stdout);
    }
  }
  TIFFClose(tif);
  std::printf("\r  %s: done      \n", std::filesystem::path(path).filename().c_str());
  return ok;
}

bool Prepare(const std::string& in, const std::string& out)
{
  const std::string partial = out + ".partial";
  vtkNew<vtkGlobeRasterPreparer> preparer;
  preparer->SetInputFileName(in.c_str());
  preparer->SetFileName(partial.c_str());
  preparer->SetTileSize(256);
  const bool ok = preparer->Write();
  if (!ok)
  {
    std::fprintf(stderr, "preparing %s failed: %s\n", in.c_str(), preparer->GetLastError());
    return false;
  }
  std::filesystem::rename(partial, out);
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: GlobeMakePlanet DATA_DIR OUT_DIR [--width 43200] [--keep-plain]\n");
    return 2;
  }
  const std::string data = argv[1], out = argv[2];
  int W = 43200;
  bool keep = false;
  for (int i = 3; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--width" && i + 1 < argc)
    {
      W = std::atoi(argv[++i]);
    }
    else if (arg == "--keep-plain")
    {
      keep = true;
    }
    else
    {
      std::fprintf(stderr, "GlobeMakePlanet: unknown argument '%s'\n"
                           "usage: GlobeMakePlanet DATA_DIR OUT_DIR [--width 43200] [--keep-plain]\n",
        arg.c_str());
      return 2;
    }
  }
  if (W < 360 || W % 2 != 0)
  {
    std::fprintf(stderr, "GlobeMakePlanet: --width must be even and at least 360 (got %d)\n", W);
    return 2;
  }
  const int H = W / 2;
  std::filesystem::create_directories(out);
  vtkNew<vtkGlobeLayer> relief, world;
  relief->SetFileName((data + "/earth/relief_2deg.tif").c_str());
  world->SetFileName((data + "/earth/world.tif").c_str());
  world->SetRoleToColor();
  if (!relief->Update() || !world->Update())
  {
    std::fprintf(stderr, "cannot read %s/earth/relief_2deg.tif and world.tif\n", data.c_str());
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  const std::string tag = std::to_string(W);
  const std::string heightsPlain = out + "/planet_heights_" + tag + "_plain.tif";
  const std::string imageryPlain = out + "/planet_imagery_" + tag + "_plain.tif";
  vtkDataArray* h = relief->GetData();
  vtkDataArray* c = world->GetData();
  const int rw = relief->GetNumberOfColumns(), rh = relief->GetNumberOfRows();
  const int cw = world->GetNumberOfColumns(), ch = world->GetNumberOfRows();
  // Relief: the 2-degree heights plus up to +-600 m of detail, more over land.
  bool ok = WritePlain(heightsPlain, W, H, 1, true, [&](int y, unsigned char* row) {
    auto* v = reinterpret_cast<float*>(row);
    for (int x = 0; x < W; ++x)
    {
      const double base = Sample(h, rw, rh, 0, x, y, W, H);
      v[x] = static_cast<float>(base + (base > 0 ? 600.0 : 150.0) * Fractal(x, y, W));
    }
  });
  vtkGlobeTest::WriteGlobalWorldFile(out + "/planet_heights_" + tag + "_plain.tfw", W, H);
  ok = ok && WritePlain(imageryPlain, W, H, 3, false, [&](int y, unsigned char* row) {
    for (int x = 0; x < W; ++x)
    {
      const double shade = 1.0 + 0.15 * Fractal(x + 17.0, y + 31.0, W);
      for (int k = 0; k < 3; ++k)
      {
        row[3 * x + k] = static_cast<unsigned char>(
          std::clamp(Sample(c, cw, ch, k, x, y, W, H) * shade, 0.0, 255.0));
      }
    }
  });
  vtkGlobeTest::WriteGlobalWorldFile(out + "/planet_imagery_" + tag + "_plain.tfw", W, H);
  std::printf("  plain rasters written in %.0f s\n",
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  ok = ok && Prepare(heightsPlain, out + "/planet_heights_" + tag + ".tif");
  ok = ok && Prepare(imageryPlain, out + "/planet_imagery_" + tag + ".tif");
  if (!keep)
  {
    for (const std::string& f : { heightsPlain, imageryPlain })
    {
      std::filesystem::remove(f);
      std::filesystem::remove(f.substr(0, f.size() - 4) + ".tfw");
    }
  }
  std::printf("%s: planet_heights_%s.tif and planet_imagery_%s.tif in %s (%.0f s)\n",
    ok ? "done" : "FAILED", tag.c_str(), tag.c_str(), out.c_str(),
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return ok ? 0 : 1;
}
