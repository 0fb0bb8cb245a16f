// Sub-pixel jitter (issue 5, Documentation/depth.md "Jitter"): Cozzi's scene, a point at
// (6378137, 0, 0) (the look-at target and the local origin; a rasterized point lands on whole
// pixels and cannot be read to 0.05 px, the triangles around it are) and two 2 m triangles
// 1 m apart in the plane x = 6378137, over a flat WGS84
// terrain (a global height layer of -0.5 m, so the terrain is the plane's neighbour without
// z-fighting it), seen from 1 m, 10 m and 800 m at 45 degrees elevation. The camera then moves
// sideways by 0.05 .. 0.5 px (10 steps); in every pose and in both depth modes:
//  - companion (the triangles, vertices in world coordinates): a vtkValuePass renders each
//    pixel's local plane coordinates (m from the point, float); the world point a pixel shows,
//    projected by the camera in double, must land on that pixel's centre within 0.05 px
//    (worst over every covered pixel and pose), and the image of the triangle centroids must
//    move as the analytic projection says (jitter: pose k minus pose 0) within 0.05 px. Run
//    with the VBO shift/scale methods: AUTO_SHIFT_SCALE (VTK's default) is exact for this
//    compact actor, DISABLE_SHIFT_SCALE must jitter (float products of 6.4e6 m in the vertex
//    shader). The same triangles in one polydata with a third triangle 2,000 km away (an
//    extended actor: AUTO's shift is the bounds' centre, 1,000 km off) jitter with AUTO and are
//    exact with FOCAL_POINT_SHIFT_SCALE.
//  - globe: every third covered pixel's depth-reconstructed point (double, in the pass's mode)
//    against the exact double ray/terrain hit: |dt| / pixel footprint within 0.05 px (an upper
//    bound of the image shift a surface error along the ray causes); and the point the G-buffer
//    names (the direction's offset from the frame's local origin + height, decoded in double,
//    Documentation/rendering.md "Geodetic precision"), projected by the camera in double, on
//    that pixel's centre within 0.05 px: the texture slip inside the surface, which depth cannot
//    see.
//  - the globe alone, looked at from 1 cm, 1 m, 10 m and 800 m away from a point of its
//    terrain, 45 degrees up (7.1 mm .. 566 m above it; the Cozzi scene's "1 m" is 1.2 m from
//    the terrain below the plane), at (0, 0) and at (179.99 E, 80 N),
//    where a float unit direction has 0.4 m steps: within 0.05 px with HighPrecisionGeodetic on,
//    more than 1 px off at the far place with it off (at (0, 0) the float direction (1, y, z) is
//    exact to first order, so the option changes nothing there).
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkGlobeRenderingTestHelpers.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderStepsPass.h"
#include "vtkValuePass.h"

