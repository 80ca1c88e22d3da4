# The ROS-free core (Bullet, Eigen, urdfdom, assimp) and its programs; included by CMakeLists.txt
# after catkin_package().
pkg_check_modules(ASSIMP REQUIRED assimp)
# The Gazebo blocks of a robot description (tinyxml2, as urdfdom), map_server's map YAML
# (yaml-cpp, as map_server) and its PGM or PNG image (stb_image).
pkg_check_modules(TINYXML2 REQUIRED tinyxml2)
pkg_check_modules(STB REQUIRED stb)
find_package(yaml-cpp REQUIRED)
# Gazebo world files (SDF), read with Debian's libsdformat-dev as Gazebo reads them.
find_package(sdformat12 REQUIRED)
# Cameras' images, ray traced on the CPU with Debian's libembree-dev (Embree 3).
find_package(embree 3 REQUIRED)
add_library(jetbot_rl_core
  src/core/config/config_fields.cpp
  src/core/config/file_checks.cpp
  src/core/config/former_names.cpp
  src/core/config/yaml_flatten.cpp
  src/core/env/action_layout.cpp
  src/core/env/batch_spec.cpp
  src/core/env/batched_env.cpp
  src/core/env/batched_env_team.cpp
  src/core/env/env_config.cpp
  src/core/env/env_movers.cpp
  src/core/env/env_obstacles.cpp
  src/core/env/env_physics.cpp
  src/core/env/env_randomizer.cpp
  src/core/env/env_setup.cpp
  src/core/env/env_view.cpp
  src/core/env/lean_dispatcher.cpp
  src/core/env/local_vec_env.cpp
  src/core/env/multi_vec_env.cpp
  src/core/env/randomization.cpp
  src/core/env/thread_pool.cpp
  src/core/planning/dwa_planner.cpp
  src/core/planning/footprint_grid.cpp
  src/core/planning/goal_watch.cpp
  src/core/planning/grid_planner.cpp
  src/core/planning/map_planner.cpp
  src/core/planning/path_tracker.cpp
  src/core/planning/speed_limit.cpp
  src/core/robot/diff_drive.cpp
  src/core/robot/dof_limits.cpp
  src/core/robot/package_path.cpp
  src/core/robot/physics_model.cpp
  src/core/robot/robot_model.cpp
  src/core/robot/robot_visuals.cpp
  src/core/robot/urdf_camera_blocks.cpp
  src/core/robot/urdf_gazebo_blocks.cpp
  src/core/scene/env_scene.cpp
  src/core/scene/movers.cpp
  src/core/scene/people_bodies.cpp
  src/core/scene/robot_team.cpp
  src/core/sensors/camera_model.cpp
  src/core/sensors/camera_robot.cpp
  src/core/sensors/camera_scene.cpp
  src/core/sensors/camera_sensor.cpp
  src/core/sensors/camera_spec.cpp
  src/core/sensors/camera_world.cpp
  src/core/sensors/upright_shapes.cpp
  src/core/sensors/seen_spheres.cpp
  src/core/sensors/camera_images.cpp
  src/core/sensors/embree_geometry.cpp
  src/core/sensors/floor_image.cpp
  src/core/sensors/laser_scanner.cpp
  src/core/sensors/depth_scan.cpp
  src/core/sensors/depth_scan_sensor.cpp
  src/core/sensors/scan_cast.cpp
  src/core/sensors/scan_reading.cpp
  src/core/sensors/scan_sensor.cpp
  src/core/tasks/command_task.cpp
  src/core/tasks/navigation_task.cpp
  src/core/tasks/observer_spec.cpp
  src/core/tasks/road_following_task.cpp
  src/core/tasks/task.cpp
  src/core/tasks/task_factory.cpp
  src/core/tasks/track.cpp
  src/core/tasks/velocity_task.cpp
  src/core/world/barn_field.cpp
  src/core/world/gazebo/gazebo_world_model.cpp
  src/core/world/gazebo/inertia_free_models.cpp
  src/core/world/gazebo/mesh_loader.cpp
  src/core/world/gazebo/plain_models.cpp
  src/core/world/gazebo/saved_state.cpp
  src/core/world/gazebo/sdf_prepass.cpp
  src/core/world/gazebo/sdf_shapes.cpp
  src/core/world/gazebo/ogre_materials.cpp
  src/core/world/primitive_uv.cpp
  src/core/world/gazebo/sdf_visuals.cpp
  src/core/world/gazebo/sdf_world_reader.cpp
  src/core/world/gazebo/world_cut.cpp
  src/core/world/map_yaml.cpp
  src/core/world/texture_image.cpp
  src/core/world/occupancy_map.cpp
  src/core/world/solid_surfaces.cpp
  src/core/world/world_generation.cpp
  src/core/world/world_model.cpp
  src/core/world/world_shapes.cpp
)
target_include_directories(jetbot_rl_core PUBLIC include)
# Bullet's headers are not -Wextra clean: system headers.
target_include_directories(jetbot_rl_core SYSTEM PUBLIC ${BULLET_INCLUDE_DIRS} ${EIGEN3_INCLUDE_DIRS}
  ${URDFDOM_INCLUDE_DIRS})
# src/core holds the private headers (Bullet-bearing internals); include/ is the installed API.
target_include_directories(jetbot_rl_core PRIVATE src/core)
target_compile_definitions(jetbot_rl_core PUBLIC ${BULLET_DEFINITIONS})
target_link_libraries(jetbot_rl_core PUBLIC ${BULLET_LIBRARIES} ${URDFDOM_LIBRARIES} Threads::Threads)
target_include_directories(jetbot_rl_core PRIVATE ${ASSIMP_INCLUDE_DIRS} ${TINYXML2_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_core PRIVATE ${ASSIMP_LIBRARIES} ${TINYXML2_LIBRARIES}
  ${STB_LIBRARIES} yaml-cpp sdformat12::sdformat12 embree)

# Headless demo of the batched core.
add_executable(jetbot_rl_demo src/nodes/demo_main.cpp)
target_compile_definitions(jetbot_rl_demo PRIVATE ${JETBOT_RL_DEFAULT_URDF_DEFINE})
target_link_libraries(jetbot_rl_demo jetbot_rl_core)
# A Gazebo world's grid as a map_server map (docs/world.md).
add_executable(jetbot_rl_world_map src/nodes/world_map_main.cpp)
target_link_libraries(jetbot_rl_world_map jetbot_rl_core)

install(TARGETS jetbot_rl_core
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_rl_demo jetbot_rl_world_map RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY include/jetbot_rl/ DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})
