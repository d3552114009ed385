# `cmake --install build --prefix P`: the headers, the three libraries, the `ridefit` command and a
# CMake package, so that a project with CMAKE_PREFIX_PATH=P writes
#   find_package(ridefit 0.1 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE ridefit::core ridefit::fitting ridefit::optimisation)
# (tests/package/ builds such a consumer against an install in a temporary prefix).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(RIDEFIT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/ridefit)

install(TARGETS ridefit_core ridefit_fitting ridefit_optimisation ridefit_sundials
        EXPORT ridefitTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ridefit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Headers keep their include paths: ridefit/model/quarter_car.h, ridefit/fitting/..., ...
foreach(dir src fitting optimisation)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ridefit
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/src/generated/ridefit/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ridefit)

install(EXPORT ridefitTargets NAMESPACE ridefit:: DESTINATION ${RIDEFIT_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ridefitConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ridefitConfig.cmake
                              INSTALL_DESTINATION ${RIDEFIT_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ridefitConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ridefitConfig.cmake
              ${PROJECT_BINARY_DIR}/ridefitConfigVersion.cmake
        DESTINATION ${RIDEFIT_CMAKE_DIR})
