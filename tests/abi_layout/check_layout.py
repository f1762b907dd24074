"""check_layout.py: checks the ABI layout printer against the header and the Python binding.
usage: check_layout.py ABI_LAYOUT_EXE HEADER   (PYTHONPATH points at bindings/python)
1. every struct of the header, and every field in declaration order, is printed (the printer is
   complete); offsets grow and fields do not overlap;
2. each ctypes Structure of bindings/python/coverage_axis/_structs.py has the printed size and, field by
   field, the printed names, offsets and sizes."""
import ctypes
import re
import subprocess
import sys


def header_structs(path):
    text = open(path).read()
    out = {}
    for m in re.finditer(r"typedef struct (\w+) \{(.*?)\} \1;", text, re.S):
        body = re.sub(r"/\*.*?\*/", "", m.group(2), flags=re.S)
        body = re.sub(r"\[\w+\]", "", body)   # an array field: its name
        fields = []
        for decl in filter(None, (d.strip() for d in body.split(";"))):
            parts = decl.split(",")
            fields.append(re.findall(r"(\w+)\s*$", parts[0])[0])
            fields += [p.strip() for p in parts[1:]]
        out[m.group(1)] = fields
    return out


def printed_layout(exe):
    structs, order = {}, []
    for line in subprocess.run([exe], check=True, capture_output=True, text=True).stdout.splitlines():
        rec = line.split(" ")
        if rec[0] == "struct":
            structs[rec[1]] = {"size": int(rec[2]), "fields": []}
            order.append(rec[1])
        elif rec[0] == "field":
            structs[rec[1]]["fields"].append((rec[2], int(rec[3]), int(rec[4])))
    return structs, order


def main():
    exe, header = sys.argv[1], sys.argv[2]
    errors = []
    expected = header_structs(header)
    layout, order = printed_layout(exe)
    if order != list(expected):
        errors.append("printed structs %s, header has %s" % (order, list(expected)))
    for name, fields in expected.items():
        got = layout.get(name, {"fields": []})
        if [f[0] for f in got["fields"]] != fields:
            errors.append("%s: printed fields %s, header has %s" % (name, [f[0] for f in got["fields"]], fields))
        end = 0
        for f, off, size in got["fields"]:
            if off < end:
                errors.append("%s.%s overlaps the previous field" % (name, f))
            end = off + size
        if name in layout and end > layout[name]["size"]:
            errors.append("%s: fields end past sizeof" % name)

    from coverage_axis import _structs
    checked, compared = 0, set()
    for attr in dir(_structs):
        cls = getattr(_structs, attr)
        if not (isinstance(cls, type) and issubclass(cls, ctypes.Structure) and attr.startswith("_")):
            continue
        cname = "ca" + re.sub(r"([A-Z])", lambda m: "_" + m.group(1).lower(), attr[1:])
        if cname not in layout:
            errors.append("Python %s: no struct %s in the header" % (attr, cname))
            continue
        want = layout[cname]
        got = [(f[0], getattr(cls, f[0]).offset, getattr(cls, f[0]).size) for f in cls._fields_]
        if got != want["fields"] or ctypes.sizeof(cls) != want["size"]:
            errors.append("Python %s (%d bytes) %s differs from %s (%d bytes) %s" %
                          (attr, ctypes.sizeof(cls), got, cname, want["size"], want["fields"]))
        checked += 1
        compared.add(cname)
    for name in layout:
        if name not in compared:
            errors.append("%s: no Python ctypes mirror in coverage_axis/_structs.py" % name)
    for e in errors:
        print("layout: " + e)
    print("abi_layout: %d structs printed, %d Python structs compared, %d errors" % (len(layout), checked, len(errors)))
    return 1 if errors or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