namespace
{
const double R = 6378137.0;
const double TerrainHeight = -0.5;

/// Cozzi's triangles (and, when `wide`, a third one 2,000 km north on the ellipsoid), with
/// point scalars "local" = (y, z) in metres relative to the point (6378137, 0, 0).
vtkSmartPointer<vtkPolyData> Triangles(bool wide)
{
  const double yz[6][2] = { { -2.5, -1.0 }, { -0.5, -1.0 }, { -1.5, 1.0 }, { 0.5, -1.0 },
    { 2.5, -1.0 }, { 1.5, 1.0 } };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> local;
  local->SetName("local");
  local->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> polys;
  for (int t = 0; t < 2; ++t)
  {
    const vtkIdType ids[3] = { 3 * t, 3 * t + 1, 3 * t + 2 };
    for (int k = 0; k < 3; ++k)
    {
      points->InsertNextPoint(R, yz[3 * t + k][0], yz[3 * t + k][1]);
      local->InsertNextTuple2(yz[3 * t + k][0], yz[3 * t + k][1]);
    }
    polys->InsertNextCell(3, ids);
  }
  if (wide)
  {
    const double z = 2.0e6, x = std::sqrt(R * R - z * z);
    const vtkIdType ids[3] = { 6, 7, 8 };
    const double corners[3][2] = { { 0, 0 }, { 10, 0 }, { 0, 10 } };
    for (const auto& p : corners)
    {
      points->InsertNextPoint(x, p[0], z + p[1]);
      local->InsertNextTuple2(p[0], z + p[1]);
    }
    polys->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  data->GetPointData()->AddArray(local);
  return data;
}

/// World -> display (pixels, origin at the window's lower-left corner) in double.
struct Projector
{
  double M[16];
  double W, H;
  Projector(vtkRenderer* renderer)
  {
    const int* size = renderer->GetRenderWindow()->GetSize();
    W = size[0];
    H = size[1];
    vtkMatrix4x4* m =
      renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(W / H, -1, 1);
    std::copy(&m->Element[0][0], &m->Element[0][0] + 16, M);
  }
  void operator()(const double p[3], double d[2]) const
  {
    double c[4];
    for (int i = 0; i < 4; ++i)
    {
      c[i] = M[4 * i] * p[0] + M[4 * i + 1] * p[1] + M[4 * i + 2] * p[2] + M[4 * i + 3];
    }
    d[0] = (c[0] / c[3] + 1.0) * 0.5 * W;
    d[1] = (c[1] / c[3] + 1.0) * 0.5 * H;
  }
};

/// Exact eye distance along a ray to the surface of constant geodetic height h (Newton on the
/// geodetic height, in double, from the hit with the ellipsoid grown by h).
double RayHeightHit(vtkGlobeEllipsoid* body, const double eye[3], const double ray[3], double h)
{
  const double* r = body->GetRadii();
  double a = 0, b = 0, c = -1;
  for (int i = 0; i < 3; ++i)
  {
    const double s = 1.0 / ((r[i] + h) * (r[i] + h));
    a += ray[i] * ray[i] * s;
    b += 2.0 * eye[i] * ray[i] * s;
    c += eye[i] * eye[i] * s;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0)
  {
    return -1;
  }
  double t = (-b - std::sqrt(disc)) / (2 * a);
  for (int it = 0; it < 8; ++it)
  {
    auto height = [&](double s) {
      const double p[3] = { eye[0] + s * ray[0], eye[1] + s * ray[1], eye[2] + s * ray[2] };
      double llh[3];
      body->CartesianToGeodeticQuiet(p, llh);
      return llh[2] - h;
    };
    const double f = height(t), step = std::max(1e-6, 1e-6 * t);
    const double df = (height(t + step) - height(t - step)) / (2 * step);
    if (df == 0)
    {
      break;
    }
    t -= f / df;
  }
  return t;
}

struct Stats
{
  double Worst = 0;  // px, over every checked pixel and pose
  double Jitter = 0; // px, centroid image motion against the analytic one
  int Pixels = 0;
  int NaN = 0;
  void Merge(const Stats& o)
  {
    Worst = std::max(Worst, o.Worst);
    Jitter = std::max(Jitter, o.Jitter);
    Pixels += o.Pixels;
    NaN += o.NaN;
  }
};

/// The globe's measures over the poses of one distance.
struct GlobeStats
{
  double Depth = 0;      // px: |dt| / footprint, worst
  double Slip = 0;       // px: G-buffer point against the pixel centre, worst
  double SlipMedian = 0; // px: the largest per-pose median
  double SlipAt[3] = { 0, 0, 0 }; // the worst slip's pixel and its distance (m)
  int Pixels = 0;
  int NaN = 0;
};

/// Camera `D` m from `target` at 45 degrees elevation and 30 degrees azimuth east of north in
/// the local frame (east, north, up) (no matrix entry is trivial), moved sideways by k * 0.05 px
/// (at the target's distance), 30 degrees up from the screen's x axis. Returns the eye.
void Pose(vtkCamera* camera, const double target[3], const double east[3], const double north[3],
  const double up[3], double D, double viewAngle, double footprint, int k, double eye[3])
{
  const double el = vtkMath::RadiansFromDegrees(45.0), az = vtkMath::RadiansFromDegrees(30.0);
  double eye0[3];
  for (int i = 0; i < 3; ++i)
  {
    eye0[i] = target[i] +
      D * (std::cos(el) * (std::sin(az) * east[i] + std::cos(az) * north[i]) + std::sin(el) * up[i]);
  }
  camera->SetPosition(eye0);
  camera->SetFocalPoint(target);
  camera->SetViewUp(up);
  camera->SetViewAngle(viewAngle);
  camera->OrthogonalizeViewUp();
  double right[3], vup[3], dop[3];
  camera->GetViewUp(vup);
  camera->GetDirectionOfProjection(dop);
  vtkMath::Cross(dop, vup, right);
  const double shift = 0.05 * k * footprint;
  double focus[3];
  for (int i = 0; i < 3; ++i)
  {
    const double s = shift * (std::cos(0.5236) * right[i] + std::sin(0.5236) * vup[i]);
    eye[i] = eye0[i] + s;
    focus[i] = target[i] + s;
  }
  camera->SetPosition(eye);
  camera->SetFocalPoint(focus);
}

/// The globe in the frame just rendered, every third pixel: the depth-reconstructed point
/// against the exact ray/terrain hit, and the G-buffer's point against the pixel centre.
void MeasureGlobe(vtkGlobeTest::Scene& scene, vtkGlobeDepthPass* pass, const double eye[3],
  double footprint, double D, GlobeStats& st)
{
  const int* size = scene.Window->GetSize();
  const int W = size[0], H = size[1];
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  const Projector project(scene.Renderer);
  const std::vector<float> depth = vtkGlobeTest::ReadDepth(scene.Window);
  const std::vector<float> gbuffer = vtkGlobeTest::ReadTexture(vtkGlobeMapperTesting::GetGBufferTexture(scene.Mapper));
  std::vector<double> slips;
  for (int y = 1; y < H; y += 3)
  {
    for (int x = 1; x < W; x += 3)
    {
      const size_t at = static_cast<size_t>(y) * W + x;
      if (std::isnan(depth[at]))
      {
        ++st.NaN;
        continue;
      }
      if (!(depth[at] < 1.0f))
      {
        continue;
      }
      double p[3], ray[3];
      vtkGlobeTest::UnprojectPixel(
        scene.Renderer, x + 0.5, y + 0.5, pass->GetPerspectiveDepth(depth[at], camera), p);
      vtkGlobeTest::PixelRay(scene.Renderer, x + 0.5, y + 0.5, ray);
      const double t = RayHeightHit(scene.Body, eye, ray, TerrainHeight);
      const double drawn = std::sqrt(vtkMath::Distance2BetweenPoints(p, eye));
      st.Depth = std::max(st.Depth, std::abs(drawn - t) / (t * footprint / D));
      ++st.Pixels;
      double g[3], d[2];
      vtkGlobeTest::GBufferPoint(scene, &gbuffer[4 * at], true, g);
      project(g, d);
      slips.push_back(std::hypot(d[0] - x - 0.5, d[1] - y - 0.5));
      if (slips.back() > st.Slip)
      {
        st.Slip = slips.back();
        st.SlipAt[0] = x;
        st.SlipAt[1] = y;
        st.SlipAt[2] = t;
      }
    }
  }
  if (!slips.empty())
  {
    std::sort(slips.begin(), slips.end());
    st.SlipMedian = std::max(st.SlipMedian, slips[slips.size() / 2]);
  }
}
}

int TestGlobeJitter(int, char*[])
{
  bool ok = true;
  vtkGlobeTest::Scene scene(300, 225, 256);
  {
    std::vector<float> flat(36 * 18, static_cast<float>(TerrainHeight));
    vtkNew<vtkGlobeLayer> terrain;
    terrain->SetHeightData(36, 18, flat.data(), -180, 180, -90, 90);
    scene.Mapper->AddLayer(terrain);
  }
  vtkGlobeEllipsoid* body = scene.Body;
  const double target[3] = { R, 0, 0 };
  double east[3], north[3], up[3];
  body->ComputeEastNorthUp(0, 0, east, north, up);

  // Companions: Cozzi's two triangles (AUTO, DISABLE), and with a far triangle (AUTO, FOCAL).
  struct Companion
  {
    const char* Name;
    bool Wide;
    int Method;
    bool Exact; // expected within 0.05 px
    vtkSmartPointer<vtkActor> Actor;
  };
  std::vector<Companion> companions = {
    { "triangles, AUTO_SHIFT_SCALE", false, vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE, true, nullptr },
    { "triangles, DISABLE_SHIFT_SCALE", false, vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE, false, nullptr },
    { "+ far triangle, AUTO_SHIFT_SCALE", true, vtkOpenGLVertexBufferObject::AUTO_SHIFT_SCALE, false, nullptr },
    { "+ far triangle, FOCAL_POINT_SHIFT_SCALE", true, vtkOpenGLVertexBufferObject::FOCAL_POINT_SHIFT_SCALE, true, nullptr },
  };
  for (Companion& c : companions)
  {
    vtkNew<vtkOpenGLPolyDataMapper> mapper;
    mapper->SetInputData(Triangles(c.Wide));
    mapper->SetVBOShiftScaleMethod(c.Method);
    mapper->SetScalarVisibility(false);
    c.Actor = vtkSmartPointer<vtkActor>::New();
    c.Actor->SetMapper(mapper);
    c.Actor->VisibilityOff();
    scene.Renderer->AddActor(c.Actor);
  }

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkValuePass> value;
  value->SetInputArrayToProcess(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA, "local");
  // Centroids of the two triangles (local y, z): where the jitter is read.
  const double centroids[2][2] = { { -1.5, -1.0 / 3.0 }, { 1.5, -1.0 / 3.0 } };

  const int W = 300, H = 225;
  const double distances[3] = { 1.0, 10.0, 800.0 };
  const double viewAngles[3] = { 90.0, 30.0, 1.0 }; // the 5 m scene spans 1/3 .. 2/3 of the width
  for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
  {
    auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
    for (int di = 0; di < 3; ++di)
    {
      const double D = distances[di];
      const double footprint = 2.0 * D * std::tan(vtkMath::RadiansFromDegrees(viewAngles[di]) / 2) / H;
      std::vector<Stats> companionStats(companions.size());
      GlobeStats globeStats;
      std::vector<std::array<double, 2>> centroid0(companions.size() * 2);
      for (int k = 0; k <= 10; ++k)
      {
        vtkCamera* camera = scene.Renderer->GetActiveCamera();
        double eye[3];
        Pose(camera, target, east, north, up, D, viewAngles[di], footprint, k, eye);

        // Globe alone.
        for (Companion& c : companions)
        {
          c.Actor->VisibilityOff();
        }
        pass->SetDelegatePass(steps);
        scene.Renderer->ResetCameraClippingRange();
        scene.Render();
        const Projector project(scene.Renderer);
        MeasureGlobe(scene, pass, eye, footprint, D, globeStats);

        // Each companion alone through the value pass (local y, then z).
        pass->SetDelegatePass(value);
        for (size_t ci = 0; ci < companions.size(); ++ci)
        {
          Companion& c = companions[ci];
          c.Actor->VisibilityOn();
          std::vector<float> local[2];
          for (int comp = 0; comp < 2; ++comp)
          {
            value->SetInputComponentToProcess(comp);
            scene.Renderer->ResetCameraClippingRange();
            scene.Window->Render();
            vtkFloatArray* values = value->GetFloatImageDataArray(scene.Renderer);
            local[comp].assign(values->GetPointer(0), values->GetPointer(0) + W * H);
          }
          c.Actor->VisibilityOff();
          Stats& st = companionStats[ci];
          // Mean error vector near each centroid's analytic image.
          double sum[2][3] = { { 0, 0, 0 }, { 0, 0, 0 } };
          double cImage[2][2];
          for (int m = 0; m < 2; ++m)
          {
            const double w[3] = { R, centroids[m][0], centroids[m][1] };
            project(w, cImage[m]);
          }
          for (int y = 0; y < H; ++y)
          {
            for (int x = 0; x < W; ++x)
            {
              const size_t at = static_cast<size_t>(y) * W + x;
              const float u = local[0][at], v = local[1][at];
              if (std::isnan(u) || std::isnan(v))
              {
                continue; // background (the value pass clears to NaN)
              }
              // Pixels on a triangle's edge may hold the neighbour triangle's interpolation:
              // only pixels whose 3x3 neighbourhood is covered.
              bool inside = x > 0 && y > 0 && x + 1 < W && y + 1 < H;
              for (int j = -1; j <= 1 && inside; ++j)
              {
                for (int i = -1; i <= 1 && inside; ++i)
                {
                  inside = !std::isnan(local[0][at + j * W + i]);
                }
              }
              if (!inside)
              {
                continue;
              }
              const double w[3] = { R, u, v };
              double d[2];
              project(w, d);
              const double ex = d[0] - (x + 0.5), ey = d[1] - (y + 0.5);
              st.Worst = std::max(st.Worst, std::hypot(ex, ey));
              ++st.Pixels;
              for (int m = 0; m < 2; ++m)
              {
                if (std::hypot(x + 0.5 - cImage[m][0], y + 0.5 - cImage[m][1]) < 2.5)
                {
                  sum[m][0] += ex;
                  sum[m][1] += ey;
                  sum[m][2] += 1;
                }
              }
            }
          }
          for (int m = 0; m < 2; ++m)
          {
            if (sum[m][2] == 0)
            {
              continue;
            }
            const std::array<double, 2> e = { sum[m][0] / sum[m][2], sum[m][1] / sum[m][2] };
            std::array<double, 2>& e0 = centroid0[2 * ci + m];
            if (k == 0)
            {
              e0 = e;
            }
            else
            {
              st.Jitter = std::max(st.Jitter, std::hypot(e[0] - e0[0], e[1] - e0[1]));
            }
          }
        }
      }
      ok &= vtkGlobeTest::NoGLError();
      std::printf("%-11s %4.0f m (view %g deg, %.3g m/px):\n", vtkGlobeDepthPass::GetModeAsString(mode), D,
        viewAngles[di], footprint);
      std::printf("  globe: depth |dt| worst %.2e px, G-buffer slip median %.2e px, worst %.2e px "
                  "(pixel (%g, %g), %.3g m away) over %d pixels x 11 poses, NaN %d\n",
        globeStats.Depth, globeStats.SlipMedian, globeStats.Slip, globeStats.SlipAt[0],
        globeStats.SlipAt[1], globeStats.SlipAt[2], globeStats.Pixels / 11, globeStats.NaN);
      ok &= globeStats.Depth <= 0.05 && globeStats.Slip <= 0.05 && globeStats.NaN == 0 &&
        globeStats.Pixels > 11 * 2000;
      for (size_t ci = 0; ci < companions.size(); ++ci)
      {
        const Stats& st = companionStats[ci];
        const bool exact = st.Worst <= 0.05 && st.Jitter <= 0.05;
        std::printf("  companion %-42s position worst %.2e px, centroid jitter %.2e px over %d "
                    "pixels x 11 poses%s\n",
          companions[ci].Name, st.Worst, st.Jitter, st.Pixels / 11,
          exact == companions[ci].Exact ? "" : "  <-- UNEXPECTED");
        ok &= st.Pixels > 11 * 200 && exact == companions[ci].Exact;
      }
    }
  }

  // The globe alone at a far place, with HighPrecisionGeodetic on and off (the depth does not
  // depend on it; the G-buffer does), and at (0, 0) with it off, for comparison.
  struct Place
  {
    const char* Name;
    double Lon, Lat;
    bool HighPrecision;
  };
  const Place places[] = { { "(0, 0), on         ", 0.0, 0.0, true },
    { "(179.99, 80), on ", 179.99, 80.0, true },
    { "(179.99, 80), off", 179.99, 80.0, false }, { "(0, 0), off       ", 0.0, 0.0, false } };
  for (const Place& place : places)
  {
    scene.Mapper->SetHighPrecisionGeodetic(place.HighPrecision);
    double here[3];
    body->GeodeticToCartesian(place.Lon, place.Lat, TerrainHeight, here);
    body->ComputeEastNorthUp(place.Lon, place.Lat, east, north, up);
    for (int mode : { vtkGlobeDepthPass::Default, vtkGlobeDepthPass::Logarithmic })
    {
      if (place.Lon == 0.0 && !place.HighPrecision && mode == vtkGlobeDepthPass::Logarithmic)
      {
        continue;
      }
      auto pass = vtkGlobeTest::UseDepthMode(scene, mode);
      // From the terrain itself: the clipping policy's smallest near plane (1 cm) upwards.
      const double groundDistances[4] = { 0.01, 1.0, 10.0, 800.0 };
      const double groundViewAngles[4] = { 90.0, 90.0, 30.0, 1.0 };
      for (int di = 0; di < 4; ++di)
      {
        const double D = groundDistances[di];
        const double footprint =
          2.0 * D * std::tan(vtkMath::RadiansFromDegrees(groundViewAngles[di]) / 2) / H;
        GlobeStats st;
        for (int k = 0; k <= 10; ++k)
        {
          double eye[3];
          Pose(scene.Renderer->GetActiveCamera(), here, east, north, up, D, groundViewAngles[di], footprint, k, eye);
          scene.Renderer->ResetCameraClippingRange();
          scene.Render();
          MeasureGlobe(scene, pass, eye, footprint, D, st);
        }
        ok &= vtkGlobeTest::NoGLError();
        // Off at the far place: float directions of 0.4 m against pixels of 9 .. 62 mm.
        const bool expected = place.Lon == 0.0 ? true
                                               : (place.HighPrecision ? st.Slip <= 0.05 : st.Slip > 1.0);
        std::printf("%s %-11s %6.2f m: depth |dt| worst %.2e px, G-buffer slip median %.2e px, "
                    "worst %.2e px (pixel (%g, %g), %.3g m away) over %d pixels x 11 poses, NaN %d%s\n",
          place.Name, vtkGlobeDepthPass::GetModeAsString(mode), D, st.Depth, st.SlipMedian, st.Slip,
          st.SlipAt[0], st.SlipAt[1], st.SlipAt[2], st.Pixels / 11, st.NaN, expected ? "" : "  <-- UNEXPECTED");
        ok &= expected && st.Depth <= 0.05 && st.NaN == 0 && st.Pixels > 11 * 2000;
      }
    }
  }
  scene.Mapper->HighPrecisionGeodeticOn();
  std::printf("%s\n", ok ? "checks passed" : "checks FAILED");
  return ok ? 0 : 1;
}
