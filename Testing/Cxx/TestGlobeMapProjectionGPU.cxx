// globe_projection.glsl on the GPU: the embedded text compiles in a real fragment shader
// (with every projection function called), and, rendered into a float texture for 256 points
// per raster (14 rasters, every family), its texture coordinates agree with GeographicLib within 0.01 source pixel
// (rasters 16384 px on the long side) and with the float C++ mirror. This is what shows that
// the driver (Mesa llvmpipe here) evaluates the common-subset text as the mirror does.
#include "globe_projection.h"
#include "vtkGlobeMapProjection.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkGlobeShaderMath.h"
#include "vtkGlobeTestHelpers.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTestErrorObserver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace
{
constexpr double Deg = 3.14159265358979323846 / 180.0;
constexpr int Side = 16; // 256 points per raster

const char* MainFS = R"(
in vec2 texCoord;
uniform sampler2D globeInput;
uniform vec4 globeProjection[7];
uniform int globeKind;
void main()
{
  vec4 ll = texelFetch(globeInput, ivec2(floor(texCoord * 16.0)), 0);
  vec2 uv;
  if (globeKind == 0)
    uv = globe_projectEquirectangular(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 1)
    uv = globe_projectMercator(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 2)
    uv = globe_projectPolarStereographic(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 3)
    uv = globe_projectTransverseMercator(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 4)
    uv = globe_projectConformalConic(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 5)
    uv = globe_projectAlbersEqualArea(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 8)
    uv = globe_projectObliqueAzimuthalEqualArea(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else if (globeKind == 7)
    uv = globe_projectSinusoidal(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  else
    uv = globe_projectCylindricalEqualArea(ll.x, ll.y, ll.z, ll.w, globeProjection[0], globeProjection[1],
      globeProjection[2], globeProjection[3], globeProjection[4], globeProjection[5], globeProjection[6]);
  gl_FragData[0] = vec4(uv, 0.0, 1.0);
}
)";

struct Case
{
  const char* Name;
  int Code; // an EPSG code; 0: MODIS's sinusoidal grid (a PROJ string)
  double West, East, South, North; // geographic box, or map box for polar (MapBox)
  bool MapBox;
};

namespace F = vtkGlobeShaderMath::f;

int ShaderKind(vtkGlobeMapProjection* p)
{
  if (std::string(p->GetShaderFunctionName()) == "globe_projectObliqueAzimuthalEqualArea")
  {
    return 8;
  }
  switch (p->GetKind())
  {
    case vtkGlobeMapProjection::Mercator:
    case vtkGlobeMapProjection::WebMercator:
      return 1;
    case vtkGlobeMapProjection::PolarStereographic:
      return 2;
    case vtkGlobeMapProjection::TransverseMercator:
      return 3;
    case vtkGlobeMapProjection::LambertConformalConic:
      return 4;
    case vtkGlobeMapProjection::AlbersEqualArea:
    case vtkGlobeMapProjection::LambertAzimuthalEqualArea:
      return 5;
    case vtkGlobeMapProjection::CylindricalEqualArea:
      return 6;
    case vtkGlobeMapProjection::Sinusoidal:
      return 7;
    default:
      return 0;
  }
}

F::vec2 Mirror(int kind, const float in[4], const float* pf)
{
  F::vec4 v[7];
  for (int i = 0; i < 7; ++i)
  {
    v[i] = F::vec4(pf[4 * i], pf[4 * i + 1], pf[4 * i + 2], pf[4 * i + 3]);
  }
  switch (kind)
  {
    case 1:
      return F::globe_projectMercator(in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 2:
      return F::globe_projectPolarStereographic(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 3:
      return F::globe_projectTransverseMercator(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 4:
      return F::globe_projectConformalConic(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 5:
      return F::globe_projectAlbersEqualArea(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 6:
      return F::globe_projectCylindricalEqualArea(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 8:
      return F::globe_projectObliqueAzimuthalEqualArea(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    case 7:
      return F::globe_projectSinusoidal(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    default:
      return F::globe_projectEquirectangular(
        in[0], in[1], in[2], in[3], v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
  }
}
} // namespace

int TestGlobeMapProjectionGPU(int, char*[])
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  window->AddRenderer(renderer);
  window->Render();
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    std::printf("FAIL: no OpenGL render window\n");
    return 1;
  }
  gl->MakeCurrent();

  const std::string fs = std::string("//VTK::System::Dec\n//VTK::Output::Dec\n"
                                     "#define GLOBE_OUT(T) out T\n") +
    globe_projection + MainFS;
  const std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
  vtkOpenGLQuadHelper quad(gl, vs.c_str(), fs.c_str(), "");
  const bool compiled = quad.Program && quad.Program->GetCompiled();
  std::string info = gl->ReportCapabilities();
  const size_t at = info.find("OpenGL renderer string:");
  const std::string rendererName = at == std::string::npos ? "unknown renderer"
                                     : info.substr(at, info.find('\n', at) - at);
  std::printf("  %-4s globe_projection.glsl compiles and links in a fragment shader (%s)\n",
    compiled ? "ok" : "FAIL", rendererName.c_str());
  if (!compiled)
  {
    return 1;
  }

  vtkNew<vtkTextureObject> input;
  input->SetContext(gl);
  vtkNew<vtkTextureObject> output;
  output->SetContext(gl);
  output->SetMinificationFilter(vtkTextureObject::Nearest);
  output->SetMagnificationFilter(vtkTextureObject::Nearest);
  output->Allocate2D(Side, Side, 4, VTK_FLOAT);
  vtkNew<vtkOpenGLFramebufferObject> fbo;
  fbo->SetContext(gl);

  const Case cases[] = {
    { "EPSG:4326 0.1 deg at 179.99, -80", 4326, 179.94, 180.04, -80.05, -79.95, false },
    { "EPSG:4326 global 0..360", 4326, 0.0, 360.0, -90.0, 90.0, false },
    { "EPSG:3395 +-85", 3395, -180.0, 180.0, -85.0, 85.0, false },
    { "EPSG:3395 0.1 deg at -179.99, -80", 3395, -180.04, -179.94, -80.05, -79.95, false },
    { "EPSG:3857 0.1 deg at 179.99, 85", 3857, 179.94, 180.04, 84.95, 85.04, false },
    { "EPSG:3413 cap to 50N", 3413, -4.9e6, 4.9e6, -4.9e6, 4.9e6, true },
    { "EPSG:3031 11 km around the pole", 3031, -5550.0, 5550.0, -5550.0, 5550.0, true },
    { "UTM 31N full zone", 32631, -0.5, 6.5, 0.0, 84.0, false },
    { "UTM 60S 1 deg at 179.99, 80S", 32760, 179.49, 180.49, -80.5, -79.5, false },
    { "EPSG:2154 France (Lambert conformal conic)", 2154, -5.5, 10.0, 41.0, 51.5, false },
    { "EPSG:3577 Australia (Albers)", 3577, 112.0, 154.0, -44.0, -10.0, false },
    { "EPSG:6931 11 km around the pole (Lambert azimuthal)", 6931, -5550.0, 5550.0, -5550.0,
      5550.0, true },
    { "EPSG:3035 Europe (oblique Lambert azimuthal)", 3035, -30.0, 45.0, 25.0, 84.0, false },
    { "EPSG:6933 global (cylindrical equal-area)", 6933, -180.0, 180.0, -90.0, 90.0, false },
    { "MODIS tile h35v09, across the cut (sinusoidal)", 0, 18903158.83, 20015109.35, -1111950.52,
      0.0, true },
  };

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkGlobeTest::Worst gpuRef("GPU vs GeographicLib (all rasters)", "px");
  vtkGlobeTest::Worst gpuMirror("GPU vs float C++ mirror (all rasters)", "px");
  bool ok = true;
  vtkOpenGLState* state = gl->GetState();
  for (const Case& c : cases)
  {
    vtkNew<vtkGlobeMapProjection> p;
    if (c.Code == 0)
    {
      p->SetFromDefinition("+proj=sinu +lon_0=0 +x_0=0 +y_0=0 +R=6371007.181 +units=m +type=crs");
    }
    else
    {
      p->SetFromEPSG(c.Code);
    }
    p->SetLongitudeWest(c.MapBox ? -180.0 : 0.5 * (c.West + c.East) - 180.0);
    double box[4] = { c.West, c.East, c.South, c.North };
    if (!c.MapBox)
    {
      // Map box: cylindrical kinds are linear in longitude; UTM is sampled.
      box[0] = box[2] = 1e300;
      box[1] = box[3] = -1e300;
      for (int i = 0; i <= 200; ++i)
      {
        for (int j = 0; j <= 200; ++j)
        {
          double xy[2];
          p->Forward(c.West + (c.East - c.West) * i / 200.0 * (i == 200 ? 0.999999999 : 1.0),
            c.South + (c.North - c.South) * j / 200.0, xy);
          box[0] = std::min(box[0], xy[0]);
          box[1] = std::max(box[1], xy[0]);
          box[2] = std::min(box[2], xy[1]);
          box[3] = std::max(box[3], xy[1]);
        }
      }
    }
    const double mapW = box[1] - box[0], mapH = box[3] - box[2];
    const double px = std::max(mapW, mapH) / 16384.0;
    const int width = std::max(1, static_cast<int>(std::lround(mapW / px)));
    const int height = std::max(1, static_cast<int>(std::lround(mapH / px)));
    const double origin[2] = { box[0], box[3] };
    const double pixel[2] = { mapW / width, mapH / height };
    float pf[28];
    p->ComputeShaderParameters(origin, pixel, width, height, pf);

    // 256 points in the raster, hi + lo pairs.
    std::vector<float> in(Side * Side * 4);
    std::vector<double> refCol(Side * Side), refRow(Side * Side);
    for (int k = 0; k < Side * Side; ++k)
    {
      double lonLat[2] = { 0.0, 0.0 }, xy[2];
      do
      {
        p->Inverse(origin[0] + unit(rng) * mapW, origin[1] - unit(rng) * mapH, lonLat);
      } while (!p->IsInValidDomain(lonLat[0], lonLat[1]));
      const float lonHi = static_cast<float>(lonLat[0] * Deg);
      const float latHi = static_cast<float>(lonLat[1] * Deg);
      const float lonLo = static_cast<float>(lonLat[0] * Deg - lonHi);
      const float latLo = static_cast<float>(lonLat[1] * Deg - latHi);
      in[4 * k] = lonHi;
      in[4 * k + 1] = lonLo;
      in[4 * k + 2] = latHi;
      in[4 * k + 3] = latLo;
      p->Forward((static_cast<double>(lonHi) + lonLo) / Deg,
        std::max(-90.0, std::min(90.0, (static_cast<double>(latHi) + latLo) / Deg)), xy);
      refCol[k] = (xy[0] - origin[0]) / pixel[0];
      refRow[k] = (origin[1] - xy[1]) / pixel[1];
    }
    input->Create2DFromRaw(Side, Side, 4, VTK_FLOAT, in.data());
    input->SetMinificationFilter(vtkTextureObject::Nearest);
    input->SetMagnificationFilter(vtkTextureObject::Nearest);

    state->PushFramebufferBindings();
    fbo->Bind();
    fbo->AddColorAttachment(0, output);
    fbo->ActivateDrawBuffers(1);
    state->vtkglViewport(0, 0, Side, Side);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_DEPTH_TEST);
    gl->GetShaderCache()->ReadyShaderProgram(quad.Program);
    input->Activate();
    quad.Program->SetUniformi("globeInput", input->GetTextureUnit());
    quad.Program->SetUniformi("globeKind", ShaderKind(p));
    quad.Program->SetUniform4fv("globeProjection", 7, reinterpret_cast<const float(*)[4]>(pf));
    quad.Render();
    input->Deactivate();
    fbo->RemoveColorAttachments(1);
    state->PopFramebufferBindings();
    const std::vector<float> uv = vtkGlobeTest::ReadTexture(output);

    vtkGlobeTest::Worst ref(std::string(c.Name) + " GPU vs GeographicLib", "px");
    vtkGlobeTest::Worst mir(std::string(c.Name) + " GPU vs C++ mirror", "px");
    for (int k = 0; k < Side * Side; ++k)
    {
      const float u = uv[4 * k], v = uv[4 * k + 1];
      const std::string where = vtkGlobeTest::Format(
        "lon %.10g lat %.10g", (in[4 * k] + static_cast<double>(in[4 * k + 1])) / Deg,
        (in[4 * k + 2] + static_cast<double>(in[4 * k + 3])) / Deg, 0.0);
      double du = std::abs(u * width - refCol[k]);
      if (c.East - c.West >= 360.0)
      {
        du = std::min(du, std::abs(du - width)); // the seam of a whole-period raster
      }
      const double e = std::max(du, std::abs(v * height - refRow[k]));
      ref.Add(e, where);
      gpuRef.Add(e, std::string(c.Name) + ", " + where);
      const F::vec2 m = Mirror(ShaderKind(p), &in[4 * k], pf);
      const double em = std::max(std::abs((u - m.x) * width), std::abs((v - m.y) * height));
      mir.Add(em, where);
      gpuMirror.Add(em, std::string(c.Name) + ", " + where);
    }
    ok = ref.Check(0.01) && ok;
    ok = mir.Check(0.01) && ok;
  }
  std::printf("Summary:\n");
  ok = gpuRef.Check(0.01) && ok;
  ok = gpuMirror.Check(0.01) && ok;
  return ok ? 0 : 1;
}
