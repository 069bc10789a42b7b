#!/usr/bin/python3
"""The VTU pieces of runs on 2 ranks in which a rank has nothing to write
(elasticity): a box of one cell (rank 1 owns no cell), and a box of two
cells cut by a fracture (one rank owns no fracture face). Every piece a
.pvtu record lists exists and is read by a VTK reader (meshio) with points
and cells, no other piece is written, the pieces hold each cell once, and
the list of files written names exactly the files in the output
directory. (A rank without cells used to write a piece without <Points>
that meshio refuses.)

usage: vtu_pieces_2_ranks.py POLYFRAC WORK_DIR
Exits non-zero on the first failed check."""
import glob
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import meshio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from files_written import files_written  # noqa: E402

program, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def check(condition, what):
    if not condition:
        sys.exit("FAILED: " + what)


def run_scene(name, scene_text, cells):
    """Runs @p scene_text on 2 ranks in WORK_DIR/name and checks its
    records; @p cells: the cells of each record, by record name."""
    directory = os.path.join(work, name)
    os.makedirs(directory)
    with open(os.path.join(directory, "scene.prm"), "w") as scene:
        scene.write("set Dimension = 2\n" + scene_text +
                    "subsection Boundary conditions\n"
                    "  set Dirichlet boundary ids = 0, 1, 2, 3\n"
                    "  set Dirichlet expression = x; 0\nend\n"
                    "subsection Output\n  set Output directory = out\n"
                    "end\n")
    run = subprocess.run(["mpirun", "-np", "2", "--oversubscribe", program,
                          "scene.prm"], cwd=directory, env=environment,
                         capture_output=True, text=True, timeout=300)
    check(run.returncode == 0, name + ": the run failed:\n" + run.stdout +
          run.stderr)
    out = os.path.join(directory, "out")
    files_written(run.stdout, "out", out)
    records = sorted(glob.glob(os.path.join(out, "*.pvtu")))
    check([os.path.basename(r) for r in records] == sorted(cells),
          "%s: the records %s" % (name, records))
    pieces_listed = set()
    for record in records:
        n_cells = 0
        for piece in ElementTree.parse(record).getroot().iter("Piece"):
            source = piece.get("Source")
            pieces_listed.add(source)
            mesh = meshio.read(os.path.join(out, source))
            check(len(mesh.points) > 0, source + " has points")
            n_cells += sum(len(block.data) for block in mesh.cells)
        expected = cells[os.path.basename(record)]
        check(n_cells == expected, "%s: the pieces hold %d cells, not %d"
              % (record, n_cells, expected))
    pieces_written = {f for f in os.listdir(out) if f.endswith(".vtu")}
    check(pieces_written == pieces_listed,
          "the pieces written are those listed: %s against %s"
          % (sorted(pieces_written), sorted(pieces_listed)))
    print(name + ": pieces " + " ".join(sorted(pieces_listed)))


run_scene("one_cell", "subsection Mesh\n  set Subdivisions = 1, 1\nend\n",
          {"solution-level-0-0000.pvtu": 1})
run_scene("fracture_on_one_rank",
          "subsection Mesh\n  set Subdivisions = 1, 2\nend\n"
          "subsection Fractures\n  set Segments = -1, 0 : 1, 0\nend\n",
          {"solution-level-0-0000.pvtu": 2,
           "fractures-level-0-0000.pvtu": 1})
