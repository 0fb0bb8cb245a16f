#include "vtkGlobeDepthPass.h"

#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
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

/// Inserts text after (or before) every occurrence of a pattern that is not in a // comment;
/// how many there were.
int InsertAt(std::string& source, const std::string& pattern, const std::string& text, bool after)
{
  int count = 0;
  for (size_t at = source.find(pattern); at != std::string::npos; at = source.find(pattern, at))
  {
    const size_t line = source.rfind('\n', at);
    const size_t comment = source.find("//", line == std::string::npos ? 0 : line);
    if (comment < at)
    {
      at += pattern.size();
      continue;
    }
    const size_t where = after ? at + pattern.size() : at;
    source.insert(where, text);
    at = where + text.size() + (after ? 0 : pattern.size());
    ++count;
  }
  return count;
}

/**
 * The logarithmic mode's code, in the last stage that writes gl_Position (the geometry shader
 * where there is one: VTK's impostor mappers project there, their vertex shader gives view
 * coordinates) and at the end of the fragment shader. Depths VTK writes itself are turned
 * into eye distances rather than overwritten (VTK 9.1's shader lines, vtkOpenGLSphereMapper,
 * vtkOpenGLStickMapper and points or lines drawn as spheres or tubes), and VTK's coincident
 * topology offset (cOffset / 65000 of the depth range) is kept as the same offset of the
 * logarithmic depth. False when a stage has no main().
 */
bool InjectLogarithmic(std::string& vs, std::string& gs, std::string& fs)
{
  const std::string clipDeclaration = "uniform vec2 vtkGlobeDepthClip;\n";
  const std::string clip = "  // vtkGlobeDepthPass (logarithmic): near plane at 1 mm\n"
                           "  gl_Position.z = gl_Position.w * vtkGlobeDepthClip.x + vtkGlobeDepthClip.y;\n";
  bool positions = false;
  const size_t gsMain = gs.find("void main");
  if (gsMain != std::string::npos && InsertAt(gs, "EmitVertex();", clip, false) > 0)
  {
    gs.insert(gsMain, clipDeclaration);
    positions = true;
  }
  else
  {
    // Clip z: a perspective z with a 1 mm near plane, so geometry up to the eye is kept (the
    // camera's near plane no longer matters); VTK's w_clip is the eye distance along the view.
    positions = Insert(vs, clipDeclaration, clip);
  }
  // Depths a mapper computes (a sphere's or tube's surface rather than its quad's): their eye
  // distance. pos = VCDCMatrix * vertexVC, so pos.w is it; VTK's points as spheres move
  // window depth d0 = S - K / w0 to (S - d0) / Q + S, i.e. to the eye distance -Q w0.
  InsertAt(fs, "gl_FragDepth = (pos.z / pos.w + 1.0) / 2.0;", "\n  vtkGlobeEyeW = pos.w;", true);
  InsertAt(fs, "gl_FragDepth = (ZCalcS - gl_FragCoord.z) / ZCalcQ + ZCalcS;",
    "\n  vtkGlobeEyeW = -ZCalcQ / gl_FragCoord.w;", true);
  InsertAt(fs, "+ 1.0*cOffset/65000;", "\n  vtkGlobeDepthBias = cOffset / 65000.0;", true);
  // Fragment depth from the exact per-fragment w (1 / gl_FragCoord.w), not interpolated z.
  const bool depth = Insert(fs,
    "uniform float vtkGlobeLogDepthScale;\n"
    "float vtkGlobeEyeW = -1.0;\n"
    "float vtkGlobeDepthBias = 0.0;\n",
    "  // vtkGlobeDepthPass (logarithmic): depth = log2(1 + w) / log2(1 + far)\n"
    "  gl_FragDepth = log2(max(1e-6, 1.0 + (vtkGlobeEyeW > 0.0 ? vtkGlobeEyeW\n"
    "                                                         : 1.0 / gl_FragCoord.w))) *\n"
    "      vtkGlobeLogDepthScale + vtkGlobeDepthBias;\n");
  return positions && depth;
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
  std::string noGeometryShader;
  if (this->Mode == Logarithmic && !InjectLogarithmic(vs, noGeometryShader, fs))
  {
    vtkErrorMacro(<< "InjectDepthCode: a shader has no main(); its depth stays perspective");
  }
}

bool vtkGlobeDepthPass::PostReplaceShaderValues(
  std::string& vs, std::string& gs, std::string& fs, vtkAbstractMapper* mapper, vtkProp*)
{
  // Polydata mappers only: the GPU volume ray caster also calls the render passes' hooks,
  // and its rays stop at the depth buffer's perspective depth (not covered, depth.md).
  if (this->Mode == Logarithmic && vtkOpenGLPolyDataMapper::SafeDownCast(mapper) &&
    !InjectLogarithmic(vs, gs, fs))
  {
    vtkErrorMacro(<< "PostReplaceShaderValues: a shader has no main(); its depth stays perspective");
  }
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
