#pragma once

#include <torch/types.h>

namespace jetbot_rl {
namespace ppo {

/**
 * An image policy's frame stack per env (the frame stacking of Atari's DQN and SB3's
 * VecFrameStack): the image part of its input is the last `frames` camera images, newest first;
 * an env that starts over holds its first image in every slot (as InputHistory does). Kept as
 * bytes.
 */
class ImageFrames {
 public:
  /// `frame_values`: one image's bytes (height x width x 3).
  ImageFrames(int num_envs, int frame_values, int frames);

  /// Pushes every env's image `pixels` [N, frame_values] (floats 0-255); rows where `fresh` [N]
  /// (bool) is true start over. Returns the stack [N, frames x frame_values] as floats.
  torch::Tensor push(const torch::Tensor& pixels, const torch::Tensor& fresh);
  /// The stack envs `rows` [R] (long) would get from push() with `pixels` [R, frame_values] and
  /// `fresh` [R]; nothing changes.
  torch::Tensor peek(const torch::Tensor& rows, const torch::Tensor& pixels,
                     const torch::Tensor& fresh) const;

 private:
  /// The slots [R, frames, frame_values] after pushing `pixels` onto `slots`.
  torch::Tensor pushed(const torch::Tensor& slots, const torch::Tensor& pixels,
                       const torch::Tensor& fresh) const;

  int frames_, frame_values_;
  torch::Tensor slots_;  // [N, frames, frame_values] bytes, newest first
};

}  // namespace ppo
}  // namespace jetbot_rl
