# Every test of the package, registered from here (docs/testing.md): gtests of the ROS-free
# libraries (no master), gtests of the ROS adapter, and one rostest per scenario (.test files
# sharing launch/jetbot_env.launch).
if(NOT CATKIN_ENABLE_TESTING)
  return()
endif()
find_package(rostest REQUIRED)
set(_robots JETBOT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf"
  TRIBOT_URDF="${PROJECT_SOURCE_DIR}/urdf/examples/tribot.urdf")

# ---- core (ROS-free) ----
catkin_add_gtest(test_core
  test/core/test_main.cpp
  test/core/test_robot_model.cpp
  test/core/test_env_config.cpp
  test/core/test_env_setup.cpp
  test/core/test_kinematics.cpp
  test/core/test_step_semantics.cpp
  test/core/test_bad_input.cpp
  test/core/test_command_task.cpp
  test/core/test_determinism.cpp
  test/core/test_thread_pool.cpp
  test/core/test_diff_drive.cpp
  test/core/test_urdf_cases.cpp
  test/core/test_tribot.cpp
  test/core/test_multi_vec_env.cpp
  test/core/test_randomization_off.cpp
  test/core/test_randomization.cpp
  test/core/test_randomization_config.cpp
  test/core/test_motor_model.cpp
  test/core/test_occupancy_map.cpp
  test/core/test_camera.cpp
  test/core/test_camera_blocks.cpp
  test/core/test_camera_gazebo.cpp
  test/core/test_camera_textures.cpp
  test/core/test_material_scripts.cpp
  test/core/test_camera_robots.cpp
  test/core/test_camera_sensor.cpp
  test/core/test_camera_tiles.cpp
  test/core/test_multicamera.cpp
  test/core/test_laser_scanner.cpp
  test/core/test_scan_cast.cpp
  test/core/test_scan_reading.cpp
  test/core/test_world.cpp
  test/core/test_spawn_reach.cpp
  test/core/test_gazebo_world.cpp
  test/core/test_plain_models.cpp
  test/core/test_published_world_quirks.cpp
  test/core/test_saved_state.cpp
  test/core/test_hostile_world_files.cpp
  test/core/test_movers.cpp
  test/core/test_team.cpp
  test/core/test_team_people.cpp
  test/core/test_team_obstacles.cpp
  test/core/test_navigation.cpp
  test/core/test_road_following.cpp
  test/core/test_depth_scan.cpp
  test/core/test_notebook_dataset.cpp
  test/core/test_task_observers.cpp
  test/core/test_world_generation.cpp
  test/core/test_barn_field.cpp
  test/core/test_grid_planner.cpp
  test/core/test_dwa_planner.cpp
  test/core/test_map_planner.cpp
  test/core/test_goal_watch.cpp
  test/core/test_speed_limit.cpp
)
target_link_libraries(test_core jetbot_rl_core jetbot_rl_dataset_writer ${STB_LIBRARIES})
target_include_directories(test_core PRIVATE src/core)
target_compile_definitions(test_core PRIVATE ${_robots} JETBOT_RL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

# ---- PPO (ROS-free) ----
catkin_add_gtest(test_ppo
  test/ppo/test_main.cpp
  test/ppo/test_gae.cpp
  test/ppo/test_checkpoint.cpp
  test/ppo/test_config.cpp
  test/ppo/test_runner.cpp
  test/ppo/test_freed_memory.cpp
  test/ppo/test_update.cpp
  test/ppo/test_in_process.cpp
  test/ppo/test_memory.cpp
  test/ppo/test_image_policy.cpp
  test/ppo/test_nav_benchmark.cpp
  test/ppo/test_navigation_metrics.cpp
  test/ppo/test_dwa_actor.cpp
  test/ppo/test_training_logger.cpp
)
target_link_libraries(test_ppo jetbot_rl_ppo jetbot_rl_eval)
set_target_properties(test_ppo PROPERTIES UNITY_BUILD_BATCH_SIZE 16)  # libtorch in each file
target_compile_definitions(test_ppo PRIVATE ${_robots} JETBOT_RL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

# ---- ROS adapter without a master ----
catkin_add_gtest(test_ros_adapter
  test/ros/test_main.cpp
  test/ros/test_inline_callback_queue.cpp
  test/ros/test_env_server.cpp
  test/ros/test_bounded_deserialization.cpp
  test/ros/test_robot_view.cpp
  test/ros/test_randomization_service.cpp
  test/ros/test_spec_schema.cpp
)
target_link_libraries(test_ros_adapter jetbot_rl_env_node jetbot_rl_client)
target_compile_definitions(test_ros_adapter PRIVATE ${_robots})

# ---- the deploy node without a master: its scan handling, the robot view's messages observed
# as the simulated task observes, the settings it takes from the checkpoint, camera images ----
catkin_add_gtest(test_deploy test/ros/test_main.cpp test/deploy/test_scan_beams.cpp
  test/deploy/test_observer_agreement.cpp test/deploy/test_trained_settings.cpp
  test/deploy/test_image_input.cpp test/deploy/test_dwa_local_planner.cpp
  test/deploy/test_depth_scan_converter.cpp)
target_link_libraries(test_deploy jetbot_rl_deploy jetbot_rl_env_node)
target_compile_definitions(test_deploy PRIVATE ${_robots})

# ---- the deploy node's goals and paths through tf, with a master ----
add_rostest_gtest(test_goal_frames test/deploy/goal_frames.test test/deploy/test_goal_frames.cpp)
target_link_libraries(test_goal_frames jetbot_rl_deploy)
# ---- jetbot_depth_scan against the env's own scan from the camera's depth ----
add_rostest(test/deploy/depth_scan.test)

# ---- the env node (rostest) ----
foreach(_scenario interface lockstep step_service reset rejection realtime_hz realtime_brake clock
    markers refuse_start hostile_bytes cmd_vel_drive cmd_vel_tribot cmd_vel_lockstep cmd_vel_brake
    cmd_vel_nan robot_state_publisher robot_unprefixed randomization)
  add_rostest(test/ros/${_scenario}.test)
endforeach()
add_rostest_gtest(test_tf test/ros/tf.test test/ros/test_tf.cpp)
target_link_libraries(test_tf ${catkin_LIBRARIES})
target_include_directories(test_tf PRIVATE ${catkin_INCLUDE_DIRS})
add_dependencies(test_tf ${${PROJECT_NAME}_EXPORTED_TARGETS})
add_rostest_gtest(test_back_to_back test/reliability/back_to_back.test
  test/reliability/test_back_to_back.cpp)
target_link_libraries(test_back_to_back ${catkin_LIBRARIES})
target_include_directories(test_back_to_back PRIVATE ${catkin_INCLUDE_DIRS})
add_dependencies(test_back_to_back ${${PROJECT_NAME}_EXPORTED_TARGETS})

# ---- the world and the laser scanner ----
add_rostest(test/world/world_scan.test)
add_rostest(test/world/world_view.test)
add_rostest(test/world/gazebo_world.test)
add_rostest(test/world/camera_view.test)
add_rostest(test/world/stereo_view.test)

# ---- the programs the rostests below start ----
set(_nodes jetbot_env_node jetbot_ppo_trainer jetbot_policy_node jetbot_deploy_node jetbot_rl_manager
  jetbot_rl_env_nodelet jetbot_rl_learner_nodelets)

# ---- several env nodes as one batch ----
add_rostest_gtest(test_concatenation test/multi/concatenation.test test/multi/test_concatenation.cpp)
target_link_libraries(test_concatenation jetbot_rl_client)
add_rostest(test/multi/two_nodes.test DEPENDENCIES ${_nodes})
add_rostest(test/multi/multi_host.test DEPENDENCIES ${_nodes})

# ---- the Python client ----
foreach(_scenario vec_env determinism bad_input timeout multi_node ppo_example ppo_example_signals
    camera)
  add_rostest(test/python/python_${_scenario}.test)
endforeach()

# ---- training, determinism, Ctrl-C and resume, start-up refusals ----
foreach(_scenario train train_command train_navigation train_tribot determinism determinism_memory
    determinism_history determinism_mix interrupt_resume refuse_start_ppo clean_end)
  add_rostest(test/ppo/${_scenario}.test DEPENDENCIES ${_nodes})
endforeach()

# ---- sim-to-real: a policy trained with randomisation drives the env's robot view (deploy node) ----
foreach(_scenario closed_loop_velocity closed_loop_command closed_loop_navigation closed_loop_path
    closed_loop_move_base
    move_base_client
    closed_loop_memory
    closed_loop_road
    closed_loop_dwa
    deploy_node
    deploy_speed_limit
    evaluator_options)
  add_rostest(test/sim2real/${_scenario}.test DEPENDENCIES ${_nodes})
endforeach()

# ---- the shipped policies (policies/): each still loads and acts as its figures say ----
add_rostest(test/policies/shipped_policies.test DEPENDENCIES jetbot_rl_evaluate)

# ---- the fault suite (docs/reliability.md): peers that die or misbehave, signals, a soak ----
foreach(_scenario signals client_killed env_killed env_hung two_learners slow_subscriber soak
    counted_losses)
  add_rostest(test/reliability/${_scenario}.test DEPENDENCIES ${_nodes})
endforeach()

# ---- the docs: parameter tables, config files and launch defaults against the C++ defaults ----
add_rostest(test/docs/param_docs.test DEPENDENCIES jetbot_rl_param_docs)
add_rostest(test/launch/task_defaults.test)
add_rostest(test/launch/rviz_configs.test)
add_rostest(test/python/python_navigation.test)
add_rostest(test/python/python_team.test)

# The test programs' own code at -O1: it compiles in 60 % of -O3's time (the libraries it tests
# keep -O3), and what it runs is the libraries.
foreach(_test test_core test_ppo test_ros_adapter test_deploy test_goal_frames test_tf
    test_concatenation test_back_to_back)
  if(TARGET ${_test})
    target_compile_options(${_test} PRIVATE -O1)
  endif()
endforeach()
