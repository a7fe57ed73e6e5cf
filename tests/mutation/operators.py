"""Single-change mutants of C, C++, OpenCL C and GLSL sources: where each operator applies.

The sources are clang-formatted: binary operators have a space on each side, template brackets,
unary minus, pointers and references do not. The operators match on that, on a copy of the text
in which comments, string and character literals and preprocessor lines (but #define's value) are
blanked, so every offset is the real file's.
"""

import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Mutant:
    path: str  # relative to the source tree
    start: int  # offsets into the file's text
    end: int
    replacement: str
    op: str
    line: int
    col: int

    @property
    def id(self):
        return f"{self.path}:{self.line}:{self.col}:{self.op}"

    def apply(self, text):
        return text[: self.start] + self.replacement + text[self.end :]

    def revert(self, mutated, original_fragment):
        """The original text from the mutated one (what --self-test checks)."""
        end = self.start + len(self.replacement)
        return mutated[: self.start] + original_fragment + mutated[end:]

    def diff(self, text):
        """Two lines: the original line and the mutated one."""
        begin = text.rfind("\n", 0, self.start) + 1
        end = text.find("\n", self.end)
        end = len(text) if end < 0 else end
        before = text[begin:end]
        after = text[begin : self.start] + self.replacement + text[self.end : end]
        return f"-{before}\n+{after}"


def blank(text):
    """The text with comments, string/char literals and directives but #define as spaces."""
    out = list(text)
    i, n = 0, len(text)

    def wipe(a, b):
        for k in range(a, b):
            if out[k] != "\n":
                out[k] = " "

    line_start = True
    while i < n:
        c = text[i]
        if line_start and c in " \t":
            i += 1
            continue
        if line_start and c == "#":
            end = i
            while True:  # the directive with its continuation lines
                nl = text.find("\n", end)
                nl = n if nl < 0 else nl
                if nl > 0 and text[nl - 1] == "\\" and nl < n:
                    end = nl + 1
                    continue
                break
            m = re.match(r"#\s*define\s+\w+(\([^)]*\))?", text[i:nl])
            wipe(i, i + m.end() if m else nl)  # a #define keeps its value
            i = i + m.end() if m else nl
            line_start = False
            continue
        line_start = c == "\n"
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            wipe(i, j)
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            wipe(i, j)
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            wipe(i, min(j + 1, n))
            i = j + 1
        else:
            i += 1
    blanked = "".join(out)
    # Lines the compiler checks at build time only: a mutant there cannot reach the output.
    return re.sub(r"^[^\n]*\b(static_assert|_Static_assert)\b[^\n]*", lambda m: " " * len(m.group()),
                  blanked, flags=re.M)


# (operator, pattern on the blanked text, replacement of group 1 or a function of the match)
_SWAPS = (
    ("arith", r" (\+) ", {"+": "-"}),
    ("arith", r" (-) ", {"-": "+"}),
    ("rel", r" (<=|>=|<|>) ", {"<": "<=", "<=": "<", ">": ">=", ">=": ">"}),
    ("eq", r" (==|!=) ", {"==": "!=", "!=": "=="}),
    ("logic", r" (&&|\|\|) ", {"&&": "||", "||": "&&"}),
    ("bit", r" (&|\||\^) ", {"&": "|", "|": "&", "^": "|"}),
    ("shift", r" (<<|>>)=? ", {"<<": ">>", ">>": "<<"}),
    ("acc-drop", r" (\+=|-=|\|=|&=|\^=) ", {"+=": "=", "-=": "=", "|=": "=", "&=": "=", "^=": "="}),
    ("acc-swap", r" (\+=|-=) ", {"+=": "-=", "-=": "+="}),
    ("incdec", r"(\+\+|--)", {"++": "--", "--": "++"}),
    # A product for a quotient (a width of `2 / radius` for `2 * radius`): clang-format spaces a
    # binary `*`, never a pointer's.
    ("muldiv", r" (\*|/) ", {"*": "/", "/": "*"}),
    # min(, std::min(, _mm_min_epu16(, GAP8_ASM_PV_MINU_B(, gap8_pv_minu_b(: not min_sad.
    ("minmax", r"(?<![A-Za-z0-9])(min|max|minu|maxu|MINU|MAXU)(?=(_ep[iu]\d+|_[bB])?\s*\()",
     {"min": "max", "max": "min", "minu": "maxu", "maxu": "minu", "MINU": "MAXU", "MAXU": "MINU"}),
)
_LITERAL = re.compile(r"(?<![\w.])(0[xX][0-9a-fA-F]+|[0-9]+)([uUlL]*)(?![\w.])")
# A declaration's start: a type (maybe qualified, templated, pointer) and a name.
_DECL = re.compile(r"^\s*(const\s+|static\s+|constexpr\s+)*[A-Za-z_][\w:<>,]*[\s*&]+[A-Za-z_]\w*\s*(=|\[|;|\()")
_STATEMENT = re.compile(r"^(\s*)([A-Za-z_*(][^;{}]*(\+=|-=|\|=|&=|\^=|<<=|>>=|\+\+|--| = )[^;{}]*;)\s*$")


