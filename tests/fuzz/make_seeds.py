#!/usr/bin/env python3
# make_seeds.py: writes the fuzz_pipeline seed corpus: the small meshes given as OBJ files, in the
# harness's structured format (8 option bytes, u16 counts, float32 coordinates, u16 indices), each
# with a few option variants. Usage: make_seeds.py OUTDIR mesh.obj...
import os, struct, sys

def read_obj(path):
    v, f = [], []
    for line in open(path):
        t = line.split()
        if not t: continue
        if t[0] == 'v': v.append(tuple(float(x) for x in t[1:4]))
        elif t[0] == 'f':
            idx = [int(x.split('/')[0]) - 1 for x in t[1:]]
            for i in range(1, len(idx) - 1): f.append((idx[0], idx[i], idx[i + 1]))
    return v, f

def encode(opt, v, f):
    b = bytes(opt) + struct.pack('<HH', len(v), len(f))
    b += b''.join(struct.pack('<3f', *p) for p in v)
    b += b''.join(struct.pack('<3H', *t) for t in f)
    return b

# option variants: Voronoi defaults; random generator + scale dilation; padded strides with a
# huge coordinate scale; prove effort with a target count and divide and conquer
VARIANTS = [[0, 60, 100, 20, 0, 0x1c, 0, 0], [0x09, 30, 50, 40, 0, 0x1d, 0, 0],
            [0x40, 80, 120, 10, 0xc5, 0x1e, 120, 1], [0x14, 20, 40, 30, 0x4a, 0x0c, 0x88, 0]]

out = sys.argv[1]
os.makedirs(out, exist_ok=True)
for path in sys.argv[2:]:
    v, f = read_obj(path)
    if len(v) > 65535 or len(f) > 65535: continue
    for k, opt in enumerate(VARIANTS):
        name = '%s-%d' % (os.path.splitext(os.path.basename(path))[0], k)
        open(os.path.join(out, name), 'wb').write(encode(opt, v, f))
