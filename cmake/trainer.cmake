# The PPO trainer and policy player (libtorch); included at the end of CMakeLists.txt.
#   jetbot_rl_ppo      ROS-free PPO core: model, normaliser, storage, GAE, update, checkpoints,
#                      training loop over the VecEnv interface
#   jetbot_rl_ppo_ros  the two nodes' logic (the env's ROS client RosVecEnv is in jetbot_rl_ros)
# ---- ROS-free PPO core ----
add_library(jetbot_rl_ppo
  src/ppo/action_scaler.cpp
  src/ppo/actor_critic.cpp
  src/ppo/checkpoint.cpp
  src/ppo/episode_tracker.cpp
  src/ppo/gae.cpp
  src/ppo/iteration_stats.cpp
  src/ppo/obs_normalizer.cpp
  src/ppo/policy.cpp
  src/ppo/policy_export.cpp
  src/ppo/ppo.cpp
  src/ppo/ppo_config.cpp
  src/ppo/ppo_losses.cpp
  src/ppo/progress_csv.cpp
  src/ppo/rollout_storage.cpp
  src/ppo/runner.cpp
  src/ppo/training_logger.cpp
)
target_include_directories(jetbot_rl_ppo PUBLIC include)
target_compile_options(jetbot_rl_ppo PUBLIC ${TORCH_CXX_FLAGS})
# libtorch's headers are not -Wextra clean: include them as system headers.
target_include_directories(jetbot_rl_ppo SYSTEM PUBLIC ${TORCH_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_ppo PUBLIC jetbot_rl_core ${TORCH_LIBRARIES})

install(TARGETS jetbot_rl_ppo
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_ppo
    test/ppo/test_main.cpp
    test/ppo/test_gae.cpp
    test/ppo/test_checkpoint.cpp
    test/ppo/test_config.cpp
    test/ppo/test_runner.cpp
    test/ppo/test_update.cpp
    test/ppo/test_in_process.cpp
  )
  target_link_libraries(test_ppo jetbot_rl_ppo)
  target_compile_definitions(test_ppo PRIVATE JETBOT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf")
endif()

# ---- ROS client of jetbot_env and the two nodes ----
add_library(jetbot_rl_ppo_ros
  src/ppo/ros/policy_node.cpp
  src/ppo/ros/robot_mode.cpp
  src/ppo/ros/stop_signal.cpp
  src/ppo/ros/trainer_node.cpp
  src/ppo/ros/trainer_params.cpp
)
target_include_directories(jetbot_rl_ppo_ros PUBLIC include ${catkin_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_ppo_ros PUBLIC jetbot_rl_ppo jetbot_rl_ros)
add_dependencies(jetbot_rl_ppo_ros ${${PROJECT_NAME}_EXPORTED_TARGETS} ${catkin_EXPORTED_TARGETS})

# Every node as a nodelet (nodelet_plugins.xml): the env and a learner in one manager pass
# messages by shared pointer.
add_library(jetbot_rl_nodelets src/nodelets/env_nodelet.cpp src/nodelets/learner_nodelets.cpp)
target_include_directories(jetbot_rl_nodelets PRIVATE src/ros)
target_link_libraries(jetbot_rl_nodelets jetbot_rl_ppo_ros ${NODELET_LIBRARY}
  ${CLASS_LOADER_LIBRARY})
target_include_directories(jetbot_rl_nodelets SYSTEM PRIVATE ${NODELET_INCLUDE_DIR}
  ${PLUGINLIB_INCLUDE_DIR} ${CLASS_LOADER_INCLUDE_DIR} ${RCPPUTILS_INCLUDE_DIR} ${RCUTILS_INCLUDE_DIR})
# The bench's round trips, without its main.
target_sources(jetbot_rl_nodelets PRIVATE src/ros/lockstep_bench.cpp)
install(TARGETS jetbot_rl_nodelets
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
# The manager the launch files start: stops on SIGINT and SIGTERM after unloading its nodelets.
add_executable(jetbot_rl_manager src/nodes/jetbot_rl_manager.cpp)
target_link_libraries(jetbot_rl_manager jetbot_rl_ros ${NODELET_LIBRARY})
target_include_directories(jetbot_rl_manager SYSTEM PRIVATE ${NODELET_INCLUDE_DIR}
  ${PLUGINLIB_INCLUDE_DIR} ${CLASS_LOADER_INCLUDE_DIR})
install(TARGETS jetbot_rl_manager RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# A policy's mean reward per step on envs configured by YAML (e.g. perturbed physics), in-process.
add_executable(jetbot_rl_evaluate src/nodes/evaluate_main.cpp)
target_link_libraries(jetbot_rl_evaluate jetbot_rl_ppo)
target_compile_definitions(jetbot_rl_evaluate PRIVATE
  JETBOT_RL_DEFAULT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf")

add_executable(jetbot_ppo_trainer src/nodes/jetbot_ppo_trainer.cpp)
target_link_libraries(jetbot_ppo_trainer jetbot_rl_ppo_ros)
add_executable(jetbot_policy_node src/nodes/jetbot_policy_node.cpp)
target_link_libraries(jetbot_policy_node jetbot_rl_ppo_ros)

install(TARGETS jetbot_rl_ppo_ros
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_ppo_trainer jetbot_policy_node jetbot_rl_evaluate
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
catkin_install_python(PROGRAMS scripts/plot_learning_curve.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# ---- rostests: training (velocity and command tasks), determinism, Ctrl-C and resume, start-up refusals ----
if(CATKIN_ENABLE_TESTING)
  find_package(rostest REQUIRED)
  set(_ppo_nodes jetbot_ppo_trainer jetbot_policy_node jetbot_env_node jetbot_rl_manager)
  add_rostest(test/ppo/train.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/train_command.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/train_tribot.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/determinism.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/interrupt_resume.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/refuse_start_ppo.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/ppo/clean_end.test DEPENDENCIES ${_ppo_nodes})
  # Sim-to-real: a policy trained with randomisation drives the env's robot view in robot mode.
  add_rostest(test/sim2real/closed_loop_velocity.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/sim2real/closed_loop_command.test DEPENDENCIES ${_ppo_nodes})
  add_rostest(test/sim2real/robot_mode.test DEPENDENCIES ${_ppo_nodes})
endif()
