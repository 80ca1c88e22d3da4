"""Observation and action spaces: gymnasium's `Box` and `Dict` when gymnasium is importable, else
`Box` and `Dict` below.

Neither gymnasium nor Stable-Baselines3 is a dependency of jetbot_rl; the stand-ins have what a
learner needs from a box space (`shape`, `low`, `high`, `dtype`, `sample()`, `seed()`,
`contains()`) and a dict of them (`spaces`, `[key]`, `sample()`, `contains()`), with gymnasium's
semantics.
"""
import collections

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
        exponential from the finite bound, or normal; integers: uniform on [low, high]."""
        if np.issubdtype(self.dtype, np.integer):
            return self.np_random.integers(self.low, self.high, size=self.shape,
                                           endpoint=True).astype(self.dtype)
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


class Dict(object):
    """A dict of named spaces (the stand-in for gymnasium.spaces.Dict): `spaces` in key order."""

    def __init__(self, spaces):
        self.spaces = collections.OrderedDict(spaces)

    def __getitem__(self, key):
        return self.spaces[key]

    def keys(self):
        return self.spaces.keys()

    def items(self):
        return self.spaces.items()

    def seed(self, seed=None):
        """Reseeds every member (member k with seed + k); returns the seeds."""
        return [s.seed(None if seed is None else seed + k)[0]
                for k, s in enumerate(self.spaces.values())]

    def sample(self):
        return collections.OrderedDict((k, s.sample()) for k, s in self.spaces.items())

    def contains(self, x):
        return (isinstance(x, dict) and set(x) == set(self.spaces)
                and all(s.contains(x[k]) for k, s in self.spaces.items()))

    def __contains__(self, x):
        return self.contains(x)

    def __eq__(self, other):
        return isinstance(other, Dict) and self.spaces == other.spaces

    def __repr__(self):
        return 'Dict(%s)' % ', '.join('%r: %r' % kv for kv in self.spaces.items())


def make_box(low, high, shape, dtype=np.float32):
    """A box of `dtype`: gymnasium.spaces.Box when gymnasium is importable, else the stand-in."""
    low = np.broadcast_to(np.asarray(low, dtype=dtype), shape)
    high = np.broadcast_to(np.asarray(high, dtype=dtype), shape)
    if HAVE_GYMNASIUM:
        return _gymnasium.spaces.Box(low=low, high=high, shape=shape, dtype=dtype)
    return Box(low, high, shape, dtype)


def make_dict(spaces):
    """A dict space of (key, space) pairs in that order: gymnasium.spaces.Dict when gymnasium is
    importable, else the stand-in."""
    if HAVE_GYMNASIUM:
        return _gymnasium.spaces.Dict(collections.OrderedDict(spaces))
    return Dict(spaces)
