# The evaluation room (src/eval/, include/jetbot_rl/eval/): the one episode loop of the programs
# that play a policy on a batch, and the navigation benchmark on it.
#   jetbot_rl_eval  runEpisodes, ObservationMeans, the benchmark's worlds and its path bookkeeping
add_library(jetbot_rl_eval
  src/eval/dwa_actor.cpp
  src/eval/episode_loop.cpp
  src/eval/nav_benchmark.cpp
  src/eval/navigation_metrics.cpp
  src/eval/observation_means.cpp
)
target_link_libraries(jetbot_rl_eval PUBLIC jetbot_rl_policy)

# A policy's mean reward per step on envs configured by YAML (e.g. perturbed physics), in-process.
add_executable(jetbot_rl_evaluate src/nodes/evaluate_main.cpp)
target_link_libraries(jetbot_rl_evaluate jetbot_rl_eval)
target_compile_definitions(jetbot_rl_evaluate PRIVATE ${JETBOT_RL_DEFAULT_URDF_DEFINE})
add_executable(jetbot_rl_nav_benchmark src/nodes/nav_benchmark_main.cpp)
target_link_libraries(jetbot_rl_nav_benchmark jetbot_rl_eval)
target_compile_definitions(jetbot_rl_nav_benchmark PRIVATE
  JETBOT_RL_DEFAULT_LIDAR_URDF="${PROJECT_SOURCE_DIR}/urdf/jetbot_lidar.urdf"
  JETBOT_RL_DEFAULT_MAP="${PROJECT_SOURCE_DIR}/maps/office.yaml"
  JETBOT_RL_DEFAULT_GAZEBO_WORLD="${PROJECT_SOURCE_DIR}/worlds/furnished_room.world"
  JETBOT_RL_NAVIGATION_ENV="${PROJECT_SOURCE_DIR}/config/navigation_env.yaml")

install(TARGETS jetbot_rl_eval
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_rl_evaluate jetbot_rl_nav_benchmark
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
