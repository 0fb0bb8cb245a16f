#include "vtkGlobeMapperTesting.h"

#include "vtkGlobeMapper.h"

vtkTextureObject* vtkGlobeMapperTesting::GetGBufferTexture(vtkGlobeMapper* mapper)
{
  return mapper ? mapper->GetGBufferTexture() : nullptr;
}

vtkTextureObject* vtkGlobeMapperTesting::GetGBufferDepthTexture(vtkGlobeMapper* mapper)
{
  return mapper ? mapper->GetGBufferDepthTexture() : nullptr;
}
