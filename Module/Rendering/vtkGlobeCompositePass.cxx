#include "vtkGlobeCompositePass.h"

#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeLayer.h"
#include "vtkGlobeLayerSet.h"
#include "vtkMath.h"
#include "vtkGlobeShaderSources.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkGlobeAtmosphere.h"
#include "vtkGlobeCompositeFS.h"
#include "vtkGlobeCompositeVS.h"
#include "vtkGlobeLines.h"

#include <array>
#include <cmath>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkGlobeCompositePass);

vtkGlobeCompositePass::vtkGlobeCompositePass()
{
  this->Timer = new vtkOpenGLRenderTimer;
}

vtkGlobeCompositePass::~vtkGlobeCompositePass()
{
  this->SetGBuffer(nullptr, nullptr);
  this->SetCoverage(nullptr, 0);
  this->SetEllipsoid(nullptr);
  this->SetLayers(nullptr);
  this->SetHeightColors(nullptr);
  if (this->HeightColorTexture)
  {
    this->HeightColorTexture->Delete();
  }
  if (this->VAO)
  {
    this->VAO->Delete();
  }
  delete this->Timer;
}

namespace
{
template <typename T>
void Assign(T*& member, T* value)
{
  if (member != value)
  {
    if (value)
    {
      value->Register(nullptr);
    }
    if (member)
    {
      member->UnRegister(nullptr);
    }
    member = value;
  }
}
} // namespace

void vtkGlobeCompositePass::SetGBuffer(vtkTextureObject* gbuffer, vtkTextureObject* depth)
{
  Assign(this->GBuffer, gbuffer);
  Assign(this->Depth, depth);
}

void vtkGlobeCompositePass::SetCoverage(vtkTextureObject* blocks, int blockSize)
{
  // Not Modified(): set per frame with the G-buffer.
  Assign(this->Coverage, blocks);
  this->CoverageBlock = blocks ? blockSize : 0;
}

void vtkGlobeCompositePass::SetEllipsoid(vtkGlobeEllipsoid* ellipsoid)
{
  Assign(this->Ellipsoid, ellipsoid);
}

void vtkGlobeCompositePass::SetLayers(vtkGlobeLayerSet* layers)
{
  Assign(this->Layers, layers);
}

void vtkGlobeCompositePass::SetHeightColors(vtkScalarsToColors* colors)
{
  if (colors != this->HeightColors)
  {
    Assign(this->HeightColors, colors);
    this->HeightColorTime = 0;
    this->Modified();
  }
}

namespace
{
constexpr int HeightColorEntries = 1024;
}

void vtkGlobeCompositePass::UpdateHeightColorTexture(vtkOpenGLRenderWindow* window)
{
  if (!this->HeightColorTexture)
  {
    this->HeightColorTexture = vtkTextureObject::New();
  }
  vtkTextureObject* t = this->HeightColorTexture;
  if (t->GetHandle() && t->GetContext() == window &&
    this->HeightColorTime >= this->HeightColors->GetMTime())
  {
    return;
  }
  const double* range = this->HeightColors->GetRange();
  double lo = range[0], hi = range[1];
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    vtkErrorMacro(<< "The height colour map's range (" << lo << ", " << hi
                  << ") is not finite; heights are coloured over [0, 1] m");
    lo = 0.0;
    hi = 1.0;
  }
  hi = hi > lo ? hi : lo + 1.0;
  std::vector<float> rgba(4 * HeightColorEntries);
  for (int i = 0; i < HeightColorEntries; ++i)
  {
    const double v = lo + (hi - lo) * i / (HeightColorEntries - 1);
    double rgb[3];
    this->HeightColors->GetColor(v, rgb);
    for (int c = 0; c < 3; ++c)
    {
      rgba[4 * i + c] = static_cast<float>(rgb[c]);
    }
    rgba[4 * i + 3] = static_cast<float>(this->HeightColors->GetOpacity(v));
  }
  t->SetContext(window);
  t->SetMinificationFilter(vtkTextureObject::Linear);
  t->SetMagnificationFilter(vtkTextureObject::Linear);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->Create2DFromRaw(HeightColorEntries, 1, 4, VTK_FLOAT, rgba.data());
  this->HeightColorRange[0] = lo;
  this->HeightColorRange[1] = hi;
  this->HeightColorTime = this->HeightColors->GetMTime();
}

