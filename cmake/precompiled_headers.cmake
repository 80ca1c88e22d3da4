# Precompiled headers: the third-party headers that most unity files include are parsed once per
# build instead of once per file. On the 2-core machine a ROS file spends 1.6 s instead of 7.5 s
# on the ROS set, a core file 0.3 s instead of 3 s on the core's; each set is made once (25 s and
# 14 s). Two sets, each made by one target and reused by the others:
#   core  the standard library and Eigen: the ROS-free targets
#   ros   the core's set, roscpp, tf2 and the messages most files use: the ROS adapter's targets
# Not for the targets compiled at -O1 (the test programs, the parameter docs program; their code
# from a header made at -O3 compiles more slowly than from the text) nor for those that include
# libtorch (no gain measured). GCC uses a precompiled header only in code compiled with the same
# code-generation flags and the same macros defined before it, and falls back to the text
# otherwise (correct but slow): every target here is compiled with -fPIC (executables too: -fPIE
# is another setting) and without CMake's <target>_EXPORTS (no code here uses them). The headers
# never replace an #include: every file still includes what it uses, and
# -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON builds without them.
set(_core_headers <algorithm> <array> <atomic> <chrono> <cmath> <cstdint> <filesystem> <fstream>
  <functional> <map> <memory> <mutex> <optional> <random> <sstream> <string> <thread> <vector>
  <Eigen/Core> <Eigen/Geometry>)
set(_ros_headers ${_core_headers} <ros/ros.h> <ros/callback_queue.h> <ros/serialization.h>
  <tf2_ros/buffer.h> <tf2_ros/transform_broadcaster.h> <tf2/utils.h> <geometry_msgs/Twist.h>
  <nav_msgs/Odometry.h> <nav_msgs/OccupancyGrid.h> <sensor_msgs/LaserScan.h>
  <diagnostic_msgs/DiagnosticArray.h>)

# One target makes each set; these reuse it.
set(_core_targets jetbot_rl_eval jetbot_rl_demo jetbot_rl_world_map jetbot_rl_evaluate
  jetbot_rl_nav_benchmark jetbot_rl_bench jetbot_rl_camera_bench)
set(_ros_targets jetbot_rl_env_node jetbot_rl_client jetbot_env_node jetbot_rl_env_nodelet
  jetbot_rl_manager jetbot_rl_ppo_ros jetbot_rl_learner_nodelets jetbot_ppo_trainer
  jetbot_policy_node jetbot_rl_deploy jetbot_deploy_node jetbot_rl_lockstep_bench
  jetbot_rl_ros_bench jetbot_rl_bench_nodelet jetbot_rl_nodes_bench)

target_precompile_headers(jetbot_rl_core PRIVATE ${_core_headers})
target_precompile_headers(jetbot_rl_ros_common PRIVATE ${_ros_headers})
foreach(_target jetbot_rl_core jetbot_rl_ros_common ${_core_targets} ${_ros_targets})
  set_target_properties(${_target} PROPERTIES DEFINE_SYMBOL "")
  target_compile_options(${_target} PRIVATE -fPIC ${TORCH_CXX_FLAGS})
  if(_target IN_LIST _core_targets)
    target_precompile_headers(${_target} REUSE_FROM jetbot_rl_core)
  elseif(_target IN_LIST _ros_targets)
    target_precompile_headers(${_target} REUSE_FROM jetbot_rl_ros_common)
  endif()
endforeach()
