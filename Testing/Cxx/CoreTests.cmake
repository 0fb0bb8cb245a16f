# Tests of VTKGlobe::Core (no OpenGL).
set(globe_core_tests
  TestGlobeEllipsoidGeographicLib.cxx
  TestGlobeEllipsoidBadInput.cxx
  TestGlobeTriaxialEllipsoid.cxx
  TestGlobeShaderMathEllipsoid.cxx
  TestGlobeNewtonIterations.cxx
  TestGlobeGeodeticTransform.cxx
  TestGlobeLayerRead.cxx
  TestGlobeLayerBadInput.cxx
  TestGlobeLayerGeoTIFF.cxx
  TestGlobeLayerVoidFill.cxx
  TestGlobeRasterReader.cxx
  TestGlobeRasterReaderHardening.cxx
  TestGlobeRasterReaderSeries.cxx
  TestGlobeLayerInput.cxx
  TestGlobeLayerReprojection.cxx
  TestGlobeFeatherDistance.cxx
  TestGlobeMapProjection.cxx
  TestGlobeMapProjectionShader.cxx
  TestGlobePageSource.cxx
  TestGlobeLayerLevels.cxx)

create_test_sourcelist(_globe_core_driver_sources GlobeCoreCxxTests.cxx ${globe_core_tests})
add_executable(GlobeCoreCxxTests ${_globe_core_driver_sources})
# The layer tests read the data with OpenImageIO directly (the reference for pixel values)
# and write small TIFF, PNG and GeoTIFF files with OpenImageIO, libtiff and libgeotiff.
target_include_directories(GlobeCoreCxxTests PRIVATE "${OIIO_INCLUDE_DIR}" "${GEOTIFF_INCLUDE_DIR}")
target_link_libraries(GlobeCoreCxxTests PRIVATE
  GlobeTestSupport VTK::CommonTransforms VTK::FiltersGeneral VTK::FiltersSources VTK::TestingCore
  VTK::ImagingCore VTK::ImagingGeneral
  "${OIIO_LIBRARY}" "${OIIO_UTIL_LIBRARY}" "${GEOTIFF_LIBRARY}" TIFF::TIFF PROJ::proj)
target_compile_definitions(GlobeCoreCxxTests PRIVATE
  "VTKGLOBE_TEMP_DIR=\"${CMAKE_CURRENT_BINARY_DIR}/Temporary\"")
file(MAKE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/Temporary")

foreach (test_file IN LISTS globe_core_tests)
  get_filename_component(test_name "${test_file}" NAME_WE)
  add_test(NAME "Core.${test_name}" COMMAND GlobeCoreCxxTests "${test_name}")
  set_tests_properties("Core.${test_name}" PROPERTIES TIMEOUT 300)
endforeach ()
