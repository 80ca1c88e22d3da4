#!/usr/bin/env python3
"""Writes chassis.stl, the tribot example robot's chassis: an octagonal prism in millimetres (the
URDF scales it by 0.001), as a robot maker's CAD export would be. Run once; the STL is committed.

    python3 make_chassis_stl.py > chassis.stl
"""

# Outline in base_link's x-y plane [mm]: a 140 x 120 box with 20 mm chamfers, centred at x = -30.
X0, X1, Y, C = -100.0, 40.0, 60.0, 20.0
OUTLINE = [(X1 - C, -Y), (X1, -Y + C), (X1, Y - C), (X1 - C, Y),
           (X0 + C, Y), (X0, Y - C), (X0, -Y + C), (X0 + C, -Y)]  # counter-clockwise from above
Z0, Z1 = 15.0, 100.0  # bottom 25 mm above the ground (base_link is 10 mm up), top [mm]


def facet(a, b, c):
    u = [b[i] - a[i] for i in range(3)]
    v = [c[i] - a[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = sum(x * x for x in n) ** 0.5
    n = [x / length for x in n]
    lines = ["  facet normal %g %g %g" % tuple(n), "    outer loop"]
    lines += ["      vertex %g %g %g" % p for p in (a, b, c)]
    return lines + ["    endloop", "  endfacet"]


def main():
    bottom = [(x, y, Z0) for x, y in OUTLINE]
    top = [(x, y, Z1) for x, y in OUTLINE]
    out = ["solid chassis"]
    n = len(OUTLINE)
    for i in range(1, n - 1):  # caps as fans, outward normals
        out += facet(top[0], top[i], top[i + 1])
        out += facet(bottom[0], bottom[i + 1], bottom[i])
    for i in range(n):  # sides
        j = (i + 1) % n
        out += facet(bottom[i], bottom[j], top[j])
        out += facet(bottom[i], top[j], top[i])
    out.append("endsolid chassis")
    print("\n".join(out))


if __name__ == "__main__":
    main()
