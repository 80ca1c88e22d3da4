#!/usr/bin/env python3
"""Writes bench/cylinders_500.world: 500 static cylinder models, BARN's posts (radius 0.075 m,
1 m tall, one model each), on a jittered grid over 22 x 22 m, the centre kept free for the spawn.
With --varied each post's radius is drawn in [0.05, 0.15] m (no two models alike: sdformat parses
each one, docs/performance.md). Deterministic (seed 1).
Usage: make_cylinder_world.py [--varied] [OUT]"""
import random
import sys

args = [a for a in sys.argv[1:] if a != "--varied"]
varied = len(args) < len(sys.argv) - 1
out = args[0] if args else "cylinders_500.world"
rng = random.Random(1)
models = []
side, count = 23, 0
for i in range(side):
    for j in range(side):
        x, y = -11.0 + i * 1.0 + rng.uniform(-0.3, 0.3), -11.0 + j * 1.0 + rng.uniform(-0.3, 0.3)
        if abs(x) < 1.0 and abs(y) < 1.0:
            continue
        if count == 500:
            break
        r = rng.uniform(0.05, 0.15) if varied else 0.075
        models.append(
            f"""    <model name="post_{count}">
      <static>true</static>
      <pose>{x:.4f} {y:.4f} 0.5 0 0 0</pose>
      <link name="link">
        <collision name="collision">
          <geometry><cylinder><radius>{r:.4f}</radius><length>1.0</length></cylinder></geometry>
        </collision>
      </link>
    </model>""")
        count += 1
with open(out, "w") as f:
    f.write('<?xml version="1.0"?>\n<!-- Written by bench/make_cylinder_world.py: 500 static '
            'cylinder models. -->\n<sdf version="1.6">\n  <world name="cylinders_500">\n')
    f.write("\n".join(models))
    f.write("\n  </world>\n</sdf>\n")
print(f"{out}: {count} cylinders")
