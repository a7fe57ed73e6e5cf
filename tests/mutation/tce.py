"""Trivially equivalent mutants: the compiled code is the unmutated build's, byte for byte.

An object file is compared by its sections but the debug ones (the line tables record columns,
which most mutants move). A linked program (the GAP8 and Cortex-M4 firmware) by the sections it
loads only: its symbol names also hold the compiler's temporary object names (ccXXXXXX.o, one
compile-and-link command), which differ from build to build. Any other file (SPIR-V) whole.
"""

import glob
import hashlib
import os
import struct

_SHF_ALLOC = 0x2  # a section of the loaded image
_SKIPPED_PREFIXES = (".debug", ".rela.debug", ".rel.debug", ".zdebug", ".comment", ".note.gnu.build-id")


def _elf_sections(data):
    """(name, type, flags, addr, bytes) of every section, from an ELF file's contents."""
    is64 = data[4] == 2
    endian = "<" if data[5] == 1 else ">"
    if is64:
        shoff, = struct.unpack_from(endian + "Q", data, 0x28)
        shentsize, shnum, shstrndx = struct.unpack_from(endian + "HHH", data, 0x3A)
        fmt = endian + "IIQQQQIIQQ"
    else:
        shoff, = struct.unpack_from(endian + "I", data, 0x20)
        shentsize, shnum, shstrndx = struct.unpack_from(endian + "HHH", data, 0x2E)
        fmt = endian + "IIIIIIIIII"
    headers = [struct.unpack_from(fmt, data, shoff + k * shentsize) for k in range(shnum)]
    names_at = headers[shstrndx][4]
    for name, kind, flags, addr, offset, size, *_ in headers:
        end = data.index(b"\0", names_at + name)
        section = data[names_at + name : end].decode("latin-1")
        body = b"" if kind == 8 else data[offset : offset + size]  # SHT_NOBITS: no bytes
        yield section, kind, flags, addr, body


def digest(path):
    """A hash of what the file's code and data are, debug information left out."""
    with open(path, "rb") as f:
        data = f.read()
    h = hashlib.sha256()
    if data[:4] != b"\x7fELF":
        h.update(data)
        return h.hexdigest()
    linked = struct.unpack_from("<H" if data[5] == 1 else ">H", data, 0x10)[0] in (2, 3)
    for name, kind, flags, addr, body in _elf_sections(data):
        if name.startswith(_SKIPPED_PREFIXES) or (linked and not flags & _SHF_ALLOC):
            continue
        h.update(repr((name, kind, flags, addr, len(body))).encode())
        h.update(body)
    return h.hexdigest()


def snapshot(build, patterns):
    """{artifact path: digest} for the globs (relative to the build folder)."""
    found = {}
    for pattern in patterns:
        for path in sorted(glob.glob(os.path.join(build, pattern))):
            found[os.path.relpath(path, build)] = digest(path)
    return found
