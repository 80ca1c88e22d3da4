#pragma once
// The parts of libtorch's C++ API the policy, the trainer and their tests use: tensors and their
// factories, modules (linear, sequential, activations), Adam, gradient clipping, serialisation and
// TorchScript modules. <torch/torch.h> includes the whole API (data loaders, every module and
// optimiser): 27 s a parse on the 2-core machine against 18 s for these, in every file that
// includes it.
#include <torch/csrc/jit/api/module.h>
#include <torch/nn/module.h>
#include <torch/nn/modules/activation.h>
#include <torch/nn/modules/container/sequential.h>
#include <torch/nn/modules/linear.h>
#include <torch/nn/utils/clip_grad.h>
#include <torch/optim/adam.h>
#include <torch/serialize.h>
#include <torch/types.h>
#include <torch/utils.h>
