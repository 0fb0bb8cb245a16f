#include "vtkGlobeGridPass.h"

#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeProjectiveGrid.h"
#include "vtkGlobeShaderSources.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkGlobeGridHeightFS.h"
#include "vtkGlobeGridPGMFS.h"

vtkStandardNewMacro(vtkGlobeGridPass);
vtkCxxSetObjectMacro(vtkGlobeGridPass, ProjectiveGrid, vtkGlobeProjectiveGrid);
vtkCxxSetObjectMacro(vtkGlobeGridPass, Layers, vtkGlobeLayerSet);

namespace
{
vtkTextureObject* NewFloatTexture(vtkOpenGLRenderWindow* window, int n, int components)
{
  vtkTextureObject* t = vtkTextureObject::New();
  t->SetContext(window);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  t->Allocate2D(n, n, components, VTK_FLOAT);
  return t;
}

void Uniform3(vtkShaderProgram* p, const char* name, const double v[3])
{
  const float f[3] = { static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]) };
  p->SetUniform3f(name, f);
}

void Uniform1(vtkShaderProgram* p, const char* name, double v)
{
  p->SetUniformf(name, static_cast<float>(v));
}
} // namespace

//------------------------------------------------------------------------------
vtkGlobeGridPass::vtkGlobeGridPass()
{
  this->PGMTimer = new vtkOpenGLRenderTimer;
  this->HeightTimer = new vtkOpenGLRenderTimer;
}

vtkGlobeGridPass::~vtkGlobeGridPass()
{
  this->SetProjectiveGrid(nullptr);
  this->SetLayers(nullptr);
  if (this->DirectionTexture || this->Framebuffer || this->PGMQuad)
  {
    vtkWarningMacro(<< "ReleaseGraphicsResources() was not called before destruction");
  }
  delete this->PGMTimer;
  delete this->HeightTimer;
}

