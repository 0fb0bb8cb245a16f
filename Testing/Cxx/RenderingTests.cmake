# Tests of VTKGlobe::Rendering (OpenGL, run under Xvfb). Image tests compare with baselines in
# Testing/Baseline (VTK's vtkRegressionTestImageThreshold); a missing or failing image is written
# to the build's Testing/Temporary folder for inspection.
set(globe_rendering_tests
  TestGlobeComposition.cxx
  TestGlobeEffects.cxx
  TestGlobeEverestHorizon.cxx
  TestGlobeFarAway.cxx
  TestGlobeGridPass.cxx
  TestGlobeInsets.cxx
  TestGlobeLookingAway.cxx
  TestGlobeMapProjectionGPU.cxx
  TestGlobeMoon.cxx
  TestGlobeNadir.cxx
  TestGlobeProjectedLayers.cxx
  TestGlobeRainier.cxx
  TestGlobeRedundantWork.cxx
  TestGlobeRenderBadInput.cxx
  TestGlobeSharedDepth.cxx
  TestGlobeWholeEarth.cxx
  TestGlobeLayerPipeline.cxx
  TestGlobeTimeSeries.cxx)
# Depth for the whole scene: clipping policy, depth modes, picking.
list(APPEND globe_rendering_tests
  TestGlobeClippingRange.cxx
  TestGlobeDepthModes.cxx
  # Logarithmic depth for impostors, points as spheres and surfaces with edges.
  TestGlobeDepthActors.cxx)

# Hard cases (issue 5, Documentation/depth.md "Hard cases"): each scene in both depth modes.
list(APPEND globe_rendering_tests
  TestGlobeEverestSummit.cxx
  TestGlobeNorthPole.cxx
  TestGlobeNadirLow.cxx
  TestGlobeVeryFar.cxx
  TestGlobeMoonSurface.cxx
  TestGlobeDeadSea.cxx
  TestGlobeInsideBody.cxx
  TestGlobePGMErrata.cxx)
# Precision: sub-pixel jitter of the globe and a companion actor; the satellite over the limb.
list(APPEND globe_rendering_tests
  TestGlobeJitter.cxx
  TestGlobeSatelliteLimb.cxx
  TestGlobeTerrainRefinement.cxx
  TestGlobeTemporalStability.cxx
  TestGlobeInteractiveDetail.cxx
  TestGlobeFeatherReach.cxx
  TestGlobeColorMatch.cxx)
# Insets without walls: the rendered slope across the SRTM insets' borders against the data's.
list(APPEND globe_rendering_tests
  TestGlobeInsetWalls.cxx)
# The sky from the ground and the limb from space (the atmosphere effect), with baselines.
list(APPEND globe_rendering_tests
  TestGlobeSky.cxx
  TestGlobeLimb.cxx)
# The limb at any grid: grid points past the limb take their horizon point (issue 18's
# refinement needs coarse grids that keep the silhouette).
list(APPEND globe_rendering_tests
  TestGlobeLimbCoverage.cxx)
# Geodetic precision (issue 5): 0.5 m data at +-180 degrees and +-80 degrees as at (0, 0).
list(APPEND globe_rendering_tests
  TestGlobeGeodeticPrecision.cxx)
# Geodetic correctness (issue 18): projected layers at the poles and the antimeridian; heights
# above the EGM96 geoid against PROJ.
list(APPEND globe_rendering_tests
  TestGlobeGeodeticEdges.cxx
  TestGlobeVerticalDatum.cxx
  # Heights filtered with float weights, not the texture unit's 8-bit ones.
  TestGlobeHeightFiltering.cxx)
# Cost (issue 19): layers out of the view are culled, and the composition skips the sky,
# without changing a pixel.
list(APPEND globe_rendering_tests
  TestGlobeLayerCulling.cxx
  TestGlobeCompositeCulling.cxx)
# Pictures (issue 14): heights coloured by any vtkScalarsToColors.
list(APPEND globe_rendering_tests
  TestGlobeHeightColors.cxx
  # Issue 14: distant terrain filtered to the footprint, flicker and speckle against a
  # supersampled reference.
  TestGlobeAliasing.cxx)
