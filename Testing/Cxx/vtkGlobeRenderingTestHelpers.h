// Helpers shared by the rendering tests: an offscreen window, camera placement in geodetic
// terms, texture and depth readback, and the exact ray/ellipsoid reference.
#ifndef vtkGlobeRenderingTestHelpers_h
#define vtkGlobeRenderingTestHelpers_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkGlobeClippingRange.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeDepthPass.h"
#include "vtkGlobeGridPass.h"
#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerTestHelpers.h"
#include "vtkGlobeMapProjection.h"
#include "vtkGlobeMapper.h"
#include "vtkGlobeMapperTesting.h"
#include "vtkGlobePageCache.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeTerrain.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkImageData.h"
#include "vtkPixelBufferObject.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkLight.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <array>
#include <cmath>
#include <map>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace vtkGlobeTest
{
/// Points the renderer's camera from a geodetic position at a geodetic target, with the
/// local up as view-up.
inline void LookAt(vtkRenderer* renderer, vtkGlobeEllipsoid* body, const double camera[3],
  const double target[3], double viewAngle)
{
  double eye[3], focus[3], east[3], north[3], up[3];
  body->GeodeticToCartesian(camera, eye);
  body->GeodeticToCartesian(target, focus);
  body->ComputeEastNorthUp(camera[0], camera[1], east, north, up);
  vtkCamera* c = renderer->GetActiveCamera();
  c->SetPosition(eye);
  c->SetFocalPoint(focus);
  // Looking down the vertical, "up" is the view direction itself: use north instead.
  double view[3] = { focus[0] - eye[0], focus[1] - eye[1], focus[2] - eye[2] };
  const double length = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
  const double along = (view[0] * up[0] + view[1] * up[1] + view[2] * up[2]) / length;
  c->SetViewUp(std::abs(along) > 0.999 ? north : up);
  c->SetViewAngle(viewAngle);
  c->OrthogonalizeViewUp();
}

/// Reads a float texture back: width * height * components values, row 0 at the bottom.
inline std::vector<float> ReadTexture(vtkTextureObject* texture)
{
  const unsigned int w = texture->GetWidth(), h = texture->GetHeight();
  const int comps = texture->GetComponents();
  std::vector<float> values(static_cast<size_t>(w) * h * comps);
  vtkPixelBufferObject* pbo = texture->Download();
  unsigned int dims[2] = { w, h };
  vtkIdType increments[2] = { 0, 0 };
  pbo->Download2D(VTK_FLOAT, values.data(), dims, comps, increments);
  pbo->Delete();
  return values;
}

/// The z-buffer of the window (VTK's depth convention, 0 near .. 1 far), row 0 at the bottom.
inline std::vector<float> ReadDepth(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  std::vector<float> depth(static_cast<size_t>(size[0]) * size[1]);
  window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
  return depth;
}

/// World position of a window pixel from its depth value, through the inverse of the
/// camera's composite projection (double).
inline void UnprojectPixel(vtkRenderer* renderer, double x, double y, double depth, double world[3])
{
  renderer->SetDisplayPoint(x, y, depth);
  renderer->DisplayToWorld();
  double p[4];
  renderer->GetWorldPoint(p);
  world[0] = p[0] / p[3];
  world[1] = p[1] / p[3];
  world[2] = p[2] / p[3];
}

/// The view ray (unit, world) through a pixel centre.
inline void PixelRay(vtkRenderer* renderer, double x, double y, double ray[3])
{
  double nearPoint[3], farPoint[3];
  UnprojectPixel(renderer, x, y, 0.0, nearPoint);
  UnprojectPixel(renderer, x, y, 1.0, farPoint);
  double n = 0;
  for (int i = 0; i < 3; ++i)
  {
    ray[i] = farPoint[i] - nearPoint[i];
    n += ray[i] * ray[i];
  }
  n = std::sqrt(n);
  for (int i = 0; i < 3; ++i)
  {
    ray[i] /= n;
  }
}
/// True when the tests run with streamed layers (VTKGLOBE_TEST_STREAMING=1, the "Streamed."
/// CTest variants): FileLayer streams its file, and Scene's mapper waits for the pages each
/// frame needs, through a small GPU page cache (pages of 64^2), so the same assertions hold
/// once refinement settled.
inline bool Streamed()
{
  const char* v = std::getenv("VTKGLOBE_TEST_STREAMING");
  return v && std::string(v) == "1";
}

/**
 * A PNG with an ESRI world file (the north-west pixel's centre, pixel size) and a .prj naming
 * EPSG:`epsg`, the plainest way a user brings a raster in a projection: `w` x `h` square
 * pixels of `pixel` map units from the north-west outer corner (west, north), coloured by
 * `colour(i, j)`. `base` is the path without extension; returns the PNG's path.
 */
inline std::string WriteWorldFilePNG(const std::string& base, int epsg, int w, int h,
  double west, double north, double pixel,
  const std::function<std::array<unsigned char, 3>(int, int)>& colour, const char* prj = nullptr)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      // VTK images run south to north; row j counts from the north.
      const auto c = colour(i, j);
      std::copy(c.begin(), c.end(), rgb + 3 * (static_cast<size_t>(h - 1 - j) * w + i));
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName((base + ".png").c_str());
  writer->Write();
  std::ofstream world(base + ".pgw");
  world.precision(17);
  world << pixel << "\n0\n0\n" << -pixel << "\n" << west + 0.5 * pixel << "\n"
        << north - 0.5 * pixel << "\n";
  if (prj)
  {
    // A CRS without a code: its definition as given (a PROJ string or WKT).
    std::ofstream(base + ".prj") << prj;
    return base + ".png";
  }
  std::ofstream(base + ".prj") << "PROJCS[\"EPSG:" << epsg << "\",GEOGCS[\"WGS 84\","
                                 "DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,298.257223563]],"
                                 "PRIMEM[\"Greenwich\",0],UNIT[\"degree\",0.0174532925199433]],"
                                 "UNIT[\"metre\",1],AUTHORITY[\"EPSG\",\""
                              << epsg << "\"]]";
  return base + ".png";
}

/// A layer from a file in the data folder.
inline vtkSmartPointer<vtkGlobeLayer> FileLayer(const std::string& file, bool height)
{
  auto layer = vtkSmartPointer<vtkGlobeLayer>::New();
  layer->SetFileName((std::string(VTKGLOBE_DATA_DIR) + "/" + file).c_str());
  if (Streamed())
  {
    layer->SetStreamingToOn();
  }
  if (height)
  {
    layer->SetRoleToHeight();
  }
  else
  {
    layer->SetRoleToColor();
  }
  return layer;
}

/// A globe scene in a small offscreen window: the mapper, its actor, a renderer and a window.
struct Scene
{
  vtkNew<vtkGlobeEllipsoid> Body;
  vtkNew<vtkGlobeMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;

