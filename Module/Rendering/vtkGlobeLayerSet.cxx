#include "vtkGlobeLayerSet.h"

#include "vtkDataArray.h"
#include "vtkGlobeLayer.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkGlobeLayerSet);

namespace
{
// Width of the feathered border of a layer that does not cover the whole globe, in texels.
constexpr double FeatherTexels = 8.0;

struct Entry
{
  vtkSmartPointer<vtkGlobeLayer> Layer;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkMTimeType UploadedTime = 0;
  bool Active = false;
  bool Reported = false; // an error about this layer was reported already
  // Uniform values, computed when the layer becomes active.
  double Extent[4] = { 0, 0, 0, 0 }; // west, east-west span, north, north-south span (rad)
  double Feather[2] = { 0, 0 };       // in texture coordinates
};
} // namespace

class vtkGlobeLayerSet::vtkInternals
{
public:
  std::vector<Entry> Entries;
  std::vector<Entry*> Heights; // active, in order
  std::vector<Entry*> Colors;
  double MinimumHeight = 0.0;
  double MaximumHeight = 0.0;
};

//------------------------------------------------------------------------------
vtkGlobeLayerSet::vtkGlobeLayerSet()
  : Internals(new vtkInternals)
{
}

vtkGlobeLayerSet::~vtkGlobeLayerSet() = default;

void vtkGlobeLayerSet::AddLayer(vtkGlobeLayer* layer)
{
  if (!layer)
  {
    vtkErrorMacro(<< "AddLayer: no layer given");
    return;
  }
  Entry entry;
  entry.Layer = layer;
  this->Internals->Entries.push_back(entry);
  this->Modified();
}

void vtkGlobeLayerSet::RemoveLayer(vtkGlobeLayer* layer)
{
  auto& entries = this->Internals->Entries;
  auto it = std::remove_if(
    entries.begin(), entries.end(), [layer](const Entry& e) { return e.Layer == layer; });
  if (it != entries.end())
  {
    entries.erase(it, entries.end());
    this->Internals->Heights.clear();
    this->Internals->Colors.clear();
    this->Modified();
  }
}

void vtkGlobeLayerSet::RemoveAllLayers()
{
  this->Internals->Entries.clear();
  this->Internals->Heights.clear();
  this->Internals->Colors.clear();
  this->Modified();
}

int vtkGlobeLayerSet::GetNumberOfLayers()
{
  return static_cast<int>(this->Internals->Entries.size());
}

vtkGlobeLayer* vtkGlobeLayerSet::GetLayer(int index)
{
  if (index < 0 || index >= this->GetNumberOfLayers())
  {
    return nullptr;
  }
  return this->Internals->Entries[index].Layer;
}

//------------------------------------------------------------------------------
int vtkGlobeLayerSet::Update()
{
  auto& in = *this->Internals;
  in.Heights.clear();
  in.Colors.clear();
  in.MinimumHeight = in.MaximumHeight = 0.0;
  bool firstHeight = true;
  for (Entry& e : in.Entries)
  {
    vtkGlobeLayer* layer = e.Layer;
    const char* name = layer->GetFileName() ? layer->GetFileName() : "(in-memory layer)";
    e.Active = false;
    if (!layer->Update() || !layer->IsValid())
    {
      // The layer reported its own error; say once that the globe goes on without it.
      if (!e.Reported)
      {
        vtkWarningMacro(<< "Layer " << name << " is skipped: it could not be loaded");
        e.Reported = true;
      }
      continue;
    }
    if (layer->GetModelType() != vtkGlobeLayer::Geographic)
    {
      if (!e.Reported)
      {
        vtkErrorMacro(<< "Layer " << name << " is skipped: its map projection (EPSG:"
                      << layer->GetEPSG()
                      << ") is not supported yet; only geographic (EPSG:4326-style) rasters are");
        e.Reported = true;
      }
      continue;
    }
    e.Reported = false;
    e.Active = true;
    double extent[4];
    layer->GetGeographicExtent(extent);
    const double deg = vtkMath::Pi() / 180.0;
    e.Extent[0] = extent[0] * deg;
    e.Extent[1] = (extent[1] - extent[0]) * deg;
    e.Extent[2] = extent[3] * deg;
    e.Extent[3] = (extent[3] - extent[2]) * deg;
    // Feather the borders of insets; a global layer wraps in longitude and has no border.
    e.Feather[0] = layer->IsGlobal() ? 0.0 : FeatherTexels / layer->GetWidth();
    const bool polesCovered = extent[2] <= -90.0 && extent[3] >= 90.0;
    e.Feather[1] = polesCovered ? 0.0 : FeatherTexels / layer->GetHeight();
    if (layer->GetRole() == vtkGlobeLayer::Height)
    {
      in.Heights.push_back(&e);
      const double lo = layer->GetMinimumValue(), hi = layer->GetMaximumValue();
      in.MinimumHeight = firstHeight ? lo : std::min(in.MinimumHeight, lo);
      in.MaximumHeight = firstHeight ? hi : std::max(in.MaximumHeight, hi);
      firstHeight = false;
    }
    else
    {
      in.Colors.push_back(&e);
    }
  }
  return static_cast<int>(in.Heights.size() + in.Colors.size());
}

