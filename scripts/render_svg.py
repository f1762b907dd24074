#!/usr/bin/env python3
"""render_svg.py: draws a mesh (shaded triangles) and a medial skeleton (.ma: balls as circles,
edges as lines, faces as translucent triangles) in orthographic projection to an SVG, for the
README. Standard library only.
usage: render_svg.py MESH.obj SKELETON.ma OUT.svg [yaw_deg] [pitch_deg] [zup]   (zup: z is up, y is across)"""
import math
import sys


def read_obj(path):
    V, F = [], []
    for line in open(path):
        p = line.split()
        if not p:
            continue
        if p[0] == 'v':
            V.append(tuple(map(float, p[1:4])))
        elif p[0] == 'f':
            idx = [int(t.split('/')[0]) for t in p[1:]]
            idx = [i - 1 if i > 0 else len(V) + i for i in idx]
            for k in range(1, len(idx) - 1):
                F.append((idx[0], idx[k], idx[k + 1]))
    return V, F


def read_ma(path):
    lines = [l.split() for l in open(path) if l.strip()]
    nv, ne, nf = map(int, lines[0])
    balls = [tuple(map(float, l[1:5])) for l in lines[1:1 + nv]]
    edges = [tuple(map(int, l[1:3])) for l in lines[1 + nv:1 + nv + ne]]
    faces = [tuple(map(int, l[1:4])) for l in lines[1 + nv + ne:1 + nv + ne + nf]]
    return balls, edges, faces


def main():
    mesh, ma, out = sys.argv[1:4]
    yaw = math.radians(float(sys.argv[4]) if len(sys.argv) > 4 else 30)
    pitch = math.radians(float(sys.argv[5]) if len(sys.argv) > 5 else 20)
    V, F = read_obj(mesh)
    balls, edges, faces = read_ma(ma)

    zup = len(sys.argv) > 6 and sys.argv[6] == 'zup'

    def rot(p):
        x, y, z = (p[1], p[2], p[0]) if zup else p
        x, z = x * math.cos(yaw) + z * math.sin(yaw), -x * math.sin(yaw) + z * math.cos(yaw)
        y, z = y * math.cos(pitch) - z * math.sin(pitch), y * math.sin(pitch) + z * math.cos(pitch)
        return x, y, z

    RV = [rot(v) for v in V]
    xs, ys = [v[0] for v in RV], [v[1] for v in RV]
    lo_x, hi_x, lo_y, hi_y = min(xs), max(xs), min(ys), max(ys)
    size, pad = 640.0, 20.0
    s = (size - 2 * pad) / max(hi_x - lo_x, hi_y - lo_y)
    W, H = (hi_x - lo_x) * s + 2 * pad, (hi_y - lo_y) * s + 2 * pad

    def px(p):
        return pad + (p[0] - lo_x) * s, H - pad - (p[1] - lo_y) * s

    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %.1f %.1f">' % (W, H, W, H),
             '<rect width="100%" height="100%" fill="white"/>']
    light = (0.3, 0.5, 0.8)
    n = math.sqrt(sum(c * c for c in light))
    light = tuple(c / n for c in light)
    tris = []
    for f in F:
        a, b, c = RV[f[0]], RV[f[1]], RV[f[2]]
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        nrm = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        ln = math.sqrt(sum(x * x for x in nrm)) or 1
        if nrm[2] / ln <= 0:
            continue  # back face
        shade = 0.55 + 0.4 * max(0, sum(nrm[i] / ln * light[i] for i in range(3)))
        tris.append(((a[2] + b[2] + c[2]) / 3, (a, b, c), shade))
    tris.sort(key=lambda t: t[0])
    for _, (a, b, c), shade in tris:
        g = int(255 * shade)
        pts = ' '.join('%.1f,%.1f' % px(p) for p in (a, b, c))
        parts.append('<polygon points="%s" fill="rgb(%d,%d,%d)" fill-opacity="0.35" stroke="none"/>' % (pts, g, g, g))
    RB = [rot(b[:3]) for b in balls]
    for f in faces:
        pts = ' '.join('%.1f,%.1f' % px(RB[i]) for i in f)
        parts.append('<polygon points="%s" fill="#e8a33d" fill-opacity="0.45" stroke="#b86e00" stroke-width="0.6"/>' % pts)
    for i, j in edges:
        (x1, y1), (x2, y2) = px(RB[i]), px(RB[j])
        parts.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#8a3b00" stroke-width="1.6"/>' % (x1, y1, x2, y2))
    for p, b in zip(RB, balls):
        x, y = px(p)
        parts.append('<circle cx="%.1f" cy="%.1f" r="%.1f" fill="#3d7be8" fill-opacity="0.12" stroke="#3d7be8" stroke-width="0.5"/>' % (x, y, b[3] * s))
        parts.append('<circle cx="%.1f" cy="%.1f" r="2.2" fill="#1b4fb0"/>' % (x, y))
    parts.append('</svg>')
    open(out, 'w').write('\n'.join(parts) + '\n')


if __name__ == '__main__':
    main()