void vtkGlobeGridPass::ReleaseGraphicsResources(vtkWindow* w)
{
  for (vtkTextureObject** t : { &this->DirectionTexture, &this->PositionTexture, &this->HeightTexture })
  {
    if (*t)
    {
      (*t)->ReleaseGraphicsResources(w);
      (*t)->Delete();
      *t = nullptr;
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer->Delete();
    this->Framebuffer = nullptr;
  }
  delete this->PGMQuad;
  this->PGMQuad = nullptr;
  delete this->HeightQuad;
  this->HeightQuad = nullptr;
  this->HeightShaderKey.clear();
  this->PGMTimer->ReleaseGraphicsResources();
  this->HeightTimer->ReleaseGraphicsResources();
}

double vtkGlobeGridPass::GetPGMTime()
{
  return vtkOpenGLRenderTimer::IsSupported() ? this->PGMTimer->GetReusableElapsedSeconds() : -1.0;
}

double vtkGlobeGridPass::GetHeightTime()
{
  return vtkOpenGLRenderTimer::IsSupported() ? this->HeightTimer->GetReusableElapsedSeconds()
                                             : -1.0;
}

//------------------------------------------------------------------------------
bool vtkGlobeGridPass::Prepare(vtkOpenGLRenderWindow* window)
{
  // A new resolution only resizes the textures: the programs do not depend on it.
  const int n = this->Resolution;
  if (this->DirectionTexture && this->DirectionTexture->GetWidth() != static_cast<unsigned int>(n))
  {
    this->DirectionTexture->Resize(n, n);
    this->PositionTexture->Resize(n, n);
    this->HeightTexture->Resize(n, n);
  }
  if (!this->DirectionTexture)
  {
    this->DirectionTexture = NewFloatTexture(window, n, 4);
    this->PositionTexture = NewFloatTexture(window, n, 4);
    this->HeightTexture = NewFloatTexture(window, n, 4);
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
  }

  const std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
  if (!this->PGMQuad)
  {
    std::string fs = vtkGlobeShaderSources::Replace(
      vtkGlobeGridPGMFS, "//GLOBE::Math", vtkGlobeShaderSources::Math());
    this->PGMQuad = new vtkOpenGLQuadHelper(window, vs.c_str(), fs.c_str(), "");
    ++this->NumberOfShaderBuilds;
  }
  // The height program is generated from the active height layers: rebuild only when they
  // change.
  const std::string key = this->Layers->GetShaderKey(vtkGlobeLayerSet::HeightRoles);
  if (this->HeightQuad && key != this->HeightShaderKey)
  {
    // Free the GL program of the old variant (VTK's shader cache would keep it for the
    // window's life); the cache recompiles it if the variant comes back.
    if (this->HeightQuad->Program)
    {
      this->HeightQuad->Program->ReleaseGraphicsResources(window);
    }
    delete this->HeightQuad;
    this->HeightQuad = nullptr;
  }
  if (!this->HeightQuad)
  {
    const std::string defines = this->Layers->GetHighPrecisionGeodetic()
      ? "#define GLOBE_HIGH_PRECISION_GEODETIC\n"
      : "";
    std::string fs = vtkGlobeShaderSources::Replace(
      vtkGlobeGridHeightFS, "//GLOBE::Math", defines + vtkGlobeShaderSources::Math());
    fs = vtkGlobeShaderSources::Replace(fs, "//GLOBE::Layers", this->Layers->GetShaderCode(vtkGlobeLayerSet::HeightRoles));
    this->HeightQuad = new vtkOpenGLQuadHelper(window, vs.c_str(), fs.c_str(), "");
    this->HeightShaderKey = key;
    ++this->NumberOfShaderBuilds;
  }
  if (!this->PGMQuad->Program || !this->PGMQuad->Program->GetCompiled() ||
    !this->HeightQuad->Program || !this->HeightQuad->Program->GetCompiled())
  {
    vtkErrorMacro(<< "The globe's grid shaders did not compile");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkGlobeGridPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->ProjectiveGrid || !this->Layers)
  {
    vtkErrorMacro(<< "Render: needs a projective grid and a layer set");
    return;
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (!window || !this->Prepare(window))
  {
    return;
  }
  vtkOpenGLState* state = window->GetState();
  const vtkGlobeShaderSources::ScopedOffscreenPass offscreen(state);

  const int n = this->Resolution;
  vtkGlobeProjectiveGrid* grid = this->ProjectiveGrid;
  this->Framebuffer->Bind();

  // Step 1: PGM.
  // Timer queries stay in flight until done; results come from the last finished frame.
  this->PGMTimer->ReusableStart();
  this->Framebuffer->AddColorAttachment(0, this->DirectionTexture);
  this->Framebuffer->AddColorAttachment(1, this->PositionTexture);
  this->Framebuffer->ActivateDrawBuffers(2);
  state->vtkglViewport(0, 0, n, n);
  window->GetShaderCache()->ReadyShaderProgram(this->PGMQuad->Program);
  vtkShaderProgram* p = this->PGMQuad->Program;
  const float size[2] = { static_cast<float>(n), static_cast<float>(n) };
  p->SetUniform2f("globeGridSize", size);
  Uniform3(p, "globeNadir", grid->GetNadir());
  Uniform3(p, "globeNadirPerpendicular", grid->GetNadirPerpendicular());
  Uniform3(p, "globeSamplingForward", grid->GetSamplingForward());
  Uniform3(p, "globeSamplingRight", grid->GetSamplingRight());
  Uniform3(p, "globeSamplingUp", grid->GetSamplingUp());
  const double* extent = grid->GetSamplingExtent();
  const float e[4] = { static_cast<float>(extent[0]), static_cast<float>(extent[1]),
    static_cast<float>(extent[2]), static_cast<float>(extent[3]) };
  p->SetUniform4f("globeSamplingExtent", e);
  Uniform1(p, "globeDistance", grid->GetDistance());
  Uniform1(p, "globePrimaryRadius", grid->GetPrimaryRadius());
  Uniform1(p, "globePrimaryAltitude", grid->GetAltitude());
  Uniform1(p, "globeTau0", grid->GetPrimaryTangentAngle());
  Uniform1(p, "globeBlendStart", grid->GetBlendStart());
  Uniform1(p, "globeSecondaryRadius", grid->GetSecondaryRadius());
  Uniform1(p, "globeSecondaryAltitude", grid->GetDistance() - grid->GetSecondaryRadius());
  Uniform1(p, "globeBlendStartS", grid->GetSecondaryBlendStart());
  Uniform1(p, "globeTauS", grid->GetSecondaryTangentAngle());
  this->PGMQuad->Render();
  this->Framebuffer->RemoveColorAttachments(2);
  this->PGMTimer->ReusableStop();

  // Step 2: height composition.
  this->HeightTimer->ReusableStart();
  this->Framebuffer->AddColorAttachment(0, this->HeightTexture);
  this->Framebuffer->ActivateDrawBuffers(1);
  window->GetShaderCache()->ReadyShaderProgram(this->HeightQuad->Program);
  p = this->HeightQuad->Program;
  this->DirectionTexture->Activate();
  this->PositionTexture->Activate();
  p->SetUniformi("globeDirection", this->DirectionTexture->GetTextureUnit());
  p->SetUniformi("globePosition", this->PositionTexture->GetTextureUnit());
  vtkGlobeShaderSources::SetRadii(p, grid->GetEllipsoid());
  // The frame's local origin for geodetic coordinates: the camera's sub-point (the grid's
  // anti-nadir), which the composition of this frame shares through the layer set.
  const double* nadir = grid->GetNadir();
  const double subPoint[3] = { -nadir[0], -nadir[1], -nadir[2] };
  this->Layers->SetGeodeticReference(subPoint, grid->GetEllipsoid()->GetRadii());
  Uniform3(p, "globeNadir", nadir);
  Uniform1(p, "globePrimaryAltitude", grid->GetAltitude());
  Uniform1(p, "globePrimaryRadius", grid->GetPrimaryRadius());
  this->Layers->BindTextures(p, vtkGlobeLayerSet::HeightRoles);
  this->HeightQuad->Render();
  this->Layers->UnbindTextures(vtkGlobeLayerSet::HeightRoles);
  this->PositionTexture->Deactivate();
  this->DirectionTexture->Deactivate();
  this->Framebuffer->RemoveColorAttachments(1);
  this->HeightTimer->ReusableStop();
  ++this->NumberOfRenderedProps;
}

//------------------------------------------------------------------------------
void vtkGlobeGridPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "NumberOfShaderBuilds: " << this->NumberOfShaderBuilds << "\n";
  os << indent << "PGMTime: " << this->GetPGMTime() << " s, HeightTime: " << this->GetHeightTime()
     << " s\n";
}