double vtkGlobeLayerSet::GetMinimumHeight()
{
  return this->Internals->MinimumHeight;
}

double vtkGlobeLayerSet::GetMaximumHeight()
{
  return this->Internals->MaximumHeight;
}

int vtkGlobeLayerSet::GetNumberOfActiveHeightLayers()
{
  return static_cast<int>(this->Internals->Heights.size());
}

int vtkGlobeLayerSet::GetNumberOfActiveColorLayers()
{
  return static_cast<int>(this->Internals->Colors.size());
}

//------------------------------------------------------------------------------
void vtkGlobeLayerSet::UploadTextures(vtkOpenGLRenderWindow* window)
{
  for (Entry& e : this->Internals->Entries)
  {
    if (!e.Active)
    {
      continue;
    }
    vtkGlobeLayer* layer = e.Layer;
    vtkDataArray* data = layer->GetData();
    const vtkMTimeType time = std::max(layer->GetMTime(), data->GetMTime());
    if (e.Texture && e.Texture->GetContext() == window && e.UploadedTime >= time)
    {
      continue;
    }
    if (!e.Texture)
    {
      e.Texture = vtkSmartPointer<vtkTextureObject>::New();
    }
    e.Texture->SetContext(window);
    const int w = layer->GetWidth(), h = layer->GetHeight();
    const int maxSize = vtkTextureObject::GetMaximumTextureSize(window);
    if (w > maxSize || h > maxSize)
    {
      vtkErrorMacro(<< "Layer " << (layer->GetFileName() ? layer->GetFileName() : "(in-memory)")
                    << " is " << w << " x " << h << " texels, more than this OpenGL allows ("
                    << maxSize << "); it is skipped");
      e.Active = false;
      continue;
    }
    const bool height = layer->GetRole() == vtkGlobeLayer::Height;
    const int components = height ? 1 : 4;
    e.Texture->SetWrapS(layer->IsGlobal() ? vtkTextureObject::Repeat : vtkTextureObject::ClampToEdge);
    e.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    e.Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    e.Texture->SetMinificationFilter(vtkTextureObject::LinearMipmapLinear);
    e.Texture->Create2DFromRaw(w, h, components, height ? VTK_FLOAT : VTK_UNSIGNED_CHAR,
      data->GetVoidPointer(0));
    e.Texture->Bind();
    glGenerateMipmap(GL_TEXTURE_2D);
    e.Texture->Deactivate();
    e.UploadedTime = time;
    ++this->NumberOfUploads;
  }
}

size_t vtkGlobeLayerSet::GetTextureMemory()
{
  size_t bytes = 0;
  for (Entry& e : this->Internals->Entries)
  {
    if (e.Texture && e.Texture->GetHandle())
    {
      // Mipmaps add a third.
      bytes += static_cast<size_t>(e.Texture->GetWidth()) * e.Texture->GetHeight() *
        e.Texture->GetComponents() * (e.Layer->GetRole() == vtkGlobeLayer::Height ? 4 : 1) * 4 / 3;
    }
  }
  return bytes;
}

//------------------------------------------------------------------------------
std::string vtkGlobeLayerSet::GetShaderKey(bool withColor)
{
  std::ostringstream key;
  key << "h" << this->Internals->Heights.size();
  if (withColor)
  {
    key << "c" << this->Internals->Colors.size();
  }
  return key.str();
}