  Scene(int width = 300, int height = 225, int grid = 256)
  {
    this->Mapper->SetEllipsoid(this->Body);
    this->Mapper->SetGridResolution(grid);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Window->SetOffScreenRendering(1);
    // VTK's anti-aliasing variants of the scenes (CTest's AntiAliased.* and Multisampled.*):
    // VTKGLOBE_TEST_FXAA=1 turns the renderer's FXAA on, VTKGLOBE_TEST_MULTISAMPLES=n asks the
    // window for n samples. Both change colour only, so the scenes' terrain checks (on depth)
    // and baselines must hold.
    const char* samples = std::getenv("VTKGLOBE_TEST_MULTISAMPLES");
    this->Window->SetMultiSamples(samples ? std::atoi(samples) : 0);
    const char* fxaa = std::getenv("VTKGLOBE_TEST_FXAA");
    this->Renderer->SetUseFXAA(fxaa && std::string(fxaa) == "1");
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    // VTKGLOBE_TEST_REFINEMENT=n runs the scenes with n terrain refinement steps (the default
    // is the mapper's): what a refined default would change (Documentation/accuracy-vs-time.md
    // "Terrain refinement"). Tests that set the refinement themselves keep theirs.
    const char* refinement = std::getenv("VTKGLOBE_TEST_REFINEMENT");
    if (refinement)
    {
      this->Mapper->SetTerrainRefinement(std::atoi(refinement));
    }
    // VTKGLOBE_TEST_HEIGHT_FILTERING=shader filters heights in the shader whatever the texture
    // unit (on llvmpipe the automatic choice keeps the texture unit, which is exact there): the
    // path GPUs take, compiled and checked here (CTest's ShaderFiltered.* variants).
    const char* filtering = std::getenv("VTKGLOBE_TEST_HEIGHT_FILTERING");
    if (filtering && std::string(filtering) == "shader")
    {
      this->Mapper->GetLayerSet()->SetHeightFiltering(vtkGlobeLayerSet::HeightFilteringShader);
    }
    if (Streamed())
    {
      this->Mapper->WaitForPagesOn();
      this->Mapper->GetPageCache()->SetPageSize(64);
      this->Mapper->GetPageCache()->SetGPUMemory(16.0);
    }
  }

  /// Streamed runs check that they streamed: every file layer of the mapper streamed and
  /// pages were loaded; otherwise the test fails (a Streamed. variant that silently ran
  /// whole would only repeat its Rendering. twin).
  ~Scene()
  {
    if (!Streamed())
    {
      return;
    }
    int files = 0, streamed = 0;
    for (int i = 0; i < this->Mapper->GetNumberOfLayers(); ++i)
    {
      vtkGlobeLayer* layer = this->Mapper->GetLayer(i);
      files += layer->GetFileName() && layer->IsValid() ? 1 : 0;
      streamed += layer->IsStreamed() ? 1 : 0;
    }
    if (files > 0 && (streamed != files || this->Mapper->GetPageCache()->GetNumberOfLoadedPages() == 0))
    {
      std::printf("FAIL streamed run: %d of %d file layers streamed, %lld pages loaded\n", streamed,
        files, this->Mapper->GetPageCache()->GetNumberOfLoadedPages());
      std::fflush(stdout);
      std::_Exit(1);
    }
    std::printf("  streamed run: %d file layers streamed, %lld pages loaded\n", files,
      this->Mapper->GetPageCache()->GetNumberOfLoadedPages());
  }

  /// The Earth with the data the demo uses: 2-degree relief, the Rainier and Everest SRTM
  /// insets, and the Blue Marble imagery.
  void AddEarthLayers(bool heights = true, bool color = true)
  {
    if (heights)
    {
      this->Mapper->AddLayer(FileLayer("earth/relief_2deg.tif", true));
      this->Mapper->AddLayer(FileLayer("earth/mt_rainier_90m.tif", true));
      this->Mapper->AddLayer(FileLayer("earth/mt_everest_90m.tif", true));
    }
    if (color)
    {
      this->Mapper->AddLayer(FileLayer("earth/world.tif", false));
    }
  }

  void Look(const double camera[3], const double target[3], double angle, double nearPlane = 0,
    double farPlane = 0)
  {
    LookAt(this->Renderer, this->Body, camera, target, angle);
    if (nearPlane > 0)
    {
      this->Renderer->GetActiveCamera()->SetClippingRange(nearPlane, farPlane);
    }
    else
    {
      this->Renderer->ResetCameraClippingRange();
    }
  }

  /// Renders twice: the second frame uses the first one's GPU reduction for the primary sphere.
  void Render()
  {
    this->Window->Render();
    this->Window->Render();
  }
};

/// A layer's texture coordinates (u east, v south, [0, 1] over the outer pixel edges) at
/// (lon, lat) in degrees, in double: geographic layers directly, projected ones through
/// vtkGlobeMapProjection (GeographicLib). False where the projection is undefined.
inline bool LayerUV(vtkGlobeLayer* layer, double lon, double lat, double& u, double& v)
{
  if (layer->GetModelType() == vtkGlobeLayer::Projected)
  {
    // By EPSG code, or by definition for a CRS without one.
    static std::map<std::string, vtkSmartPointer<vtkGlobeMapProjection>> projections;
    auto& projection = projections[std::to_string(layer->GetEPSG()) + layer->GetCRSDefinition()];
    if (!projection)
    {
      projection = vtkSmartPointer<vtkGlobeMapProjection>::New();
      layer->GetMapProjection(projection);
    }
    double xy[2], origin[2], pixel[2];
    if (!projection->IsInValidDomain(lon, lat) || !projection->Forward(lon, lat, xy))
    {
      return false;
    }
    layer->GetProjectedGeoTransform(origin, pixel);
    u = (xy[0] - origin[0]) / (pixel[0] * layer->GetNumberOfColumns());
    v = (origin[1] - xy[1]) / (pixel[1] * layer->GetNumberOfRows());
    return true;
  }
  double e[4];
  layer->GetGeographicExtent(e);
  u = std::fmod(lon - e[0] + 720.0, 360.0) / (e[1] - e[0]);
  v = (e[3] - lat) / (e[3] - e[2]);
  return true;
}

/// A layer's values read whole: its own, or for a streamed layer those of a twin that reads
/// the same file whole with the same settings (the reference the streamed pictures meet).
inline vtkGlobeLayer* WholeLayer(vtkGlobeLayer* layer)
{
  if (!layer->IsStreamed())
  {
    return layer;
  }
  // Keyed by what the twin reads, not by the layer's address (addresses are reused).
  const std::string key = std::string(layer->GetFileName()) + "|" + std::to_string(layer->GetRole()) +
    "|" + std::to_string(layer->GetValueScale()) + "|" + std::to_string(layer->GetValueOffset()) +
    "|" + std::to_string(layer->GetFillVoids()) + "|" + std::to_string(layer->GetPlausibleRange()[0]) +
    "|" + std::to_string(layer->GetPlausibleRange()[1]);
  static std::map<std::string, vtkSmartPointer<vtkGlobeLayer>> twins;
  auto& twin = twins[key];
  if (!twin)
  {
    twin = vtkSmartPointer<vtkGlobeLayer>::New();
    twin->SetFileName(layer->GetFileName());
    twin->SetRole(layer->GetRole());
    twin->SetValueScale(layer->GetValueScale());
    twin->SetValueOffset(layer->GetValueOffset());
    twin->SetFillVoids(layer->GetFillVoids());
    twin->SetPlausibleRange(layer->GetPlausibleRange());
    twin->SetStreamingToOff();
    twin->Update();
  }
  return twin;
}

inline vtkDataArray* WholeData(vtkGlobeLayer* layer)
{
  return WholeLayer(layer)->GetData();
}

/// One component of a layer's data at (lon, lat) in degrees as the GPU samples it at level 0:
/// bilinear between texel centres, clamped at the edges, wrapped in longitude for global
/// layers (raw values: metres, or 0..255 for images). Returns false outside the layer.
/**
 * A layer's component at (lon, lat) in degrees as the GPU samples its whole-raster texture:
 * at level of detail `lod` trilinearly between the two levels around it
 * (vtkGlobeLayer::GetLevelData, LINEAR_MIPMAP_LINEAR), bilinear within each; lod 0: level 0.
 */
