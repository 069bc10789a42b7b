"""The list of files a PolyFrac run prints at its end, checked.

The run ends with `Files written in DIR:` and one indented line per file,
except that a series of VTU files is one line,
`name.pvd with N steps: name-0000.vtu to name-NNNN.vtu` (`.pvtu` on several
ranks, then `, their M pieces name-0000.0000.vtu to ...`).
"""
import os
import re
import sys

SERIES_FILE = re.compile(r"(.+)-[0-9]{4}(\.[0-9]{4})?\.p?vtu$")
SERIES_LINE = re.compile(r"(\S+)\.pvd with (\d+) steps?: (\S+)(?: to (\S+))?"
                         r"(?:, their (\d+) pieces? (\S+)(?: to (\S+))?)?$")


def files_written(stdout, label, directory):
    """The files named by the block `Files written in LABEL:` of stdout,
    after checking that they are exactly the files in directory: each series
    line has the number of steps and pieces that the directory holds, and
    its first and last files. Exits non-zero on the first failed check."""
    lines = stdout.splitlines()
    header = "Files written in " + label + ":"
    starts = [i for i, line in enumerate(lines) if line == header]
    if len(starts) != 1:
        sys.exit(f"{len(starts)} lines '{header}' in the output, not one")
    present = sorted(os.listdir(directory))
    named = []
    for line in lines[starts[0] + 1:]:
        if not line.startswith("  "):
            break
        entry = line[2:]
        match = SERIES_LINE.match(entry)
        if not match:
            named.append(entry)
            continue
        name = match.group(1)
        files = [(f, SERIES_FILE.match(f)) for f in present]
        steps = [f for f, m in files if m and m.group(1) == name
                 and not m.group(2)]
        pieces = [f for f, m in files if m and m.group(1) == name
                  and m.group(2)]
        for what, found, count, first, last in (
                ("steps", steps, match.group(2), match.group(3),
                 match.group(4)),
                ("pieces", pieces, match.group(5) or "0", match.group(6),
                 match.group(7))):
            listed = [first, last or first] if first else []
            ends = [found[0], found[-1]] if found else []
            if int(count) != len(found) or listed != ends:
                sys.exit(f"'{entry}': the directory holds {len(found)} "
                         f"{what} of {name}: {ends}")
        named += steps + pieces + [name + ".pvd"]
    if sorted(named) != present:
        sys.exit(f"files named {sorted(named)}, in the directory {present}")
    return named
