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
  TestGlobeLayerPipeline.cxx)
# Depth for the whole scene: clipping policy, depth modes, picking.
list(APPEND globe_rendering_tests
  TestGlobeClippingRange.cxx
  TestGlobeDepthModes.cxx)

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
  TestGlobeSatelliteLimb.cxx)
# Geodetic precision (issue 5): 0.5 m data at +-180 degrees and +-80 degrees as at (0, 0).
list(APPEND globe_rendering_tests
  TestGlobeGeodeticPrecision.cxx)
# Reliability (issue 16): extreme heights, layers removed while loading, failures reported
# once, cameras that see nothing reported once.
list(APPEND globe_rendering_tests
  TestGlobeReliability.cxx)

create_test_sourcelist(_globe_rendering_driver_sources GlobeRenderingCxxTests.cxx
  ${globe_rendering_tests}
  EXTRA_INCLUDE vtkTestDriver.h)
add_executable(GlobeRenderingCxxTests ${_globe_rendering_driver_sources})
target_link_libraries(GlobeRenderingCxxTests PRIVATE
  GlobeTestSupport VTKGlobe::Rendering VTK::RenderingCore VTK::RenderingOpenGL2
  VTK::TestingRendering VTK::FiltersSources VTK::IOImage VTK::InteractionStyle VTK::opengl
  VTK::ImagingCore)
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
