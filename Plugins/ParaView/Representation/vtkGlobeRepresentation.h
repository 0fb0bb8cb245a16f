/**
 * @class   vtkGlobeRepresentation
 * @brief   ParaView's "Globe" representation: a georeferenced raster as one layer of the globe
 *          of its render view.
 *
 * Every raster shown as "Globe" in a render view (the output of the Globe Raster Reader, or of
 * any image filter that keeps its georeferencing field data) becomes one vtkGlobeLayer of a
 * single vtkGlobeMapper that the view's representations share: the pipeline browser is the
 * layer list (the eye shows or hides a layer), and each representation's properties are its
 * layer's (role, blend mode, opacity, draw order, value scale and offset, feather,
 * interpolation). The globe's own settings (body, grid, refinement, effects) are properties
 * of every Globe representation and set the view's one globe: for each setting, its last
 * change in any of them is in force. The globe's actor is in the view's renderer, so it
 * shares the depth buffer with every other representation, and IceT composites it by depth.
 *
 * Each rendering process draws the whole globe with the whole raster: the representation
 * asks its input for the whole extent as piece 0 of 1 on every rank (a raster layer is
 * small next to distributed geometry), so under MPI every rank's globe is the same and
 * depth compositing is exact. A time-varying input (a series of rasters) follows the view's
 * time; a new step re-uploads that layer alone. Documentation/user-guide.md, "ParaView".
 */
#ifndef vtkGlobeRepresentation_h
#define vtkGlobeRepresentation_h

#include "vtkGlobeParaViewModule.h" // for export macro
#include "vtkNew.h"                 // for vtkNew
#include "vtkPVDataRepresentation.h"
#include "vtkType.h" // for vtkMTimeType

#include <memory> // for std::shared_ptr

class vtkGlobeLayer;
class vtkImageData;
struct vtkGlobeRepresentationGlobe;

class VTKGLOBEPARAVIEW_EXPORT vtkGlobeRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkGlobeRepresentation* New();
  vtkTypeMacro(vtkGlobeRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;
  void SetVisibility(bool visible) override;

  ///@{
  /**
   * This raster's layer (vtkGlobeLayer's settings of the same names). LayerRole is one of
   * vtkGlobeLayer::Roles, or -1 (the default): automatic, Color for a raster of 3 or 4
   * channels and Height for one of 1.
   */
  void SetLayerRole(int role);
  vtkGetMacro(LayerRole, int);
  void SetBlendMode(int mode);
  void SetOpacity(double opacity);
  void SetDrawOrder(int order);
  void SetValueScale(double scale);
  void SetValueOffset(double offset);
  void SetFeatherWidth(double texels);
  void SetInterpolation(int interpolation);
  vtkGlobeLayer* GetLayer();
  ///@}

  ///@{
  /**
   * The view's globe: Body 0 is WGS 84, 1 the Moon, 2 Mars; the mapper's GridPixelsPerCell,
   * TerrainRefinement, AutoAdjustDetail (ParaView's interactive renders ask for 5 frames/s)
   * and effects (Lighting, Atmosphere, Graticule, NightLights, SpecularWater, Contours).
   */
  void SetBody(int body);
  vtkGetMacro(Body, int);
  void SetGridPixelsPerCell(double pixels);
  vtkGetMacro(GridPixelsPerCell, double);
  void SetTerrainRefinement(int steps);
  vtkGetMacro(TerrainRefinement, int);
  void SetAutoAdjustDetail(bool on);
  vtkGetMacro(AutoAdjustDetail, bool);
  void SetLighting(bool on);
  vtkGetMacro(Lighting, bool);
  void SetAtmosphere(bool on);
  vtkGetMacro(Atmosphere, bool);
  void SetGraticule(bool on);
  vtkGetMacro(Graticule, bool);
  void SetNightLights(bool on);
  vtkGetMacro(NightLights, bool);
  void SetSpecularWater(bool on);
  vtkGetMacro(SpecularWater, bool);
  void SetContours(bool on);
  vtkGetMacro(Contours, bool);
  ///@}

  /// The globe settings above, each in force as last changed in any of the view's Globe
  /// representations.
  enum GlobeSettings
  {
    BodySetting,
    GridSetting,
    RefinementSetting,
    DetailSetting,
    LightingSetting,
    AtmosphereSetting,
    GraticuleSetting,
    NightLightsSetting,
    SpecularWaterSetting,
    ContoursSetting,
    NumberOfGlobeSettings
  };

  /// The number of layers the globe of this representation's view holds (0 when not in a view).
  int GetNumberOfGlobeLayers();
  /// Textures the view's globe has uploaded so far (vtkGlobeLayerSet::GetNumberOfUploads).
  int GetNumberOfGlobeUploads();

protected:
  vtkGlobeRepresentation();
  ~vtkGlobeRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

  int LayerRole = -1;
  int Body = 0;
  double GridPixelsPerCell = 1.6;
  int TerrainRefinement = 1;
  bool AutoAdjustDetail = true; // as vtkGlobeMapper
  bool Lighting = true; // as vtkGlobeMapper
  bool Atmosphere = false;
  bool Graticule = false;
  bool NightLights = false;
  bool SpecularWater = false;
  bool Contours = false;

private:
  vtkGlobeRepresentation(const vtkGlobeRepresentation&) = delete;
  void operator=(const vtkGlobeRepresentation&) = delete;

  void GlobeSettingChanged(int setting);
  void ApplyLayerRole();
  void ApplyGlobeSettings(bool all = false);

  // The globe of the view this representation is in, shared with the view's other ones.
  std::shared_ptr<vtkGlobeRepresentationGlobe> ViewGlobe;
  vtkNew<vtkGlobeLayer> Layer;
  vtkNew<vtkImageData> Cache;     // the input raster, handed to the view for delivery
  vtkNew<vtkImageData> Shown;     // the delivered raster, the layer's input
  vtkMTimeType SettingTimes[NumberOfGlobeSettings] = {}; // when each was changed here
  bool InGlobe = false;           // the layer is one of the view's globe's
};

#endif
