# The deploy node: a trained policy driving a robot (odometry, scan, images and goals in, cmd_vel
# out), and jetbot_depth_scan (a depth camera's scan, as training made it).
#   jetbot_rl_deploy  the driver, its inputs and parameters (over jetbot_rl_policy's Policy and the
#                     core's task observers)
add_library(jetbot_rl_deploy
  src/ros/deploy/deploy_driver.cpp
  src/ros/deploy/depth_scan_publisher.cpp
  src/ros/deploy/deploy_node.cpp
  src/ros/deploy/deploy_params.cpp
  src/ros/deploy/dwa_local_planner.cpp
  src/ros/deploy/map_input.cpp
  src/ros/deploy/move_base_server.cpp
  src/ros/deploy/goal_pursuit.cpp
  src/ros/deploy/image_input.cpp
  src/ros/deploy/path_follower.cpp
  src/ros/deploy/planar_transform.cpp
  src/ros/deploy/scan_beams.cpp
)
target_link_libraries(jetbot_rl_deploy PUBLIC jetbot_rl_policy jetbot_rl_ros_common
  ${IMAGE_TRANSPORT_LIBRARY} PRIVATE ${OPENCV_IMGPROC_LIBRARY} ${OPENCV_CORE_LIBRARY})
target_include_directories(jetbot_rl_deploy SYSTEM PRIVATE ${OPENCV_INCLUDE_DIR})

add_executable(jetbot_deploy_node src/nodes/jetbot_deploy_node.cpp)
target_link_libraries(jetbot_deploy_node jetbot_rl_deploy)
# A robot's depth camera -> the LaserScan training made of the simulated camera's depth.
add_executable(jetbot_depth_scan src/nodes/jetbot_depth_scan.cpp)
target_link_libraries(jetbot_depth_scan jetbot_rl_deploy)

install(TARGETS jetbot_rl_deploy
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_deploy_node jetbot_depth_scan
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
