// Exact page addressing of streamed layers (issue "Planetary-scale data", Documentation/
// streaming.md "Exact addressing"): a global raster 2^20 texels wide (38 m at the equator, the
// width class of a 1" global data set), self-encoding (each texel's colour is its own index),
// seen from 300 m and 30 m above the ground at several longitudes. Float texture coordinates
// over the whole raster are 2^-24 of its extent, 1/16 of a texel there (2.4 m); pages are
// addressed from the hi + lo geodetic coordinates instead, so every pixel shows the texel at
// its own (lon, lat) (from the G-buffer, in double) except within 0.1 % of a texel of its
// edges. Written as a tiled TIFF with its own reduced-resolution levels and a world file, zip-compressed
// (the pattern compresses to a few MB), so the test costs seconds.
// The same strip in Web Mercator (EPSG:3857, texels of 2 pi a / 2^20 = 38.2 m), a projected
// layer: its texel coordinates are the projection's float offset from a reference point added
// to the reference's own in hi + lo; the offset carries 2^-24 of the distance from the reference,
// 1/32 texel at the raster's edge when the reference was the raster's centre. The reference now
// follows the view (vtkGlobeLayerSet::SetGeodeticReference), and across the seam the hi part
// moves by a turn: every pixel again shows its own texel.
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeTestHelpers.h"

#include "vtkGlobePageCache.h"
#include "vtkMath.h"

#include <tiffio.h>

#include <chrono>
#include <unistd.h>
#include <fstream>
#include <thread>

namespace
{
vtkGlobeTest::Checklist Checks;
const std::string Temp = VTKGLOBE_TEMP_DIR;
constexpr int Width = 1 << 20, Height = 64;

// Texel (x, y) of level 0, y from the north: R, G = x's low 16 bits, B = x's next 4 and y's
// low 4. Unique within 16 rows and 2^20 columns.
std::array<unsigned char, 3> Code(int x, int y)
{
  return { static_cast<unsigned char>(x & 255), static_cast<unsigned char>((x >> 8) & 255),
    static_cast<unsigned char>(((x >> 16) & 15) | ((y & 15) << 4)) };
}

// Every level encodes its own texels the same way (the test looks at level 0 only; the
// others must exist so that nothing is averaged from 2^26 texels): tiled, one reduced-
// resolution IFD per level, as vtkGlobeRasterPreparer writes them.
bool WriteRaster(const std::string& path, bool mercator)
{
  TIFF* tif = TIFFOpen(path.c_str(), "w");
  if (!tif)
  {
    return false;
  }
  const int tile = 256;
  int w = Width, h = Height;
  bool ok = true;
  for (int level = 0; ok; ++level)
  {
    TIFFSetField(tif, TIFFTAG_SUBFILETYPE, level > 0 ? FILETYPE_REDUCEDIMAGE : 0);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(w));
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(h));
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 3);
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 8);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(tif, TIFFTAG_TILEWIDTH, static_cast<uint32_t>(tile));
    TIFFSetField(tif, TIFFTAG_TILELENGTH, static_cast<uint32_t>(tile));
    TIFFSetField(tif, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
    TIFFSetField(tif, TIFFTAG_ZIPQUALITY, 1);
    if (level == 0)
    {
      TIFFSetField(tif, TIFFTAG_PIXAR_TEXTUREFORMAT, "Plain Texture");
    }
    std::vector<unsigned char> pixels(static_cast<size_t>(tile) * tile * 3);
    for (int ty = 0; ty < h && ok; ty += tile)
    {
      for (int tx = 0; tx < w && ok; tx += tile)
      {
        for (int j = 0; j < tile; ++j)
        {
          for (int i = 0; i < tile; ++i)
          {
            const std::array<unsigned char, 3> c = Code(std::min(tx + i, w - 1), std::min(ty + j, h - 1));
            std::copy(c.begin(), c.end(), &pixels[3 * (static_cast<size_t>(j) * tile + i)]);
          }
        }
        ok = TIFFWriteTile(tif, pixels.data(), static_cast<uint32_t>(tx), static_cast<uint32_t>(ty), 0, 0) >= 0;
      }
    }
    ok = ok && TIFFWriteDirectory(tif);
    if (w <= tile && h <= tile)
    {
      break;
    }
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
  }
  TIFFClose(tif);
  if (!ok)
  {
    return false;
  }
  // A strip along the equator, all longitudes: texels of 360 / 2^20 degrees both ways, or of
  // 2 pi a / 2^20 metres in Web Mercator.
  const double texel = mercator ? 2.0 * vtkMath::Pi() * 6378137.0 / Width : 360.0 / Width;
  const double west = mercator ? -vtkMath::Pi() * 6378137.0 : -180.0;
  std::ofstream world(path.substr(0, path.size() - 4) + ".tfw");
  world.precision(17);
  world << texel << "\n0\n0\n" << -texel << "\n" << west + 0.5 * texel << "\n"
        << 0.5 * Height * texel - 0.5 * texel << "\n";
  if (mercator)
  {
    std::ofstream(path.substr(0, path.size() - 4) + ".prj")
      << "PROJCS[\"WGS 84 / Pseudo-Mercator\",GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\","
         "SPHEROID[\"WGS 84\",6378137,298.257223563]],PRIMEM[\"Greenwich\",0],"
         "UNIT[\"degree\",0.0174532925199433]],UNIT[\"metre\",1],AUTHORITY[\"EPSG\",\"3857\"]]";
  }
  return static_cast<bool>(world);
}

