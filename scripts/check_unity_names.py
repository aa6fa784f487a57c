#!/usr/bin/env python3
"""Names that would clash in a unity build (the quickstart's IGA_UNITY_BUILD): a unity batch
compiles several .cpp files of one layer as one translation unit, so two files of a layer that
define the same name with internal linkage (in an anonymous namespace, or `static` at namespace
scope) break the build as soon as a batch holds both — and which files share a batch shifts
whenever a file is added. The ctest `unity_names` runs this over the tree; the normal build never
sees such a clash. Usage:

    scripts/check_unity_names.py ROOT LAYER... [--separate FILE...]

Files given after --separate are compiled on their own (IGA_UNITY_SEPARATE, the PETSc
implementation); so are files that call Gmsh or libseccomp (CMakeLists.txt's rule, repeated
here). Functions clash when their parameter types match (overloads do not); classes and variables
when their names do."""
import os
import re
import sys

KEYWORDS = {"if", "for", "while", "switch", "return", "sizeof", "catch", "decltype", "alignof", "operator"}


def strip(text):
    """The code without comments, string and character literals, and preprocessor lines."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            i = text.find("\n", i)
            i = n if i < 0 else i
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
            out.append(" ")
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            j = text.find("(", i)
            delim = text[i + 2:j]
            k = text.find(")" + delim + '"', j)
            i = n if k < 0 else k + len(delim) + 2
            out.append('""')
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            out.append('""' if c == '"' else "0")
        else:
            out.append(c)
            i += 1
    lines = [l for l in "".join(out).split("\n") if not l.lstrip().startswith("#")]
    return "\n".join(lines)


def top_level_split(text):
    """`text` split at the commas outside brackets."""
    parts, depth, cur = [], 0, ""
    for c in text:
        if c in "<([{":
            depth += 1
        elif c in ">)]}":
            depth -= 1
        if c == "," and depth == 0:
            parts.append(cur)
            cur = ""
        else:
            cur += c
    parts.append(cur)
    return parts


def parameter_types(text):
    """The types of a parameter list: names and default values dropped, spaces normalised."""
    types = []
    for q in top_level_split(text):
        q = q.split("=")[0].strip()
        q = re.sub(r"(?<=[\w&*>\]])\s+\w+$", "", q) if len(q.split()) > 1 or re.search(r"[&*>]\s*\w+$", q) else q
        q = re.sub(r"([&*])\s*\w+$", r"\1", q)
        types.append(" ".join(q.split()))
    return ", ".join(t for t in types if t)


def defined_name(prefix, opens_block):
    """The name a namespace-scope definition with this text before its '{' or ';' defines."""
    p = " ".join(prefix.split())
    if not p or p.startswith("namespace ") or p.startswith("using ") or p.startswith("friend ") or p.startswith("template <") and p.endswith(">"):
        return None
    p = re.sub(r"^template\s*<[^{};]*?>\s*", "", p)
    m = re.match(r"^(?:\w+\s+)*(?:class|struct|union|enum(?:\s+class)?)\s+(\w+)", p)
    if m:
        return m.group(1)
    eq = p.find("=")
    paren = p.find("(")
    if eq >= 0 and (paren < 0 or eq < paren):  # variables (lambdas, constants), maybe several
        names = []
        for i, part in enumerate(top_level_split(p)):
            part = part.split("=")[0]
            m = re.search(r"(\w+)\s*(?:\[[^\]]*\])?\s*$", part) if i == 0 else re.match(r"\s*(\w+)", part)
            if m:
                names.append(m.group(1))
        return names
    if paren >= 0:
        if not opens_block:
            return None  # a declaration: only definitions clash
        m = re.search(r"(\w+)\s*$", p[:paren])
        if not m or m.group(1) in KEYWORDS:
            return None
        return m.group(1) + "(" + parameter_types(p[paren + 1:p.rfind(")")]) + ")"
    m = re.search(r"(\w+)\s*$", p)  # `Type name{...}` or `Type name;`
    return m.group(1) if m and len(p.split()) >= 2 else None


def as_list(name):
    return [] if not name else name if isinstance(name, list) else [name]


def internal_names(path):
    code = strip(open(path, encoding="utf-8").read())
    stack, names, start = [], set(), 0
    for i, c in enumerate(code):
        if c not in "{};":
            continue
        prefix = code[start:i]
        top = stack[-1] if stack else "ns"
        if c == "{":
            p = " ".join(prefix.split())
            if re.search(r"(^|\s)namespace$", p):
                kind = "anon"
            elif re.search(r"(^|\s)namespace\s+[\w:]+$", p) or re.fullmatch(r'extern ""', p):
                kind = "ns"
            else:
                kind = "block"
                if top == "anon" or (top == "ns" and re.match(r"(\w+\s+)*static\b", p)):
                    names.update(as_list(defined_name(re.sub(r"\bstatic\b", "", p), True)))
            stack.append(kind)
        elif c == ";":
            if top == "anon" or (top == "ns" and re.match(r"\s*(\w+\s+)*static\b", prefix)):
                names.update(as_list(defined_name(re.sub(r"\bstatic\b", "", prefix), False)))
        else:
            if stack:
                stack.pop()
        start = i + 1
    return names


def main(argv):
    if "--separate" in argv:
        k = argv.index("--separate")
        args, separate = argv[:k], {os.path.realpath(f) for f in argv[k + 1:]}
    else:
        args, separate = argv, set()
    root, layers = args[0], args[1:]
    clashes = []
    for layer in layers:
        seen = {}
        for folder, _, files in sorted(os.walk(os.path.join(root, layer))):
            for f in sorted(files):
                path = os.path.join(folder, f)
                if not f.endswith(".cpp") or f.endswith("_main.cpp") or os.path.realpath(path) in separate:
                    continue
                if re.search(r"gmsh::|seccomp_", open(path, encoding="utf-8").read()):
                    continue
                for name in internal_names(path):
                    seen.setdefault(name, []).append(os.path.relpath(path, root))
        clashes += [(layer, name, paths) for name, paths in sorted(seen.items()) if len(paths) > 1]
    for layer, name, paths in clashes:
        print(f"{layer}: '{name}' has internal linkage in {len(paths)} files: {', '.join(paths)}")
    if clashes:
        print(f"{len(clashes)} names would clash in a unity build (IGA_UNITY_BUILD): rename them, share them, or "
              "list a file in IGA_UNITY_SEPARATE (CMakeLists.txt)")
        return 1
    print(f"no internal name defined twice in a layer ({len(layers)} layers)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
