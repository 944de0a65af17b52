# Install rules, the CMake package (find_package(b2b COMPONENTS C Fortran))
# and the pkg-config files (b2b.pc, b2b-fortran.pc). Without
# B2B_ENABLE_FORTRAN only the C parts are installed.
include(CMakePackageConfigHelpers)
set(B2B_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/b2b")

install(TARGETS b2b EXPORT b2bTargetsC
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  PUBLIC_HEADER DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/b2b")
install(EXPORT b2bTargetsC FILE b2bTargets-C.cmake NAMESPACE b2b::
  DESTINATION "${B2B_INSTALL_CMAKEDIR}")

if(B2B_ENABLE_FORTRAN)
  set_target_properties(b2b_fortran PROPERTIES EXPORT_NAME fortran)
  install(TARGETS b2b_fortran EXPORT b2bTargetsFortran
    RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
    ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
  install(EXPORT b2bTargetsFortran FILE b2bTargets-Fortran.cmake NAMESPACE b2b::
    DESTINATION "${B2B_INSTALL_CMAKEDIR}")
  install(FILES "${B2B_FORTRAN_MODULE_FILE}" DESTINATION "${B2B_FORTRAN_INSTALL_MODDIR}")
  # The module source, for hosts built with another Fortran compiler.
  install(FILES ${B2B_FORTRAN_SOURCES} DESTINATION "${CMAKE_INSTALL_DATADIR}/b2b/fortran")
endif()
install(FILES "${PROJECT_SOURCE_DIR}/COPYING" DESTINATION "${CMAKE_INSTALL_DOCDIR}")

# What a program needs besides libb2b itself when libb2b is static: the C++
# runtime (what the C++ compiler links and the C compiler does not, e.g.
# -lstdc++ -lm), libm and the OpenMP runtime libb2b was built with.
get_target_property(_b2b_type b2b TYPE)
get_target_property(_b2b_links b2b LINK_LIBRARIES)
set(B2B_CONFIG_STATIC OFF)
if(_b2b_type STREQUAL "STATIC_LIBRARY")
  set(B2B_CONFIG_STATIC ON)
endif()
set(B2B_CONFIG_OPENMP OFF)
set(_b2b_private_libs "")
foreach(_lib IN LISTS CMAKE_CXX_IMPLICIT_LINK_LIBRARIES)
  if(NOT _lib IN_LIST CMAKE_C_IMPLICIT_LINK_LIBRARIES)
    if(IS_ABSOLUTE "${_lib}")
      list(APPEND _b2b_private_libs "${_lib}")
    else()
      list(APPEND _b2b_private_libs "-l${_lib}")
    endif()
  endif()
endforeach()
if("m" IN_LIST _b2b_links)
  list(APPEND _b2b_private_libs "-lm")
endif()
if("OpenMP::OpenMP_CXX" IN_LIST _b2b_links)
  set(B2B_CONFIG_OPENMP ON)
  # Found by src/ already (cached): the runtime libb2b links.
  find_package(OpenMP COMPONENTS CXX QUIET)
  foreach(_name IN LISTS OpenMP_CXX_LIB_NAMES)
    get_filename_component(_dir "${OpenMP_${_name}_LIBRARY}" DIRECTORY)
    if(_dir AND NOT _dir IN_LIST CMAKE_CXX_IMPLICIT_LINK_DIRECTORIES)
      list(APPEND _b2b_private_libs "-L${_dir}")
    endif()
    list(APPEND _b2b_private_libs "-l${_name}")
  endforeach()
endif()
list(REMOVE_DUPLICATES _b2b_private_libs)
list(JOIN _b2b_private_libs " " _b2b_private_libs)
# pkg-config: a shared libb2b carries its dependencies (Libs.private is for
# pkg-config --static); a static one needs them in every link, so they are
# part of Libs, and its users compile with B2B_STATIC_DEFINE.
if(B2B_CONFIG_STATIC)
  set(B2B_PC_LIBS "Libs: -L\${libdir} -lb2b ${_b2b_private_libs}")
  set(B2B_PC_LIBS_PRIVATE "")
  set(B2B_PC_CFLAGS "-I\${includedir} -DB2B_STATIC_DEFINE")
else()
  set(B2B_PC_LIBS "Libs: -L\${libdir} -lb2b")
  set(B2B_PC_LIBS_PRIVATE "Libs.private: ${_b2b_private_libs}")
  set(B2B_PC_CFLAGS "-I\${includedir}")
endif()
string(STRIP "${B2B_PC_LIBS}" B2B_PC_LIBS)
string(STRIP "${B2B_PC_LIBS_PRIVATE}" B2B_PC_LIBS_PRIVATE)

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
set(_b2b_pc_files b2b)
if(B2B_ENABLE_FORTRAN)
  list(APPEND _b2b_pc_files b2b-fortran)
endif()
foreach(pc IN LISTS _b2b_pc_files)
  configure_file("${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in" "${PROJECT_BINARY_DIR}/${pc}.pc" @ONLY)
  install(FILES "${PROJECT_BINARY_DIR}/${pc}.pc" DESTINATION "${B2B_PC_INSTALL_DIR}")
endforeach()