std::string vtkGlobeLayerSet::GetShaderCode(bool withColor)
{
  const auto& in = *this->Internals;
  std::ostringstream s;
  s << "// Generated by vtkGlobeLayerSet for " << in.Heights.size() << " height and "
    << in.Colors.size() << " colour layers.\n";
  for (size_t i = 0; i < in.Heights.size(); ++i)
  {
    s << "uniform sampler2D globeHeight" << i << ";\n"
      << "uniform vec4 globeHeightExtent" << i << ";\n"
      << "uniform vec2 globeHeightFeather" << i << ";\n";
  }
  for (size_t i = 0; withColor && i < in.Colors.size(); ++i)
  {
    s << "uniform sampler2D globeColor" << i << ";\n"
      << "uniform vec4 globeColorExtent" << i << ";\n"
      << "uniform vec2 globeColorFeather" << i << ";\n";
  }
  // Coverage of a layer at (lon, lat): its texture coordinates and a weight in [0, 1] that
  // falls to 0 across the feathered border and outside the extent. Longitude is taken
  // modulo 2 pi from the west edge, so layers crossing the date line work too.
  s << "float globe_layerCoverage(float lon, float lat, vec4 extent, vec2 feather, out vec2 uv)\n"
       "{\n"
       "  float u = mod(lon - extent.x, 6.283185307179586) / extent.y;\n"
       "  float v = (extent.z - lat) / extent.w;\n"
       "  uv = vec2(u, v);\n"
       "  if (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0) return 0.0;\n"
       "  float w = 1.0;\n"
       "  if (feather.x > 0.0) w *= clamp(min(u, 1.0 - u) / feather.x, 0.0, 1.0);\n"
       "  if (feather.y > 0.0) w *= clamp(min(v, 1.0 - v) / feather.y, 0.0, 1.0);\n"
       "  return w;\n"
       "}\n";
  // Texture-coordinate derivatives across the longitude seam jump by a whole turn; wrap them
  // so mipmap selection does not blur a line of pixels there.
  s << "vec2 globe_wrapDerivative(vec2 d, float span)\n"
       "{\n"
       "  float turn = 6.283185307179586 / span;\n"
       "  if (abs(d.x) > 0.5 * turn) d.x -= sign(d.x) * turn;\n"
       "  return d;\n"
       "}\n";
  // Heights: value and gradient (per radian of lon and lat), "replace" by weight, in order.
  s << "float globe_composeHeight(float lon, float lat, vec2 dLonLatdx, vec2 dLonLatdy, "
       "out vec2 gradient)\n"
       "{\n"
       "  float h = 0.0;\n"
       "  vec2 g = vec2(0.0);\n"
       "  vec2 uv;\n"
       "  float w;\n";
  for (size_t i = 0; i < in.Heights.size(); ++i)
  {
    const std::string n = std::to_string(i);
    s << "  w = globe_layerCoverage(lon, lat, globeHeightExtent" << n << ", globeHeightFeather" << n
      << ", uv);\n"
      << "  if (w > 0.0)\n"
      << "  {\n"
      << "    vec2 scale = vec2(1.0 / globeHeightExtent" << n << ".y, -1.0 / globeHeightExtent" << n
      << ".w);\n"
      << "    vec2 dx = globe_wrapDerivative(dLonLatdx, globeHeightExtent" << n << ".y) * scale;\n"
      << "    vec2 dy = globe_wrapDerivative(dLonLatdy, globeHeightExtent" << n << ".y) * scale;\n"
      << "    vec2 texel = 1.0 / vec2(textureSize(globeHeight" << n << ", 0));\n"
      << "    float hi = textureGrad(globeHeight" << n << ", uv, dx, dy).r;\n"
      << "    float hE = textureGrad(globeHeight" << n << ", uv + vec2(texel.x, 0.0), dx, dy).r;\n"
      << "    float hW = textureGrad(globeHeight" << n << ", uv - vec2(texel.x, 0.0), dx, dy).r;\n"
      << "    float hN = textureGrad(globeHeight" << n << ", uv - vec2(0.0, texel.y), dx, dy).r;\n"
      << "    float hS = textureGrad(globeHeight" << n << ", uv + vec2(0.0, texel.y), dx, dy).r;\n"
      << "    vec2 gi = vec2((hE - hW) / (2.0 * texel.x * globeHeightExtent" << n << ".y),\n"
      << "                   (hN - hS) / (2.0 * texel.y * globeHeightExtent" << n << ".w));\n"
      << "    if (!isnan(hi) && !isnan(gi.x) && !isnan(gi.y))\n"
      << "    {\n"
      << "      h = mix(h, hi, w);\n"
      << "      g = mix(g, gi, w);\n"
      << "    }\n"
      << "  }\n";
  }
  s << "  gradient = g;\n"
       "  return h;\n"
       "}\n";
  if (!withColor)
  {
    return s.str();
  }
  // Colours: RGBA; coverage times alpha is the weight.
  s << "vec4 globe_composeColor(float lon, float lat, vec2 dLonLatdx, vec2 dLonLatdy)\n"
       "{\n"
       "  vec4 c = vec4(0.0);\n"
       "  vec2 uv;\n"
       "  float w;\n";
  for (size_t i = 0; i < in.Colors.size(); ++i)
  {
    const std::string n = std::to_string(i);
    s << "  w = globe_layerCoverage(lon, lat, globeColorExtent" << n << ", globeColorFeather" << n
      << ", uv);\n"
      << "  if (w > 0.0)\n"
      << "  {\n"
      << "    vec2 scale = vec2(1.0 / globeColorExtent" << n << ".y, -1.0 / globeColorExtent" << n
      << ".w);\n"
      << "    vec4 ci = textureGrad(globeColor" << n << ", uv,\n"
      << "      globe_wrapDerivative(dLonLatdx, globeColorExtent" << n << ".y) * scale,\n"
      << "      globe_wrapDerivative(dLonLatdy, globeColorExtent" << n << ".y) * scale);\n"
      << "    float a = w * ci.a;\n"
      << "    c = vec4(mix(c.rgb, ci.rgb, a), max(c.a, a));\n"
      << "  }\n";
  }
  s << "  return c;\n"
       "}\n";
  return s.str();
}

