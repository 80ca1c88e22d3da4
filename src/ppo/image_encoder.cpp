#include "jetbot_rl/ppo/image_encoder.h"

#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/conv.h>

#include <string>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/ppo/torch_api.h"

namespace jetbot_rl {
namespace ppo {

ImageShape imageShapeOf(const BatchSpec& spec) {
  ImageShape shape;
  if (spec.observer.camera_image.empty()) return shape;
  shape.height = spec.observer.camera_height;
  shape.width = spec.observer.camera_width;
  return shape;
}

torch::Tensor imageInput(const std::vector<std::uint8_t>& bytes, int rows, ImageShape shape,
                         const std::string& what) {
  const auto expected =
      static_cast<std::size_t>(rows) * static_cast<std::size_t>(shape.frameValues());
  if (bytes.size() != expected) {
    throw InputError("expected " + std::to_string(expected) + " bytes of " + what + " (" +
                     std::to_string(rows) + " rgb8 images of " + std::to_string(shape.width) +
                     " x " + std::to_string(shape.height) + "), got " +
                     std::to_string(bytes.size()));
  }
  return torch::from_blob(const_cast<std::uint8_t*>(bytes.data()), {rows, shape.frameValues()},
                          torch::kUInt8)
      .to(torch::kFloat);
}

ImageEncoderImpl::ImageEncoderImpl(const NetworkConfig& c, ImageShape shape)
    : shape_(shape),
      grayscale_(c.image_grayscale),
      features_(c.image_features),
      strides_(c.conv_strides) {
  const std::size_t layers = c.conv_channels.size();
  if (c.conv_kernels.size() != layers || c.conv_strides.size() != layers) {
    throwInvalid("conv_kernels", listText(c.conv_kernels),
                 "conv_channels, conv_kernels and conv_strides must have as many values (" +
                     std::to_string(layers) + " convolutions in conv_channels, " +
                     std::to_string(c.conv_strides.size()) + " strides)");
  }
  shape_.frames = c.image_frames;
  convs_ = register_module("convolutions", torch::nn::Sequential());
  int channels = (grayscale_ ? 1 : 3) * shape_.frames, height = shape.height, width = shape.width;
  for (std::size_t i = 0; i < layers; ++i) {
    const int k = c.conv_kernels[i], s = c.conv_strides[i];
    if (height < k || width < k) {
      throwInvalid("conv_kernels", listText(c.conv_kernels),
                   "convolution " + std::to_string(i) + " gets a " + std::to_string(width) + " x " +
                       std::to_string(height) + " px image, smaller than its kernel " +
                       std::to_string(k) + " (the camera image is " + std::to_string(shape.width) +
                       " x " + std::to_string(shape.height) +
                       "): fewer or smaller layers, or a larger image");
    }
    convs_->push_back(
        torch::nn::Conv2d(torch::nn::Conv2dOptions(channels, c.conv_channels[i], k).stride(s)));
    convs_->push_back(torch::nn::ReLU());
    channels = c.conv_channels[i];
    height = (height - k) / s + 1;
    width = (width - k) / s + 1;
  }
  linear_ = register_module("linear", torch::nn::Linear(channels * height * width, features_));
}

torch::Tensor ImageEncoderImpl::forward(const torch::Tensor& pixels) {
  torch::Tensor x;
  if (shape_.frames == 1) {
    x = pixels.view({-1, shape_.height, shape_.width, 3}).permute({0, 3, 1, 2}) * (1.0 / 255.0);
    if (grayscale_) {
      const torch::Tensor luma = torch::tensor({0.299f, 0.587f, 0.114f}).view({1, 3, 1, 1});
      x = (x * luma).sum(1, /*keepdim=*/true);
    }
  } else {  // the frames' channels one after another: [B, frames x channels, H, W]
    x = pixels.view({-1, shape_.frames, shape_.height, shape_.width, 3}).permute({0, 1, 4, 2, 3}) *
        (1.0 / 255.0);
    if (grayscale_) {
      const torch::Tensor luma = torch::tensor({0.299f, 0.587f, 0.114f}).view({1, 1, 3, 1, 1});
      x = (x * luma).sum(2);
    } else {
      x = x.reshape({-1, shape_.frames * 3, shape_.height, shape_.width});
    }
  }
  x = convs_->forward(x.contiguous());
  return torch::relu(linear_->forward(x.flatten(1)));
}

}  // namespace ppo
}  // namespace jetbot_rl
