"""What JetbotVecEnv returns as its observation (`observation=`): the task's vector, the camera's
rgb image, or a dict of the vector and every image the nodes send; their spaces, and the
observation made from the nodes' batches."""
import numpy as np

from jetbot_rl.node_link import IMAGE_KINDS
from jetbot_rl.spaces import make_box, make_dict

#: What JetbotVecEnv's `observation` may be.
OBSERVATIONS = ('vector', 'image', 'dict')
# Per image kind: the bounds of its observation space (depth: REP 118's infinities included).
_IMAGE_BOUNDS = {'rgb': (0, 255), 'depth': (-np.inf, np.inf), 'label': (0, 255)}


class Observations(object):
    """Observation `mode` (one of OBSERVATIONS) of vectors bounded by `low`, `high` (float32,
    (obs_dim,)) and the images of `layout` (node_link.ImageLayout)."""

    def __init__(self, mode, low, high, layout):
        self.mode = mode
        self.low, self.high = low, high
        self.layout = layout

    def space(self, batch):
        """The space of one env's observation (`batch` ()) or of a batch's ((num_envs,))."""
        vector = make_box(np.tile(self.low, batch + (1,)).reshape(batch + (-1,)),
                          np.tile(self.high, batch + (1,)).reshape(batch + (-1,)),
                          batch + (self.low.shape[0],))
        if self.mode == 'vector':
            return vector
        images = []
        for kind in self.layout.kinds:
            low, high = _IMAGE_BOUNDS[kind]
            images.append((kind, make_box(low, high, batch + self.layout.shape(kind),
                                          IMAGE_KINDS[kind][2])))
        if self.mode == 'image':
            return dict(images)['rgb']
        return make_dict([('vector', vector)] + images)

    def of(self, batches, final=False):
        """The observation of the nodes' `batches` (node_link.Batch), concatenated in order;
        `final`: of their ended episodes (final_obs, final_images)."""
        vectors = np.concatenate([b.final_obs if final else b.obs for b in batches])
        if self.mode == 'vector':
            return vectors
        images = {kind: np.concatenate([(b.final_images if final else b.images)[kind]
                                        for b in batches])
                  for kind in self.layout.kinds}
        if self.mode == 'image':
            return images['rgb']
        out = {'vector': vectors}
        out.update(images)
        return out


def scatter(values, ids, n):
    """Rows `values` (an array, or a dict of arrays) placed at `ids` of `n` zero rows."""
    if isinstance(values, dict):
        return {k: scatter(v, ids, n) for k, v in values.items()}
    out = np.zeros((n,) + values.shape[1:], dtype=values.dtype)
    out[ids] = values
    return out
