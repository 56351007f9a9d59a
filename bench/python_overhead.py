"""Bench: what passing a mesh in and out of Python adds to a `repair` call
(issue 49: under 5% on a 1M-triangle mesh).

Builds a closed UV sphere of about a million triangles with numpy (int64
indices, as most Python mesh libraries hold them), then times, best of
--repeat runs: making the fabvdb.Mesh from the arrays (the one conversion
and the library's copy), fabvdb.repair on it, and taking the result out as
numpy arrays (views, then copies to own them). Prints the figures and the
overhead as a share of the repair.

    PYTHONPATH=build/python python3 bench/python_overhead.py [--triangles N] [--repeat R]
"""
import argparse
import time

import numpy as np

import fabvdb


def uv_sphere(triangles, radius=50.0):
    """A closed, outward-oriented UV sphere with about `triangles` triangles (poles as single vertices)."""
    rings = max(3, int(np.sqrt(triangles / 4.0)))
    segments = 2 * rings
    theta = np.linspace(0, np.pi, rings + 1)[1:-1]
    phi = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    body = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1).reshape(-1, 3)
    vertices = np.concatenate([[[0, 0, 1]], body, [[0, 0, -1]]]) * radius
    ring = lambda r: 1 + r * segments + (np.arange(segments) % segments)
    nxt = lambda r: 1 + r * segments + ((np.arange(segments) + 1) % segments)
    faces = [np.stack([np.zeros(segments, np.int64), ring(0), nxt(0)], axis=1)]
    for r in range(rings - 2):
        a, b, c, d = ring(r), nxt(r), ring(r + 1), nxt(r + 1)
        faces += [np.stack([a, c, b], axis=1), np.stack([b, c, d], axis=1)]
    south = len(vertices) - 1
    last = rings - 2
    faces.append(np.stack([np.full(segments, south, np.int64), nxt(last), ring(last)], axis=1))
    return vertices, np.concatenate(faces).astype(np.int64)


def best(function, repeat):
    times, value = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        value = function()
        times.append(time.perf_counter() - start)
    return min(times), value


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    vertices, triangles = uv_sphere(args.triangles)
    print(f"UV sphere: {len(vertices)} vertices, {len(triangles)} triangles (float64, int64)")
    t_in, mesh = best(lambda: fabvdb.Mesh(vertices, triangles), args.repeat)
    t_repair, result = best(lambda: fabvdb.repair(mesh, report=False), args.repeat)
    out = result.mesh
    t_view, _ = best(lambda: (out.vertices, out.triangles), args.repeat)
    t_copy, _ = best(lambda: (np.array(out.vertices), np.array(out.triangles, dtype=np.int64)), args.repeat)
    print(f"in:  fabvdb.Mesh(vertices, triangles)       {t_in * 1000:8.1f} ms")
    print(f"     fabvdb.repair(mesh, report=False)      {t_repair * 1000:8.1f} ms  ({out.triangle_count} triangles out)")
    print(f"out: .vertices, .triangles (views)          {t_view * 1000:8.3f} ms")
    print(f"     copies as float64 / int64 arrays       {t_copy * 1000:8.1f} ms")
    print(f"overhead of in + out (views): {100 * (t_in + t_view) / t_repair:.2f}% of the repair; "
          f"with owned copies: {100 * (t_in + t_copy) / t_repair:.2f}%")


if __name__ == "__main__":
    main()