inline bool SampleLayer(vtkGlobeLayer* layer, double lon, double lat, int component, double& value,
  double lod = 0.0)
{
  double u, v;
  if (!LayerUV(layer, lon, lat, u, v) || u < 0 || u > 1 || v < 0 || v > 1)
  {
    return false;
  }
  vtkGlobeLayer* whole = WholeLayer(layer);
  const bool wrap = layer->IsGlobal();
  auto level = [&](int l) {
    int size[2];
    whole->GetLevelDimensions(l, size);
    const int w = size[0], h = size[1];
    vtkDataArray* data = whole->GetLevelData(l);
    auto at = [&](int i, int j) {
      i = wrap ? ((i % w) + w) % w : std::max(0, std::min(i, w - 1));
      j = std::max(0, std::min(j, h - 1));
      return data->GetComponent(static_cast<vtkIdType>(j) * w + i, component);
    };
    const double x = u * w - 0.5, y = v * h - 0.5;
    const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
    const double fx = x - i, fy = y - j;
    return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
      fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
  };
  lod = std::min(std::max(lod, 0.0), whole->GetNumberOfLevels() - 1.0);
  const int l = static_cast<int>(std::floor(lod));
  const double f = lod - l;
  value = level(l);
  if (f > 0.0)
  {
    value += (level(l + 1) - value) * f;
  }
  return true;
}

/**
 * The level of detail the screen pass takes for a layer at a pixel (log2 of the longer screen
 * step in texels) from its footprint (PixelFootprint: degrees of lon and lat per pixel along x
 * and y).
 */
inline double PixelLod(vtkGlobeLayer* layer, const double here[2], const double footprint[4])
{
  double u, v, ux, vx, uy, vy;
  if (!LayerUV(layer, here[0], here[1], u, v) ||
    !LayerUV(layer, here[0] + footprint[0], here[1] + footprint[1], ux, vx) ||
    !LayerUV(layer, here[0] + footprint[2], here[1] + footprint[3], uy, vy))
  {
    return 0.0;
  }
  const double w = layer->GetNumberOfColumns(), h = layer->GetNumberOfRows();
  double dxu = ux - u, dyu = uy - u;
  if (layer->IsGlobal())
  {
    dxu -= std::floor(dxu + 0.5);
    dyu -= std::floor(dyu + 0.5);
  }
  const double rho = std::max(std::hypot(dxu * w, (vx - v) * h), std::hypot(dyu * w, (vy - v) * h));
  return std::max(0.0, std::log2(std::max(rho, 1e-300)));
}

/// A height layer's value (m) at (lon, lat) in degrees as the GPU samples it at level 0.
inline bool SampleHeight(vtkGlobeLayer* layer, double lon, double lat, double& value)
{
  return SampleLayer(layer, lon, lat, 0, value);
}

/// The window's RGB pixels (3 bytes each), row 0 at the bottom.
inline std::vector<unsigned char> ReadPixels(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  unsigned char* data = window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0);
  std::vector<unsigned char> rgb(data, data + 3 * size[0] * size[1]);
  delete[] data;
  return rgb;
}

/// How many pixels of two ReadPixels frames differ in colour.
inline int DifferingPixels(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int pixels = 0;
  for (size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3)
  {
    pixels += (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2]) ? 1 : 0;
  }
  return pixels;
}

/// Two frames of one window (ReadPixels and ReadDepth of each): how many pixels differ in
/// colour and how many in depth.
inline void CountDifferences(const std::vector<unsigned char>& imageA,
  const std::vector<float>& depthA, const std::vector<unsigned char>& imageB,
  const std::vector<float>& depthB, int& pixels, int& depths)
{
  pixels = depths = 0;
  for (size_t i = 0; i < depthA.size() && i < depthB.size(); ++i)
  {
    depths += depthA[i] != depthB[i] ? 1 : 0;
    pixels += (imageA[3 * i] != imageB[3 * i] || imageA[3 * i + 1] != imageB[3 * i + 1] ||
                imageA[3 * i + 2] != imageB[3 * i + 2])
      ? 1
      : 0;
  }
}

/// A sun for the scene: a scene light 1.5e11 m out above the geodetic point (lon, lat)
/// (degrees), shining at the body's centre; the renderer holds it.
inline vtkLight* AddSunOver(Scene& scene, double lon, double lat, double position[3])
{
  vtkNew<vtkLight> sun;
  const double llh[3] = { lon, lat, 1.5e11 };
  scene.Body->GeodeticToCartesian(llh, position);
  sun->SetPosition(position);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetLightTypeToSceneLight();
  scene.Renderer->AddLight(sun);
  return sun;
}

/// The scene rendered without ([0]) and with ([1]) the atmosphere: pixels and depth.
inline void RenderWithoutAndWithAtmosphere(
  Scene& scene, std::vector<unsigned char> rgb[2], std::vector<float> depth[2])
{
  for (int on = 0; on < 2; ++on)
  {
    scene.Mapper->SetAtmosphere(on == 1);
    scene.Render();
    rgb[on] = ReadPixels(scene.Window);
    depth[on] = ReadDepth(scene.Window);
  }
}

/// Along-ray error of a depth-reconstructed point at eye distance z: 4 steps of a 24-bit depth
/// buffer under VTK's perspective projection (the window's rounding, and ~2 ulp of the float
/// z_ndc ~ 1 computed on the GPU), plus float rounding of the projection (8 ulp of z).
inline double DepthBound(vtkCamera* camera, double z)
{
  const double n = camera->GetClippingRange()[0], f = camera->GetClippingRange()[1];
  const double step = 1.0 / 16777215.0;
  return 4.0 * z * z * (f - n) / (f * n) * step + 8.0 * z / 16777216.0;
}

/// The same for a logarithmic depth buffer (vtkGlobeDepthPass): 4 steps of 24 bits of
/// log2(1 + z) / log2(1 + far), 4 float ulps of the shader's log2, and 8 ulp of its z.
inline double LogDepthBound(vtkGlobeDepthPass* pass, double z)
{
  const double perStep = (1.0 + z) * std::log(2.0) * std::log2(1.0 + pass->GetLastFar());
  return perStep * (4.0 / 16777215.0 + 4.0 / 16777216.0) + 8.0 * z / 16777216.0;
}

/// The texel size (m, north-south) of the finest height layer covering (lon, lat).
inline double FinestTexel(const std::vector<vtkGlobeLayer*>& layers, double lon, double lat, double radius)
{
  double best = 1e30;
  for (vtkGlobeLayer* layer : layers)
  {
    double value;
    if (layer->GetRole() == vtkGlobeLayer::Height && layer->IsValid() &&
      SampleHeight(layer, lon, lat, value))
    {
      if (layer->GetModelType() == vtkGlobeLayer::Projected)
      {
        double origin[2], pixel[2];
        layer->GetProjectedGeoTransform(origin, pixel);
        best = std::min(best, std::min(pixel[0], pixel[1]));
        continue;
      }
      double e[4];
      layer->GetGeographicExtent(e);
      best = std::min(best, (e[3] - e[2]) / layer->GetNumberOfRows() * radius * 3.14159265358979 / 180.0);
    }
  }
  return best;
}