void vtkGlobeCompositePass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->HeightColorTexture)
  {
    this->HeightColorTexture->ReleaseGraphicsResources(window);
  }
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
  }
  this->Program = nullptr;
  this->ShaderKey.clear();
  this->SpareProgram = nullptr;
  this->SpareKey.clear();
  this->Timer->ReleaseGraphicsResources();
}

double vtkGlobeCompositePass::GetCompositeTime()
{
  return vtkOpenGLRenderTimer::IsSupported() ? this->Timer->GetReusableElapsedSeconds() : -1.0;
}

//------------------------------------------------------------------------------
void vtkGlobeCompositePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->GBuffer || !this->Depth || !this->Ellipsoid || !this->Layers)
  {
    vtkErrorMacro(<< "Render: needs a G-buffer, its depth, an ellipsoid and layers");
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (!window)
  {
    return;
  }
  const std::string key = this->GetShaderKey();
  if (this->Program && key != this->ShaderKey)
  {
    // VTK's shader cache keeps every program it compiled for the window's life (MiBs each on
    // Mesa): free the GL program of a variant no longer drawn; the cache recompiles it if it
    // comes back. Only the other detail level's program is kept, while the level alone
    // alternates (interaction), so that neither switch compiles.
    if (this->RefinementSuspended != this->ProgramSuspended)
    {
      std::swap(this->Program, this->SpareProgram);
      std::swap(this->ShaderKey, this->SpareKey);
      std::swap(this->FragmentSource, this->SpareSource);
      this->ProgramSuspended = this->RefinementSuspended;
    }
    else if (this->SpareProgram)
    {
      this->SpareProgram->ReleaseGraphicsResources(window); // a setting changed: stale too
      this->SpareProgram = nullptr;
    }
    if (this->Program && key != this->ShaderKey)
    {
      this->Program->ReleaseGraphicsResources(window);
      this->Program = nullptr;
    }
  }
  if (!this->Program)
  {
    this->FragmentSource = this->BuildFragmentShader();
    this->Program = window->GetShaderCache()->ReadyShaderProgram(
      vtkGlobeCompositeVS, this->FragmentSource.c_str(), "");
    this->ShaderKey = key;
    this->ProgramSuspended = this->RefinementSuspended;
    ++this->NumberOfShaderBuilds;
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Program);
  }
  vtkShaderProgram* p = this->Program;
  if (!p || !p->GetCompiled())
  {
    vtkErrorMacro(<< "The globe's composition shader did not compile");
    return;
  }

  this->Timer->ReusableStart();
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  if (this->Atmosphere)
  {
    // Terrain is opaque (alpha 1); the sky is added to what is behind it (alpha 0).
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    state->vtkglDisable(GL_BLEND);
  }

  this->GBuffer->Activate();
  this->Depth->Activate();
  p->SetUniformi("globeGBuffer", this->GBuffer->GetTextureUnit());
  p->SetUniformi("globeDepth", this->Depth->GetTextureUnit());
  vtkGlobeShaderSources::SetRadii(p, this->Ellipsoid);
  const double* radii = this->Ellipsoid->GetRadii();
  p->SetUniformf("globeMeanRadius", static_cast<float>((radii[0] + radii[1] + radii[2]) / 3.0));
  auto f3 = [](const double v[3]) {
    return std::array<float, 3>{ static_cast<float>(v[0]), static_cast<float>(v[1]),
      static_cast<float>(v[2]) };
  };
  p->SetUniform3f("globeLightDirection", f3(this->LightDirection).data());
  p->SetUniform3f("globeLightColor", f3(this->LightColor).data());
  p->SetUniform3f("globeBaseColor", f3(this->BaseColor).data());
  p->SetUniformf("globeAmbient", static_cast<float>(this->Ambient));
  p->SetUniformf("globeMaximumRadius", static_cast<float>(this->Ellipsoid->GetMaximumRadius()));
  const double r = this->Ellipsoid->GetMaximumRadius();
  const double eye[3] = { this->Eye[0] / r, this->Eye[1] / r, this->Eye[2] / r };
  p->SetUniform3f("globeEye", f3(eye).data());
  float clipToEye[16];
  for (int row = 0; row < 4; ++row)
  {
    for (int c = 0; c < 4; ++c)
    {
      clipToEye[c * 4 + row] = static_cast<float>(this->ClipToEye[row * 4 + c]);
    }
  }
  p->SetUniformMatrix4x4("globeClipToEye", clipToEye);
  if (this->Refines())
  {
    const float chord[4] = { static_cast<float>(this->Chord[0]), static_cast<float>(this->Chord[1]),
      static_cast<float>(this->Chord[2]), static_cast<float>(this->Chord[3]) };
    const float clipW[4] = { static_cast<float>(this->ClipW[0]), static_cast<float>(this->ClipW[1]),
      static_cast<float>(this->ClipW[2]), static_cast<float>(this->ClipW[3]) };
    p->SetUniform4f("globeChord", chord);
    p->SetUniform4f("globeClipW", clipW);
    p->SetUniform3f("globeDepthMap", f3(this->DepthMap).data());
  }
  p->SetUniform2f("globeSpecular",
    std::array<float, 2>{ static_cast<float>(this->SpecularStrength),
      static_cast<float>(this->SpecularPower) }
      .data());
  p->SetUniformf("globeAtmosphereIntensity", static_cast<float>(this->AtmosphereIntensity));
  p->SetUniform3f("globeLines",
    std::array<float, 3>{ static_cast<float>(this->GraticuleSpacing * vtkMath::Pi() / 180.0),
      static_cast<float>(this->ContourInterval), static_cast<float>(this->LineWidth) }
      .data());
  p->SetUniform3f("globeGraticuleColor", f3(this->GraticuleColor).data());
  p->SetUniform3f("globeContourColor", f3(this->ContourColor).data());
  if (this->HeightColors)
  {
    this->UpdateHeightColorTexture(window);
    this->HeightColorTexture->Activate();
    p->SetUniformi("globeHeightColors", this->HeightColorTexture->GetTextureUnit());
    // Height -> texture coordinate: the range's ends at the first and last texel centres.
    const double n = HeightColorEntries;
    const double scale = (n - 1.0) / n / (this->HeightColorRange[1] - this->HeightColorRange[0]);
    const float map[3] = { static_cast<float>(scale),
      static_cast<float>(0.5 / n - this->HeightColorRange[0] * scale),
      static_cast<float>(this->HeightColorOpacity) };
    p->SetUniform3f("globeHeightColorMap", map);
  }
  this->Layers->BindTextures(p, this->GetRoles());

  // The geometry: a rectangle per band of rows (vtkGlobeCompositeVS).
  int viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  const int band = 64;
  const bool cull = this->BlockCulling && !this->Atmosphere && this->Coverage &&
    this->CoverageBlock > 0;
  if (cull)
  {
    this->Coverage->Activate();
  }
  // Unread without culling, but bound to a 2D float texture all the same: a sampler left on
  // unit 0 could share it with a sampler of another type, which fails the draw.
  p->SetUniformi("globeCoverage",
    cull ? this->Coverage->GetTextureUnit() : this->GBuffer->GetTextureUnit());
  p->SetUniform2i("globeViewportSize", std::array<int, 2>{ viewport[2], viewport[3] }.data());
  p->SetUniformi("globeBand", band);
  p->SetUniformi("globeBlock", cull ? this->CoverageBlock : 0);
  if (!this->VAO)
  {
    this->VAO = vtkOpenGLVertexArrayObject::New();
  }
  this->VAO->Bind();
  glDrawArrays(GL_TRIANGLES, 0, 6 * ((viewport[3] + band - 1) / band));
  this->VAO->Release();
  if (cull)
  {
    this->Coverage->Deactivate();
  }

  this->Layers->UnbindTextures(this->GetRoles());
  if (this->HeightColors)
  {
    this->HeightColorTexture->Deactivate();
  }
  this->Depth->Deactivate();
  this->GBuffer->Deactivate();
  this->Timer->ReusableStop();
  ++this->NumberOfRenderedProps;
}

