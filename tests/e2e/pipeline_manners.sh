#!/usr/bin/env bash
# pipeline_manners.sh: end-to-end tests of the tool as an asset-pipeline step: --version, the JSON
# report's versions and its error object on failure, the batch command (every input reported,
# failures as errors, exit 1, the same .ma files as single runs, reruns skipped until an input
# or an option changes, --force), the glTF writer read back, and the preview picture's size.
# usage: pipeline_manners.sh PATH/TO/coverage-axis PATH/TO/tests/data
set -u
source "$(dirname "$0")/check.bash" "$@"
# py 'python expression over the JSON object j' FILE: exit status of the boolean
# pylines 'expression over the list of line objects L' FILE

# 1. versions
"$tool" --version > "$tmp/v" 2>&1
check "--version exits 0" test $? -eq 0
check "--version names the tool, library and ABI versions" grep -Eq '^coverage-axis [0-9]+\.[0-9]+\.[0-9]+ \(library [0-9]+\.[0-9]+\.[0-9]+, ABI [0-9]+\)$' "$tmp/v"
tool_version=$(cut -d' ' -f2 "$tmp/v")
"$tool" "$data/torus.obj" -o "$tmp/t.ma" --json > "$tmp/t.json"
check "JSON has format_version 1 and the tool version" py "j['format_version'] == 1 and j['tool_version'] == '$tool_version'" "$tmp/t.json"

# 1b. standard input with --format, a glTF input, and folder expansion by readable format
"$tool" "$data/fox.obj" -o "$tmp/fox_file.ma" --quiet
"$tool" - --format obj -o "$tmp/fox_stdin.ma" --quiet < "$data/fox.obj"
check "- with --format obj reads standard input: the same .ma as the file" cmp -s "$tmp/fox_file.ma" "$tmp/fox_stdin.ma"
"$tool" - --json < "$data/fox.obj" > "$tmp/e0.json"
check "- without -o is a usage error (exit 2, JSON error)" test $? -eq 2
check "the stdin usage error names -o" py "'-o' in j['error']['message']" "$tmp/e0.json"
"$tool" "$data/formats/fox.glb" -o "$tmp/fox_glb.ma" --json > "$tmp/glb.json"
check "fox.glb (float32 positions) gives fox.obj's 63 balls" py "j['selected'] == 63" "$tmp/glb.json"
"$tool" --help > "$tmp/help"
check "--help lists the glTF and assimp formats" grep -q "glb; through assimp:.*fbx" "$tmp/help"

# 2. --json failures: one JSON error object on stdout, non-zero exit
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n' > "$tmp/flat.obj"
"$tool" "$tmp/flat.obj" -o "$tmp/flat.ma" --volumetric-only --json > "$tmp/e1.json" 2> "$tmp/err"
code=$?
check "library failure with --json: exit 1 (got $code)" test "$code" -eq 1
check "library failure: the error object names a CA_ERROR status and its code" \
  py "j['error']['status'].startswith('CA_ERROR_') and j['error']['code'] > 0 and len(j['error']['message']) > 0" "$tmp/e1.json"
check "library failure: nothing on stderr" test ! -s "$tmp/err"
"$tool" "$tmp/missing.obj" --json > "$tmp/e2.json"
code=$?
check "missing file with --json: exit 3 (got $code)" test "$code" -eq 3
check "missing file: FILE_ERROR" py "j['error']['status'] == 'FILE_ERROR' and 'missing.obj' in j['error']['message']" "$tmp/e2.json"
"$tool" "$data/torus.obj" --delta -1 --json > "$tmp/e3.json"
code=$?
check "bad option with --json: exit 2 (got $code)" test "$code" -eq 2
check "bad option: USAGE_ERROR naming the option" py "j['error']['status'] == 'USAGE_ERROR' and '--delta' in j['error']['message']" "$tmp/e3.json"

# 3. batch: a folder of bundled models and a broken file (the default time limit does not bind on
# these, so the covers do not depend on how the jobs share the cores)
mkdir -p "$tmp/in"
cp "$data/fox.obj" "$data/torus.obj" "$data/genus3.obj" "$data/fish_points.xyz" "$tmp/in/"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$tmp/in/broken.obj"
echo "not a mesh" > "$tmp/in/readme.txt"
"$tool" batch -O "$tmp/out" -j 2 --write glb,png "$tmp/in" > "$tmp/b1.jsonl"
code=$?
check "batch with a broken input exits 1 (got $code)" test "$code" -eq 1
check "batch: one line per mesh file, sorted, readme.txt not taken" \
  pylines "[l['input'].split('/')[-1] for l in L] == ['broken.obj', 'fish_points.xyz', 'fox.obj', 'genus3.obj', 'torus.obj']" "$tmp/b1.jsonl"
