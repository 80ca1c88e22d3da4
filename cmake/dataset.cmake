# The Jetbot notebooks' data sets from simulated worlds (src/dataset/, docs/dataset.md):
#   jetbot_rl_dataset  collision avoidance's blocked/free and road following's xy_ images (JPEG)
add_library(jetbot_rl_dataset_writer src/dataset/notebook_dataset.cpp)
target_link_libraries(jetbot_rl_dataset_writer PUBLIC jetbot_rl_core ${STB_LIBRARIES})
add_executable(jetbot_rl_dataset src/nodes/dataset_main.cpp)
target_link_libraries(jetbot_rl_dataset jetbot_rl_dataset_writer)
target_compile_definitions(jetbot_rl_dataset PRIVATE
  JETBOT_RL_CAMERA_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot_camera.urdf")

install(TARGETS jetbot_rl_dataset_writer
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_rl_dataset RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
