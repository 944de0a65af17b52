# Target doc: the API reference of the public C headers by Doxygen
# (cmake/Doxyfile.in), in <build>/doc/api/html/. Any Doxygen warning fails
# it. Not part of the default build; scripts/quickstart.sh doc builds it (CI).
# Without Doxygen the target exists and fails, saying so.
find_package(Doxygen QUIET)
set(B2B_DOC_OUTPUT_DIR "${PROJECT_BINARY_DIR}/doc/api")
if(DOXYGEN_FOUND)
  # The headers as installed: the generated b2b_version.h, not its template;
  # b2b_export.h holds only the export macros.
  set(B2B_DOC_INPUT
      "\"${PROJECT_SOURCE_DIR}/include/b2b/b2b.h\" \"${PROJECT_SOURCE_DIR}/include/b2b/b2b_curve.h\" \"${PROJECT_SOURCE_DIR}/include/b2b/b2b_pair.h\" \"${PROJECT_SOURCE_DIR}/include/b2b/b2b_model.h\" \"${PROJECT_BINARY_DIR}/include/b2b/b2b_version.h\"")
  configure_file("${PROJECT_SOURCE_DIR}/cmake/Doxyfile.in" "${PROJECT_BINARY_DIR}/doc/Doxyfile" @ONLY)
  add_custom_target(doc
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${B2B_DOC_OUTPUT_DIR}"
    COMMAND Doxygen::doxygen "${PROJECT_BINARY_DIR}/doc/Doxyfile"
    DEPENDS "${PROJECT_SOURCE_DIR}/cmake/doxygen_filter.sed"
    WORKING_DIRECTORY "${PROJECT_BINARY_DIR}/doc"
    COMMENT "API reference (Doxygen ${DOXYGEN_VERSION}) in ${B2B_DOC_OUTPUT_DIR}/html"
    VERBATIM)
else()
  add_custom_target(doc
    COMMAND "${CMAKE_COMMAND}" -E echo "doc: Doxygen was not found (Debian: doxygen); install it and configure again"
    COMMAND "${CMAKE_COMMAND}" -E false
    VERBATIM)
endif()
