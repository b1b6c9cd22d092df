"""The per-run CSV of a campaign, byte for byte the format of `slowdrift montecarlo`
(src/montecarlo/runs_file.rs): one line per finished run, appended and flushed as runs
finish, read back on a restart.

Columns: case, seed, fingerprint, status (`ok` or `failed`), mean/rms/max/min of surge and
sway (m) and yaw (deg) (empty for a failed run), error (double-quoted, inner quotes doubled;
empty for an ok run). Numbers in Rust's shortest round-trip form (`numbers.rust_display`).
Reading keeps the last line of each (case, seed); a last line without its newline (cut off
by a kill) is dropped, and cut off before anything is appended.

One campaign per file, whichever tool runs it: `lock` takes the exclusive lock the native
tool takes (src/files/lock.rs): `flock` on NAME.lock beside the file, which holds the pid of
the holder and is removed by it when done; the kernel drops the lock when the process ends.
"""

import fcntl
import os
from dataclasses import dataclass

from .numbers import rust_display

DOFS = (("surge", "m"), ("sway", "m"), ("yaw", "deg"))
STATISTICS = ("mean", "rms", "max", "min")
FIELDS = 4 + 3 * len(STATISTICS) + 1


class RunsFileError(ValueError):
    """A per-run file that is not of this format (names the file and line)."""


@dataclass
class RunRow:
    case: str
    seed: int
    fingerprint: str
    # The 12 statistics of an ok run, or None for a failed one.
    values: list = None
    # The error message of a failed run.
    error: str = ""

    @property
    def ok(self):
        return self.values is not None


def header():
    columns = ["case", "seed", "fingerprint", "status"]
    columns += [f"{dof}_{stat}_{unit}" for dof, unit in DOFS for stat in STATISTICS]
    return ",".join(columns + ["error"])


def quote(text):
    return '"' + text.replace('"', '""') + '"'


def format_row(row):
    """A line of the file, newline included."""
    fields = [row.case, str(row.seed), row.fingerprint]
    if row.ok:
        fields += ["ok"] + [rust_display(v) for v in row.values] + [""]
    else:
        fields += ["failed"] + [""] * 12 + [quote(row.error)]
    return ",".join(fields) + "\n"


def split(line):
    """The fields of a CSV line, honouring double quotes (as the Rust reader)."""
    fields, field, quoted, i = [], [], False, 0
    while i < len(line):
        c = line[i]
        if c == '"' and quoted and line[i + 1:i + 2] == '"':
            field.append('"')
            i += 1
        elif c == '"':
            quoted = not quoted
        elif c == "," and not quoted:
            fields.append("".join(field))
            field = []
        else:
            field.append(c)
        i += 1
    return fields + ["".join(field)]


def parse(text, source):
    """The runs of a per-run file's text (the last line of each (case, seed), in file order)."""
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    if not lines:
        return []
    if lines[0] != header():
        raise RunsFileError(
            f"{source}:1: not a per-run file of this version: the header must be {header()}")
    runs = {}
    for number, line in enumerate(lines[1:], start=2):
        fields = split(line)
        if len(fields) != FIELDS:
            raise RunsFileError(f"{source}:{number}: {len(fields)} fields, expected {FIELDS}")
        if not fields[1].isdigit():
            raise RunsFileError(f"{source}:{number}: seed '{fields[1]}' is not a whole number")
        row = RunRow(fields[0], int(fields[1]), fields[2])
        if fields[3] == "ok":
            try:
                row.values = [float(v) for v in fields[4:16]]
            except ValueError:
                bad = next(k for k, v in enumerate(fields[4:16]) if not _is_number(v))
                raise RunsFileError(f"{source}:{number}: field {5 + bad} '{fields[4 + bad]}' "
                                    "is not a number") from None
        elif fields[3] == "failed":
            row.error = fields[16]
        else:
            raise RunsFileError(
                f"{source}:{number}: status '{fields[3]}' is neither 'ok' nor 'failed'")
        runs.pop((row.case, row.seed), None)
        runs[(row.case, row.seed)] = row
    return list(runs.values())


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def open_runs(path):
    """Opens (or creates) the per-run file for appending: (runs already in it, file object).
    A last line without its newline is cut off first; a new file gets the header."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except FileNotFoundError:
        data = b""
    complete = data.rfind(b"\n") + 1
    runs = parse(data[:complete].decode("utf-8"), path)
    f = open(path, "a+b")
    f.truncate(complete)
    f.seek(0, os.SEEK_END)
    if complete == 0:
        f.write((header() + "\n").encode("utf-8"))
        f.flush()
    return runs, f


class RunsFileLocked(Exception):
    """Another process (the native tool or another client) runs a campaign on this file."""


class Lock:
    """The exclusive lock of a runs file, held until `release`."""

    def __init__(self, path, fd):
        self.path = path
        self._fd = fd

    def release(self):
        # Removed while still locked (a process that opened it meanwhile finds it gone and
        # starts again), then unlocked by closing it.
        try:
            os.remove(self.path)
        except OSError:
            pass
        os.close(self._fd)


def lock(path):
    """Takes the lock of the runs file `path` at once, or raises RunsFileLocked naming the
    process that holds it (the message of the native tool)."""
    lock_path = path + ".lock"
    while True:
        fd = os.open(lock_path, os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            os.close(fd)
            raise RunsFileLocked(_held(path, lock_path)) from None
        # The holder that just let go removed its file: lock the one now at the path.
        mine = os.fstat(fd)
        try:
            there = os.stat(lock_path)
        except FileNotFoundError:
            there = None
        if there is None or (there.st_dev, there.st_ino) != (mine.st_dev, mine.st_ino):
            os.close(fd)
            continue
        os.ftruncate(fd, 0)
        os.write(fd, f"{os.getpid()}\n".encode())
        return Lock(lock_path, fd)


def _held(path, lock_path):
    """The message for `path` held by another process, named by the pid in its lock file
    (read again for up to a tenth of a second while the holder has not yet written it)."""
    import time

    holder = None
    for _ in range(10):
        try:
            with open(lock_path) as f:
                text = f.read().strip()
            if text.isdigit():
                holder = f"process {text}"
                break
        except OSError:
            pass
        time.sleep(0.01)
    holder = holder or "another process (its pid not yet written)"
    return (f"{path}: in use by {holder}, which holds its lock {lock_path}: two campaigns on "
            "one file would mix their runs; wait for that one to end, or stop it")
