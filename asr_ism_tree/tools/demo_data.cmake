# `asr_demo_data`: writes the suite's own breakfast demo data (included by tools/CMakeLists.txt).
add_executable(asr_demo_data ${CMAKE_CURRENT_LIST_DIR}/demo_data.cpp)
target_link_libraries(asr_demo_data asr_ism_tree_cli)
target_compile_options(asr_demo_data PRIVATE -Wall -Wextra)
install(TARGETS asr_demo_data RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
