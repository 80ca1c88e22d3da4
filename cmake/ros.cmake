# The ROS adapter, one library per side (docs/architecture.md):
#   jetbot_rl_ros_common  helpers both sides use: bounded deserialisation, parameters, signals, ...
#   jetbot_rl_env_node    the env node's server side (topics, services, tf, robot view)
#   jetbot_rl_client      the learner's side: RosVecEnv and connectEnvs
# and the env node's program and nodelet.
add_library(jetbot_rl_ros_common
  src/ros/common/bounded_deserialization.cpp
  src/ros/common/counted_subscriber_queues.cpp
  src/ros/common/drop_counter.cpp
  src/ros/common/geometry_conversion.cpp
  src/ros/common/inline_callback_queue.cpp
  src/ros/common/msg_conversion.cpp
  src/ros/common/msg_fields.cpp
  src/ros/common/package_resolver.cpp
  src/ros/common/param_reader.cpp
  src/ros/common/peer_links.cpp
  src/ros/common/publication_flush.cpp
  src/ros/common/publication_pacer.cpp
  src/ros/common/robot_description.cpp
  src/ros/common/stop_signal.cpp
)
target_include_directories(jetbot_rl_ros_common PUBLIC include ${catkin_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_ros_common PUBLIC jetbot_rl_core ${catkin_LIBRARIES})
add_dependencies(jetbot_rl_ros_common ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

add_library(jetbot_rl_env_node
  src/ros/env_node/camera_output.cpp
  src/ros/env_node/cmd_vel_mixer.cpp
  src/ros/env_node/env_diagnostics.cpp
  src/ros/env_node/env_node.cpp
  src/ros/env_node/env_server.cpp
  src/ros/env_node/map_publisher.cpp
  src/ros/env_node/world_geometry_publisher.cpp
  src/ros/env_node/marker_publisher.cpp
  src/ros/env_node/node_params.cpp
  src/ros/env_node/randomization_service.cpp
  src/ros/env_node/robot_state_output.cpp
  src/ros/env_node/scan_output.cpp
  src/ros/env_node/sim_clock.cpp
  src/ros/env_node/state_output.cpp
  src/ros/env_node/tf_publisher.cpp
  src/ros/env_node/tf_tree.cpp
)
target_link_libraries(jetbot_rl_env_node PUBLIC jetbot_rl_ros_common ${IMAGE_TRANSPORT_LIBRARY})

add_library(jetbot_rl_client
  src/ros/client/connect_envs.cpp
  src/ros/client/ros_vec_env.cpp
)
target_link_libraries(jetbot_rl_client PUBLIC jetbot_rl_ros_common)

add_executable(jetbot_env_node src/nodes/jetbot_env_node.cpp)
target_link_libraries(jetbot_env_node jetbot_rl_env_node)

# A nodelet library (nodelet_plugins.xml): `target` links nodelet and sees its headers.
function(jetbot_rl_nodelet_library target)
  add_library(${target} ${ARGN})
  target_link_libraries(${target} ${NODELET_LIBRARY} ${CLASS_LOADER_LIBRARY})
  target_include_directories(${target} SYSTEM PRIVATE ${NODELET_INCLUDE_DIR} ${PLUGINLIB_INCLUDE_DIR}
    ${CLASS_LOADER_INCLUDE_DIR} ${RCPPUTILS_INCLUDE_DIR} ${RCUTILS_INCLUDE_DIR})
  install(TARGETS ${target}
    ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
    LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
endfunction()

# The env as a nodelet: no libtorch in a manager that only hosts envs.
jetbot_rl_nodelet_library(jetbot_rl_env_nodelet src/nodelets/env_nodelet.cpp)
target_link_libraries(jetbot_rl_env_nodelet jetbot_rl_env_node)

# The manager the launch files start: stops on SIGINT and SIGTERM after unloading its nodelets.
add_executable(jetbot_rl_manager src/nodes/jetbot_rl_manager.cpp)
target_link_libraries(jetbot_rl_manager jetbot_rl_ros_common ${NODELET_LIBRARY})
target_include_directories(jetbot_rl_manager SYSTEM PRIVATE ${NODELET_INCLUDE_DIR}
  ${PLUGINLIB_INCLUDE_DIR} ${CLASS_LOADER_INCLUDE_DIR})

install(TARGETS jetbot_rl_ros_common jetbot_rl_env_node jetbot_rl_client
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_env_node jetbot_rl_manager
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