check "batch: the broken file is an error line" pylines "L[0]['error']['status'] == 'FILE_ERROR' and 'selected' not in L[0]" "$tmp/b1.jsonl"
check "batch: the others succeeded, not skipped" pylines "all('error' not in l and l['skipped'] is False and l['selected'] > 0 for l in L[1:])" "$tmp/b1.jsonl"
for m in fish_points fox genus3 torus; do
  ext=obj; [ "$m" = fish_points ] && ext=xyz
  "$tool" "$tmp/in/$m.$ext" -o "$tmp/single_$m.ma" --quiet
  check "batch $m.ma is identical to a single run's" cmp -s "$tmp/out/$m.ma" "$tmp/single_$m.ma"
  check "batch wrote $m.glb, $m.png and sidecars" test -s "$tmp/out/$m.glb" -a -s "$tmp/out/$m.png" -a -s "$tmp/out/$m.ma.sidecar.json"
done
check "batch: no output for the broken file" test ! -e "$tmp/out/broken.ma"

# reruns: up to date -> skipped (outputs untouched); a changed input or option -> redone
touch -d '2001-01-01' "$tmp/out/fox.ma"
"$tool" batch -O "$tmp/out" -j 2 --write glb,png "$tmp/in" > "$tmp/b2.jsonl"
check "rerun: still exit 1 (the broken file)" test $? -eq 1
check "rerun: every good input skipped, with its report" pylines "all(l['skipped'] is True and l['selected'] > 0 for l in L[1:])" "$tmp/b2.jsonl"
check "rerun: fox.ma not rewritten" test "$(date -r "$tmp/out/fox.ma" +%Y)" = 2001
cat "$data/torus.obj" > "$tmp/in/torus.obj"; echo "# changed" >> "$tmp/in/torus.obj"
"$tool" batch -O "$tmp/out" -j 2 --write glb,png "$tmp/in" > "$tmp/b3.jsonl"
check "changed input: redone, the others skipped" \
  pylines "[l.get('skipped') for l in L[1:]] == [True, True, True, False]" "$tmp/b3.jsonl"
"$tool" batch -O "$tmp/out" -j 2 --write glb,png --seed 3 "$tmp/in/fox.obj" > "$tmp/b4.jsonl"
check "changed option: redone" pylines "L[0]['skipped'] is False" "$tmp/b4.jsonl"
check "changed option: fox.ma rewritten" test "$(date -r "$tmp/out/fox.ma" +%Y)" != 2001
"$tool" batch -O "$tmp/out" -j 2 --write glb,png --seed 3 "$tmp/in/fox.obj" > "$tmp/b5.jsonl"
check "same options again: skipped" pylines "L[0]['skipped'] is True" "$tmp/b5.jsonl"
rm "$tmp/out/fox.png"
"$tool" batch -O "$tmp/out" -j 2 --write glb,png --seed 3 "$tmp/in/fox.obj" > "$tmp/b6.jsonl"
check "a missing output: redone" pylines "L[0]['skipped'] is False" "$tmp/b6.jsonl"
check "a missing output: written again" test -s "$tmp/out/fox.png"
"$tool" batch -O "$tmp/out" --force --write glb,png "$tmp/in/genus3.obj" "$tmp/in/fox.obj" > "$tmp/b7.jsonl"
code=$?
check "--force: exit 0 when all succeed (got $code)" test "$code" -eq 0
check "--force: redone" pylines "len(L) == 2 and all(l['skipped'] is False for l in L)" "$tmp/b7.jsonl"
"$tool" batch -O "$tmp/out" "$tmp/in/fox.obj" "$tmp/fox_copy/fox.obj" > "$tmp/b8.jsonl" 2> /dev/null
check "batch: two inputs with one stem: the second is an error" pylines "'error' not in L[0] and 'same file stem' in L[1]['error']['message']" "$tmp/b8.jsonl"

# 4. glTF: the .glb read back against the .ma (counts, accessor min/max, radii, ball nodes)
"$tool" "$data/fox.obj" -o "$tmp/fox.ma" --gltf "$tmp/fox.glb" --quiet
check "--gltf .glb written" test -s "$tmp/fox.glb"
cat > "$tmp/glb.py" <<'PY'
import json, struct, sys
glb, ma = open(sys.argv[1], 'rb').read(), open(sys.argv[2]).read().split('\n')
magic, version, length = struct.unpack_from('<III', glb, 0)
assert magic == 0x46546C67 and version == 2 and length == len(glb), 'header'
jlen, jtype = struct.unpack_from('<II', glb, 12)
assert jtype == 0x4E4F534A and jlen % 4 == 0, 'JSON chunk'
doc = json.loads(glb[20:20 + jlen])
blen, btype = struct.unpack_from('<II', glb, 20 + jlen)
assert btype == 0x004E4942 and 28 + jlen + blen == len(glb), 'BIN chunk'
assert doc['buffers'][0]['byteLength'] == blen
binary = glb[28 + jlen:]
nv, ne, nf = map(int, ma[0].split())
balls = [list(map(float, l.split()[1:5])) for l in ma if l.startswith('v ')]
def read(acc):
    a = doc['accessors'][acc]; v = doc['bufferViews'][a['bufferView']]
    n = {'SCALAR': 1, 'VEC3': 3}[a['type']] * a['count']
    fmt = {5126: 'f', 5125: 'I', 5123: 'H'}[a['componentType']]
    return a, struct.unpack_from('<%d%s' % (n, fmt), binary, v['byteOffset'] + a.get('byteOffset', 0))
