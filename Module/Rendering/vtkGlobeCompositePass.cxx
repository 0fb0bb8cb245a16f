#include "vtkGlobeCompositePass.h"

#include "vtkGlobeEllipsoid.h"
#include "vtkGlobeLayerSet.h"
#include "vtkGlobeShaderSources.h"
#include "vtkObjectFactory.h"
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

#include "vtkGlobeCompositeFS.h"

#include <array>

vtkStandardNewMacro(vtkGlobeCompositePass);

vtkGlobeCompositePass::vtkGlobeCompositePass()
{
  this->Timer = new vtkOpenGLRenderTimer;
}

vtkGlobeCompositePass::~vtkGlobeCompositePass()
{
  this->SetGBuffer(nullptr, nullptr);
  this->SetEllipsoid(nullptr);
  this->SetLayers(nullptr);
  delete this->Quad;
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

void vtkGlobeCompositePass::SetEllipsoid(vtkGlobeEllipsoid* ellipsoid)
{
  Assign(this->Ellipsoid, ellipsoid);
}

void vtkGlobeCompositePass::SetLayers(vtkGlobeLayerSet* layers)
{
  Assign(this->Layers, layers);
}

void vtkGlobeCompositePass::ReleaseGraphicsResources(vtkWindow*)
{
  delete this->Quad;
  this->Quad = nullptr;
  this->ShaderKey.clear();
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
  const std::string key = this->Layers->GetShaderKey();
  if (this->Quad && key != this->ShaderKey)
  {
    delete this->Quad;
    this->Quad = nullptr;
  }
  if (!this->Quad)
  {
    std::string fs = vtkGlobeShaderSources::Replace(
      vtkGlobeCompositeFS, "//GLOBE::Math", vtkGlobeShaderSources::Math());
    fs = vtkGlobeShaderSources::Replace(fs, "//GLOBE::Layers", this->Layers->GetShaderCode());
    this->FragmentSource = fs;
    this->Quad = new vtkOpenGLQuadHelper(
      window, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), fs.c_str(), "");
    this->ShaderKey = key;
    ++this->NumberOfShaderBuilds;
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkShaderProgram* p = this->Quad->Program;
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
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);

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
  this->Layers->BindTextures(p);

  this->Quad->Render();

  this->Layers->UnbindTextures();
  this->Depth->Deactivate();
  this->GBuffer->Deactivate();
  this->Timer->ReusableStop();
  ++this->NumberOfRenderedProps;
}

//------------------------------------------------------------------------------
void vtkGlobeCompositePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightDirection: " << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << "\n";
  os << indent << "Ambient: " << this->Ambient << "\n";
  os << indent << "NumberOfShaderBuilds: " << this->NumberOfShaderBuilds << "\n";
}
