"""check_julia_layout.py: checks the struct declarations of bindings/julia/src/CoverageAxis.jl against
the C layout printed by tests/abi_layout (Julia is not packaged in Debian 12, so the binding cannot
run here). Every immutable `struct` whose first field is `struct_size::UInt32` is parsed, laid out
with C's rules (each field at the next multiple of its alignment, the size rounded up to the largest
alignment) and compared field by field (names, offsets, sizes) with the printer's output; every
printed struct must be declared.
usage: check_julia_layout.py ABI_LAYOUT_EXE bindings/julia/src/CoverageAxis.jl"""
import re
import sys

from check_layout import printed_layout

# size (= alignment) of the Julia types a C struct may hold, on this 64-bit platform
SIZES = {"UInt8": 1, "Int8": 1, "Int32": 4, "UInt32": 4, "Cint": 4, "Cuint": 4, "Float32": 4,
         "Int64": 8, "UInt64": 8, "Float64": 8, "Cdouble": 8, "Csize_t": 8, "Int": 8, "UInt": 8}


def type_size(t):
    """(size, alignment) of a Julia field type; NTuple{N, T} is a C array T[N]."""
    if re.fullmatch(r"Ptr\{.*\}", t):
        return 8, 8
    m = re.fullmatch(r"NTuple\{(\d+),\s*(\w+)\}", t)
    if m:
        size, align = type_size(m.group(2))
        return int(m.group(1)) * size, align
    if t not in SIZES:
        raise ValueError("no C size known for Julia type %s" % t)
    return SIZES[t], SIZES[t]


def julia_structs(path):
    """{C name: (sizeof, [(field, offset, size)])} for the C structs the file declares."""
    out = {}
    text = open(path).read()
    for m in re.finditer(r"^struct (\w+)\n(.*?)^end\b", text, re.S | re.M):
        fields = []
        for line in m.group(2).splitlines():
            decl = line.split("#")[0].strip()
            if decl:
                name, _, typ = decl.partition("::")
                fields.append((name.strip(), typ.strip()))
        if not fields or fields[0] != ("struct_size", "UInt32"):
            continue
        offset, align, laid = 0, 1, []
        for name, typ in fields:
            size, field_align = type_size(typ)
            offset = (offset + field_align - 1) // field_align * field_align
            laid.append((name, offset, size))
            offset += size
            align = max(align, field_align)
        cname = "ca" + re.sub(r"([A-Z])", lambda c: "_" + c.group(1).lower(), m.group(1))
        out[cname] = ((offset + align - 1) // align * align, laid)
    return out


def main():
    exe, julia = sys.argv[1], sys.argv[2]
    layout, order = printed_layout(exe)
    declared = julia_structs(julia)
    errors, matched = [], 0
    for name in order:
        if name not in declared:
            errors.append("%s is not declared in %s" % (name, julia))
            continue
        size, fields = declared[name]
        want = layout[name]
        if fields != want["fields"] or size != want["size"]:
            errors.append("Julia %s (%d bytes) %s differs from the C layout (%d bytes) %s" %
                          (name, size, fields, want["size"], want["fields"]))
        else:
            matched += 1
    for name in declared:
        if name not in layout:
            errors.append("Julia declares %s, which the header does not have" % name)
    for e in errors:
        print("julia layout: " + e)
    print("julia_layout: %d Julia structs compared with %d printed, %d errors" % (len(declared), len(order), len(errors)))
    print("%d passed, %d failed" % (matched, len(errors)))
    return 1 if errors or not declared else 0


if __name__ == "__main__":
    sys.exit(main())