/// Where float texture coordinates put a sample (m), worst over the height layers covering
/// (lon, lat): u and v are differences from the layer's west and north edges, divided by its
/// span and scaled to texels by the GPU, three roundings of 2^-24 relative each, so 3 * 2^-24
/// of the distance from those edges (with exact (lon, lat): 7 m across a global layer, far
/// below its 8-bit filter weights' texel / 256; sub-millimetre for a small inset).
inline double UVRounding(const std::vector<vtkGlobeLayer*>& layers, double lon, double lat, double radius)
{
  double worst = 0.0;
  for (vtkGlobeLayer* layer : layers)
  {
    double value, u, v;
    if (layer->GetRole() != vtkGlobeLayer::Height || !layer->IsValid() ||
      !SampleHeight(layer, lon, lat, value) || !LayerUV(layer, lon, lat, u, v))
    {
      continue;
    }
    double spanU, spanV; // m
    if (layer->GetModelType() == vtkGlobeLayer::Projected)
    {
      double origin[2], pixel[2];
      layer->GetProjectedGeoTransform(origin, pixel);
      spanU = std::abs(pixel[0]) * layer->GetNumberOfColumns();
      spanV = std::abs(pixel[1]) * layer->GetNumberOfRows();
    }
    else
    {
      double e[4];
      layer->GetGeographicExtent(e);
      const double perDegree = radius * 3.14159265358979 / 180.0;
      spanU = (e[1] - e[0]) * perDegree * std::cos(lat * 3.14159265358979 / 180.0);
      spanV = (e[3] - e[2]) * perDegree;
    }
    worst = std::max(worst, 3.0 / 16777216.0 * (std::abs(u) * spanU + std::abs(v) * spanV));
  }
  return worst;
}

/// The weight of a layer's coverage at (lon, lat) in degrees (0 outside), with its feathered
/// border, as the generated GLSL computes it, before opacity and data validity.
inline double CoverageWeight(vtkGlobeLayer* layer, double lon, double lat)
{
  double u, v;
  if (!LayerUV(layer, lon, lat, u, v) || u < 0 || u > 1 || v < 0 || v > 1)
  {
    return 0.0;
  }
  double e[4] = { 0, 0, 0, 0 };
  if (layer->GetModelType() == vtkGlobeLayer::Geographic)
  {
    layer->GetGeographicExtent(e);
  }
  double w = 1.0;
  const double feather = layer->GetFeatherWidth();
  if (feather > 0 && !layer->IsGlobal())
  {
    w *= std::min(1.0, std::min(u, 1.0 - u) * layer->GetNumberOfColumns() / feather);
  }
  if (feather > 0 && !(e[2] <= -90.0 && e[3] >= 90.0))
  {
    w *= std::min(1.0, std::min(v, 1.0 - v) * layer->GetNumberOfRows() / feather);
  }
  return w;
}

/// The composed terrain height at (lon, lat) as vtkGlobeLayerSet composes it on the GPU: the
/// library's own CPU composition, vtkGlobeTerrain (layers in composition order, each weighted
/// by coverage, feathered border and opacity, zero where its value is NaN or outside its valid
/// range, blended by its mode, heights above a geoid made ellipsoidal). One terrain is kept for
/// the last list of layers asked about.
inline double ComposedHeight(const std::vector<vtkGlobeLayer*>& layers, double lon, double lat,
  const double* footprint = nullptr, int rule = vtkGlobeTerrain::GridFootprint)
{
  static vtkSmartPointer<vtkGlobeTerrain> terrain = vtkSmartPointer<vtkGlobeTerrain>::New();
  bool same = terrain->GetNumberOfLayers() == static_cast<int>(layers.size());
  for (size_t i = 0; same && i < layers.size(); ++i)
  {
    same = terrain->GetLayer(static_cast<int>(i)) == layers[i];
  }
  if (!same)
  {
    terrain->RemoveAllLayers();
    for (vtkGlobeLayer* layer : layers)
    {
      terrain->AddLayer(layer);
    }
  }
  return footprint ? terrain->GetFilteredHeight(lon, lat, footprint, rule) : terrain->GetHeight(lon, lat);
}

/// Image layers derived from a global height layer, for the effects: a water mask (1 where the
/// height is below 0) and night lights (a deterministic scatter of "cities" on low land).
inline void AddWaterMaskAndNightLights(vtkGlobeMapper* mapper, vtkGlobeLayer* heights)
{
  heights->Update();
  const int w = heights->GetNumberOfColumns(), h = heights->GetNumberOfRows();
  std::vector<unsigned char> mask, lights;
  for (int i = 0; i < w * h; ++i)
  {
    const double z = heights->GetData()->GetComponent(i, 0);
    const unsigned char water = z < 0.0 ? 255 : 0;
    mask.insert(mask.end(), { water, water, water, 255 });
    const bool city = z > 0.0 && z < 800.0 && ((i * 2654435761u) >> 28) < 6;
    const unsigned char l = city ? 255 : 0;
    lights.insert(lights.end(),
      { l, static_cast<unsigned char>(0.8 * l), static_cast<unsigned char>(0.4 * l), 255 });
  }
  double e[4];
  heights->GetGeographicExtent(e);
  vtkNew<vtkGlobeLayer> maskLayer, lightLayer;
  maskLayer->SetColorData(w, h, 4, mask.data(), e[0], e[1], e[2], e[3]);
  maskLayer->SetRoleToMask();
  lightLayer->SetColorData(w, h, 4, lights.data(), e[0], e[1], e[2], e[3]);
  lightLayer->SetRoleToNightLights();
  lightLayer->SetInterpolationToNearest();
  mapper->AddLayer(maskLayer);
  mapper->AddLayer(lightLayer);
}

/// The height layers of a mapper, in order.
inline std::vector<vtkGlobeLayer*> HeightLayers(vtkGlobeMapper* mapper)
{
  std::vector<vtkGlobeLayer*> layers;
  for (int i = 0; i < mapper->GetNumberOfLayers(); ++i)
  {
    layers.push_back(mapper->GetLayer(i));
  }
  return layers;
}

/// Result of comparing depth-reconstructed terrain with the composed height data.
struct TerrainCheck
{
  int Pixels = 0;          // covered pixels checked
  int Failures = 0;        // beyond their bound
  int NaNs = 0;            // NaN depth or position
  double WorstRatio = 0.0; // worst |dh| / bound
  double WorstRatioFloat = 0.0; // the same with float (lon, lat)'s sampling term (comparison)
  double MedianError = 0.0;
  double WorstError = 0.0;
  std::string Where;
};

/// The step (dLon, dLat, degrees) from grid point (i, j) of an n x n grid (geodetic llh, valid
/// points) to its nearer valid neighbour on the ground along (di, dj): the grid pass's footprint
/// per axis (vtkGlobeTerrain::GridFootprint). A zero step (neighbours sharing a horizon point)
/// says nothing of the footprint; with no neighbour the step is (none, none).
inline void GridShorterStep(const std::vector<std::array<double, 3>>& llh,
  const std::vector<char>& valid, int n, int i, int j, int di, int dj, double none, double step[2])
{
  const size_t k = static_cast<size_t>(j) * n + i;
  double best = 1e300;
  step[0] = step[1] = none;
  for (int s = -1; s <= 1; s += 2)
  {
    const int a = i + s * di, b = j + s * dj;
    if (a < 0 || b < 0 || a >= n || b >= n || !valid[static_cast<size_t>(b) * n + a])
    {
      continue;
    }
    const double* o = llh[static_cast<size_t>(b) * n + a].data();
    double dLon = o[0] - llh[k][0];
    dLon -= 360.0 * std::floor(dLon / 360.0 + 0.5);
    const double dLat = o[1] - llh[k][1];
    const double l = std::hypot(dLon * std::cos(llh[k][1] * 3.14159265358979 / 180.0), dLat);
    if (l > 0.0 && l < best)
    {
      best = l;
      step[0] = dLon;
      step[1] = dLat;
    }
  }
}