//------------------------------------------------------------------------------
void vtkGlobeCompositePass::SetView(const double eye[3], const double clipToEye[16])
{
  // Not Modified(): the view changes every frame and rebuilds nothing.
  std::copy(eye, eye + 3, this->Eye);
  std::copy(clipToEye, clipToEye + 16, this->ClipToEye);
}

void vtkGlobeCompositePass::SetRefinementFrame(
  const double chord[4], const double clipW[4], const double depthMap[3])
{
  // Not Modified(): per frame, like the view.
  std::copy(chord, chord + 4, this->Chord);
  std::copy(clipW, clipW + 4, this->ClipW);
  std::copy(depthMap, depthMap + 3, this->DepthMap);
}

bool vtkGlobeCompositePass::Refines()
{
  // Refinement needs the G-buffer's precise offsets: a float unit direction carries 0.4 m of
  // noise in the chord's sag, which a grazing ray turns into steps of hundreds of metres
  // (depth jitter of 181 px 10 m above the ground in TestGlobeJitter). Without them the
  // program, its key and its uniforms are those of no refinement.
  return this->TerrainRefinement > 0 && !this->RefinementSuspended && this->Layers &&
    this->Layers->GetHighPrecisionGeodetic();
}

int vtkGlobeCompositePass::GetRoles()
{
  // Night lights and water masks only matter to the effects that use them, lit.
  int roles = vtkGlobeLayerSet::AllRoles;
  const int count[2] = { this->Layers->GetNumberOfComposedLayers(vtkGlobeLayer::NightLights),
    this->Layers->GetNumberOfComposedLayers(vtkGlobeLayer::Mask) };
  if (!this->Lighting || !this->NightLights || !count[0])
  {
    roles &= ~(1 << vtkGlobeLayer::NightLights);
  }
  if (!this->Lighting || !this->SpecularWater || !count[1])
  {
    roles &= ~(1 << vtkGlobeLayer::Mask);
  }
  return roles;
}