struct Count
{
  int Covered = 0, Checked = 0, Wrong = 0;
  double WorstOffset = 0.0; // texels: how far past a texel edge a wrong pixel's position lies
};

// Every covered pixel against the level-0 texel at its G-buffer position (double; Web
// Mercator through vtkGlobeMapProjection).
Count CheckFrame(vtkGlobeTest::Scene& scene, double margin, bool mercator)
{
  vtkNew<vtkGlobeMapProjection> webMercator;
  webMercator->SetFromEPSG(3857);
  Count count;
  const int* size = scene.Window->GetSize();
  const std::vector<unsigned char> rgb = vtkGlobeTest::ReadPixels(scene.Window);
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const std::vector<float> g = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
  const double texel = mercator ? 2.0 * vtkMath::Pi() * 6378137.0 / Width : 360.0 / Width;
  for (size_t i = 0; i < static_cast<size_t>(size[0]) * size[1]; ++i)
  {
    if (!(depth[i] < 1.0f))
    {
      continue;
    }
    ++count.Covered;
    double p[3], llh[3];
    vtkGlobeTest::GBufferPoint(scene, &g[4 * i], false, p);
    scene.Body->CartesianToGeodetic(p, llh);
    double xy[2] = { llh[0], llh[1] };
    if (mercator && !webMercator->ForwardInDomain(llh[0], llh[1], xy))
    {
      continue;
    }
    double tx = (xy[0] + (mercator ? vtkMath::Pi() * 6378137.0 : 180.0)) / texel;
    tx -= Width * std::floor(tx / Width);
    const double ty = (0.5 * Height * texel - xy[1]) / texel;
    const double fx = tx - std::floor(tx), fy = ty - std::floor(ty);
    if (ty < 0.0 || ty >= Height || std::min(fx, 1.0 - fx) < margin || std::min(fy, 1.0 - fy) < margin)
    {
      continue;
    }
    ++count.Checked;
    const std::array<unsigned char, 3> c =
      Code(static_cast<int>(std::floor(tx)) % Width, static_cast<int>(std::floor(ty)));
    if (c[0] != rgb[3 * i] || c[1] != rgb[3 * i + 1] || c[2] != rgb[3 * i + 2])
    {
      ++count.Wrong;
      count.WorstOffset = std::max(count.WorstOffset, std::min(std::min(fx, 1.0 - fx), std::min(fy, 1.0 - fy)));
    }
  }
  return count;
}