/**
 * The longest triangle edge (m) of the frame's PGM mesh covering each pixel: the grid of the
 * last frame rebuilt on the CPU (vtkGlobeProjectiveGrid, double, with the composed heights
 * filtered as the grid pass filters them: to the step towards the nearer neighbour along each
 * grid axis, vtkGlobeTerrain::GetFilteredHeight), each triangle projected and its edge written
 * over its screen bounding box. 0: uncovered.
 */
inline std::vector<double> MeshEdgeMap(Scene& scene)
{
  const int* size = scene.Window->GetSize();
  std::vector<double> map(static_cast<size_t>(size[0]) * size[1], 0.0);
  vtkGlobeProjectiveGrid* grid = scene.Mapper->GetProjectiveGrid();
  const int n = scene.Mapper->GetGridResolution();
  const std::vector<vtkGlobeLayer*> layers = HeightLayers(scene.Mapper);
  const double* radii = scene.Body->GetRadii();
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  const double rp = grid->GetPrimaryRadius();
  std::vector<double> world(static_cast<size_t>(n) * n * 3), screen(static_cast<size_t>(n) * n * 2);
  std::vector<char> valid(static_cast<size_t>(n) * n, 0);
  std::vector<std::array<double, 3>> sdirs(static_cast<size_t>(n) * n), ps(sdirs.size()), llhs(sdirs.size());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const size_t k = static_cast<size_t>(j) * n + i;
      // A miss gives its horizon point, a vertex as the shader draws it.
      grid->ComputeGridPoint(static_cast<double>(i) / (n - 1), static_cast<double>(j) / (n - 1),
        sdirs[k].data(), ps[k].data());
      const double* sdir = sdirs[k].data();
      double surface[3] = { sdir[0] * radii[0], sdir[1] * radii[1], sdir[2] * radii[2] };
      scene.Body->CartesianToGeodeticQuiet(surface, llhs[k].data());
      valid[k] = 1;
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const size_t k = static_cast<size_t>(j) * n + i;
      if (!valid[k])
      {
        continue;
      }
      const double* sdir = sdirs[k].data();
      const double* p = ps[k].data();
      double normal[3] = { sdir[0] / radii[0], sdir[1] / radii[1], sdir[2] / radii[2] };
      const double nn = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      double footprint[4];
      GridShorterStep(llhs, valid, n, i, j, 1, 0, 0.0, footprint);
      GridShorterStep(llhs, valid, n, i, j, 0, 1, 0.0, footprint + 2);
      const double h = ComposedHeight(layers, llhs[k][0], llhs[k][1], footprint);
      double* w = &world[3 * k];
      for (int c = 0; c < 3; ++c)
      {
        w[c] = eye[c] + (p[c] + (1.0 - rp) * sdir[c]) * radii[c] + h * normal[c] / nn;
      }
      scene.Renderer->SetWorldPoint(w[0], w[1], w[2], 1.0);
      scene.Renderer->WorldToDisplay();
      const double* d = scene.Renderer->GetDisplayPoint();
      screen[2 * k] = d[0];
      screen[2 * k + 1] = d[1];
    }
  }
  auto edge = [&](size_t a, size_t b) {
    double dd = 0;
    for (int c = 0; c < 3; ++c)
    {
      dd += (world[3 * a + c] - world[3 * b + c]) * (world[3 * a + c] - world[3 * b + c]);
    }
    return std::sqrt(dd);
  };
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const size_t a = static_cast<size_t>(j) * n + i, b = a + 1, c = a + n, d = c + 1;
      if (!valid[a] || !valid[b] || !valid[c] || !valid[d])
      {
        continue;
      }
      const double longest = std::max({ edge(a, b), edge(a, c), edge(b, d), edge(c, d), edge(a, d) });
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (size_t v : { a, b, c, d })
      {
        x0 = std::min(x0, screen[2 * v]);
        x1 = std::max(x1, screen[2 * v]);
        y0 = std::min(y0, screen[2 * v + 1]);
        y1 = std::max(y1, screen[2 * v + 1]);
      }
      const int px0 = std::max(0, static_cast<int>(std::floor(x0 - 1))),
                px1 = std::min(size[0] - 1, static_cast<int>(std::ceil(x1 + 1)));
      const int py0 = std::max(0, static_cast<int>(std::floor(y0 - 1))),
                py1 = std::min(size[1] - 1, static_cast<int>(std::ceil(y1 + 1)));
      for (int y = py0; y <= py1; ++y)
      {
        for (int x = px0; x <= px1; ++x)
        {
          double& m = map[static_cast<size_t>(y) * size[0] + x];
          m = std::max(m, longest);
        }
      }
    }
  }
  return map;
}

/**
 * For every stride-th covered pixel: the world point reconstructed from the depth buffer
 * (double), its geodetic height, and the composed data height at the same (lon, lat). The
 * bound is the depth quantization along the ray (times 1 + slope) plus what the PGM mesh can
 * represent there: a planar triangle of longest edge L deviates from the curved body by at
 * most L^2 / 6R, and from the data by its own deviation from linear over L (second
 * differences around the point), or, where L is more than 4 texels, by the local relief over
 * L; plus how the GPU samples (float coordinates, a texel / 256 term, mipmap offset).
 */
