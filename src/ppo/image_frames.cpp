#include "jetbot_rl/ppo/image_frames.h"

#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

ImageFrames::ImageFrames(int num_envs, int frame_values, int frames)
    : frames_(frames),
      frame_values_(frame_values),
      slots_(torch::zeros({num_envs, frames, frame_values}, torch::kUInt8)) {}

torch::Tensor ImageFrames::pushed(const torch::Tensor& slots, const torch::Tensor& pixels,
                                  const torch::Tensor& fresh) const {
  const torch::Tensor newest = pixels.to(torch::kUInt8).view({-1, 1, frame_values_});
  const torch::Tensor shifted = torch::cat({newest, slots.narrow(1, 0, frames_ - 1)}, 1);
  return torch::where(fresh.view({-1, 1, 1}), newest.expand_as(shifted), shifted);
}

torch::Tensor ImageFrames::push(const torch::Tensor& pixels, const torch::Tensor& fresh) {
  slots_ = pushed(slots_, pixels, fresh);
  return slots_.reshape({-1, frames_ * frame_values_}).to(torch::kFloat);
}

torch::Tensor ImageFrames::peek(const torch::Tensor& rows, const torch::Tensor& pixels,
                                const torch::Tensor& fresh) const {
  return pushed(slots_.index_select(0, rows), pixels, fresh)
      .reshape({-1, frames_ * frame_values_})
      .to(torch::kFloat);
}

}  // namespace ppo
}  // namespace jetbot_rl
