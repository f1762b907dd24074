"""check_defaults.py: every default the header's comments name is the library's default.
usage: check_defaults.py LIBRARY HEADER   (PYTHONPATH points at bindings/python)
The header states each option's default once, in the comment of its field ("default 60",
"default VORONOI" with the constants' prefix named as CA_CANDIDATES_*, or "0 (default)"). For every
struct with a ca_<name>_defaults function, the struct is filled by the library through the Python
binding's ctypes layout, and each stated default is compared with the field's value. A field whose
comment names no default must be 0 / NULL, as the header's opening comment says."""
import ctypes
import re
import sys

from coverage_axis import _structs

NUMBER = r"-?\d+(?:\.\d+)?(?:e-?\d+)?"


def constants(text):
    return {m.group(1): int(m.group(2)) for m in re.finditer(r"^#define (CA_\w+)\s+\(?(-?\d+)\)?", text, re.M)}


def stated_defaults(text):
    """(struct, field, value as text, comment) for every field whose comment names a default."""
    out = []
    for m in re.finditer(r"typedef struct (\w+) \{(.*?)\} \1;", text, re.S):
        body = m.group(2)
        decls = list(re.finditer(r"([A-Za-z_][\w\s\*]*?)\b(\w+)\s*;", re.sub(r"/\*.*?\*/", lambda c: " " * len(c.group(0)), body, flags=re.S)))
        for i, d in enumerate(decls):
            end = decls[i + 1].start() if i + 1 < len(decls) else len(body)
            comment = " ".join(re.findall(r"/\*(.*?)\*/", body[d.end():end], re.S))
            comment = re.sub(r"\s+", " ", comment)
            v = re.search(r"\bdefault (%s|[A-Z][A-Z_]+)\b" % NUMBER, comment) or \
                re.search(r"(?:^|[\s.:])(%s|[A-Z][A-Z_]+) \(default\b" % NUMBER, comment)
            if v:
                out.append((m.group(1), d.group(2), v.group(1), comment))
    return out


def filled(lib, struct):
    """The struct as ca_<name>_defaults fills it, or None (no binding layout or no defaults function)."""
    cls = getattr(_structs, "_" + "".join(w.capitalize() for w in struct[3:].split("_")), None)
    fn = getattr(lib, "%s_defaults" % struct, None)
    if cls is None or fn is None:
        return None
    obj = cls()
    fn.restype, fn.argtypes = ctypes.c_int32, [ctypes.c_void_p, ctypes.c_uint32]
    return obj if fn(ctypes.byref(obj), ctypes.sizeof(obj)) == 0 else False


def unstated_are_zero(lib, text, stated):
    """(passed, failures): every field with no stated default, of a struct with ca_*_defaults, is 0 / NULL."""
    passed, failed = 0, []
    for struct in re.findall(r"typedef struct (\w+) \{.*?\} \1;", text, re.S):
        obj = filled(lib, struct)
        if not obj:
            continue
        for field, _ in obj._fields_:
            if field == "struct_size" or (struct, field) in stated:
                continue
            if getattr(obj, field) in (0, None):
                passed += 1
            else:
                failed.append("%s.%s states no default, so it must default to 0 / NULL; the library gives %s"
                              % (struct, field, getattr(obj, field)))
    return passed, failed


def main():
    lib = ctypes.CDLL(sys.argv[1])
    text = open(sys.argv[2]).read()
    defs = constants(text)
    passed, failed = 0, []
    for struct, field, value, comment in stated_defaults(text):
        obj = filled(lib, struct)
        if obj is None:
            failed.append("%s.%s states a default, but there is no ca_*_defaults or binding layout" % (struct, field))
            continue
        if obj is False:
            failed.append("%s_defaults failed" % struct)
            continue
        got = getattr(obj, field)
        if re.fullmatch(NUMBER, value):
            want = float(value)
        else:
            # the constants' prefix as the comment names it (CA_FIT_*), or a constant it names whole
            prefixes = re.findall(r"(CA_\w+?_)\*", comment)
            names = [p + value for p in prefixes if p + value in defs] or \
                [n for n in set(re.findall(r"CA_\w+", comment)) if n.endswith("_" + value) and n in defs]
            if len(names) != 1:
                failed.append("%s.%s: default %s names no one constant (prefixes %s)" % (struct, field, value, prefixes))
                continue
            want = defs[names[0]]
        if abs(float(got) - want) <= 1e-12 * max(1.0, abs(want)):
            passed += 1
        else:
            failed.append("%s.%s: the header says default %s, the library gives %s" % (struct, field, value, got))
    zero_passed, zero_failed = unstated_are_zero(lib, text, {(s, f) for s, f, _, _ in stated_defaults(text)})
    passed += zero_passed
    failed += zero_failed
    for f in failed:
        print("FAILED", f)
    print("check_defaults: %d passed, %d failed" % (passed, len(failed)))
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