/// With a vtkGlobeDepthPass, depth is read back in its mode (depth modes, Documentation/depth.md).
inline TerrainCheck CheckTerrain(Scene& scene, int stride, vtkGlobeDepthPass* depthPass = nullptr)
{
  TerrainCheck result;
  vtkRenderer* renderer = scene.Renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  const std::vector<float> depth = ReadDepth(scene.Window);
  const std::vector<double> edges = MeshEdgeMap(scene);
  const int* size = scene.Window->GetSize();
  const std::vector<vtkGlobeLayer*> layers = HeightLayers(scene.Mapper);
  const double* eye = camera->GetPosition();
  double view[3];
  camera->GetDirectionOfProjection(view);
  const double radius = scene.Body->GetMinimumRadius();
  // The frame's local origin for geodetic coordinates: the surface point under the camera.
  const bool highPrecision = scene.Mapper->GetHighPrecisionGeodetic();
  const double largest = scene.Body->GetMaximumRadius();
  double subPoint[3];
  {
    const double* nadir = scene.Mapper->GetProjectiveGrid()->GetNadir();
    const double* radii = scene.Body->GetRadii();
    for (int k = 0; k < 3; ++k)
    {
      subPoint[k] = -nadir[k] * radii[k];
    }
  }
  std::vector<double> errors;
  for (int y = stride / 2; y < size[1]; y += stride)
  {
    for (int x = stride / 2; x < size[0]; x += stride)
    {
      const size_t at = static_cast<size_t>(y) * size[0] + x;
      const float d = depth[at];
      if (!(d < 1.0f))
      {
        result.NaNs += std::isnan(d) ? 1 : 0;
        continue;
      }
      double p[3];
      UnprojectPixel(renderer, x + 0.5, y + 0.5, depthPass ? depthPass->GetPerspectiveDepth(d, camera) : d, p);
      double llh[3];
      if (!scene.Body->CartesianToGeodeticQuiet(p, llh))
      {
        ++result.NaNs;
        continue;
      }
      const double z = (p[0] - eye[0]) * view[0] + (p[1] - eye[1]) * view[1] + (p[2] - eye[2]) * view[2];
      const double h = ComposedHeight(layers, llh[0], llh[1]);
      const double spacing = edges[at] > 0 ? edges[at] : 1e30;
      // The data's deviation from linear over the triangle's size (second differences along
      // both axes and the bilinear twist), and its slope.
      const double mPerDeg = radius * 3.14159265358979 / 180.0;
      const double dLat = std::min(spacing, 1e7) / mPerDeg;
      const double dLon = dLat / std::max(std::cos(llh[1] * 3.14159265358979 / 180.0), 1e-3);
      double curvature = 0.0, slope = 0.0;
      if (spacing < 1e29)
      {
        for (int k = 0; k < 2; ++k)
        {
          const double a = ComposedHeight(layers, llh[0] + (k ? 0 : dLon), llh[1] + (k ? dLat : 0));
          const double b = ComposedHeight(layers, llh[0] - (k ? 0 : dLon), llh[1] - (k ? dLat : 0));
          curvature = std::max(curvature, std::abs(h - 0.5 * (a + b)));
          slope = std::max(slope, std::abs(a - b) / (2.0 * spacing));
        }
        const double pp = ComposedHeight(layers, llh[0] + dLon, llh[1] + dLat);
        const double pm = ComposedHeight(layers, llh[0] + dLon, llh[1] - dLat);
        const double mp = ComposedHeight(layers, llh[0] - dLon, llh[1] + dLat);
        const double mm = ComposedHeight(layers, llh[0] - dLon, llh[1] - dLat);
        curvature = std::max(curvature, 0.25 * std::abs(pp - pm - mp + mm));
        // Where the grid is much coarser than the data, its vertices carry mip-filtered heights
        // and a triangle can only be bounded by the local relief at its scale.
        const double texelHere = FinestTexel(layers, llh[0], llh[1], radius);
        if (spacing > 4.0 * texelHere)
        {
          double lo = h, hi = h;
          for (int a = -1; a <= 1; ++a)
          {
            for (int b = -1; b <= 1; ++b)
            {
              const double v = ComposedHeight(layers, llh[0] + a * dLon, llh[1] + b * dLat);
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
          }
          curvature = std::max(curvature, 0.5 * (hi - lo));
        }
      }
      // How the GPU samples the data: where it samples (float (lon, lat), ~1 m on a planet, or
      // with HighPrecisionGeodetic the hi + lo conversion from the frame's local origin, within
      // 0.1 mm + 3e-7 of the distance from it (TestGlobeGeodeticPrecision A), and the layers'
      // float texture coordinates), slope * texel / 256 (written for 8-bit bilinear weights,
      // which heights no longer use; TestGlobeNorthPole and TestGlobeTerrainQuery fail without
      // it, so it covers sampling effects the other terms miss), and, where the grid is coarser
      // than the texels, a mipmap level whose box filter is off-centre by up to half the grid
      // spacing.
      const double texel = FinestTexel(layers, llh[0], llh[1], radius);
      double where = radius * 2.0 / 16777216.0 * 8.0;
      if (highPrecision)
      {
        double surface[3];
        const double onEllipsoid[3] = { llh[0], llh[1], 0.0 };
        scene.Body->GeodeticToCartesianQuiet(onEllipsoid, surface);
        const double chord = std::sqrt((surface[0] - subPoint[0]) * (surface[0] - subPoint[0]) +
          (surface[1] - subPoint[1]) * (surface[1] - subPoint[1]) +
          (surface[2] - subPoint[2]) * (surface[2] - subPoint[2]));
        const double arc = 2.0 * largest * std::asin(std::min(1.0, chord / (2.0 * largest)));
        where = 1e-4 + 3e-7 * arc + UVRounding(layers, llh[0], llh[1], radius);
      }
      const double filter = std::min(texel, 1e7) / 256.0 + (spacing > texel && spacing < 1e29 ? 0.5 * spacing : 0.0);
      const double sampling = slope * (where + filter);
      const double floatSampling = slope * (radius * 2.0 / 16777216.0 * 8.0 + filter);
      const bool logDepth = depthPass && depthPass->GetMode() == vtkGlobeDepthPass::Logarithmic;
      const double bound = (logDepth ? LogDepthBound(depthPass, z) : DepthBound(camera, z)) * (1.0 + slope) + 2.0 * curvature + sampling +
        (spacing < 1e29 ? spacing * spacing / (6.0 * radius) : 0.0) + 1e-3;
      const double error = std::abs(llh[2] - h);
      result.WorstRatioFloat = std::max(result.WorstRatioFloat, error / (bound - sampling + floatSampling));
      errors.push_back(error);
      ++result.Pixels;
      const double ratio = error / bound;
      if (ratio > 1.0)
      {
        ++result.Failures;
        if (std::getenv("VTKGLOBE_TEST_VERBOSE"))
        {
          std::printf("    beyond: pixel (%d, %d) lon %.3f lat %.3f h %.1f data %.1f bound %.1f "
                      "spacing %.0f curvature %.1f\n",
            x, y, llh[0], llh[1], llh[2], h, bound, spacing, curvature);
        }
      }
      if (ratio > result.WorstRatio)
      {
        result.WorstRatio = ratio;
        char where[200];
        std::snprintf(where, sizeof(where),
          "pixel (%d, %d) lon %.4f lat %.4f: h %.1f m, data %.1f m, bound %.1f m", x, y, llh[0],
          llh[1], llh[2], h, bound);
        result.Where = where;
      }
      result.WorstError = std::max(result.WorstError, error);
    }
  }
  if (!errors.empty())
  {
    std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
    result.MedianError = errors[errors.size() / 2];
  }
  std::printf("  terrain check: %d pixels, median |dh| %.2f m, worst %.1f m, worst/bound %.3f "
              "(%.3f with float (lon, lat)'s sampling term), %d beyond bound, %d NaN\n    worst at %s\n",
    result.Pixels, result.MedianError, result.WorstError, result.WorstRatio, result.WorstRatioFloat, result.Failures,
    result.NaNs, result.Where.c_str());
  return result;
}

/// The depth-reconstructed geodetic position (deg, deg, m) of every pixel, row 0 at the
/// bottom; NaN where nothing is drawn.
inline std::vector<std::array<double, 3>> GeodeticPixels(Scene& scene)
{
  const int* size = scene.Window->GetSize();
  const std::vector<float> depth = ReadDepth(scene.Window);
  std::vector<std::array<double, 3>> llh(depth.size(), { NAN, NAN, NAN });
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const size_t i = static_cast<size_t>(y) * size[0] + x;
      if (depth[i] < 1.0f)
      {
        double p[3];
        UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, depth[i], p);
        scene.Body->CartesianToGeodetic(p, llh[i].data());
      }
    }
  }
  return llh;
}

/// The world point (double) a texel of the G-buffer names, for the frame just rendered
/// (Documentation/rendering.md "Geodetic precision"). With HighPrecisionGeodetic (the default)
/// the texel holds the scaled-space direction's offset from the frame's local origin, the
/// sub-point -nadir (in double on the CPU); off, the float direction itself. The point is the
/// ellipsoid's along that direction, raised by the texel's height (w) along the geodetic normal
/// when `withHeight`.
inline void GBufferPoint(Scene& scene, const float texel[4], bool withHeight, double point[3])
{
  const double* nadir = scene.Mapper->GetProjectiveGrid()->GetNadir();
  const bool offsets = scene.Mapper->GetHighPrecisionGeodetic();
  const double* radii = scene.Body->GetRadii();
  double s[3], n = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    s[k] = (offsets ? -nadir[k] : 0.0) + static_cast<double>(texel[k]);
    n += s[k] * s[k];
  }
  for (int k = 0; k < 3; ++k)
  {
    point[k] = s[k] / std::sqrt(n) * radii[k];
  }
  if (withHeight)
  {
    double llh[3];
    scene.Body->CartesianToGeodeticQuiet(point, llh);
    llh[2] = texel[3];
    scene.Body->GeodeticToCartesianQuiet(llh, point);
  }
}

