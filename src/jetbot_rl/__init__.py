"""jetbot_rl: Python client of the jetbot_env node (and, beside it, the generated jetbot_rl.msg
and jetbot_rl.srv).

    from jetbot_rl import JetbotVecEnv        # gymnasium-style vector env over ROS
    from jetbot_rl import JetbotSB3VecEnv     # Stable-Baselines3 VecEnv adapter

The client's modules are imported on first use, so that `import jetbot_rl.msg` stays as light as
any generated message package.
"""
__all__ = ['JetbotVecEnv', 'JetbotSB3VecEnv', 'EnvRejectedError', 'Box', 'NODE_SEED_STRIDE']

_LAZY = {
    'JetbotVecEnv': 'vec_env',
    'NODE_SEED_STRIDE': 'vec_env',
    'EnvRejectedError': 'node_link',
    'JetbotSB3VecEnv': 'sb3',
    'Box': 'spaces',
}


def __getattr__(name):
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError("module 'jetbot_rl' has no attribute %r" % name)
    import importlib
    return getattr(importlib.import_module('jetbot_rl.' + module), name)