# Reliability (issue 16): extreme heights, layers removed while loading, failures reported
# once, cameras that see nothing reported once.
list(APPEND globe_rendering_tests
  TestGlobeReliability.cxx)
# Streamed layers (issue "Planetary-scale data"): a self-encoding raster through a GPU page
# cache of 8 pages (0 wrong texels, levels within one, no undefined texel, no load without
# need), and a raster many times the caches with bounded RSS.
list(APPEND globe_rendering_tests
  TestGlobeStreaming.cxx)
# Exact page addressing: a 2^20-wide self-encoding raster, written with libtiff.
list(APPEND globe_rendering_tests
  TestGlobeStreamingAddressing.cxx)
# Interaction (issue 13): vtkGlobeInteractorStyle driven by vtkInteractorEventRecorder on the
# Earth (the stream in Testing/Data/Events), the Moon and a triaxial body.
list(APPEND globe_rendering_tests
  TestGlobeInteractorStyle.cxx)
# Terrain queries (issue 13): vtkGlobeTerrain against PROJ, arithmetic and the depth buffer;
# vtkGlobeTerrainClamp's points on it and along GeographicLib's geodesics.
list(APPEND globe_rendering_tests
  TestGlobeTerrainQuery.cxx
  TestGlobeTerrainClamp.cxx)
# Draped lines without gaps at 1 km and 100 km (vtkGlobeTerrainClamp + vtkGlobeDepthOffset).
list(APPEND globe_rendering_tests
  TestGlobeDrapedTrack.cxx)
# Camera helpers: look at (lon, lat, height) by heading, tilt and range; fly-to views.
list(APPEND globe_rendering_tests
  TestGlobeCamera.cxx)

create_test_sourcelist(_globe_rendering_driver_sources GlobeRenderingCxxTests.cxx
  ${globe_rendering_tests}
  EXTRA_INCLUDE vtkTestDriver.h)
add_executable(GlobeRenderingCxxTests ${_globe_rendering_driver_sources})
target_link_libraries(GlobeRenderingCxxTests PRIVATE
  GlobeTestSupport VTKGlobe::Rendering VTK::RenderingCore VTK::RenderingOpenGL2
  VTK::TestingRendering VTK::FiltersSources VTK::IOImage VTK::InteractionStyle VTK::RenderingUI VTK::opengl
  VTK::ImagingCore PROJ::proj TIFF::TIFF)
vtk_module_autoinit(TARGETS GlobeRenderingCxxTests
  MODULES VTK::RenderingOpenGL2 VTK::InteractionStyle)

set(_globe_baselines "${PROJECT_SOURCE_DIR}/Testing/Baseline")
set(_globe_temporary "${CMAKE_BINARY_DIR}/Testing/Temporary")
file(MAKE_DIRECTORY "${_globe_temporary}")
# The insets once more, feathered, against their own baseline.
add_test(NAME "Rendering.TestGlobeInsetsFeathered"
  COMMAND GlobeRenderingCxxTests TestGlobeInsets -feather
    -D "${VTKGLOBE_DATA_DIR}"
    -T "${_globe_temporary}"
    -V "${_globe_baselines}/TestGlobeInsetsFeathered.png")
set_tests_properties("Rendering.TestGlobeInsetsFeathered" PROPERTIES TIMEOUT 600)
target_compile_definitions(GlobeRenderingCxxTests PRIVATE
  "VTKGLOBE_TEMP_DIR=\"${_globe_temporary}\"")
foreach (test_file IN LISTS globe_rendering_tests)
  get_filename_component(test_name "${test_file}" NAME_WE)
  add_test(NAME "Rendering.${test_name}"
    COMMAND GlobeRenderingCxxTests "${test_name}"
      -D "${VTKGLOBE_DATA_DIR}"
      -T "${_globe_temporary}"
      -V "${_globe_baselines}/${test_name}.png")
  set_tests_properties("Rendering.${test_name}" PROPERTIES TIMEOUT 600)
endforeach ()

