# Install rules and the exported package: find_package(stickslip) then link
# stickslip::stickslip (and stickslip::model_file to read model files).
include(CMakePackageConfigHelpers)

install(TARGETS stickslip stickslip_model_file stickslip_model_file_core stickslip_model_compiler
  EXPORT stickslipTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# Model files from C++: ReadModel / ParseModel (the rest of systems/model_file is private).
install(FILES ${PROJECT_SOURCE_DIR}/systems/model_file/model_file.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stickslip)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/stickslip DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")
install(TARGETS ${STICKSLIP_APP_TARGETS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The apps' model compiler, loaded when they read a model file (CMakeLists.txt).
install(TARGETS stickslip_model_compiler_module LIBRARY DESTINATION ${STICKSLIP_MODEL_MODULE_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/CITATION.cff
  ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/stickslip)
# The docs (with their figures) and the studies: `--study NAME` finds an
# installed study by name (src/cli/study_path.cpp).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/stickslip)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/studies/ DESTINATION ${CMAKE_INSTALL_DATADIR}/stickslip/studies
  FILES_MATCHING PATTERN "*.ini")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/notebooks/
  DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/stickslip/examples/notebooks OPTIONAL
  FILES_MATCHING PATTERN "*.ipynb")

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
