#include "vtkGlobeDepthPass.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkGlobeDepthPass);
vtkCxxSetObjectMacro(vtkGlobeDepthPass, DelegatePass, vtkRenderPass);

namespace
{
// The near plane that still clips in Logarithmic mode: geometry nearer than 1 mm to the eye.
// Depth itself comes from the fragment shader, so this only decides what is cut away.
const double LogarithmicNear = 1e-3;

/// Inserts declarations before "void main" and code before the closing brace of main (the
/// last '}' of a VTK shader). False when the source has neither.
bool Insert(std::string& source, const std::string& declarations, const std::string& code)
{
  const size_t main = source.find("void main");
  const size_t end = source.rfind('}');
  if (main == std::string::npos || end == std::string::npos || end < main)
  {
    return false;
  }
  source.insert(end, code);
  source.insert(main, declarations);
  return true;
}
} // namespace

//------------------------------------------------------------------------------
vtkGlobeDepthPass::vtkGlobeDepthPass()
{
  this->ShaderStageTime.Modified();
}

vtkGlobeDepthPass::~vtkGlobeDepthPass()
{
  this->SetDelegatePass(nullptr);
}

void vtkGlobeDepthPass::SetMode(int mode)
{
  if (mode != Default && mode != Logarithmic)
  {
    vtkErrorMacro(<< "SetMode: " << mode << " is not a depth mode (0 Default, 1 Logarithmic); "
                  << "the mode stays " << GetModeAsString(this->Mode));
    return;
  }
  if (mode != this->Mode)
  {
    this->Mode = mode;
    // Mappers compare this with the time their shaders were built.
    this->ShaderStageTime.Modified();
    this->Modified();
  }
}

const char* vtkGlobeDepthPass::GetModeAsString(int mode)
{
  switch (mode)
  {
    case Default:
      return "Default";
    case Logarithmic:
      return "Logarithmic";
    default:
      return "Unknown";
  }
}

vtkMTimeType vtkGlobeDepthPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

void vtkGlobeDepthPass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkGlobeDepthPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkNew<vtkRenderStepsPass> steps;
    this->SetDelegatePass(steps);
  }
  vtkCamera* camera = s->GetRenderer()->GetActiveCamera();
  this->LastFar = std::max(camera->GetClippingRange()[1], 2.0 * LogarithmicNear);
  // In Default mode the pass is not announced to the mappers: their shaders stay VTK's own.
  const bool inject = this->Mode != Default;
  if (inject)
  {
    this->PreRender(s);
  }
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  if (inject)
  {
    this->PostRender(s);
  }
}

//------------------------------------------------------------------------------
void vtkGlobeDepthPass::InjectDepthCode(std::string& vs, std::string& fs)
{
  if (this->Mode != Logarithmic)
  {
    return;
  }
  // Clip z: a perspective z with a 1 mm near plane, so geometry up to the eye is kept (the
  // camera's near plane no longer matters); VTK's w_clip is the eye distance along the view.
  const bool vsOk = Insert(vs, "uniform vec2 vtkGlobeDepthClip;\n",
    "  // vtkGlobeDepthPass (logarithmic): near plane at 1 mm\n"
    "  gl_Position.z = gl_Position.w * vtkGlobeDepthClip.x + vtkGlobeDepthClip.y;\n");
  // Fragment depth from the exact per-fragment w (1 / gl_FragCoord.w), not interpolated z.
  const bool fsOk = Insert(fs, "uniform float vtkGlobeLogDepthScale;\n",
    "  // vtkGlobeDepthPass (logarithmic): depth = log2(1 + w) / log2(1 + far)\n"
    "  gl_FragDepth = log2(max(1e-6, 1.0 + 1.0 / gl_FragCoord.w)) * vtkGlobeLogDepthScale;\n");
  if (!vsOk || !fsOk)
  {
    vtkErrorMacro(<< "InjectDepthCode: a shader has no main(); its depth stays perspective");
  }
}

bool vtkGlobeDepthPass::PostReplaceShaderValues(
  std::string& vs, std::string&, std::string& fs, vtkAbstractMapper*, vtkProp*)
{
  this->InjectDepthCode(vs, fs);
  return true;
}

void vtkGlobeDepthPass::SetDepthUniforms(vtkShaderProgram* program)
{
  if (this->Mode != Logarithmic || !program)
  {
    return;
  }
  const double n = LogarithmicNear, f = this->LastFar;
  const float clip[2] = { static_cast<float>((f + n) / (f - n)),
    static_cast<float>(-2.0 * f * n / (f - n)) };
  if (program->IsUniformUsed("vtkGlobeDepthClip"))
  {
    program->SetUniform2f("vtkGlobeDepthClip", clip);
  }
  if (program->IsUniformUsed("vtkGlobeLogDepthScale"))
  {
    program->SetUniformf("vtkGlobeLogDepthScale", static_cast<float>(1.0 / std::log2(1.0 + f)));
  }
}

bool vtkGlobeDepthPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  this->SetDepthUniforms(program);
  return true;
}

//------------------------------------------------------------------------------
double vtkGlobeDepthPass::GetViewDistance(double windowDepth, vtkCamera* camera)
{
  if (this->Mode == Logarithmic)
  {
    return std::exp2(windowDepth * std::log2(1.0 + this->LastFar)) - 1.0;
  }
  const double n = camera->GetClippingRange()[0], f = camera->GetClippingRange()[1];
  // VTK's projection: z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) w), window z = (z_ndc + 1) / 2.
  return 2.0 * f * n / ((f + n) - (2.0 * windowDepth - 1.0) * (f - n));
}

double vtkGlobeDepthPass::GetPerspectiveDepth(double windowDepth, vtkCamera* camera)
{
  if (this->Mode == Default || windowDepth >= 1.0)
  {
    return windowDepth;
  }
  const double w = this->GetViewDistance(windowDepth, camera);
  const double n = camera->GetClippingRange()[0], f = camera->GetClippingRange()[1];
  const double ndc = (f + n) / (f - n) - 2.0 * f * n / ((f - n) * w);
  return 0.5 * (ndc + 1.0);
}

vtkGlobeDepthPass* vtkGlobeDepthPass::FindInProp(vtkProp* prop)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  if (!info || !info->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    return nullptr;
  }
  const int n = info->Length(vtkOpenGLRenderPass::RenderPasses());
  for (int i = 0; i < n; ++i)
  {
    if (auto* pass =
          vtkGlobeDepthPass::SafeDownCast(info->Get(vtkOpenGLRenderPass::RenderPasses(), i)))
    {
      return pass;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkGlobeDepthPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << GetModeAsString(this->Mode) << "\n";
  os << indent << "LastFar: " << this->LastFar << "\n";
  os << indent << "DelegatePass: " << (this->DelegatePass ? this->DelegatePass->GetClassName() : "(none)")
     << "\n";
}