// One raster (geographic or Web Mercator) through six views; returns the wrong pixels and
// adds the checked ones.
int RunRaster(bool mercator, int& checked)
{
  // Per process: a suite run beside a hand-run of the same test must not share the file.
  const std::string path = Temp + "/streaming_addressing_" + (mercator ? "3857_" : "") +
    std::to_string(getpid()) + ".tif";
  const auto start = std::chrono::steady_clock::now();
  Checks.Expect(WriteRaster(path, mercator),
    std::string("the 2^20 x 64 self-encoding raster is written") + (mercator ? " (EPSG:3857)" : ""));
  std::printf("  wrote %s in %.1f s\n", path.c_str(),
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  vtkGlobeTest::Scene scene(200, 150, 128);
  scene.Mapper->LightingOff();
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetFileName(path.c_str());
  layer->SetRoleToColor();
  layer->SetInterpolationToNearest();
  layer->SetStreamingToOn();
  scene.Mapper->AddLayer(layer);

  struct View
  {
    double Lon, Height;
  };
  // Longitudes where the raster's float u is coarsest (u near 1: 2^-24, 1/16 texel), finest
  // (near 0) and at the antimeridian's seam; 300 m (about 6 texels across) and 30 m above.
  const View views[] = { { 170.3, 300.0 }, { 179.99, 300.0 }, { -179.7, 300.0 }, { 90.01, 300.0 },
    { 170.30001, 30.0 }, { -0.02, 300.0 } };
  const double margin = 0.001; // texels (3.8 cm): the G-buffer position is good to about 1e-5 m here
  int wrong = 0;
  for (const View& v : views)
  {
    const double texel = 360.0 / Width;
    const double lat = 0.3 * texel;
    const double camera[3] = { v.Lon, lat - 1e-6, v.Height }, target[3] = { v.Lon, lat, 0.0 };
    // Explicit planes: the first frame has no terrain range yet for VTK's own reset.
    scene.Look(camera, target, 30.0, 0.05 * v.Height, 10.0 * v.Height);
    int frame = 0;
    for (; frame < 500; ++frame)
    {
      scene.Window->Render();
      if (scene.Mapper->IsStreamingIdle() && frame > 1)
      {
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const Count c = CheckFrame(scene, margin, mercator);
    std::printf("  %s lon %10.5f, %5.0f m, settled after %3d frames: %5d px covered, %5d checked, "
                "%4d show another texel (the worst %.4f texel inside its own)\n",
      mercator ? "EPSG:3857" : "EPSG:4326", v.Lon, v.Height, frame + 1, c.Covered, c.Checked,
      c.Wrong, c.WorstOffset);
    Checks.Expect(frame < 500, "streaming settles");
    Checks.Expect(c.Checked > 1000, vtkGlobeTest::Printf("lon %.5f, %.0f m: the raster covers the view", v.Lon, v.Height));
    wrong += c.Wrong;
    checked += c.Checked;
  }
  Checks.Expect(scene.Mapper->GetPageCache()->GetNumberOfLoadedPages() > 0, "the layer streams");
  std::remove(path.c_str());
  std::remove((path.substr(0, path.size() - 4) + ".tfw").c_str());
  std::remove((path.substr(0, path.size() - 4) + ".prj").c_str());
  return wrong;
}
} // namespace

int TestGlobeStreamingAddressing(int, char*[])
{
  int checked = 0, checkedMercator = 0;
  const int wrong = RunRaster(false, checked);
  Checks.Expect(wrong == 0,
    vtkGlobeTest::Printf("geographic: every pixel shows the texel at its own (lon, lat): %d of %d differ", wrong, checked));
  const int wrongMercator = RunRaster(true, checkedMercator);
  Checks.Expect(wrongMercator == 0,
    vtkGlobeTest::Printf("Web Mercator: every pixel shows the texel at its own (lon, lat): %d of %d differ",
      wrongMercator, checkedMercator));
  Checks.Expect(vtkGlobeTest::NoGLError(), "no OpenGL error");
  return Checks.Result();
}
