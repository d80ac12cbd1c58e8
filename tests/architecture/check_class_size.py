#!/usr/bin/env python3
"""Fails when a class in a layer's public headers has more than --limit public member functions.

Issue #13: "no class with more than ~12 public member functions outside plain data
structs". Scans engine/*/include/**/*.h under --root. Every `class` and `struct`
definition is checked (a struct's members are public until an access label says
otherwise, so a plain data struct with a helper or two passes on its own); nested
classes are checked on their own. Counted: each public member function declaration,
overloads one by one, static and virtual ones included. Not counted: constructors,
destructors, assignment operators, `= delete`d functions, friends, data members,
type aliases. EXEMPT names a class that may exceed the limit, with the reason.
Exit 0 when every class is within the limit, 1 otherwise (one line per class).
"""
import argparse
import re
import sys
from pathlib import Path

# "Name": "why it may have more public member functions" (none today).
EXEMPT: dict[str, str] = {}

ACCESS = re.compile(r"^\s*(public|private|protected)\s*:(?!:)")
CLASS_HEAD = re.compile(
    r"^(?:template\s*<.*>\s*)?(class|struct)\s+(?:\[\[[^\]]*\]\]\s*)?(\w+)\s*(?:final\s*)?(?::[^{]*)?$",
    re.S)
SKIP_WORDS = ("friend", "using", "typedef", "static_assert", "enum", "class", "struct", "union")


def strip_code(text):
    """Source without comments, string/char literals and preprocessor lines."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', '""', text)
    return re.sub(r"^[ \t]*#[^\n]*(?:\\\n[^\n]*)*", " ", text, flags=re.M)


def function_name(decl):
    """The name of the member function `decl` declares, or None for anything else."""
    decl = re.sub(r"^template\s*<[^;]*?>\s*(?=[A-Za-z_~])", "", decl.strip())
    first = decl.split(None, 1)[0] if decl else ""
    if not decl or first in SKIP_WORDS:
        return None
    depth = 0  # template angle brackets before the parameter list
    for i, ch in enumerate(decl):
        if ch == "<" and not decl[:i].rstrip().endswith("operator"):
            depth += 1
        elif ch == ">" and depth and not decl[:i].rstrip().endswith("operator"):
            depth -= 1
        elif ch in "={" and depth == 0 and not re.search(r"operator\s*\W*$", decl[:i + 1]):
            return None  # a data member with an initializer
        elif ch == "(" and depth == 0:
            m = re.search(r"(operator\s*(?:\(\)|[^\w\s(]+|\w[\w\s:<>*&]*?)|~?\w+)\s*$", decl[:i])
            if not m or decl[i + 1:].lstrip().startswith("*"):
                return None  # a function pointer member or something we cannot name
            return m.group(1).replace(" ", "")
    return None


def scan(text):
    """[(class name, line, public member functions)] for every class defined in `text`."""
    text = strip_code(text)
    classes = []
    # Scope stack: ("class", record) or ("other", None); record = [name, line, count, access]
    stack = [("other", None)]
    buf, line = "", 1

    def take_access(stmt):
        kind, rec = stack[-1]
        while kind == "class":
            m = ACCESS.match(stmt)
            if not m:
                break
            rec[3] = m.group(1)
            stmt = stmt[m.end():]
        return stmt.strip()

    def member(stmt):
        kind, rec = stack[-1]
        if kind != "class" or rec[3] != "public":
            return
        name = function_name(stmt)
        if name is None or name in (rec[0], "~" + rec[0]) or name.startswith("~"):
            return
        if name == "operator=" or re.search(r"=\s*delete\s*$", stmt):
            return
        rec[2] += 1

    for ch in text:
        if ch == "\n":
            line += 1
        if ch == "{":
            head = take_access(buf)
            head_line = line - buf[buf.rfind(head):].count("\n") if head else line
            buf = ""
            m = CLASS_HEAD.match(head)
            if m and not head.startswith("enum"):
                rec = [m.group(2), head_line, 0, "public" if m.group(1) == "struct" else "private"]
                classes.append(rec)
                stack.append(("class", rec))
            elif re.match(r"^(namespace\b|extern\s*\"\"|$)", head) and stack[-1][0] != "block":
                stack.append(("other" if head else "block", None))
            else:
                member(head)  # an inline function body (or an initializer: not counted)
                stack.append(("block", None))
        elif ch == "}":
            if len(stack) > 1:
                stack.pop()
            buf = ""
        elif ch == ";":
            if stack[-1][0] == "class":
                member(take_access(buf))
            buf = ""
        elif stack[-1][0] != "block":
            buf += ch
    return [(name, at, count) for name, at, count, _ in classes]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", required=True, type=Path)
    ap.add_argument("--limit", type=int, default=12)
    ap.add_argument("--list", action="store_true", help="print every class with its count")
    args = ap.parse_args(argv)
    headers = sorted(args.root.glob("engine/*/include/**/*.h"))
    if not headers:
        print(f"no public headers under {args.root}/engine/*/include")
        return 1
    over = 0
    for path in headers:
        rel = path.relative_to(args.root)
        for name, at, count in scan(path.read_text(encoding="utf-8", errors="replace")):
            if args.list:
                print(f"{count:3d} {name} ({rel}:{at})")
            if count > args.limit and name not in EXEMPT:
                over += 1
                print(f"{rel}:{at}: class {name} has {count} public member functions "
                      f"(limit {args.limit}): split it along its seams")
    print(f"{len(headers)} header(s), {over} class(es) over {args.limit} public member functions")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
