"""The operand-format column of the GAP8 model's instruction tables (xpulp.tbl, rv32imc.tbl).

A format is the operands as the assembler writes them, comma-separated, or - for none; each
token names an instruction field, so the same column gives the disassembly and the registers
the instruction reads and writes (the hazard masks). Register tokens:

  rd        bits 11..7, written            rd+    bits 11..7, read and written (accumulators)
  rs1       bits 19..15, read              rs2    bits 24..20, read
  rs3       bits 11..7, read (the p.s* register offset)
  crd       RVC bits 11..7, written        crd+   RVC bits 11..7, read and written
  crs1      RVC bits 11..7, read           crs2   RVC bits 6..2, read
  crd'      RVC x8 + bits 4..2, written    crs2'  RVC x8 + bits 4..2, read
  crs1'     RVC x8 + bits 9..7, read       crs1'+ RVC x8 + bits 9..7, read and written
  sp        x2, read                       sp+    x2, read and written
  ^ra       x1, written, not printed (c.jal, c.jalr)

An address is OFFSET(BASE) or OFFSET(BASE!) (post-increment: BASE is also written), OFFSET an
immediate or a register token. Every other token is an immediate, printed by the disassembler
(src/disasm.cpp); in xpulp.tbl the tokens imm and target stand for the row's immediate kind
(its imm column) and are made concrete by concrete().
"""

# Register tokens: (field, read, written).
REGISTERS = {
    "rd": ("rd", False, True), "rd+": ("rd", True, True), "rs1": ("rs1", True, False),
    "rs2": ("rs2", True, False), "rs3": ("rd", True, False),
    "crd": ("rd", False, True), "crd+": ("rd", True, True), "crs1": ("rd", True, False),
    "crs2": ("c_rs2", True, False), "crd'": ("c_rs2p", False, True),
    "crs2'": ("c_rs2p", True, False), "crs1'": ("c_rs1p", True, False),
    "crs1'+": ("c_rs1p", True, True), "sp": ("sp", True, False), "sp+": ("sp", True, True),
    "^ra": ("ra", False, True),
}
# Fields, in the order of the generated Field bits (include/gap8/disasm.h).
FIELDS = ["rd", "rs1", "rs2", "c_rs2", "c_rs2p", "c_rs1p", "sp", "ra"]
IMMEDIATES = {
    # RV32IMC
    "u20", "jt", "bt", "i12", "s12", "shamt", "csr", "fence", "ci6", "cshamt", "clui", "c16sp",
    "c4spn", "clw", "clwsp", "cswsp", "cj", "cb",
    # Xpulp (concrete forms of imm and target)
    "simm6", "uimm6", "is2", "is3", "bitfield", "simm5", "uimm12", "loop", "lt", "lt5",
}
# xpulp.tbl's imm column -> the concrete token of the format's imm (None: not printable).
XPULP_IMM = {
    "simm6": "simm6", "uimm6": "uimm6", "lane6": "uimm6", "shufh": "uimm6",
    "shufi0": "uimm6", "shufi1": "uimm6", "shufi2": "uimm6", "shufi3": "uimm6", "is2": "is2",
    "is3": "is3", "bitfield": "bitfield", "i12": "i12", "s12": "s12", "hwloop": "uimm12",
}
XPULP_TARGET = {"b13": "bt", "hwloop": "lt"}


class FormatError(Exception):
    pass


def table_rows(path, columns):
    """(line number, columns) of each row of an instruction table: blank and # lines skipped,
    the last column the rest of the line."""
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.startswith("#"):
                continue
            cols = line.split(None, columns - 1)
            if len(cols) != columns:
                raise FormatError(f"{path}:{number}: {columns} columns expected, got {len(cols)}")
            yield number, [c.strip() for c in cols]


def tokens(fmt):
    """The tokens of a format, an address's offset and base split: 'rd,i12(rs1!)' ->
    ['rd', 'i12', 'rs1!']."""
    if fmt == "-":
        return []
    out = []
    for part in fmt.split(","):
        if part.endswith(")") and "(" in part:
            offset, base = part[:-1].split("(", 1)
            out += [offset, base]
        else:
            out.append(part)
    return out


def concrete(fmt, imm_kind):
    """An xpulp.tbl format with imm and target replaced by the tokens of the row's imm kind."""
    def one(tok):
        if tok in ("imm", "target"):
            table = XPULP_IMM if tok == "imm" else XPULP_TARGET
            if imm_kind not in table:
                raise FormatError(f"{tok} in the format, but the immediate is {imm_kind}")
            return table[imm_kind]
        return tok
    out = []
    for part in ([] if fmt == "-" else fmt.split(",")):
        if part.endswith(")") and "(" in part:
            offset, base = part[:-1].split("(", 1)
            out.append(f"{one(offset)}({base})")
        else:
            out.append(one(part))
    return ",".join(out) or "-"


def check(fmt):
    """Raises FormatError for an unknown token."""
    for tok in tokens(fmt):
        if tok.rstrip("!") not in REGISTERS and tok not in IMMEDIATES:
            raise FormatError(f"unknown operand token {tok} in {fmt}")


def reads_writes(fmt):
    """(fields read, fields written), each a list in FIELDS order."""
    check(fmt)
    reads, writes = set(), set()
    for tok in tokens(fmt):
        post_increment = tok.endswith("!")
        reg = REGISTERS.get(tok.rstrip("!"))
        if reg is None:
            continue
        field, read, written = reg
        if read:
            reads.add(field)
        if written or post_increment:
            writes.add(field)
    order = FIELDS.index
    return sorted(reads, key=order), sorted(writes, key=order)


def field_bits(fields):
    """The generated Field bit mask of a list of fields."""
    return sum(1 << FIELDS.index(f) for f in fields)
