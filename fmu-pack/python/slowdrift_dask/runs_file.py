"""The per-run CSV of a campaign, byte for byte the format of `slowdrift montecarlo`
(src/montecarlo/runs_file.rs): one line per finished run, appended and flushed as runs
finish, read back on a restart.

Columns: case, seed, fingerprint, status (`ok` or `failed`), mean/rms/max/min of surge and
sway (m) and yaw (deg) (empty for a failed run), error (double-quoted, inner quotes doubled;
empty for an ok run). Numbers in Rust's shortest round-trip form (`numbers.rust_display`).
Reading keeps the last line of each (case, seed); a last line without its newline (cut off
by a kill) is dropped, and cut off before anything is appended.
"""

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
