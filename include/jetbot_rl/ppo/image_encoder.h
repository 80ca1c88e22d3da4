#pragma once

#include <torch/nn/module.h>
#include <torch/nn/modules/container/sequential.h>
#include <torch/nn/modules/linear.h>

#include <cstdint>
#include <string>
#include <vector>

#include "jetbot_rl/env/step_result.h"
#include "jetbot_rl/ppo/network_config.h"

namespace jetbot_rl {
namespace ppo {

/// The camera image a policy observes: rgb8, height x width, as the batch carries it.
struct ImageShape {
  int height = 0, width = 0;  ///< [px]; 0: no image.
  int frames = 1;             ///< Images in a network input (a frame stack, newest first).
  bool empty() const { return height == 0 || width == 0; }
  /// One image's values: height x width x 3 bytes, row-major from the top left.
  int frameValues() const { return height * width * 3; }
  /// Its values in a network input: `frames` images, one after another.
  int values() const { return frames * frameValues(); }
};

/// The image `spec`'s observation contract names (camera_image), or none.
ImageShape imageShapeOf(const BatchSpec& spec);

/// `rows` rgb8 images of `shape` in `bytes` (one after another), one per row: [rows,
/// frameValues()] floats 0-255. InputError naming `what` and both sizes when `bytes` holds
/// another number of values.
torch::Tensor imageInput(const std::vector<std::uint8_t>& bytes, int rows, ImageShape shape,
                         const std::string& what);

/**
 * The convolutional encoder of an image policy: its input is the camera's rgb8 bytes (as floats
 * 0-255, height x width x 3 per row, the layout a ROS image or a numpy array has), scaled to
 * [0, 1] and, with image_grayscale, turned grey (BT.601 luma); then conv_channels convolutions
 * (conv_kernels, conv_strides, no padding, each with a ReLU), flattened, a Linear to
 * image_features and a ReLU.
 */
class ImageEncoderImpl : public torch::nn::Module {
 public:
  /// ConfigError naming the field when the layer lists differ in length or a layer gets an image
  /// smaller than its kernel (naming the layer and the size it gets). Its input holds
  /// config.image_frames images of `shape` (shape().frames).
  ImageEncoderImpl(const NetworkConfig& config, ImageShape shape);
  /// [B, values()] pixel bytes as floats -> [B, features()].
  torch::Tensor forward(const torch::Tensor& pixels);
  int features() const { return features_; }
  ImageShape shape() const { return shape_; }
  bool grayscale() const { return grayscale_; }
  /// The convolutions (Conv2d and ReLU layers).
  const torch::nn::Sequential& convolutions() const { return convs_; }
  const torch::nn::Linear& linear() const { return linear_; }
  /// Strides, one per convolution.
  const std::vector<int>& strides() const { return strides_; }

 private:
  ImageShape shape_;
  bool grayscale_;
  int features_;
  std::vector<int> strides_;
  torch::nn::Sequential convs_{nullptr};
  torch::nn::Linear linear_{nullptr};
};
TORCH_MODULE(ImageEncoder);

}  // namespace ppo
}  // namespace jetbot_rl
