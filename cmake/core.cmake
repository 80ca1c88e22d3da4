# The ROS-free core (Bullet, Eigen, urdfdom), its programs and its gtests; included by CMakeLists.txt
# after catkin_package().

# ---- ROS-free core: Bullet, Eigen, urdfdom, assimp (collision meshes) ----
pkg_check_modules(ASSIMP REQUIRED assimp)
add_library(jetbot_rl_core
  src/core/batched_env.cpp
  src/core/command_task.cpp
  src/core/config_fields.cpp
  src/core/diff_drive.cpp
  src/core/dof_limits.cpp
  src/core/env_config.cpp
  src/core/env_randomizer.cpp
  src/core/env_world.cpp
  src/core/lean_dispatcher.cpp
  src/core/local_vec_env.cpp
  src/core/mesh_loader.cpp
  src/core/multi_vec_env.cpp
  src/core/physics_model.cpp
  src/core/randomization.cpp
  src/core/robot_model.cpp
  src/core/task_factory.cpp
  src/core/thread_pool.cpp
  src/core/velocity_task.cpp
)
target_include_directories(jetbot_rl_core PUBLIC include)
# Bullet's headers are not -Wextra clean: system headers.
target_include_directories(jetbot_rl_core SYSTEM PUBLIC ${BULLET_INCLUDE_DIRS} ${EIGEN3_INCLUDE_DIRS}
  ${URDFDOM_INCLUDE_DIRS})
# src/core holds the private headers (Bullet-bearing internals); include/ is the installed API.
target_include_directories(jetbot_rl_core PRIVATE src/core)
target_compile_definitions(jetbot_rl_core PUBLIC ${BULLET_DEFINITIONS})
target_link_libraries(jetbot_rl_core PUBLIC ${BULLET_LIBRARIES} ${URDFDOM_LIBRARIES} Threads::Threads)
target_include_directories(jetbot_rl_core PRIVATE ${ASSIMP_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_core PRIVATE ${ASSIMP_LIBRARIES})

add_executable(jetbot_rl_bench src/nodes/bench_main.cpp)
target_compile_definitions(jetbot_rl_bench PRIVATE JETBOT_RL_DEFAULT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf")
target_link_libraries(jetbot_rl_bench jetbot_rl_core)

# MuJoCo counterpart of jetbot_rl_bench, for the comparison of scripts/bench16.sh (README,
# "Performance"); off by default: it needs libmujoco-dev, which the package does not depend on.
option(JETBOT_RL_MUJOCO_BENCH "Build mujoco_bench (needs libmujoco-dev)" OFF)
if(JETBOT_RL_MUJOCO_BENCH)
  find_package(mujoco REQUIRED)
  add_executable(mujoco_bench bench/mujoco_bench.cpp)
  target_link_libraries(mujoco_bench mujoco::mujoco Threads::Threads)
  install(TARGETS mujoco_bench RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endif()

add_executable(jetbot_rl_demo src/nodes/demo_main.cpp)
target_compile_definitions(jetbot_rl_demo PRIVATE JETBOT_RL_DEFAULT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf")
target_link_libraries(jetbot_rl_demo jetbot_rl_core)

install(TARGETS jetbot_rl_core
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_rl_bench jetbot_rl_demo
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY include/jetbot_rl/ DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})

# ---- Tests ----
if(CATKIN_ENABLE_TESTING)
  catkin_add_gtest(test_core
    test/core/test_main.cpp
    test/core/test_robot_model.cpp
    test/core/test_env_config.cpp
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
  )
  target_link_libraries(test_core jetbot_rl_core)
  target_include_directories(test_core PRIVATE src/core)
  target_compile_definitions(test_core PRIVATE JETBOT_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot.urdf"
    TRIBOT_URDF="${PROJECT_SOURCE_DIR}/test/urdf/tribot.urdf"
    JETBOT_RL_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