/**
 * A pixel's footprint as the screen pass takes it (vtkGlobeCompositeFS.glsl): per axis, the
 * change of (lon, lat) in degrees to the nearer (on the ground) of the two neighbours that are
 * covered; 0 where neither is. llh: GeodeticPixels' positions.
 */
inline void PixelFootprint(const int size[2], const std::vector<std::array<double, 3>>& llh, int x,
  int y, double footprint[4])
{
  const auto& here = llh[static_cast<size_t>(y) * size[0] + x];
  for (int axis = 0; axis < 2; ++axis)
  {
    double* d = footprint + 2 * axis;
    d[0] = d[1] = 0.0;
    double best = 1e300;
    for (int k : { -1, 1 })
    {
      const int a = x + (axis == 0 ? k : 0), b = y + (axis == 1 ? k : 0);
      if (a < 0 || b < 0 || a >= size[0] || b >= size[1])
      {
        continue;
      }
      const auto& o = llh[static_cast<size_t>(b) * size[0] + a];
      if (std::isnan(o[0]))
      {
        continue;
      }
      double dLon = k * (o[0] - here[0]);
      dLon -= 360.0 * std::floor(dLon / 360.0 + 0.5);
      const double dLat = k * (o[1] - here[1]);
      const double l = std::hypot(dLon * std::cos(here[1] * 3.14159265358979 / 180.0), dLat);
      if (l < best)
      {
        best = l;
        d[0] = dLon;
        d[1] = dLat;
      }
    }
  }
}

/**
 * The composed height at each pixel of GeodeticPixels' positions as the screen passes filter
 * it (vtkGlobeTerrain::PixelFootprint) at the pixel's footprint (PixelFootprint). NaN where
 * nothing is drawn.
 */
inline std::vector<double> PixelHeights(Scene& scene, const std::vector<vtkGlobeLayer*>& layers,
  const std::vector<std::array<double, 3>>& llh)
{
  const int* size = scene.Window->GetSize();
  std::vector<double> heights(llh.size(), NAN);
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const size_t i = static_cast<size_t>(y) * size[0] + x;
      if (std::isnan(llh[i][0]))
      {
        continue;
      }
      double footprint[4];
      PixelFootprint(size, llh, x, y, footprint);
      heights[i] = ComposedHeight(layers, llh[i][0], llh[i][1], footprint, vtkGlobeTerrain::PixelFootprint);
    }
  }
  return heights;
}

/// Counts pixels whose depth is not the background's.
inline int CoveredPixels(const std::vector<float>& depth)
{
  int n = 0;
  for (float d : depth)
  {
    n += d < 1.0f ? 1 : 0;
  }
  return n;
}
//------------------------------------------------------------------------------
// Hard cases (Documentation/depth.md, "Hard cases"): a scene run in each depth mode, checked
// for GL errors, NaN in every texel the globe wrote, and terrain within CheckTerrain's bound.

/// NaN values in a float buffer.
inline int CountNaN(const std::vector<float>& values)
{
  int n = 0;
  for (float v : values)
  {
    n += std::isnan(v) ? 1 : 0;
  }
  return n;
}

/// True when OpenGL reports no error (drains the error queue).
inline bool NoGLError()
{
  bool ok = true;
  while (glGetError() != GL_NO_ERROR)
  {
    ok = false;
  }
  return ok;
}

/// The ray's height over the composed terrain at eye distance s (m).
inline double RayHeightOverTerrain(vtkGlobeEllipsoid* body, const std::vector<vtkGlobeLayer*>& layers,
  const double eye[3], const double ray[3], double s)
{
  const double p[3] = { eye[0] + s * ray[0], eye[1] + s * ray[1], eye[2] + s * ray[2] };
  double llh[3];
  body->CartesianToGeodeticQuiet(p, llh);
  return llh[2] - ComposedHeight(layers, llh[0], llh[1]);
}

/// The exact ray/terrain intersection (double, the composed data): marched in steps of
/// `relativeStep` of the distance (at least `minimumStep` m), then bisected. -1 when none
/// within tMax.
inline double RayTerrainHit(vtkGlobeEllipsoid* body, const std::vector<vtkGlobeLayer*>& layers,
  const double eye[3], const double ray[3], double tMax, double minimumStep = 0.05,
  double relativeStep = 0.001)
{
  double previous = 0.0;
  for (double s = minimumStep; s < tMax; s += std::max(minimumStep, relativeStep * s))
  {
    if (RayHeightOverTerrain(body, layers, eye, ray, s) < 0.0)
    {
      double lo = previous, hi = s;
      for (int i = 0; i < 60; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (RayHeightOverTerrain(body, layers, eye, ray, mid) < 0.0 ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = s;
  }
  return -1.0;
}

/// Eye distance of a ray's first hit with a box (centre, unit axes as rows, half side), or -1.
inline double RayBoxHit(const double centre[3], const double axes[3][3], double half,
  const double eye[3], const double ray[3])
{
  double t0 = 0, t1 = 1e300;
  for (int a = 0; a < 3; ++a)
  {
    double p = 0, d = 0;
    for (int i = 0; i < 3; ++i)
    {
      p += (eye[i] - centre[i]) * axes[a][i];
      d += ray[i] * axes[a][i];
    }
    if (std::abs(d) < 1e-15)
    {
      if (std::abs(p) > half)
      {
        return -1;
      }
      continue;
    }
    double ta = (-half - p) / d, tb = (half - p) / d;
    if (ta > tb)
    {
      std::swap(ta, tb);
    }
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1 && t0 > 0 ? t0 : -1;
}

/// Eye distance of a ray's first hit with a sphere, or -1.
inline double RaySphereHit(const double centre[3], double radius, const double eye[3], const double ray[3])
{
  const double rel[3] = { eye[0] - centre[0], eye[1] - centre[1], eye[2] - centre[2] };
  const double b = rel[0] * ray[0] + rel[1] * ray[1] + rel[2] * ray[2];
  const double c = rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2] - radius * radius;
  const double disc = b * b - c;
  if (disc < 0)
  {
    return -1;
  }
  const double t = -b - std::sqrt(disc);
  return t > 0 ? t : -1;
}

/// What one hard-case frame gave.
struct HardCaseResult
{
  TerrainCheck Terrain;
  int DepthNaN = 0;          // in the window's depth buffer
  int GBufferNaN = 0;        // in the G-buffer (direction, height) and its depth
  int GridNaN = 0;           // in the PGM textures (direction, position, height)
  bool GLOk = true;
  double Nearest = 0.0;      // nearest and farthest depth-reconstructed terrain (m from the eye)
  double Farthest = 0.0;
  double NearPlane = 0.0, FarPlane = 0.0;
};

/**
 * Checks the frame just rendered: no GL error; no NaN in the window's depth, the globe's
 * G-buffer and its PGM textures; the terrain from depth (read in the pass's mode) within
 * CheckTerrain's bound. Prints one line per mode with the clipping range, the nearest and
 * farthest terrain distances and the worst error / bound.
 */
inline HardCaseResult CheckHardCase(Scene& scene, vtkGlobeDepthPass* pass, int stride)
{
  HardCaseResult r;
  r.GLOk = NoGLError();
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->GetClippingRange(r.NearPlane, r.FarPlane);
  const std::vector<float> depth = ReadDepth(scene.Window);
  r.DepthNaN = CountNaN(depth);
  if (vtkTextureObject* g = vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper))
  {
    r.GBufferNaN += CountNaN(ReadTexture(g));
  }
  if (vtkTextureObject* g = vtkGlobeMapperTesting::GetGBufferDepthTexture(scene.Mapper))
  {
    r.GBufferNaN += CountNaN(ReadTexture(g));
  }
  vtkGlobeGridPass* grid = scene.Mapper->GetGridPass();
  for (vtkTextureObject* t :
    { grid->GetDirectionTexture(), grid->GetPositionTexture(), grid->GetHeightTexture() })
  {
    r.GridNaN += t ? CountNaN(ReadTexture(t)) : 0;
  }
  r.GLOk = NoGLError() && r.GLOk;
  const int* size = scene.Window->GetSize();
  const double* eye = camera->GetPosition();
  r.Nearest = 1e300;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      const float d = depth[static_cast<size_t>(y) * size[0] + x];
      if (d < 1.0f)
      {
        double p[3];
        UnprojectPixel(scene.Renderer, x + 0.5, y + 0.5, pass->GetPerspectiveDepth(d, camera), p);
        const double t = std::sqrt((p[0] - eye[0]) * (p[0] - eye[0]) +
          (p[1] - eye[1]) * (p[1] - eye[1]) + (p[2] - eye[2]) * (p[2] - eye[2]));
        r.Nearest = std::min(r.Nearest, t);
        r.Farthest = std::max(r.Farthest, t);
      }
    }
  }
  if (stride > 0) // 0: no terrain check (scenes whose depth is not the terrain's)
  {
    r.Terrain = CheckTerrain(scene, stride, pass);
  }
  std::printf("  %-11s clip [%.4g, %.4g] m, terrain seen %.4g .. %.4g m: worst/bound %.3f "
              "(worst %.3g m), NaN: depth %d, G-buffer %d, grid %d; GL %s\n",
    vtkGlobeDepthPass::GetModeAsString(pass->GetMode()), r.NearPlane, r.FarPlane,
    r.Nearest < 1e299 ? r.Nearest : 0.0, r.Farthest, r.Terrain.WorstRatio, r.Terrain.WorstError,
    r.DepthNaN, r.GBufferNaN, r.GridNaN, r.GLOk ? "ok" : "ERROR");
  return r;
}