# The same scenes with their layers streamed (VTKGLOBE_TEST_STREAMING=1: every file layer
# through the GPU page cache in pages of 64^2, each frame waiting for its pages): the same
# per-pixel bounds and baselines hold once refinement settled (issue "Planetary-scale data"),
# their references filtered to the footprint as both paths filter.
set(globe_streamed_tests
  TestGlobeRainier
  TestGlobeEverestSummit
  TestGlobeInsets
  TestGlobeEverestHorizon
  TestGlobeWholeEarth
  TestGlobeNadir
  TestGlobeDeadSea
  TestGlobeMoonSurface
  TestGlobeSharedDepth
  TestGlobeProjectedLayers
  TestGlobeNorthPole
  TestGlobeTemporalStability
  TestGlobeInteractiveDetail
  TestGlobeInsetWalls)
foreach (test_name IN LISTS globe_streamed_tests)
  add_test(NAME "Streamed.${test_name}"
    COMMAND GlobeRenderingCxxTests "${test_name}"
      -D "${VTKGLOBE_DATA_DIR}"
      -T "${_globe_temporary}"
      -V "${_globe_baselines}/${test_name}.png")
  set_tests_properties("Streamed.${test_name}" PROPERTIES
    TIMEOUT 600 ENVIRONMENT "VTKGLOBE_TEST_STREAMING=1")
endforeach ()
# The same scenes with VTK's anti-aliasing (issue "Pictures": the globe renders correctly with
# vtkRenderer::UseFXAAOn and with multisampled windows): FXAA on, and a window that asks for 8
# samples (VTK's default; off-screen llvmpipe gives 4), against the same terrain checks and
# baselines. SharedDepth runs with FXAA only: its satellite check reads a VTK sphere's depth at
# a pixel centre, which a resolved multisampled depth is not (Documentation/rendering.md
# "Anti-aliasing").
set(globe_antialiased_tests
  TestGlobeRainier
  TestGlobeEverestHorizon
  TestGlobeSharedDepth)
foreach (test_name IN LISTS globe_antialiased_tests)
  set(_globe_variants AntiAliased Multisampled)
  if (test_name STREQUAL "TestGlobeSharedDepth")
    set(_globe_variants AntiAliased)
  endif ()
  foreach (variant IN LISTS _globe_variants)
    add_test(NAME "${variant}.${test_name}"
      COMMAND GlobeRenderingCxxTests "${test_name}"
        -D "${VTKGLOBE_DATA_DIR}"
        -T "${_globe_temporary}"
        -V "${_globe_baselines}/${test_name}.png")
    if (variant STREQUAL "AntiAliased")
      set(_globe_env "VTKGLOBE_TEST_FXAA=1")
    else ()
      set(_globe_env "VTKGLOBE_TEST_MULTISAMPLES=8")
    endif ()
    set_tests_properties("${variant}.${test_name}" PROPERTIES TIMEOUT 600 ENVIRONMENT "${_globe_env}")
  endforeach ()
endforeach ()
# The same scenes with heights filtered in the shader (VTKGLOBE_TEST_HEIGHT_FILTERING=shader):
# the path of GPUs whose texture unit filters with 8-bit weights, which llvmpipe's automatic
# choice does not take (Documentation/composition.md "Exact height filtering"), whole and
# streamed, against the same checks and baselines.
set(globe_shader_filtered_tests
  TestGlobeRainier
  TestGlobeEverestSummit
  TestGlobeInsetWalls
  TestGlobeProjectedLayers
  TestGlobeNorthPole)
foreach (test_name IN LISTS globe_shader_filtered_tests)
  foreach (variant IN ITEMS ShaderFiltered ShaderFilteredStreamed)
    add_test(NAME "${variant}.${test_name}"
      COMMAND GlobeRenderingCxxTests "${test_name}"
        -D "${VTKGLOBE_DATA_DIR}"
        -T "${_globe_temporary}"
        -V "${_globe_baselines}/${test_name}.png")
    set(_globe_env "VTKGLOBE_TEST_HEIGHT_FILTERING=shader")
    if (variant STREQUAL "ShaderFilteredStreamed")
      list(APPEND _globe_env "VTKGLOBE_TEST_STREAMING=1")
    endif ()
    set_tests_properties("${variant}.${test_name}" PROPERTIES TIMEOUT 600 ENVIRONMENT "${_globe_env}")
  endforeach ()
endforeach ()
# TestGlobeTerrainClamp checks geodesics with GeographicLib.
target_link_libraries(GlobeRenderingCxxTests PRIVATE ${GeographicLib_LIBRARIES})
