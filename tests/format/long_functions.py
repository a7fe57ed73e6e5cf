#!/usr/bin/env python3
"""Lists the C++ functions longer than a limit under the folders given (STYLE.md: short functions).

Usage: long_functions.py [--max N] [--fail] FOLDER_OR_FILE...

A heuristic on braces, not a parser: preprocessor lines, comments, strings and character literals
are blanked, then a brace is a function's body when the text before it (since the last ';', '{'
or '}') has a ')' and it opens at namespace or class level. A function's length is its lines from the signature's first
line to its closing brace. One line per function over N lines (default 60), longest first:
"path:line: name: L lines". With --fail the exit status is 1 when any is listed (the
hosts_short_functions test), else 0.
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".cc"}
LITERAL = re.compile(r'^[ \t]*#(?:\\\n|[^\n])*|//[^\n]*|/\*.*?\*/|R"([^(]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|'
                     r"'(?:\\.|[^'\\\n])*'", re.S | re.M)


def blank(match):
    """Keeps a literal's newlines (line numbers stay right) and drops the rest."""
    return re.sub(r"[^\n]", " ", match.group(0))


def functions(text):
    """Yields (first line, last line, name) of every function body at namespace or class level."""
    code = LITERAL.sub(blank, text)
    stack = []  # for each open brace: "fn" (a function's body, or inside one) or "scope"
    head_start = 0  # where the text before the next brace begins
    for i, c in enumerate(code):
        if c == ";":
            head_start = i + 1
        elif c == "{":
            head = code[head_start:i]
            inside_fn = bool(stack) and stack[-1][0] == "fn"
            is_fn = not inside_fn and ")" in head and not re.search(r"=\s*$", head)
            if is_fn:
                lead = len(head) - len(head.lstrip())
                start = head_start + lead
                name = re.findall(r"([~\w:<>]+)\s*\(", head)
                stack.append(("fn", start, name[0] if name else "?", True))
            else:
                stack.append(("fn" if inside_fn else "scope", 0, "", False))
            head_start = i + 1
        elif c == "}":
            if stack:
                kind, start, name, opens = stack.pop()
                if opens:
                    yield code.count("\n", 0, start) + 1, code.count("\n", 0, i) + 1, name
            head_start = i + 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max", type=int, default=60)
    parser.add_argument("--fail", action="store_true")
    parser.add_argument("folders", nargs="+", metavar="FOLDER_OR_FILE")
    args = parser.parse_args()
    found = []
    for folder in args.folders:
        root = pathlib.Path(folder)
        if not root.exists():
            print(f"long_functions: {folder}: no such file or folder", file=sys.stderr)
            return 2
        paths = [root] if root.is_file() else root.rglob("*")
        for path in sorted(p for p in paths if p.suffix in SOURCE_SUFFIXES):
            for first, last, name in functions(path.read_text(errors="replace")):
                if last - first + 1 > args.max:
                    found.append((last - first + 1, f"{path}:{first}: {name}"))
    for lines, where in sorted(found, key=lambda f: (-f[0], f[1])):
        print(f"{where}: {lines} lines")
    if args.fail and found:
        print(f"long_functions: {len(found)} functions over {args.max} lines; split them into "
              "named steps", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
