# Each doctest test suite is one ctest test, so `ctest` output names the area that failed.
set(RASTER_TEST_SUITES format simd math_methods methods geometry texture hostile gl_backend raster_vs_gl derivatives shadow_compare shaders scene_shadow scene_deferred determinism cli assets gl_math hdr_features scene_hdr image_io)
foreach(suite ${RASTER_TEST_SUITES})
  add_test(NAME ${suite} COMMAND raster_tests --test-suite=${suite} --no-intro)
  set_tests_properties(${suite} PROPERTIES ENVIRONMENT "RASTER_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
endforeach()
