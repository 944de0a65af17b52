# Install rules, the CMake package (find_package(b2b COMPONENTS C Fortran))
# and the pkg-config files (b2b.pc, b2b-fortran.pc).
include(CMakePackageConfigHelpers)
set(B2B_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/b2b")

install(TARGETS b2b EXPORT b2bTargetsC
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  PUBLIC_HEADER DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/b2b")
install(EXPORT b2bTargetsC FILE b2bTargets-C.cmake NAMESPACE b2b::
  DESTINATION "${B2B_INSTALL_CMAKEDIR}")

set_target_properties(b2b_fortran PROPERTIES EXPORT_NAME fortran)
install(TARGETS b2b_fortran EXPORT b2bTargetsFortran
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(EXPORT b2bTargetsFortran FILE b2bTargets-Fortran.cmake NAMESPACE b2b::
  DESTINATION "${B2B_INSTALL_CMAKEDIR}")
install(FILES "${B2B_FORTRAN_MODULE_FILE}" DESTINATION "${B2B_FORTRAN_INSTALL_MODDIR}")
# The module source, for hosts built with another Fortran compiler.
install(FILES ${B2B_FORTRAN_SOURCES} DESTINATION "${CMAKE_INSTALL_DATADIR}/b2b/fortran")
install(FILES "${PROJECT_SOURCE_DIR}/COPYING" DESTINATION "${CMAKE_INSTALL_DOCDIR}")

configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/b2bConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/b2bConfig.cmake"
  INSTALL_DESTINATION "${B2B_INSTALL_CMAKEDIR}")
# The release version follows the ABI: same major, same promise.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/b2bConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMajorVersion)
install(FILES "${PROJECT_BINARY_DIR}/b2bConfig.cmake" "${PROJECT_BINARY_DIR}/b2bConfigVersion.cmake"
  DESTINATION "${B2B_INSTALL_CMAKEDIR}")

# pkg-config files locate the prefix relative to themselves (relocatable).
set(B2B_PC_INSTALL_DIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
file(RELATIVE_PATH B2B_PC_TO_PREFIX "/root/${B2B_PC_INSTALL_DIR}" "/root")
string(REGEX REPLACE "/$" "" B2B_PC_TO_PREFIX "${B2B_PC_TO_PREFIX}")
foreach(pc b2b b2b-fortran)
  configure_file("${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in" "${PROJECT_BINARY_DIR}/${pc}.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/${pc}.pc" DESTINATION "${B2B_PC_INSTALL_DIR}")
endforeach()
