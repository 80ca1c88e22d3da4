# The policy (inference) and the PPO trainer (libtorch):
#   jetbot_rl_policy   ROS-free inference: the network, the normaliser, the action scaler, the
#                      policy's memory, checkpoint reading, the TorchScript export, Policy; what
#                      plays or deploys a trained policy without the trainer
#   jetbot_rl_ppo      ROS-free PPO core: storage, GAE, update, saving and resuming checkpoints,
#                      training loop over the VecEnv interface
#   jetbot_rl_ppo_ros  the trainer's and the policy node's logic (over jetbot_rl_client)
# and the deploy node (cmake/deploy.cmake) on jetbot_rl_policy.
add_library(jetbot_rl_policy
  src/ppo/action_scaler.cpp
  src/ppo/actor_critic.cpp
  src/ppo/checkpoint.cpp
  src/ppo/image_encoder.cpp
  src/ppo/image_frames.cpp
  src/ppo/input_history.cpp
  src/ppo/network_config.cpp
  src/ppo/obs_normalizer.cpp
  src/ppo/policy.cpp
  src/ppo/policy_export.cpp
  src/ppo/policy_memory.cpp
  src/ppo/policy_memory_script.cpp
  src/ppo/recurrent_memory.cpp
)
target_include_directories(jetbot_rl_policy PUBLIC include)
target_compile_options(jetbot_rl_policy PUBLIC ${TORCH_CXX_FLAGS})
# libtorch's headers are not -Wextra clean: include them as system headers.
target_include_directories(jetbot_rl_policy SYSTEM PUBLIC ${TORCH_INCLUDE_DIRS})
target_link_libraries(jetbot_rl_policy PUBLIC jetbot_rl_core ${TORCH_LIBRARIES})

add_library(jetbot_rl_ppo
  src/ppo/episode_tracker.cpp
  src/ppo/freed_memory.cpp
  src/ppo/gae.cpp
  src/ppo/iteration_stats.cpp
  src/ppo/ppo.cpp
  src/ppo/ppo_checkpoint.cpp
  src/ppo/ppo_config.cpp
  src/ppo/ppo_losses.cpp
  src/ppo/progress_csv.cpp
  src/ppo/rollout_storage.cpp
  src/ppo/runner.cpp
  src/ppo/training_logger.cpp
)
target_link_libraries(jetbot_rl_ppo PUBLIC jetbot_rl_policy)
# Every file of these includes libtorch (ppo/torch_api.h: 18 s a parse here): one unity file each.
set_target_properties(jetbot_rl_policy jetbot_rl_ppo PROPERTIES UNITY_BUILD_BATCH_SIZE 16)

add_library(jetbot_rl_ppo_ros
  src/ppo/ros/policy_node.cpp
  src/ppo/ros/policy_params.cpp
  src/ppo/ros/trainer_node.cpp
  src/ppo/ros/trainer_params.cpp
)
target_link_libraries(jetbot_rl_ppo_ros PUBLIC jetbot_rl_ppo jetbot_rl_client)

# The learners as nodelets (with libtorch).
jetbot_rl_nodelet_library(jetbot_rl_learner_nodelets src/nodelets/learner_nodelets.cpp)
target_link_libraries(jetbot_rl_learner_nodelets jetbot_rl_ppo_ros)

add_executable(jetbot_ppo_trainer src/nodes/jetbot_ppo_trainer.cpp)
target_link_libraries(jetbot_ppo_trainer jetbot_rl_ppo_ros)
add_executable(jetbot_policy_node src/nodes/jetbot_policy_node.cpp)
target_link_libraries(jetbot_policy_node jetbot_rl_ppo_ros)

install(TARGETS jetbot_rl_policy jetbot_rl_ppo jetbot_rl_ppo_ros
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
install(TARGETS jetbot_ppo_trainer jetbot_policy_node
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