def _line_col(text, offset):
    line = text.count("\n", 0, offset) + 1
    return line, offset - (text.rfind("\n", 0, offset) + 1) + 1


def _literal_mutants(path, text, masked):
    for m in _LITERAL.finditer(masked):
        digits = m.group(1)
        value = int(digits, 16 if digits[:2].lower() == "0x" else 10)
        for op, new in (("const+1", value + 1), ("const-1", value - 1)):
            if new < 0:
                continue
            if digits[:2].lower() == "0x":
                width = len(digits) - 2
                repl = digits[:2] + format(new, f"0{width}{'X' if digits[2:].isupper() else 'x'}")
            else:
                repl = str(new)
            yield m.start(1), m.end(1), repl, op


# A literal term added to or taken from a size, a bound or an index: `row_bytes + 10` -> `row_bytes`.
_TERM = re.compile(r" [+-] (0[xX][0-9a-fA-F]+|[0-9]+)[uUlL]*(?![\w.])")


def _term_mutants(masked):
    for m in _TERM.finditer(masked):
        yield m.start(), m.end(), "", "term-drop"


def _statement_mutants(text, masked):
    offset = 0
    for line in masked.split("\n"):
        m = _STATEMENT.match(line)
        if m and not _DECL.match(line) and not line.lstrip().startswith(("return", "for", "if", "case")):
            yield offset + m.start(2), offset + m.end(2), "{}", "stmt-del"
        offset += len(line) + 1


def _loop_mutants(masked):
    """for (init; A < B; step): the bound B moved by one (B + 1, B - 1)."""
    for m in re.finditer(r"\bfor \(", masked):
        depth, i, semis = 1, m.end(), []
        while i < len(masked) and depth:
            c = masked[i]
            depth += c == "("
            depth -= c == ")"
            if c == ";" and depth == 1:
                semis.append(i)
            i += 1
        if len(semis) != 2:
            continue
        cond = masked[semis[0] + 1 : semis[1]]
        r = re.search(r" (<=|>=|<|>|!=) ", cond)
        if not r or re.search(r"&&|\|\||\?", cond) or "\n" in cond:
            continue
        bound_end = semis[1]
        yield bound_end, bound_end, " + 1", "loop+1"
        yield bound_end, bound_end, " - 1", "loop-1"


def mutants(path, text):
    """Every single-change mutant of one file, in file order."""
    masked = blank(text)
    found = []
    for op, pattern, table in _SWAPS:
        for m in re.finditer(pattern, masked):
            found.append((m.start(1), m.end(1), table[m.group(1)], op))
    found.extend(_literal_mutants(path, text, masked))
    found.extend(_term_mutants(masked))
    found.extend(_statement_mutants(text, masked))
    found.extend(_loop_mutants(masked))
    result, seen = [], set()
    for start, end, repl, op in sorted(found):
        line, col = _line_col(text, start)
        mutant = Mutant(path, start, end, repl, op, line, col)
        if mutant.id in seen or text[start:end] == repl:
            continue
        seen.add(mutant.id)
        result.append(mutant)
    return result


OPERATORS = ("arith", "rel", "eq", "logic", "bit", "shift", "acc-drop", "acc-swap", "incdec",
             "minmax", "const+1", "const-1", "stmt-del", "loop+1", "loop-1", "term-drop", "muldiv")
# What a campaign draws from unless told otherwise (`--operators`): the operators of the
# campaigns docs/measurements/mutation-campaigns.md logs, so that a seed draws the same mutants as
# it did there.
DEFAULT_OPERATORS = OPERATORS[:15]
# Mutants that make a kernel read or write out of bounds more often than they change a result: a
# length or a bound one off, a term of a size dropped, a size's product turned into a quotient.
MEMORY_OPERATORS = ("const+1", "const-1", "rel", "loop+1", "term-drop", "muldiv")
