# Every benchmark (docs/performance.md): programs, the lockstep round trips (built once, for the
# program and the nodelet), scripts and the nodelet launch file, all in bench/.
add_executable(jetbot_rl_bench bench/core_bench_main.cpp)
target_compile_definitions(jetbot_rl_bench PRIVATE ${JETBOT_RL_DEFAULT_URDF_DEFINE})
target_link_libraries(jetbot_rl_bench jetbot_rl_core)

# Camera frames/s of the Embree renderer (RGB + depth + labels) for a batch in the office map.
add_executable(jetbot_rl_camera_bench bench/camera_bench_main.cpp)
target_compile_definitions(jetbot_rl_camera_bench PRIVATE
  JETBOT_RL_DEFAULT_MAP="${PROJECT_SOURCE_DIR}/maps/office.yaml")
target_link_libraries(jetbot_rl_camera_bench jetbot_rl_core)

# The trainer's in-process training without ROS, for training experiments on hosts without ROS.
add_executable(jetbot_rl_train_bench bench/train_bench_main.cpp)
target_compile_definitions(jetbot_rl_train_bench PRIVATE
  JETBOT_RL_DEFAULT_LIDAR_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot_lidar.urdf")
target_link_libraries(jetbot_rl_train_bench jetbot_rl_ppo)

# The lockstep round trips against a running env node: jetbot_rl_ros_bench and the nodelet.
add_library(jetbot_rl_lockstep_bench bench/lockstep_bench.cpp)
target_include_directories(jetbot_rl_lockstep_bench PUBLIC bench)
target_link_libraries(jetbot_rl_lockstep_bench PUBLIC jetbot_rl_ros_common)
add_executable(jetbot_rl_ros_bench bench/ros_bench_main.cpp)
target_link_libraries(jetbot_rl_ros_bench jetbot_rl_lockstep_bench)
jetbot_rl_nodelet_library(jetbot_rl_bench_nodelet bench/lockstep_bench_nodelet.cpp)
target_link_libraries(jetbot_rl_bench_nodelet jetbot_rl_lockstep_bench)

# Lockstep env steps/s through one or several env nodes stepped as one batch.
add_executable(jetbot_rl_nodes_bench bench/nodes_bench_main.cpp)
target_link_libraries(jetbot_rl_nodes_bench jetbot_rl_client)

# MuJoCo counterpart of jetbot_rl_bench, for the comparison of bench/bench16.sh
# (docs/performance.md); off by default: it needs libmujoco-dev, which the package does not
# depend on.
option(JETBOT_RL_MUJOCO_BENCH "Build mujoco_bench (needs libmujoco-dev)" OFF)
if(JETBOT_RL_MUJOCO_BENCH)
  find_package(mujoco REQUIRED)
  add_executable(mujoco_bench bench/mujoco_bench.cpp)
  target_link_libraries(mujoco_bench mujoco::mujoco Threads::Threads)
  install(TARGETS mujoco_bench RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endif()

install(TARGETS jetbot_rl_lockstep_bench
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(TARGETS jetbot_rl_bench jetbot_rl_camera_bench jetbot_rl_ros_bench jetbot_rl_nodes_bench
  jetbot_rl_train_bench
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(PROGRAMS bench/bench.sh bench/bench16.sh bench/bench_nodes.sh bench/bench_world.sh bench/bench_team.sh
  bench/bench_camera_ros.sh
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# Sourced by the bench scripts from their own folder: installed beside them, not as a program.
install(FILES bench/bench_common.sh DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
# bench_world.sh's inputs (world_map.yaml names ../maps/office.yaml: beside the installed maps).
install(FILES bench/world_obstacles.yaml bench/world_map.yaml bench/world_gazebo.yaml bench/cylinders_500.world bench/world_clutter.yaml
  bench/world_people.yaml bench/world_team.yaml bench/world_team_solo.yaml
  bench/scan_24.yaml bench/scan_360.yaml bench/scan_360_every_step.yaml bench/camera_64.yaml
  DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/bench)
install(FILES bench/bench_nodelets.launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/bench)
catkin_install_python(PROGRAMS bench/python_bench.py bench/soak.py bench/move_base_goals.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

