#include "vtkGlobeDepthOffset.h"

#include "vtkActor.h"
#include "vtkObjectFactory.h"
#include "vtkShaderProperty.h"
#include "vtkUniforms.h"

vtkStandardNewMacro(vtkGlobeDepthOffset);

namespace
{
// After VTK's own position code (the replacement is applied first, so VTK's code replaces
// the tag it keeps at the front): the normalized depth moves forward, x, y and w stay.
const char* const Tag = "//VTK::PositionVC::Impl";
const char* const Uniform = "vtkGlobeDepthOffset";
}

bool vtkGlobeDepthOffset::Apply(vtkActor* actor, double offset)
{
  if (!actor)
  {
    vtkGenericWarningMacro(<< "vtkGlobeDepthOffset::Apply: no actor");
    return false;
  }
  if (!(offset > 0.0 && offset < 1.0))
  {
    vtkErrorWithObjectMacro(actor, << "vtkGlobeDepthOffset::Apply: the offset " << offset
                                   << " is not in (0, 1) (normalized device depth)");
    return false;
  }
  vtkShaderProperty* property = actor->GetShaderProperty();
  property->ClearVertexShaderReplacement(Tag, true);
  property->AddVertexShaderReplacement(Tag, true,
    std::string(Tag) + "\n  // vtkGlobeDepthOffset: nearer in depth, same pixel\n" +
      "  gl_Position.z -= " + Uniform + " * gl_Position.w;\n",
    false);
  property->GetVertexCustomUniforms()->SetUniformf(Uniform, static_cast<float>(offset));
  return true;
}

void vtkGlobeDepthOffset::Remove(vtkActor* actor)
{
  if (!actor)
  {
    return;
  }
  vtkShaderProperty* property = actor->GetShaderProperty();
  property->ClearVertexShaderReplacement(Tag, true);
  property->GetVertexCustomUniforms()->RemoveUniform(Uniform);
}

void vtkGlobeDepthOffset::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DefaultOffset: " << GetDefaultOffset() << "\n";
}