sk = next(m for m in doc['meshes'] if m['name'] == 'skeleton')
modes = {p['mode']: p for p in sk['primitives']}
pa, pos = read(modes[1]['attributes']['POSITION'])
ra, rad = read(modes[1]['attributes']['_RADIUS'])
assert pa['count'] == nv and ra['count'] == nv, 'vertex count'
for k in range(3):
    c = pos[k::3]
    assert pa['min'][k] == min(c) and pa['max'][k] == max(c), 'POSITION min/max'
assert ra['min'][0] == min(rad) and ra['max'][0] == max(rad), '_RADIUS min/max'
for i, b in enumerate(balls):
    assert abs(rad[i] - b[3]) <= 1e-6 * max(1, b[3]) and all(abs(pos[3*i+k] - b[k]) <= 1e-5 * max(1, abs(b[k])) for k in range(3)), 'ball %d' % i
ea, edges = read(modes[1]['indices'])
fa, faces = read(modes[4]['indices'])
assert ea['count'] == 2 * ne and fa['count'] == 3 * nf, 'edge/face counts'
ma_edges = [tuple(map(int, l.split()[1:3])) for l in ma if l.startswith('e ')]
assert sorted(map(lambda e: tuple(sorted(e)), zip(edges[::2], edges[1::2]))) == sorted(tuple(sorted(e)) for e in ma_edges), 'edges'
nodes = [n for n in doc['nodes'] if n.get('mesh') == 0]
assert len(nodes) == nv and len(doc['nodes'][0]['children']) == nv, 'ball nodes'
for n, b in zip(nodes, balls):
    close = lambda x, y: abs(x - y) <= 1e-8 * max(1, abs(y))  # the .ma holds 9 digits, the glTF JSON all 17
    assert all(close(s, b[3]) for s in n['scale']) and all(close(t, c) for t, c in zip(n['translation'], b[:3])), 'ball node transform'
print('ok', nv, ne, nf)
PY
check "glb read back matches the .ma" python3 "$tmp/glb.py" "$tmp/fox.glb" "$tmp/fox.ma"
"$tool" "$data/fox.obj" -o "$tmp/fox2.ma" --gltf "$tmp/fox.gltf" --quiet
check ".gltf: JSON with an embedded base64 buffer of the declared length" python3 -c "
import json, base64, sys
d = json.load(open(sys.argv[1]))
uri = d['buffers'][0]['uri']
assert uri.startswith('data:application/octet-stream;base64,')
assert len(base64.b64decode(uri.split(',', 1)[1])) == d['buffers'][0]['byteLength']
assert d['asset']['version'] == '2.0'" "$tmp/fox.gltf"
"$tool" "$data/fox.obj" -o "$tmp/x.ma" --gltf "$tmp/fox.fbx" --quiet 2> "$tmp/err"
check "--gltf with another extension: exit 3 and a message" test $? -eq 3 -a -s "$tmp/err"

# 5. preview: a PNG of the requested size (IHDR), an SVG of the requested size
"$tool" "$data/fox.obj" -o "$tmp/p.ma" --preview "$tmp/p.png" --preview-size 321x123 --view 30,20 --quiet
check "--preview writes a PNG" test -s "$tmp/p.png"
check "PNG signature and IHDR 321 x 123, 8-bit RGB" python3 -c "
import struct, sys
b = open(sys.argv[1], 'rb').read()
assert b[:8] == b'\x89PNG\r\n\x1a\n' and b[12:16] == b'IHDR'
w, h, depth, color = struct.unpack('>IIBB', b[16:26])
assert (w, h, depth, color) == (321, 123, 8, 2), (w, h, depth, color)" "$tmp/p.png"
"$tool" "$data/fox.obj" -o "$tmp/p.ma" --preview "$tmp/p.svg" --preview-size 300x200 --up z --quiet
check "--preview .svg of the requested size" grep -q '<svg xmlns="http://www.w3.org/2000/svg" width="300" height="200"' "$tmp/p.svg"
check "SVG: one circle per ball" test "$(grep -c 'url(#ball)' "$tmp/p.svg")" -eq "$(head -1 "$tmp/p.ma" | cut -d' ' -f1)"
"$tool" "$data/fox.obj" --preview "$tmp/p.png" --preview-size 10x10 --quiet 2> "$tmp/err"
check "--preview-size below 16: exit 2" test $? -eq 2

finish pipeline_manners
