#!/usr/bin/env python3
"""check_markdown.py: checks that Markdown files render as written (standard library only).

  check_markdown.py [FILE.md ...]   (default: README.md and docs/*.md of this repository)
  check_markdown.py --self-test     (plants each kind of fault once and checks it is reported)

Checks, outside code fences and code spans:
  - every code fence (``` or ~~~) is closed;
  - every table row has as many cells as the table's header, and the delimiter row too;
  - every relative link or image ([text](path), ![alt](path)) names a file that exists, and a
    #fragment names a heading of that file (GitHub's anchors).
Prints one line per fault (file:line: what) and exits 1 when there is any.
"""
import os
import re
import sys
import tempfile

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})(.*)$")
LINK = re.compile(r"!?\[(?:[^\]\\]|\\.)*\]\(\s*<?([^)\s>]*)>?(?:\s+\"[^\"]*\")?\s*\)")
DELIMITER_CELL = re.compile(r"^\s*:?-+:?\s*$")
EXTERNAL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")  # http:, https:, mailto:, ...


def strip_code_spans(line):
    """The line with its code spans blanked (links in them are not links)."""
    out, i = [], 0
    while i < len(line):
        if line[i] == "`":
            n = len(line[i:]) - len(line[i:].lstrip("`"))
            ticks = line[i:i + n]
            end = line.find(ticks, i + n)
            if end >= 0:
                out.append(" " * (end + n - i))
                i = end + n
                continue
            out.append(ticks)
            i += n
            continue
        out.append(line[i])
        i += 1
    return "".join(out)


def cells(row):
    """Cells of a table row: split on pipes not escaped by a backslash, outer pipes dropped."""
    parts = re.split(r"(?<!\\)\|", row.strip())
    if parts and parts[0].strip() == "":
        parts = parts[1:]
    if parts and parts[-1].strip() == "" and row.strip().endswith("|"):
        parts = parts[:-1]
    return parts


def slug(heading):
    """GitHub's anchor for a heading text."""
    text = re.sub(r"`", "", heading)
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)  # links keep their text
    text = re.sub(r"<[^>]+>", "", text)
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def parse(path):
    """(lines outside fences as (number, text), unclosed fence line or None, anchors)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    prose, anchors, seen = [], set(), {}
    fence, fence_line = None, None
    for n, line in enumerate(lines, 1):
        m = FENCE.match(line)
        if fence is None and m:
            fence, fence_line = m.group(1), n
            continue
        if fence is not None:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) and not m.group(2).strip():
                fence = None
            continue
        prose.append((n, line))
        h = re.match(r"^ {0,3}#{1,6}\s+(.*?)\s*#*\s*$", line)
        if h:
            s = slug(h.group(1))
            k = seen.get(s, 0)
            seen[s] = k + 1
            anchors.add(s if k == 0 else "%s-%d" % (s, k))
    for n, line in prose:  # explicit anchors: <a name="x"> or id="x"
        for a in re.findall(r"<a\s+(?:name|id)=\"([^\"]+)\"", line):
            anchors.add(a)
    return prose, (fence_line if fence is not None else None), anchors


def check_tables(path, prose, faults):
    i = 0
    while i + 1 < len(prose):
        n, head = prose[i]
        _, delim = prose[i + 1]
        dcells = cells(delim) if "|" in delim or "-" in delim else []
        is_delim = "-" in delim and dcells and all(DELIMITER_CELL.match(c) for c in dcells)
        if "|" in head and is_delim and prose[i + 1][0] == n + 1:
            want = len(cells(head))
            if len(dcells) != want:
                faults.append("%s:%d: table delimiter row has %d cells, the header %d" % (path, n + 1, len(dcells), want))
            j = i + 2
            while j < len(prose) and prose[j][1].strip() and "|" in prose[j][1] and prose[j][0] == prose[j - 1][0] + 1:
                rn, row = prose[j]
                got = len(cells(row))
                if got != want:
                    faults.append("%s:%d: table row has %d cells, the header %d" % (path, rn, got, want))
                j += 1
            i = j
            continue
        i += 1


def check_links(path, prose, anchors_of, faults):
    base = os.path.dirname(os.path.abspath(path))
    for n, line in prose:
        for target in LINK.findall(strip_code_spans(line)):
            if not target or EXTERNAL.match(target):
                continue
            file_part, _, fragment = target.partition("#")
            dest = os.path.normpath(os.path.join(base, file_part)) if file_part else os.path.abspath(path)
            if not os.path.exists(dest):
                faults.append("%s:%d: link to %s: no such file" % (path, n, target))
                continue
            if fragment and dest.endswith(".md") and os.path.isfile(dest):
                if fragment.lower() not in anchors_of(dest):
                    faults.append("%s:%d: link to %s: no heading #%s in %s" % (path, n, target, fragment, os.path.basename(dest)))


def check(paths):
    faults, cache = [], {}

    def anchors_of(p):
        if p not in cache:
            cache[p] = parse(p)[2]
        return cache[p]

    for path in paths:
        prose, unclosed, anchors = parse(path)
        cache[os.path.abspath(path)] = anchors
        if unclosed is not None:
            faults.append("%s:%d: code fence never closed" % (path, unclosed))
        check_tables(path, prose, faults)
        check_links(path, prose, anchors_of, faults)
    return faults


def self_test():
    good = "# Title\n\n## A `code` heading\n\n| a | b |\n|---|---|\n| 1 | `x\\|y` |\n\n```sh\necho [x](nowhere.md)\n```\n\n[up](#title) [here](#a-code-heading) [me](good.md)\n"
    cases = {
        "good.md": (good, None),
        "table.md": ("| a | b |\n|---|---|\n| 1 | 2 | 3 |\n", "table row has 3 cells"),
        "delimiter.md": ("| a | b | c |\n|---|---|\n| 1 | 2 | 3 |\n", "delimiter row has 2 cells"),
        "fence.md": ("text\n\n```c\nint x;\n", "code fence never closed"),
        "link.md": ("[gone](missing.md)\n", "no such file"),
        "anchor.md": ("# Here\n\n[bad](good.md#nothing)\n", "no heading #nothing"),
    }
    ok = True
    with tempfile.TemporaryDirectory() as d:
        for name, (text, _) in cases.items():
            with open(os.path.join(d, name), "w", encoding="utf-8") as f:
                f.write(text)
        for name, (_, expect) in cases.items():
            faults = check([os.path.join(d, name)])
            if expect is None and faults:
                print("self-test: %s should pass but gave %s" % (name, faults))
                ok = False
            if expect is not None and (len(faults) != 1 or expect not in faults[0]):
                print("self-test: %s should give one fault '%s' but gave %s" % (name, expect, faults))
                ok = False
    print("self-test: %s" % ("ok" if ok else "FAILED"))
    return 0 if ok else 1


def main(argv):
    if argv[1:] == ["--self-test"]:
        return self_test()
    paths = argv[1:]
    if not paths:
        root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        docs = os.path.join(root, "docs")
        paths = [os.path.join(root, "README.md")] + sorted(
            os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    faults = check(paths)
    for f in faults:
        print(f)
    print("%d file(s), %d fault(s)" % (len(paths), len(faults)))
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
