#!/usr/bin/env python3
"""Files and signals, every command: a test matrix generated from pxflow's own option table.

`pxflow --list-options` names every command's options, the path kind of each (hosts/cli/
path_options.hpp) and each command's cheap runs ("matrix runs") and long runs. From those alone
this script makes its cases, so a new option or command is covered without a new test:

  declarations  every option with a value says what it is (a path kind or a type name of its own,
                never CLI11's TEXT); a command with a path option has a run; every real-valued
                option (real_options.hpp) refuses nan, inf, -inf, both sides of its range and
                "1x" with one line, exit 2.
  outputs       each output option, in the first run that accepts it, written: onto each input of
                every run that accepts it (the same path, a symlink, a hard link, a ../ spelling),
                inside an input folder, as a symlink (written at its target), onto a 0600 file
                (mode kept), onto a read-only file (refused, intact), to /dev/null, to a FIFO, as
                /dev/stdout redirected to a file, on a full file system (a 64 KiB tmpfs), beside a
                SIGKILLed run's temporary; a required output left out; an owned folder holding a
                user's file; a folder output holding an earlier run's files.
  signals       SIGINT, SIGTERM, SIGHUP at moments of each long run, SIGINT twice, SIGPIPE on
                standard output, and SIGINT on a run whose input is a FIFO nobody writes.

Every case checks the exit code, that inputs are byte-identical, that each output is its previous
bytes or a whole new file (a stopped run's streams and check or bench files marked incomplete),
that no temporary is left, and that every exit code seen is listed under "Exit status" in the
command's --help. Usage: file_matrix.py PXFLOW [--only NAME-SUBSTRING] [--part outputs|signals|
declarations] [--list]. One line per case (PASS, FAIL or SKIP with its reason), then a summary.
"""
import argparse
import errno
import hashlib
import json
import os
import re
import resource
import shutil
import signal
import stat
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib

ACCURACY_IMAGES = ["rubberwhale1.png", "basketball1.png", "baboon.jpg", "fruits.jpg",
                   "building.jpg", "home.jpg"]
HANG_GUARD = 300  # seconds one pxflow run may take before it is called hung (not a speed bound)
STOP_WITHIN = 10.0  # seconds a stopped run may take to end (a wait on input must see the stop)
TEMPORARY = re.compile(r"(\.pxflow-\d+\.tmp$|\.tmp\.\d+$|^\.pxflow-probe\.)")