//------------------------------------------------------------------------------
void vtkGlobeLayerSet::BindTextures(vtkShaderProgram* program, bool withColor)
{
  const auto& in = *this->Internals;
  auto bind = [program](Entry* e, const std::string& prefix, size_t i) {
    const std::string n = std::to_string(i);
    e->Texture->Activate();
    program->SetUniformi((prefix + n).c_str(), e->Texture->GetTextureUnit());
    const float extent[4] = { static_cast<float>(e->Extent[0]), static_cast<float>(e->Extent[1]),
      static_cast<float>(e->Extent[2]), static_cast<float>(e->Extent[3]) };
    program->SetUniform4f((prefix + "Extent" + n).c_str(), extent);
    const float feather[2] = { static_cast<float>(e->Feather[0]), static_cast<float>(e->Feather[1]) };
    program->SetUniform2f((prefix + "Feather" + n).c_str(), feather);
  };
  for (size_t i = 0; i < in.Heights.size(); ++i)
  {
    bind(in.Heights[i], "globeHeight", i);
  }
  for (size_t i = 0; withColor && i < in.Colors.size(); ++i)
  {
    bind(in.Colors[i], "globeColor", i);
  }
}

void vtkGlobeLayerSet::UnbindTextures(bool withColor)
{
  for (Entry* e : this->Internals->Heights)
  {
    e->Texture->Deactivate();
  }
  for (size_t i = 0; withColor && i < this->Internals->Colors.size(); ++i)
  {
    this->Internals->Colors[i]->Texture->Deactivate();
  }
}

void vtkGlobeLayerSet::ReleaseGraphicsResources(vtkWindow* window)
{
  for (Entry& e : this->Internals->Entries)
  {
    if (e.Texture)
    {
      e.Texture->ReleaseGraphicsResources(window);
      e.Texture = nullptr;
      e.UploadedTime = 0;
    }
  }
}

//------------------------------------------------------------------------------
void vtkGlobeLayerSet::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Layers: " << this->Internals->Entries.size() << "\n";
  for (const Entry& e : this->Internals->Entries)
  {
    os << indent.GetNextIndent() << (e.Layer->GetFileName() ? e.Layer->GetFileName() : "(in-memory)")
       << (e.Active ? " (active)" : " (inactive)") << "\n";
  }
  os << indent << "NumberOfUploads: " << this->NumberOfUploads << "\n";
}
