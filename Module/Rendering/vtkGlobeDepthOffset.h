/**
 * @class   vtkGlobeDepthOffset
 * @brief   Draws an actor's lines and points a little in front of the terrain, by an offset
 *          that grows with distance like the terrain's own error, so draped lines show
 *          without gaps.
 *
 * A line clamped onto the composed terrain (vtkGlobeTerrainClamp) lies on the terrain the CPU
 * computes; the GPU draws the terrain through a grid of planar triangles (vtkGlobeTerrain
 * states the bound), so between its vertices the line dips into the drawn terrain and breaks
 * into gaps. Lifting the line by a fixed height cannot fix every distance: a metre suffices at
 * 1 km and is far too little at 100 km, where the grid's triangles are hundreds of metres.
 *
 * Apply(actor, offset) adds one line to the actor's vertex shader (a vtkShaderProperty
 * replacement, the same program for any mapper):
 *   gl_Position.z -= offset * gl_Position.w
 * which moves each vertex's normalized depth forward by `offset`, leaving its screen position
 * unchanged: in view distance d, with VTK's perspective depth and near plane n, it is drawn as
 * if offset * d^2 / (2 n) nearer (with vtkGlobeClippingRange's near plane, about 2 m at 1 km
 * above the ground and 300 m at 100 km for the default 2e-3), the scale at which the grid's
 * triangles grow. Terrain nearer than that in front of the line no longer hides it.
 *
 * The offset applies to VTK's perspective depth (vtkGlobeDepthPass Default mode, the default);
 * with the Logarithmic mode the pass recomputes depth from the distance and the offset has no
 * effect. Remove(actor) takes the replacement away.
 */
#ifndef vtkGlobeDepthOffset_h
#define vtkGlobeDepthOffset_h

#include "vtkGlobeRenderingModule.h" // for export macro
#include "vtkObject.h"

class vtkActor;

class VTKGLOBERENDERING_EXPORT vtkGlobeDepthOffset : public vtkObject
{
public:
  static vtkGlobeDepthOffset* New();
  vtkTypeMacro(vtkGlobeDepthOffset, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The offset used by the examples and tests: 2e-3 of normalized depth.
  static double GetDefaultOffset() { return 2e-3; }

  /// Draws the actor `offset` (normalized device depth, in (0, 1)) nearer; replaces an offset
  /// applied before. False (with an error) without an actor or for an offset outside (0, 1).
  static bool Apply(vtkActor* actor, double offset);

  /// Removes the offset (no-op for an actor without one).
  static void Remove(vtkActor* actor);

protected:
  vtkGlobeDepthOffset() = default;
  ~vtkGlobeDepthOffset() override = default;

private:
  vtkGlobeDepthOffset(const vtkGlobeDepthOffset&) = delete;
  void operator=(const vtkGlobeDepthOffset&) = delete;
};

#endif
