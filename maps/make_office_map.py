#!/usr/bin/env python3
"""Writes office.pgm: a small office-like floor plan as map_saver writes maps (binary PGM, 254 free,
0 occupied, 205 unknown outside), 10 x 8 m at 0.05 m per cell, for maps/office.yaml. Run it from
this folder to regenerate the image."""

RES = 0.05
W, H = 200, 160  # cells: 10 x 8 m
FREE, OCCUPIED, UNKNOWN = 254, 0, 205


def main():
    img = [[UNKNOWN] * W for _ in range(H)]  # row 0 is the top of the image

    def fill(x0, y0, x1, y1, value):
        """Metres from the map's lower-left corner, [x0, x1) x [y0, y1)."""
        for y in range(int(round(y0 / RES)), int(round(y1 / RES))):
            for x in range(int(round(x0 / RES)), int(round(x1 / RES))):
                img[H - 1 - y][x] = value

    fill(0.5, 0.5, 9.5, 7.5, FREE)                 # the floor
    for x0, y0, x1, y1 in [
            (0.4, 0.4, 9.6, 0.5), (0.4, 7.5, 9.6, 7.6),  # outer walls
            (0.4, 0.4, 0.5, 7.6), (9.5, 0.4, 9.6, 7.6),
            (4.0, 0.5, 4.1, 2.5), (4.0, 3.5, 4.1, 7.5),  # a wall with a 1 m door
            (4.1, 4.5, 6.0, 4.6), (7.0, 4.5, 9.5, 4.6),  # a room in the upper right, 1 m door
            (1.5, 5.5, 3.0, 6.3),                        # a desk
            (1.2, 1.5, 2.0, 2.3),                        # a cabinet
            (6.5, 1.5, 8.0, 2.5),                        # a table
            (7.5, 5.8, 8.5, 6.8)]:                       # a desk in the room
        fill(x0, y0, x1, y1, OCCUPIED)
    with open('office.pgm', 'wb') as f:
        f.write(b'P5\n# CREATOR: make_office_map.py %.3f m/pix\n%d %d\n255\n' % (RES, W, H))
        for row in img:
            f.write(bytes(row))


if __name__ == '__main__':
    main()