/// The usual verdict of a hard case: GL clean, no NaN anywhere, every checked pixel within
/// its bound, at least `minimumPixels` checked.
inline bool HardCasePassed(const HardCaseResult& r, int minimumPixels)
{
  return r.GLOk && r.DepthNaN == 0 && r.GBufferNaN == 0 && r.GridNaN == 0 &&
    r.Terrain.NaNs == 0 && r.Terrain.Failures == 0 && r.Terrain.Pixels >= minimumPixels;
}

/// A depth pass in a mode, set on the scene's renderer with the clipping policy installed.
inline vtkSmartPointer<vtkGlobeDepthPass> UseDepthMode(Scene& scene, int mode)
{
  auto pass = vtkSmartPointer<vtkGlobeDepthPass>::New();
  pass->SetMode(mode);
  scene.Renderer->SetPass(pass);
  vtkGlobeClippingRange::Install(scene.Renderer);
  return pass;
}
/// Wrong-surface pixels of an object in front of or behind terrain (see CountWrongSurface).
struct SurfaceCount
{
  int Checked = 0;  // object pixels off its silhouette and clear of a terrain crossing
  int Wrong = 0;    // where the drawn surface (object or not) is not the exact nearest one
  int Hidden = 0;   // checked pixels where terrain is nearer than the object
  int Grazing = 0;  // left out: the ray passes the terrain within the margin before the object
};

/**
 * For every pixel whose exact ray (double) meets an object (`hit`: eye distance or -1) and
 * whose 3x3 neighbours do too: is terrain nearer along the ray (the composed data marched in
 * steps of `relativeStep` of the distance, at least `minimumStep`), judged against
 * `margin(s)`, what the PGM mesh may deviate at distance s? A ray that passes within the
 * margin is left out (too close to call); otherwise the drawn colour (`isObject`) must agree.
 */
inline SurfaceCount CountWrongSurface(Scene& scene,
  const std::function<double(const double*, const double*)>& hit,
  const std::function<bool(const unsigned char*)>& isObject,
  const std::function<double(double)>& margin, double minimumStep, double relativeStep)
{
  SurfaceCount count;
  const int* size = scene.Window->GetSize();
  const double* eye = scene.Renderer->GetActiveCamera()->GetPosition();
  const std::vector<vtkGlobeLayer*> layers = HeightLayers(scene.Mapper);
  vtkNew<vtkUnsignedCharArray> rgb;
  scene.Window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb);
  std::vector<double> distance(static_cast<size_t>(size[0]) * size[1], -1.0);
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = 0; x < size[0]; ++x)
    {
      double ray[3];
      PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      distance[static_cast<size_t>(y) * size[0] + x] = hit(eye, ray);
    }
  }
  for (int y = 1; y + 1 < size[1]; ++y)
  {
    for (int x = 1; x + 1 < size[0]; ++x)
    {
      const size_t at = static_cast<size_t>(y) * size[0] + x;
      const double t = distance[at];
      bool inside = t > 0;
      for (int j = -1; j <= 1 && inside; ++j)
      {
        for (int i = -1; i <= 1 && inside; ++i)
        {
          inside = distance[at + j * size[0] + i] > 0;
        }
      }
      if (!inside)
      {
        continue;
      }
      double ray[3];
      PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      double lowest = 1e300;
      for (double s = minimumStep;; s = std::min(t, s + std::max(minimumStep, relativeStep * s)))
      {
        lowest = std::min(lowest, RayHeightOverTerrain(scene.Body, layers, eye, ray, s) / margin(s));
        if (s >= t || lowest < -1.0)
        {
          break;
        }
      }
      if (std::abs(lowest) < 1.0)
      {
        ++count.Grazing;
        continue;
      }
      const bool objectInFront = lowest > 0;
      const bool objectDrawn = isObject(rgb->GetPointer(3 * static_cast<vtkIdType>(at)));
      ++count.Checked;
      count.Hidden += objectInFront ? 0 : 1;
      count.Wrong += objectInFront != objectDrawn ? 1 : 0;
      if (objectInFront != objectDrawn && std::getenv("VTKGLOBE_TEST_VERBOSE"))
      {
        std::printf("    wrong: pixel (%d, %d) at %.0f m, clearance/margin %.2f\n", x, y, t, lowest);
      }
    }
  }
  return count;
}

/// A flat-coloured actor (ambient only) for a source.
inline vtkSmartPointer<vtkActor> FlatActor(vtkPolyDataAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

/// The highest point of the composed data near (lon, lat), refined to 1e-5 degree: the summit
/// of the bilinear posts. Returns its height; lon and lat move to it.
inline double ComposedSummit(const std::vector<vtkGlobeLayer*>& layers, double& lon, double& lat)
{
  double ground = -1e300;
  for (double step : { 1e-3, 1e-4, 1e-5 })
  {
    const double lon0 = lon, lat0 = lat;
    for (int i = -10; i <= 10; ++i)
    {
      for (int j = -10; j <= 10; ++j)
      {
        const double g = ComposedHeight(layers, lon0 + i * step, lat0 + j * step);
        if (g > ground)
        {
          ground = g;
          lon = lon0 + i * step;
          lat = lat0 + j * step;
        }
      }
    }
  }
  return ground;
}

/// Points the camera from a world position along a direction, with an up vector.
inline void LookAlong(vtkRenderer* renderer, const double eye[3], const double direction[3],
  const double up[3], double viewAngle)
{
  vtkCamera* c = renderer->GetActiveCamera();
  c->SetPosition(eye);
  c->SetFocalPoint(eye[0] + direction[0], eye[1] + direction[1], eye[2] + direction[2]);
  c->SetViewUp(up);
  c->SetViewAngle(viewAngle);
  c->OrthogonalizeViewUp();
}
} // namespace vtkGlobeTest

#endif
