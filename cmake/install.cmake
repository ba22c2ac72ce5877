# Install rules and the exported package: find_package(stickslip) then link
# stickslip::stickslip.
include(CMakePackageConfigHelpers)

install(TARGETS stickslip EXPORT stickslipTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/stickslip DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
install(TARGETS ${STICKSLIP_APP_TARGETS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff
  DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/stickslip)

set(STICKSLIP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/stickslip)
install(EXPORT stickslipTargets NAMESPACE stickslip:: DESTINATION ${STICKSLIP_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/stickslipConfig.cmake.in
  ${PROJECT_BINARY_DIR}/stickslipConfig.cmake INSTALL_DESTINATION ${STICKSLIP_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/stickslipConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/stickslipConfig.cmake
  ${PROJECT_BINARY_DIR}/stickslipConfigVersion.cmake DESTINATION ${STICKSLIP_CMAKE_DIR})

# The Python package (python/CMakeLists.txt says where and why there).
if(TARGET stickslip_python)
  set(py_dest ${STICKSLIP_PYTHON_INSTALL_DIR}/stickslip)
  install(TARGETS stickslip_python LIBRARY DESTINATION ${py_dest})
  foreach(f ${STICKSLIP_PY_FILES})
    install(FILES ${PROJECT_SOURCE_DIR}/python/stickslip/${f} DESTINATION ${py_dest})
  endforeach()
endif()
