"""Observation and action spaces: gymnasium's `Box` when gymnasium is importable, else `Box` below.

Neither gymnasium nor Stable-Baselines3 is a dependency of jetbot_rl; the stand-in has what a
learner needs from a box space (`shape`, `low`, `high`, `dtype`, `sample()`, `seed()`,
`contains()`), with gymnasium's semantics.
"""
import numpy as np

try:  # optional
    import gymnasium as _gymnasium
except ImportError:
    _gymnasium = None

HAVE_GYMNASIUM = _gymnasium is not None


class Box(object):
    """A box in R^shape, `low <= x <= high` elementwise (bounds may be +-inf); float32 here.

    The stand-in for gymnasium.spaces.Box when gymnasium is not installed.
    """

    def __init__(self, low, high, shape=None, dtype=np.float32, seed=None):
        self.dtype = np.dtype(dtype)
        if shape is None:
            shape = np.shape(low)
        self.shape = tuple(int(s) for s in shape)
        self.low = np.broadcast_to(np.asarray(low, dtype=self.dtype), self.shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=self.dtype), self.shape).copy()
        if np.any(self.low > self.high):
            raise ValueError('Box: low %s exceeds high %s' % (self.low, self.high))
        self.np_random = np.random.default_rng(seed)

    def seed(self, seed=None):
        """Reseeds sample()'s generator; returns [seed]."""
        self.np_random = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        """A random point: uniform where both bounds are finite, else (as gymnasium) normal,
        exponential from the finite bound, or normal."""
        low, high = self.low.astype(np.float64), self.high.astype(np.float64)
        lo_ok, hi_ok = np.isfinite(low), np.isfinite(high)
        out = self.np_random.normal(size=self.shape)
        expo = self.np_random.exponential(size=self.shape)
        out = np.where(lo_ok & ~hi_ok, low + expo, out)
        out = np.where(~lo_ok & hi_ok, high - expo, out)
        both = lo_ok & hi_ok
        uniform = self.np_random.uniform(np.where(both, low, 0.0), np.where(both, high, 1.0))
        out = np.where(both, uniform, out)
        return np.clip(out, low, high).astype(self.dtype)

    def contains(self, x):
        """Whether `x` has this shape and lies within the bounds."""
        x = np.asarray(x)
        return (x.shape == self.shape and bool(np.all(x >= self.low))
                and bool(np.all(x <= self.high)))

    def __contains__(self, x):
        return self.contains(x)

    def __eq__(self, other):
        return (isinstance(other, Box) and self.shape == other.shape
                and self.dtype == other.dtype and np.array_equal(self.low, other.low)
                and np.array_equal(self.high, other.high))

    def __repr__(self):
        return 'Box(%s, %s, %s, %s)' % (self.low.min(), self.high.max(), self.shape, self.dtype)


def make_box(low, high, shape):
    """A float32 box: gymnasium.spaces.Box when gymnasium is importable, else the stand-in."""
    low = np.broadcast_to(np.asarray(low, dtype=np.float32), shape)
    high = np.broadcast_to(np.asarray(high, dtype=np.float32), shape)
    if HAVE_GYMNASIUM:
        return _gymnasium.spaces.Box(low=low, high=high, shape=shape, dtype=np.float32)
    return Box(low, high, shape, np.float32)