std::string vtkGlobeCompositePass::GetShaderKey()
{
  if (!this->Layers)
  {
    return std::string();
  }
  const int roles = this->GetRoles();
  std::string key = this->Layers->GetShaderKey(roles) + "|";
  key += this->HeightColors ? "H" : "";
  key += this->Lighting ? "L" : "";
  key += (roles >> vtkGlobeLayer::NightLights) & 1 ? "N" : "";
  key += (roles >> vtkGlobeLayer::Mask) & 1 ? "S" : "";
  key += this->Atmosphere ? "A" : "";
  key += this->Graticule ? "G" : "";
  key += this->Contours ? "C" : "";
  key += this->Refines() ? "R" + std::to_string(this->TerrainRefinement) : "";
  return key;
}

std::string vtkGlobeCompositePass::BuildFragmentShader()
{
  const std::string key = this->GetShaderKey();
  const std::string effects = key.substr(key.find('|') + 1);
  auto has = [&effects](char c) { return effects.find(c) != std::string::npos; };
  vtkGlobeLayerSet* layers = this->Layers;
  const bool normalMaps = layers->GetNumberOfComposedLayers(vtkGlobeLayer::NormalMap) > 0;
  const bool overlays = layers->GetNumberOfComposedLayers(vtkGlobeLayer::Overlay) > 0;
  const bool colors = layers->GetNumberOfComposedLayers(vtkGlobeLayer::Color) > 0;

  std::string functions;
  std::string sample;
  std::string sky;
  std::string normal;
  std::string shade;
  if (colors)
  {
    sample += "  albedo = globe_composeColor(lonHi, lonLo, latHi, latLo, albedo);\n";
  }
  if (has('H'))
  {
    // globeHeightColorMap: height -> texture coordinate (scale, offset), opacity.
    functions += "uniform sampler2D globeHeightColors;\nuniform vec3 globeHeightColorMap;\n";
    sample += "  vec4 tint = texture(globeHeightColors,\n"
              "    vec2(h * globeHeightColorMap.x + globeHeightColorMap.y, 0.5));\n"
              "  albedo = mix(albedo, tint.rgb, tint.a * globeHeightColorMap.z);\n";
  }
  if (normalMaps)
  {
    sample += "  vec4 mapNormal = globe_composeNormal(lonHi, lonLo, latHi, latLo);\n";
    normal += "  tangentNormal = mix(globe_normalize(tangentNormal), mapNormal.xyz, mapNormal.w);\n";
  }
  if (has('L'))
  {
    functions += "uniform vec2 globeSpecular;\n";
    shade += "  float sunUp = dot(normal, globeLightDirection);\n"
             "  color = albedo * (globeAmbient + (1.0 - globeAmbient) * max(sunUp, 0.0) * "
             "globeLightColor);\n";
  }
  if (has('N'))
  {
    sample += "  vec3 nightLights = globe_composeNightLights(lonHi, lonLo, latHi, latLo);\n";
    // Lights fade in across the terminator, judged on the ellipsoid's normal, not the slope.
    shade += "  color += nightLights * (1.0 - smoothstep(-0.1, 0.1, dot(n, globeLightDirection)));\n";
  }
  if (has('S'))
  {
    sample += "  float water = globe_composeMask(lonHi, lonLo, latHi, latLo);\n";
    shade += "  vec3 halfway = globe_normalize(globeLightDirection - ray);\n"
             "  color += water * step(0.0, sunUp) * globeSpecular.x * globeLightColor *\n"
             "    pow(max(dot(normal, halfway), 0.0), globeSpecular.y);\n";
  }
  if (has('G') || has('C'))
  {
    functions += vtkGlobeLines;
    functions += "\nuniform vec3 globeLines; // graticule spacing (rad), contour interval (m), "
                 "width (px)\nuniform vec3 globeGraticuleColor;\nuniform vec3 globeContourColor;\n";
  }
  if (has('G'))
  {
    sample += "  float graticule = max(\n"
              "    globe_lineCoverage(lon, globeLines.x, globe_longitudePerPixel(lon), globeLines.z),\n"
              "    globe_lineCoverage(lat, globeLines.x, abs(dFdx(lat)) + abs(dFdy(lat)), "
              "globeLines.z));\n"
              "  lineColor = globeGraticuleColor;\n"
              "  lines = graticule;\n";
  }
  if (has('C'))
  {
    sample += "  float contour = globe_lineCoverage(h, globeLines.y, fwidth(h), globeLines.z);\n"
              "  if (contour > lines) lineColor = globeContourColor;\n"
              "  lines = max(lines, contour);\n";
  }
  if (overlays)
  {
    sample += "  vec4 overlay = globe_composeOverlay(lonHi, lonLo, latHi, latLo);\n";
    shade += "  color = color * (1.0 - overlay.a) + overlay.rgb;\n";
  }
  if (has('A'))
  {
    functions += vtkGlobeAtmosphere;
    functions += "\nuniform float globeAtmosphereIntensity;\n";
    // Sky: where the ray crosses the shell and no terrain is drawn; added to the background.
    sky += "  vec3 sky, skyTransmittance;\n"
           "  if (globe_atmosphereAlong(globeEye, ray, -1.0, globeLightDirection,\n"
           "        globeAtmosphereIntensity, sky, skyTransmittance))\n"
           "  {\n"
           "    gl_FragData[0] = vec4(sky, 0.0);\n"
           "    gl_FragDepth = 1.0;\n"
           "    return;\n"
           "  }\n";
    // Ground: haze in front of the terrain, seen from space or from inside the shell.
    shade += "  {\n"
             "    vec3 ground = s * globeRadiiScaled + (g.w / globeMaximumRadius) * n;\n"
             "    vec3 haze, transmittance;\n"
             "    if (globe_atmosphereAlong(globeEye, ray, length(ground - globeEye),\n"
             "          globeLightDirection, globeAtmosphereIntensity, haze, transmittance))\n"
             "    {\n"
             "      color = color * transmittance + haze;\n"
             "    }\n"
             "  }\n";
  }
  using vtkGlobeShaderSources::Replace;
  std::string defines =
    layers->GetHighPrecisionGeodetic() ? "#define GLOBE_HIGH_PRECISION_GEODETIC\n" : "";
  if (this->Refines())
  {
    defines += "#define GLOBE_REFINE " + std::to_string(this->TerrainRefinement) + "\n";
  }
  std::string fs =
    Replace(vtkGlobeCompositeFS, "//GLOBE::Math", defines + vtkGlobeShaderSources::Math());
  fs = Replace(fs, "//GLOBE::Layers", layers->GetShaderCode(this->GetRoles()));
  fs = Replace(fs, "//GLOBE::EffectFunctions", functions);
  fs = Replace(fs, "//GLOBE::Sample", sample);
  fs = Replace(fs, "//GLOBE::Sky", sky);
  fs = Replace(fs, "//GLOBE::Normal", normal);
  fs = Replace(fs, "//GLOBE::Shade", shade);
  return fs;
}

//------------------------------------------------------------------------------
void vtkGlobeCompositePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightDirection: " << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << "\n";
  os << indent << "Ambient: " << this->Ambient << "\n";
  os << indent << "HeightColors: " << this->HeightColors << " (opacity "
     << this->HeightColorOpacity << ")\n";
  os << indent << "Effects: " << (this->Lighting ? "Lighting " : "")
     << (this->NightLights ? "NightLights " : "") << (this->SpecularWater ? "SpecularWater " : "")
     << (this->Atmosphere ? "Atmosphere " : "") << (this->Graticule ? "Graticule " : "")
     << (this->Contours ? "Contours" : "") << "\n";
  os << indent << "TerrainRefinement: " << this->TerrainRefinement
     << (this->RefinementSuspended ? " (suspended)" : "") << "\n";
  os << indent << "BlockCulling: " << this->BlockCulling << "\n";
  os << indent << "ShaderKey: " << this->ShaderKey << "\n";
  os << indent << "NumberOfShaderBuilds: " << this->NumberOfShaderBuilds << "\n";
}