def png_gray(width, height, pixel):
    """A grayscale 8-bit PNG (no dependency: zlib and struct)."""
    rows = b"".join(b"\0" + bytes(pixel(x, y) for x in range(width)) for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0,
                                                               0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def texture(x, y, shift=0):
    x -= shift
    return (x * 37 + y * 101 + (x * y) % 29 * 7 + ((x // 5 + y // 3) % 2) * 90) % 256


def release_fifo_reader(fifo, reader):
    """Ends `reader`, a thread reading the FIFO `fifo` to its end, whether or not pxflow opened the
    FIFO: a reader still waiting in open() is let go by a writer's open and close. The writer's
    open never waits (O_NONBLOCK): a blocking one waited forever when the reader had finished
    between the check and the open (a fresh-clone run hung there, 2026-12-07)."""
    while reader.is_alive():
        try:
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError as e:
            if e.errno != errno.ENXIO:  # ENXIO: no reader has it open (it just finished)
                raise
        reader.join(0.1)


class Fixtures:
    """The inputs the placeholders of the runs name, made once in `root` (never an output)."""

    def __init__(self, pxflow, root, sample_data):
        # The sample data (pxflow's --data default) is read only: never written, not even here.
        self.pxflow, self.root, self.sample_data = pxflow, root, sample_data
        self.paths = {}
        self.problems = []

    def path(self, name):
        return os.path.join(self.root, name)

    def make(self):
        w = h = 64
        with open(self.path("prev.png"), "wb") as f:
            f.write(png_gray(w, h, lambda x, y: texture(x, y)))
        with open(self.path("next.png"), "wb") as f:
            f.write(png_gray(w, h, lambda x, y: texture(x, y, 2)))
        self.paths["{PREV}"], self.paths["{NEXT}"] = self.path("prev.png"), self.path("next.png")
        raw = b"".join(bytes(texture(x, y, k) for y in range(h) for x in range(w))
                       for k in range(4))
        with open(self.path("frames.raw"), "wb") as f:
            f.write(raw)
        self.paths["{RAW}"] = self.path("frames.raw")
        os.mkdir(self.path("frames"))
        for k in range(3):
            with open(self.path("frames/f%d.raw" % k), "wb") as f:
                f.write(raw[k * w * h:(k + 1) * w * h])
        self.paths["{FRAMES}"] = self.path("frames")
        with open(self.path("pairs.txt"), "w") as f:
            f.write("prev.png next.png\n")
        self.paths["{PAIRS}"] = self.path("pairs.txt")
        os.mkdir(self.path("data"))
        for name in ACCURACY_IMAGES:
            shutil.copyfile(os.path.join(self.sample_data, name), self.path("data/" + name))
        self.paths["{DATA}"] = self.path("data")
        self.paths["{VIDEO}"] = os.path.join(self.sample_data, "vtest.avi")
        for k, name in ((1, "{CHECK}"), (2, "{CHECK2}")):
            self.paths[name] = self.produce(
                "shard%d.json" % k,
                ["check", "--backends", "ref-original,ref-local", "--limits-only", "--no-repro",
                 "--shard", "%d/2" % k, "--json"])
        for k, name in ((1, "{BENCH}"), (2, "{BENCH2}")):
            self.paths[name] = self.produce(
                "bench%d.json" % k, ["bench", "--backend", "ref-local", "--batch", "1",
                                     "--sizes", "64x64", "--min-time", "0", "--json"])
        vectors = self.path("vectors")
        r = run([self.pxflow, "vectors", "--out", vectors, "--cases", "1"])
        if r.returncode != 0:
            self.problems.append("fixture vectors: exit %d: %s" % (r.returncode, r.stderr))
        self.paths["{VECTORS}"] = vectors
        self.paths["{RECORDS}"] = os.path.join(vectors, "records.bin")
        return self

    def produce(self, name, args):
        out = self.path(name)
        r = run([self.pxflow] + args + [out])
        if r.returncode not in (0, 1) or not os.path.exists(out):
            self.problems.append("fixture %s: exit %d: %s" % (name, r.returncode, r.stderr))
        return out

    def files(self):
        """Every fixture file, for the byte-identical check."""
        found = []
        for base, _, names in os.walk(self.root):
            found += [os.path.join(base, n) for n in names]
        return sorted(found)


def run(argv, **kw):
    return subprocess.run(argv, capture_output=True, text=True, timeout=HANG_GUARD, **kw)


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def temporaries(folder):
    found = []
    for base, _, names in os.walk(folder):
        found += [os.path.join(base, n) for n in names if TEMPORARY.search(n)]
    return found


class Command:
    def __init__(self, entry):
        self.name = entry["name"]
        self.options = [o for o in entry["options"] if not o["hidden"]]
        self.runs = [r.split() for r in entry["matrix_runs"]]
        self.long_runs = [r.split() for r in entry["long_runs"]]

    def outputs(self):
        return [o for o in self.options if o.get("path") in
                ("output-file", "output-folder", "owned-folder")]

    def has_paths(self):
        return any("path" in o for o in self.options)


class Matrix:
    def __init__(self, pxflow, fixtures, only):
        self.pxflow, self.fx, self.only = pxflow, fixtures, only
        self.results = []  # (status, name, detail)
        self.codes = {}  # command -> exit codes seen
        self.fixture_digests = {p: digest(p) for p in fixtures.files()}
        self.pristine = fixtures.root + ".pristine"
        shutil.copytree(fixtures.root, self.pristine, symlinks=True)
        self.counter = 0

    # ---- bookkeeping
    def record(self, status, name, detail=""):
        self.results.append((status, name, detail))
        print("%s %s%s" % (status, name, (": " + detail) if detail else ""), flush=True)

    def wanted(self, name):
        return not self.only or self.only in name

    def workdir(self):
        self.counter += 1
        d = os.path.join(self.fx.root, "..", "cases", "c%04d" % self.counter)
        os.makedirs(d)
        return os.path.abspath(d)

    def substitute(self, args):
        out = []
        for a in args:
            for key, value in self.fx.paths.items():
                a = a.replace(key, value)
            out.append(a)
        return out

    def inputs_of(self, args):
        """The fixture files a run reads (its placeholders; a folder's files; a list's frames)."""
        found = []
        for a in args:
            for key in re.findall(r"\{[A-Z0-9]+\}", a):
                p = self.fx.paths[key]
                if key == "{VIDEO}":
                    continue  # the sample data is read only: never an output target here
                if os.path.isdir(p):
                    continue
                found.append(p)
                if key == "{PAIRS}":
                    found += [self.fx.paths["{PREV}"], self.fx.paths["{NEXT}"]]
        return list(dict.fromkeys(found))

    def folders_of(self, args):
        found = []
        for a in args:
            for key in re.findall(r"\{[A-Z0-9]+\}", a):
                if key != "{VIDEO}" and os.path.isdir(self.fx.paths[key]):
                    found.append(self.fx.paths[key])
        return found

    def pxflow_run(self, command, args, **kw):
        r = run([self.pxflow, command.name] + args, **kw)
        if r.returncode >= 0:  # a death by signal is its case's failure, not an exit status
            self.codes.setdefault(command.name, set()).add(r.returncode)
        return r

    def fixtures_intact(self):
        """The inputs' problems; a changed input is then restored, so that each case is judged
        on its own."""
        changed = [p for p, d in self.fixture_digests.items()
                   if not os.path.exists(p) or digest(p) != d]
        extra = [p for p in self.fx.files() if p not in self.fixture_digests]
        if changed or extra:
            shutil.rmtree(self.fx.root)
            shutil.copytree(self.pristine, self.fx.root, symlinks=True)
        return ["input changed: " + p for p in changed] + ["file written among inputs: " + p
                                                            for p in extra]

    # ---- which run takes an output
    def output_value(self, option, folder, stem="out"):
        kind = option["path"]
        if kind in ("output-folder", "owned-folder"):
            path = os.path.join(folder, stem + "-dir")
            if kind == "output-folder":
                os.makedirs(path, exist_ok=True)
            return path
        return os.path.join(folder, stem + (option.get("suffix") or ".out"))

    def accepting_runs(self, command, option):
        """Every run that accepts `option` as a file (or, failing that, as a folder), with the
        baseline exit code: (run args, value kind, exit code)."""
        found = []
        for run_args in command.runs:
            for kind in ([option["path"]] if option["path"] != "output-file"
                         else ["output-file", "output-folder"]):
                d = self.workdir()
                probe = dict(option, path=kind)
                value = self.output_value(probe, d)
                r = self.pxflow_run(command, self.substitute(run_args) + [option["name"], value])
                made = os.path.isdir(value) if kind != "output-file" else os.path.isfile(value)
                if r.returncode in (0, 1) and made:
                    found.append((run_args, kind, r.returncode))
                    break
        return found

    # ---- checks shared by the cases
    def common_checks(self, r, folder, expect, stderr_has=None):
        problems = []
        if r.returncode != expect:
            problems.append("exit %d, expected %d (stderr: %s)" % (r.returncode, expect,
                                                                    r.stderr.strip()[-300:]))
        wanted = (stderr_has,) if isinstance(stderr_has, str) else stderr_has or ()
        if wanted and not any(w in r.stderr for w in wanted):
            problems.append("stderr lacks %s: %s" % (" or ".join(map(repr, wanted)),
                                                    r.stderr.strip()[-300:]))
        problems += ["temporary left: " + t for t in temporaries(folder)]
        problems += self.fixtures_intact()
        return problems

    def case(self, name, body):
        if not self.wanted(name):
            return
        try:
            problems = body()
        except subprocess.TimeoutExpired:
            problems = ["hung: no exit within %d s" % HANG_GUARD]
        if problems is None:
            return
        if isinstance(problems, str):
            self.record("SKIP", name, problems)
        elif problems:
            self.record("FAIL", name, "; ".join(problems))
        else:
            self.record("PASS", name)

    # ---- declarations
    def declarations(self, listing):
        scopes = [("global", listing["global"])]
        for c in listing["commands"]:
            scopes.append((c["name"], c["options"]))
            scopes += [(c["name"] + " " + s["name"], s["options"]) for s in c["subcommands"]]
        for scope, options in scopes:
            for o in options:
                if o["hidden"] or not o["takes_value"]:
                    continue
                name = "declarations %s %s" % (scope, o["name"])

                def check(o=o):
                    if o["type_name"] == "TEXT":
                        return ["a string value with no kind: declare_path() or a type name"]
                    looks_like_path = re.search(r"FILE|DIR|PREV|NEXT|SOURCE|ELF", o["type_name"])
                    if looks_like_path and "path" not in o:
                        return ["type %s names a path but no path kind is declared" %
                                o["type_name"]]
                    return []

                self.case(name, check)
        for c in listing["commands"]:
            self.reals(Command(c))
        for c in listing["commands"]:
            command = Command(c)
            self.case("declarations %s has matrix runs" % command.name,
                      lambda command=command: [] if command.runs or not command.has_paths()
                      else ["it has path options but no matrix_runs"])

    def reals(self, command):
        """Every real-valued option (declare_real) refuses nan, infinities and values outside its
        range with one line and exit 2, on the command's first matrix run."""
        for o in command.options:
            if "real" not in o or not command.runs:
                continue
            lo, hi = o["real"]
            for value in ("nan", "inf", "-inf", "%g" % (lo - 1), "%g" % (hi * 2 + 1), "1x"):
                def body(o=o, value=value):
                    d = self.workdir()
                    r = self.pxflow_run(command, self.substitute(command.runs[0]) +
                                        [o["name"], value], cwd=d)
                    problems = self.common_checks(r, d, 2, o["name"])
                    if len(r.stderr.strip().splitlines()) != 1:
                        problems.append("stderr is not one line: " + r.stderr.strip()[-300:])
                    return problems
                self.case("declarations %s %s %s" % (command.name, o["name"], value), body)

    # ---- outputs
    def outputs(self, command):
        for option in command.outputs():
            if option["positional"]:
                self.case("%s %s" % (command.name, option["name"]),
                          lambda: ["an output named by position: name it by an option"])
                continue
            label = "%s %s" % (command.name, option["name"])
            if option["required"] and command.runs:
                self.case("%s omitted" % label, lambda: self.omitted(command, command.runs[0]))
            runs = self.accepting_runs(command, option)
            if not runs:
                self.case(label + " accepted", lambda: ["no matrix run accepts it"])
                continue
            first_args, first_kind, code = runs[0]
            folder_runs = [r for r in runs if r[1] != "output-file"]
            for run_args, kind, run_code in runs:
                for target in self.inputs_of(run_args):
                    for spelling in ("same", "symlink", "hardlink", "dotdot"):
                        self.case("%s onto-input:%s:%s%s" % (label, os.path.basename(target),
                                                            spelling, run_tag(run_args)),
                                  lambda r=run_args, t=target, s=spelling:
                                  self.onto_input(command, option, r, t, s))
                for folder in self.folders_of(run_args):
                    self.case("%s inside-input-folder:%s%s" % (label, os.path.basename(folder),
                                                                run_tag(run_args)),
                              lambda r=run_args, f=folder, k=kind:
                              self.inside_folder(command, option, r, f, k))
            if first_kind == "output-file":
                probe = dict(option, path=first_kind)
                for scenario in ("symlink-output", "mode-0600", "read-only", "dev-null", "fifo",
                                 "dev-stdout", "full-disk", "leftover-temporary"):
                    self.case("%s %s" % (label, scenario),
                              lambda s=scenario: self.file_scenario(command, probe, first_args,
                                                                    code, s))
            if folder_runs:
                f_args, f_kind, f_code = folder_runs[0]
                probe = dict(option, path=f_kind)
                for scenario in ("foreign-file", "earlier-run-files", "leftover-temporary"):
                    self.case("%s %s%s" % (label, scenario, run_tag(f_args)),
                              lambda s=scenario: self.folder_scenario(command, probe, f_args,
                                                                      f_code, s))


    def onto_input(self, command, option, run_args, target, spelling):
        d = self.workdir()
        if spelling == "same":
            value = target
        elif spelling == "symlink":
            value = os.path.join(d, "link" + (option.get("suffix") or ""))
            os.symlink(target, value)
        elif spelling == "hardlink":
            value = os.path.join(d, "hard" + (option.get("suffix") or ""))
            try:
                os.link(target, value)
            except OSError as e:
                return "no hard link here (%s)" % e
        else:
            value = os.path.join(os.path.dirname(target), "..",
                                 os.path.basename(os.path.dirname(target)),
                                 os.path.basename(target))
        r = self.pxflow_run(command, self.substitute(run_args) + [option["name"], value])
        # A folder output named by an input file is no folder: refused as such.
        return self.common_checks(r, d, 2, ("pxflow never overwrites an input",
                                            "is a file, not a folder", "names no existing folder"))

    def inside_folder(self, command, option, run_args, folder, kind):
        d = self.workdir()
        value = os.path.join(folder, "out" + (option.get("suffix") or ""))
        if kind != "output-file":
            value = folder
        r = self.pxflow_run(command, self.substitute(run_args) + [option["name"], value])
        return self.common_checks(r, d, 2, "pxflow never writes where it reads")

    def file_scenario(self, command, option, run_args, code, scenario):
        d = self.workdir()
        args = self.substitute(run_args)
        value = self.output_value(option, d)
        old = b"previous output\n"
        if scenario == "symlink-output":
            target = os.path.join(d, "target" + (option.get("suffix") or ""))
            with open(target, "wb") as f:
                f.write(old)
            os.chmod(target, 0o600)
            os.symlink(target, value)
            r = self.pxflow_run(command, args + [option["name"], value])
            p = self.common_checks(r, d, code)
            if not os.path.islink(value):
                p.append("the symlink was replaced by a file")
            if open(target, "rb").read() == old:
                p.append("the link's target was not written (stale)")
            if stat.S_IMODE(os.stat(target).st_mode) != 0o600:
                p.append("target mode %o, was 600" % stat.S_IMODE(os.stat(target).st_mode))
            return p
        if scenario in ("mode-0600", "read-only"):
            with open(value, "wb") as f:
                f.write(old)
            mode = 0o600 if scenario == "mode-0600" else 0o444
            os.chmod(value, mode)
            r = self.pxflow_run(command, args + [option["name"], value])
            p = self.common_checks(r, d, code if mode == 0o600 else 2,
                                   None if mode == 0o600 else option["name"] + " ")
            now = open(value, "rb").read()
            if mode == 0o444 and now != old:
                p.append("a read-only output was replaced")
            if mode == 0o600 and now == old:
                p.append("not written")
            if stat.S_IMODE(os.stat(value).st_mode) != mode:
                p.append("mode %o, was %o" % (stat.S_IMODE(os.stat(value).st_mode), mode))
            return p
        if scenario == "dev-null":
            r = self.pxflow_run(command, args + [option["name"], "/dev/null"])
            p = self.common_checks(r, d, code)
            if not stat.S_ISCHR(os.stat("/dev/null").st_mode):
                p.append("/dev/null is no longer a character device")
            return p
        if scenario == "fifo":
            fifo = os.path.join(d, "fifo")
            os.mkfifo(fifo)
            got = []
            reader = threading.Thread(target=lambda: got.append(open(fifo, "rb").read()))
            reader.start()
            r = self.pxflow_run(command, args + [option["name"], fifo])
            release_fifo_reader(fifo, reader)
            p = self.common_checks(r, d, code)
            if not stat.S_ISFIFO(os.stat(fifo).st_mode):
                p.append("the FIFO was replaced")
            if not got or not got[0]:
                p.append("nothing came through the FIFO")
            return p
        if scenario == "dev-stdout":
            out = os.path.join(d, "stdout.txt")
            before = os.readlink("/dev/stdout") if os.path.islink("/dev/stdout") else None
            with open(out, "wb") as f:
                r = subprocess.run([self.pxflow, command.name] + args +
                                   [option["name"], "/dev/stdout"], stdout=f,
                                   stderr=subprocess.PIPE, text=True, timeout=HANG_GUARD)
            self.codes.setdefault(command.name, set()).add(r.returncode)
            p = self.common_checks(r, d, code)
            if before is not None and (not os.path.islink("/dev/stdout") or
                                       os.readlink("/dev/stdout") != before):
                p.append("/dev/stdout was replaced (put back)")
                os.remove("/dev/stdout")  # the machine's, for every later test
                os.symlink(before, "/dev/stdout")
            if os.path.getsize(out) == 0:
                p.append("nothing reached the redirected standard output")
            return p
        if scenario == "full-disk":
            return self.full_disk(command, option, args, d)
        if scenario == "leftover-temporary":
            with open(value, "wb") as f:
                f.write(old)
            base = os.path.basename(value)
            dead = dead_pid()
            for name in (".%s.pxflow-%d.tmp" % (base, dead),):
                with open(os.path.join(d, name), "wb") as f:
                    f.write(b"half")
            r = self.pxflow_run(command, args + [option["name"], value])
            return self.common_checks(r, d, code)
        raise ValueError(scenario)

    def full_disk(self, command, option, args, d):
        mnt = os.path.join(d, "tmpfs")
        os.mkdir(mnt)
        m = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", mnt],
                           capture_output=True, text=True)
        if m.returncode != 0:
            return "cannot mount a small tmpfs here (%s)" % m.stderr.strip()
        try:
            value = os.path.join(mnt, "out" + (option.get("suffix") or ""))
            old = b"previous output\n"
            with open(value, "wb") as f:
                f.write(old)
            try:
                with open(os.path.join(mnt, "filler"), "wb") as f:
                    f.write(b"\0" * (1 << 20))
            except OSError:
                pass  # full: what the case needs
            r = self.pxflow_run(command, args + [option["name"], value])
            p = []
            if r.returncode not in (1, 2):
                p.append("exit %d on a full disk, expected 1 or 2" % r.returncode)
            if open(value, "rb").read() != old:
                p.append("the previous file was changed")
            if "kept" in r.stderr:
                p.append("claims something was kept: " + r.stderr.strip()[-200:])
            p += ["temporary left: " + t for t in temporaries(mnt)]
            return p + self.fixtures_intact()
        finally:
            subprocess.run(["umount", mnt], capture_output=True)

    def folder_scenario(self, command, option, run_args, code, scenario):
        d = self.workdir()
        args = self.substitute(run_args)
        value = self.output_value(option, d)
        os.makedirs(value, exist_ok=True)
        if scenario == "foreign-file":
            if option["path"] != "owned-folder":
                return None  # an existing folder written into: a user's files are beside ours
            mine = os.path.join(value, "manifest.json")
            with open(mine, "w") as f:
                f.write("a user's file\n")
            r = self.pxflow_run(command, args + [option["name"], value])
            p = self.common_checks(r, d, 2, "no file of yours is replaced")
            if open(mine).read() != "a user's file\n":
                p.append("a user's file in the folder was replaced")
            return p
        if scenario == "earlier-run-files":
            r = self.pxflow_run(command, args + [option["name"], value])
            written = sorted(n for n in os.listdir(value) if not n.startswith("."))
            numbered = [n for n in written if re.search(r"\d", n)]
            if not numbered:
                return None  # no numbered files: nothing an earlier, longer run leaves
            stale = re.sub(r"\d+", lambda m: "9" * len(m.group()), numbered[-1])
            with open(os.path.join(value, stale), "wb") as f:
                f.write(b"an earlier run's")
            r = self.pxflow_run(command, args + [option["name"], value])
            p = self.common_checks(r, d, code)
            if os.path.exists(os.path.join(value, stale)):
                p.append("an earlier run's %s is left beside this run's files" % stale)
            return p
        if scenario == "leftover-temporary":
            r = self.pxflow_run(command, args + [option["name"], value])  # an earlier run
            dead = dead_pid()
            for name in os.listdir(value):
                if not name.startswith(".pxflow-probe"):
                    with open(os.path.join(value, ".%s.pxflow-%d.tmp" % (name, dead)), "wb") as f:
                        f.write(b"half")
                    break
            r = self.pxflow_run(command, args + [option["name"], value])
            return self.common_checks(r, d, code)
        raise ValueError(scenario)

    def omitted(self, command, run_args):
        d = self.workdir()
        r = self.pxflow_run(command, self.substitute(run_args))
        return self.common_checks(r, d, 2)

    # ---- signals
    def signals(self, command):
        for run_args in command.long_runs:
            tag = run_tag(run_args)
            for sig, at in ((signal.SIGINT, 0.15), (signal.SIGINT, 2.0), (signal.SIGTERM, 0.5),
                            (signal.SIGHUP, 0.5)):
                self.case("%s long%s %s@%.2fs" % (command.name, tag, sig.name, at),
                          lambda s=sig, t=at, a=run_args: self.stop(command, a, [s], t))
            self.case("%s long%s SIGINT-twice" % (command.name, tag),
                      lambda a=run_args: self.stop(command, a, [signal.SIGINT] * 2, 0.5))
            self.case("%s long%s SIGPIPE" % (command.name, tag),
                      lambda a=run_args: self.sigpipe(command, a))
            if any("{KEPT}." in a and a.endswith((".jsonl", ".csv")) for a in run_args):
                self.case("%s long%s file-size-limit" % (command.name, tag),
                          lambda a=run_args: self.size_limit(command, a))
        for run_args in command.runs[:1]:
            for key in re.findall(r"\{[A-Z0-9]+\}", " ".join(run_args)):
                if key in ("{VIDEO}",) or os.path.isdir(self.fx.paths[key]):
                    continue
                self.case("%s stalled-input:%s SIGINT" % (command.name, key),
                          lambda a=run_args, k=key: self.stalled(command, a, k))
                break

    def long_outputs(self, args, d):
        """A long run's outputs: {OUT}.ext keeps its previous bytes or is replaced whole when the
        run stops; {KEPT}.ext keeps the work finished before the stop, marked incomplete. Each is
        made beforehand with previous bytes. Returns (args, [(path, kept)])."""
        outs, final = [], []
        for a in args:
            for key, kept in (("{OUT}", False), ("{KEPT}", True)):
                if key in a:
                    a = a.replace(key, os.path.join(d, "out"))
                    outs.append((a, kept))
            final.append(a)
        for p, _ in outs:
            if os.path.splitext(p)[1]:
                with open(p, "wb") as f:
                    f.write(b"previous output\n")
        return final, outs

    def start(self, command, args):
        return subprocess.Popen([self.pxflow, command.name] + args, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, start_new_session=True)

    def finish(self, command, proc, within):
        """(exit code or None when it did not end `within` s, stderr)."""
        try:
            code = proc.wait(timeout=within)
        except subprocess.TimeoutExpired:
            return None, ""
        err = proc.stderr.read().decode(errors="replace")
        if code >= 0:
            self.codes.setdefault(command.name, set()).add(code)
        return code, err

    def stop(self, command, run_args, signals, at):
        d = self.workdir()
        args, outs = self.long_outputs(self.substitute(run_args), d)
        proc = self.start(command, args)
        threading.Thread(target=proc.stdout.read, daemon=True).start()
        time.sleep(at)
        if proc.poll() is not None:
            code, err = self.finish(command, proc, 1)
            return ["ended (exit %s) before the signal at %.2f s: the long run is too short (%s)"
                    % (code, at, err.strip()[-200:])]
        for k, sig in enumerate(signals):
            if k:
                time.sleep(0.02)
            os.kill(proc.pid, sig)
        code, err = self.finish(command, proc, STOP_WITHIN)
        if code is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            return ["not stopped within %.0f s of the signal" % STOP_WITHIN]
        p = self.stop_verdict(code, 128 + signals[0], err, d)
        # pxflow's own claim that nothing was done excuses a previous file early in the run; two
        # seconds into it, a long run has finished work to keep, whatever it claims.
        nothing_done = "no output file was changed" in err and at < 2.0
        for out, kept in outs:
            p += kept_output(out, must_keep=kept and not nothing_done)
        return p + self.fixtures_intact()

    def sigpipe(self, command, run_args):
        """head -3: the reader takes three lines (or waits a second), then goes."""
        d = self.workdir()
        args, outs = self.long_outputs(self.substitute(run_args), d)
        proc = self.start(command, args)
        lines, deadline = 0, time.monotonic() + 1.0
        os.set_blocking(proc.stdout.fileno(), False)
        while lines < 3 and time.monotonic() < deadline and proc.poll() is None:
            chunk = proc.stdout.read()
            lines += chunk.count(b"\n") if chunk else 0
            time.sleep(0.01)
        proc.stdout.close()
        code, err = self.finish(command, proc, 2.0)  # a write soon after: the stop, 141
        expect = 141
        if code is None:  # it writes nothing to standard output while it works: stop it
            os.kill(proc.pid, signal.SIGINT)
            code, err = self.finish(command, proc, STOP_WITHIN)
            expect = 130
            if code is None:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
                return ["not stopped within %.0f s of SIGINT" % STOP_WITHIN]
        p = self.stop_verdict(code, expect, err, d)
        for out, _ in outs:
            p += kept_output(out, must_keep=False)
        return p + self.fixtures_intact()

    def size_limit(self, command, run_args):
        """A disk that fills during the work, as `ulimit -f 32` has it (any file system): the
        run ends with exit 1, the previous files intact, and nothing claimed as kept."""
        d = self.workdir()
        args, outs = self.long_outputs(self.substitute(run_args), d)

        def limit():
            resource.setrlimit(resource.RLIMIT_FSIZE, (32 << 10, 32 << 10))

        r = subprocess.run([self.pxflow, command.name] + args, capture_output=True, text=True,
                           timeout=HANG_GUARD, preexec_fn=limit)
        p = self.stop_verdict(r.returncode, 1, r.stderr, d)
        failed = re.findall(r"--[a-z-]+ (\S+): cannot write", r.stderr)
        if not failed and r.returncode >= 0:
            p.append("no output named as failed: " + r.stderr.strip()[-200:])
        kept_line = "".join(l for l in r.stderr.splitlines() if "kept" in l)
        for out, _ in outs:
            if out in failed:
                if open(out, "rb").read() != b"previous output\n":
                    p.append("%s: not the previous file after its write failed" %
                             os.path.basename(out))
                if out in kept_line:
                    p.append("claims the failed %s was kept" % os.path.basename(out))
            else:
                p += kept_output(out, must_keep=False)
        return p + self.fixtures_intact()

    def stop_verdict(self, code, expect, err, d):
        p = []
        if code < 0:
            p.append("died of %s (no handler)" % signal.Signals(-code).name)
        elif code != expect:
            p.append("exit %d, expected %d (stderr: %s)" % (code, expect, err.strip()[-300:]))
        return p + ["temporary left: " + t for t in temporaries(d)]

    def stalled(self, command, run_args, key):
        d = self.workdir()
        fifo = os.path.join(d, "stalled" + os.path.splitext(self.fx.paths[key])[1])
        os.mkfifo(fifo)
        keep = os.open(fifo, os.O_RDWR)  # a writer that never writes: the reader waits
        try:
            args = self.substitute([a.replace(key, fifo) for a in run_args])
            for o in command.outputs():
                if o["required"]:
                    args += [o["name"], self.output_value(o, d)]
            proc = subprocess.Popen([self.pxflow, command.name] + args, stdout=subprocess.PIPE,
                                    stderr=subprocess.PIPE, start_new_session=True)
            time.sleep(0.5)
            os.kill(proc.pid, signal.SIGINT)
            try:
                out, errb = proc.communicate(timeout=STOP_WITHIN)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.communicate()
                return ["a stop while waiting on input was not seen within %.0f s" % STOP_WITHIN]
            if proc.returncode >= 0:
                self.codes.setdefault(command.name, set()).add(proc.returncode)
            p = []
            if proc.returncode != 130:
                p.append("exit %d, expected 130 (stderr: %s)" % (
                    proc.returncode, errb.decode(errors="replace").strip()[-300:]))
            return p + ["temporary left: " + t for t in temporaries(d)] + self.fixtures_intact()
        finally:
            os.close(keep)

    # ---- exit status
    def exit_status(self, listing):
        for c in listing["commands"]:
            name = c["name"]
            if name not in self.codes:
                continue

            def check(name=name):
                listed = documented_codes(self.pxflow, name)
                missing = sorted(self.codes[name] - listed)
                return ["exit %s seen but not under Exit status in --help" % ", ".join(
                    str(m) for m in missing)] if missing else []

            self.case("exit-status %s" % name, check)


def kept_output(path, must_keep):
    """A stopped run's output: its previous bytes, or a whole new file. With `must_keep` (the run
    keeps finished work), a new file whose last line (a stream) or "complete" field (JSON) marks
    it incomplete, never the previous bytes."""
    name = os.path.basename(path)
    if not os.path.exists(path):
        return ["%s: gone" % name]
    if os.path.isdir(path):
        return []
    data = open(path, "rb").read()
    if data == b"previous output\n":
        return ["%s: the work finished before the stop was not kept" % name] if must_keep else []
    if not data.endswith(b"\n"):
        return ["%s: ends in a cut-off line" % name]
    text = data.decode(errors="replace")
    last = text.rstrip("\n").split("\n")[-1]
    if path.endswith((".jsonl", ".csv")):
        if must_keep and "incomplete" not in last:
            return ["%s: a stopped stream whose last line does not mark it incomplete: %s" % (
                name, last[:120])]
        return []
    if path.endswith(".json"):
        try:
            j = json.loads(text)
        except ValueError:
            return ["%s: not whole JSON" % name]
        if must_keep and j.get("complete") is not False:
            return ["%s: a stopped run's file is not marked incomplete" % name]
    return []


def documented_codes(pxflow, command):
    text = run([pxflow, command, "--help"]).stdout
    section = text.split("Exit status:", 1)[1].split("\n\n", 1)[0] if "Exit status:" in text \
        else ""
    return {int(n) for n in re.findall(r"(?<![\d.])(\d{1,3})(?![\d.%x])", section)}


def dead_pid():
    """A process ID that no process has now."""
    pid = 999999
    while True:
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            return pid
        except PermissionError:
            pass
        pid -= 1


def run_tag(run_args):
    return " [" + " ".join(run_args) + "]"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("pxflow")
    ap.add_argument("--only", default="", help="only cases whose name holds this text")
    ap.add_argument("--part", choices=["declarations", "outputs", "signals", "all"],
                    default="all")
    ap.add_argument("--commands", default="", help="comma-separated commands (default: all)")
    ap.add_argument("--listing-from", default="",
                    help="take the option table from this pxflow and run the cases on PXFLOW "
                         "(an older build, to show which cases it fails)")
    a = ap.parse_args()
    pxflow = os.path.abspath(a.pxflow)
    listing = json.loads(run([os.path.abspath(a.listing_from or a.pxflow),
                              "--list-options"]).stdout)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="pxflow-matrix-") as root:
        fixtures_dir = os.path.join(root, "fixtures")
        os.mkdir(fixtures_dir)
        fx = Fixtures(pxflow, fixtures_dir, listing["sample_data"]).make()
        for problem in fx.problems:
            print("FAIL fixtures: " + problem)
        if fx.problems:
            return 1
        m = Matrix(pxflow, fx, a.only)
        if a.part in ("declarations", "all"):
            m.declarations(listing)
        chosen = [c for c in listing["commands"]
                  if not a.commands or c["name"] in a.commands.split(",")]
        for c in chosen:
            command = Command(c)
            if a.part in ("outputs", "all"):
                m.outputs(command)
            if a.part in ("signals", "all"):
                m.signals(command)
        m.exit_status({"commands": chosen})
    failed = [r for r in m.results if r[0] == "FAIL"]
    skipped = [r for r in m.results if r[0] == "SKIP"]
    print("file_matrix: %d cases, %d passed, %d failed, %d skipped, %.0f s" % (
        len(m.results), len(m.results) - len(failed) - len(skipped), len(failed), len(skipped),
        time.monotonic() - started))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
