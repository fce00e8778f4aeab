#!/usr/bin/env python3
"""Writes maze.world and maze.route: a hedge maze of 1.2 m corridors on grass,
a random inner maze inside a long ring corridor, small holes in some hedges at
the laser's height, and a route from the centre to the exit. Deterministic.

    python3 worlds/make_maze.py    # from the repository root
"""
import os
import random
from collections import deque

N = 10           # cells per side; the outer ring of cells is a ring corridor
CELL = 4         # plan characters per corridor width (4 x 0.3 m = 1.2 m)
CHAR = 0.3       # [m] per plan character; hedges are one character thick
HOLES = 14       # hedge characters with a hole at the laser's height
SEED = 7

rng = random.Random(SEED)
size = N * (CELL + 1) + 1
plan = [['#'] * size for _ in range(size)]


def centre_char(i, j):
    return 1 + (CELL + 1) * i + CELL // 2, 1 + (CELL + 1) * j + CELL // 2


def open_cell(i, j):
    for dy in range(CELL):
        for dx in range(CELL):
            plan[1 + (CELL + 1) * j + dy][1 + (CELL + 1) * i + dx] = ' '


def open_between(a, b):
    (i, j), (k, l) = a, b
    if i == k:   # vertical neighbours: open the hedge between them
        y = (CELL + 1) * max(j, l)
        for dx in range(CELL):
            plan[y][1 + (CELL + 1) * i + dx] = ' '
    else:
        x = (CELL + 1) * max(i, k)
        for dy in range(CELL):
            plan[1 + (CELL + 1) * j + dy][x] = ' '


edges = set()


def link(a, b):
    open_between(a, b)
    edges.add((a, b))
    edges.add((b, a))


for j in range(N):
    for i in range(N):
        open_cell(i, j)

# The ring corridor: every outer cell linked to the next one around.
ring = [(i, 0) for i in range(N)] + [(N - 1, j) for j in range(1, N)] + \
       [(i, N - 1) for i in range(N - 2, -1, -1)] + [(0, j) for j in range(N - 2, 0, -1)]
for a, b in zip(ring, ring[1:] + ring[:1]):
    link(a, b)

# The inner maze: a recursive backtracker over the inner cells.
inner = {(i, j) for i in range(1, N - 1) for j in range(1, N - 1)}
start = (N // 2, N // 2)
seen, stack = {start}, [start]
while stack:
    i, j = stack[-1]
    nbrs = [(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))
            if (i + di, j + dj) in inner and (i + di, j + dj) not in seen]
    if not nbrs:
        stack.pop()
        continue
    n = rng.choice(nbrs)
    link((i, j), n)
    seen.add(n)
    stack.append(n)
link((1, 1), (1, 0))           # the inner maze opens to the ring at its top-left
# The exit: a gap in the outer hedge below the bottom-right cell.
ex, ey = centre_char(N - 1, N - 1)
for dx in range(-(CELL // 2), CELL // 2):
    plan[size - 1][ex + dx] = ' '

# Holes: single hedge characters between two corridors, away from posts.
candidates = [(x, y) for y in range(1, size - 1) for x in range(1, size - 1)
              if plan[y][x] == '#' and x % (CELL + 1) and y % (CELL + 1) == 0
              and plan[y - 1][x] == ' ' and plan[y + 1][x] == ' ']
candidates += [(x, y) for y in range(1, size - 1) for x in range(1, size - 1)
               if plan[y][x] == '#' and y % (CELL + 1) and x % (CELL + 1) == 0
               and plan[y][x - 1] == ' ' and plan[y][x + 1] == ' ']
for x, y in rng.sample(sorted(candidates), HOLES):
    plan[y][x] = 'o'

# The route: breadth-first from the centre to the exit cell, then outside.
prev, q = {start: None}, deque([start])
while q:
    c = q.popleft()
    for e in [b for (a, b) in edges if a == c]:
        if e not in prev:
            prev[e] = c
            q.append(e)
path, c = [], (N - 1, N - 1)
while c is not None:
    path.append(c)
    c = prev[c]
path.reverse()

half = size * CHAR / 2
to_xy = lambda cx, cy: (-half + CHAR * (cx + 0.5), half - CHAR * (cy + 0.5))
points = [to_xy(*centre_char(*c)) for c in path]
points.append((points[-1][0], points[-1][1] - 2.0))   # out through the exit
route = [points[0]]                                    # drop collinear points
for p, nxt in zip(points[1:], points[2:] + [None]):
    if nxt is None or not ((route[-1][0] == p[0] == nxt[0]) or (route[-1][1] == p[1] == nxt[1])):
        route.append(p)

here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, 'maze.world'), 'w') as f:
    f.write(f"""omnirange-world 1
# The maze: hedges of a green close to the grass floor's, 1.2 m corridors, a
# random inner maze inside a long ring corridor, and small holes in some
# hedges through which the laser (at 0.30 m) reaches the next corridor.
# Written by worlds/make_maze.py (seed {SEED}); edit the plan freely.
name maze
bounds xmin={-half - 1:.2f} ymin={-half - 3:.2f} xmax={half + 1:.2f} ymax={half + 1:.2f}
floor material=grass
sky rgb=200,215,235
light azimuth=0.8 elevation=1.2 ambient=0.85 diffuse=0.2

material name=hedge rgb=40,90,36 grain=0.04 grain_contrast=0.18 patch=0.6 patch_contrast=0.08 hue_jitter=0.06   # a darker green than the grass
legend char=# material=hedge z1=1.8
legend char=o material=hedge z1=1.8 gap0=0.24 gap1=0.36
plan x0={-half:.2f} y0={half:.2f} cell={CHAR}
""")
    for row in plan:
        f.write(''.join(row).replace(' ', '.').rstrip() + '\n')
    f.write('end\n')
with open(os.path.join(here, 'maze.route'), 'w') as f:
    f.write('# From the maze centre to the exit (bottom right). Written by worlds/make_maze.py.\n')
    for x, y in route:
        f.write(f'{x:.2f} {y:.2f}\n')
print(f'maze: {size}x{size} plan, route of {len(route)} waypoints')
