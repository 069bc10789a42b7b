#!/usr/bin/python3
"""Runs the polyfrac program on wrong inputs and checks what a user sees.

Each case is one ctest test (bad_input/<case>): in a fresh directory it writes
the case's files, runs `polyfrac ARGS`, and checks
- the exit status (non-zero for every wrong input; 0 for --help, --version and
  the inputs that are right although they look unusual),
- that the message contains the expected text (what is wrong, the entry or
  file, how to fix it) and none of the texts it must not contain,
- that nothing that looks like a result was written: no convergence.csv and
  no VTU file anywhere, and no output directory at all when the input is
  refused before the mesh is built (stage "parse").

  bad_input.py --list                  the case names
  bad_input.py --list-ranks N          the cases run under mpirun -np N
  bad_input.py run POLYFRAC CASE DIR   one case, in DIR (emptied first);
                                       exit status 77: skipped
  bad_input.py table POLYFRAC DIR      all cases, a markdown table of the
                                       inputs and first lines of the messages
"""

import os
import pathlib
import resource
import shutil
import subprocess
import sys

# A small 2D scene; each case appends its entries (later entries win).
BASE_2D = """set Dimension = 2
subsection Mesh
  set Subdivisions = 4, 4
end
subsection Output
  set Output directory = results
  set Print timings = false
  set Write VTU = true
end
"""

BASE_3D = BASE_2D.replace("set Dimension = 2", "set Dimension = 3").replace(
    "set Subdivisions = 4, 4", "set Subdivisions = 4, 4, 4")

SEGMENT = "subsection Fractures\n  set Segments = 0, -0.5 : 0, 0.5\nend\n"
# A gmsh box [0, 2]^2: its sides are physical group 1, its surface 100.
BOX_GEO = ("Point(1) = {0, 0, 0, 1};\nPoint(2) = {2, 0, 0, 1};\n"
           "Point(3) = {2, 2, 0, 1};\nPoint(4) = {0, 2, 0, 1};\n"
           "Line(1) = {1, 2};\nLine(2) = {2, 3};\n"
           "Line(3) = {3, 4};\nLine(4) = {4, 1};\n"
           "Curve Loop(1) = {1, 2, 3, 4};\n"
           "Plane Surface(1) = {1};\n"
           "Physical Curve(1) = {1, 2, 3, 4};\n"
           "Physical Surface(100) = {1};\n")
# The same box meshed 20 times finer along its sides (944 triangles).
FINE_BOX_GEO = BOX_GEO.replace(", 0, 1};", ", 0, 0.1};")
# A fractured poromechanical scene that runs on several ranks (no face
# bubbles), two steps, no VTU (a failure in a later step must not leave
# result files behind).
POROMECHANICS_2_RANKS = (
    "subsection Model\n  set Model = poromechanics\nend\n"
    "subsection Fractures\n  set Segments = -0.5, 0 : 0.5, 0\nend\n"
    "subsection Boundary conditions\n  set Dirichlet boundary ids = "
    "0, 1, 2, 3\nend\n"
    "subsection Time\n  set End time = 0.2\n  set Time step = 0.1\nend\n"
    "subsection Flow\n  set Fracture source = 1e-6\n"
    "  set Face bubbles = false\nend\n"
    "subsection Output\n  set Write VTU = false\nend\n")
CONTACT = "subsection Model\n  set Model = contact mechanics\nend\n"
# prm/nucleation-2d.prm on 3.1 m faces, without its fault.
NUCLEATION = (
    "set Dimension = 2\n" + CONTACT +
    "subsection Mesh\n  set Lower left corner = -100, -100\n"
    "  set Upper right corner = 100, 100\n  set Subdivisions = 16, 16\n"
    "  set Local refinement box = -20, -20 : 20, 20\n"
    "  set Local refinements = 2\nend\n"
    "subsection Material\n  set Lame lambda = 1e10\n  set Lame mu = 1e10\n"
    "end\n"
    "subsection Initial stress\n  set Stress = -1e7; 5e6; 5e6; -1e7\nend\n"
    "subsection Boundary conditions\n  set Dirichlet boundary ids = "
    "0, 1, 2, 3\nend\n"
    "subsection Contact\n  set Friction law = linear slip weakening\n"
    "  set Friction coefficient = 0.6\n"
    "  set Dynamic friction coefficient = 0.5\n"
    "  set Slip-weakening distance = 1e-3\n"
    "  set Quasi-static time steps = true\nend\n"
    "subsection Output\n  set Output directory = results\n"
    "  set Print timings = false\nend\n")
FLOW = "subsection Model\n  set Model = flow\nend\n"


def section(name, **entries):
    """A subsection with its entries (keyword = entry name, '_' for ' ')."""
    lines = "".join("  set %s = %s\n" % (key.replace("_", " "), value)
                    for key, value in entries.items())
    return "subsection %s\n%s" % (name, lines) + "end\n"


def case(input_text, expect, files=None, args=None, stage="parse", status=1,
         absent=(), written=(), address_space=None, base=BASE_2D, ranks=1):
    """One case: input_text (a sentence for the table), the message parts
    expected, the files written (name -> text or bytes; "scene.prm" gets the
    base scene in front), the arguments (default: scene.prm), the stage at
    which the input is refused (parse: before any output; level: after
    used_parameters.prm, before any result), the exit status, texts that
    must not appear, files the run must write, a limit of the address
    space (bytes) to run out of memory, the number of MPI ranks (several:
    under mpirun, where a run that does not end within TIMEOUT_RANKS
    seconds has hung)."""
    if files is None:
        files = {}
    files = dict(files)
    if "scene.prm" in files:
        files["scene.prm"] = base + files["scene.prm"]
    return dict(input=input_text, expect=expect, files=files,
                args=["scene.prm"] if args is None else args, stage=stage,
                status=status, absent=absent, written=written,
                address_space=address_space, ranks=ranks)


CASES = {
    # The first hour: help, version, the command line.
    "help": case("`polyfrac --help`",
                 ["Usage: polyfrac [FILE.prm]", "--set Subsection/Entry=value",
                  "--print-parameters [2|3]", "--version", "Where to start",
                  "/prm/default.prm", "README.md",
                  "taken from its directory", "by Model:",
                  "poromechanics: b4-mandel b4-terzaghi", "flow: flow-2d",
                  "contact mechanics: b1-inclined-crack"],
                 args=["--help"], status=0),
    "version": case("`polyfrac --version`", ["PolyFrac 0.1.0 (deal.II 9.4"],
                    args=["--version"], status=0),
    "print_parameters_bad_dimension": case(
        "`polyfrac --print-parameters x`",
        ["--print-parameters takes the dimension 2 or 3"],
        args=["--print-parameters", "x"], absent=["stoi"]),
    "unknown_option": case("`polyfrac --frobnicate`",
                           ["Unknown option <--frobnicate>", "--help"],
                           args=["--frobnicate"]),
    "two_parameter_files": case("`polyfrac a.prm b.prm`",
                                ["Unexpected argument <b.prm>"],
                                args=["a.prm", "b.prm"]),
    # Files.
    "parameter_file_missing": case("`polyfrac missing.prm`",
                                   ["The parameter file <missing.prm> does "
                                    "not exist", "a relative path starts in "
                                    "the current directory"],
                                   args=["missing.prm"]),
    "parameter_file_directory": case(
        "a directory given as the parameter file",
        ["The parameter file <scenes> is a directory, not a parameter file",
         "it holds a.prm"],
        files={"scenes/a.prm": BASE_2D}, args=["scenes"]),
    "parameter_file_binary": case(
        "a binary file given as the parameter file",
        ["The parameter file <scene.gz> is not a text file (byte 0 is 31)"],
        files={"scene.gz": b"\x1f\x8b\x08\x00\x00\x00"}, args=["scene.gz"]),
    "include_missing": case(
        "`include missing.prm` naming no file",
        ["In <scene.prm>, line", "the included file <missing.prm> does not "
         "exist", "relative to the directory of the parameter file"],
        files={"scene.prm": "include missing.prm\n"}),
    "include_itself": case(
        "a parameter file that includes itself (was SIGSEGV: deal.II "
        "recursed until the stack overflowed)",
        ["the included file <scene.prm> is included again by itself",
         "scene.prm> includes", "Remove the include line that closes the "
         "cycle"],
        files={"scene.prm": "include scene.prm\n"}),
    "include_cycle": case(
        "`a.prm` includes `b.prm`, which includes `a.prm`",
        ["the included file <", "a.prm> is included again by itself",
         "a.prm> includes <", "b.prm> includes <"],
        files={"a.prm": "include b.prm\n" + BASE_2D,
               "b.prm": "include a.prm\n"}, args=["a.prm"]),
    "include_twice": case(
        "`scene.prm` includes `common.prm` twice (not a cycle): a correct run",
        [], files={"scene.prm": "include common.prm\ninclude common.prm\n",
                   "common.prm": BASE_2D}, status=0,
        written=["results/convergence.csv"]),
    "include_relative_to_file": case(
        "`sub/scene.prm` includes `common.prm` (next to it), `Output "
        "directory = results`, run from elsewhere: right, outputs in "
        "`sub/results`",
        [], files={"sub/scene.prm": "include common.prm\n" + section(
            "Output", Output_directory="results"),
            "sub/common.prm": BASE_2D}, args=["sub/scene.prm"], status=0,
        written=["sub/results/convergence.csv"]),
    # The command line overrides.
    "set_unknown_entry": case(
        "`--set Mesh/Subdivisons=4,4` (typo)",
        ["The command-line option --set \"Mesh/Subdivisons=4,4\": No entry "
         "with name <Subdivisons>", "--print-parameters"],
        files={"scene.prm": ""},
        args=["scene.prm", "--set", "Mesh/Subdivisons=4,4"],
        absent=["input string", "Line <"]),
    "set_bad_value": case(
        "`--set \"Mesh/Subdivisions=a, 4\"`",
        ["--set \"Mesh/Subdivisions=a, 4\"", "does not match the given "
         "pattern"],
        files={"scene.prm": ""},
        args=["scene.prm", "--set", "Mesh/Subdivisions=a, 4"],
        absent=["input string", "Line <"]),
    "set_dimension": case(
        "`--set Dimension=3`",
        ["--set \"Dimension=3\": Dimension cannot be overridden"],
        files={"scene.prm": ""}, args=["scene.prm", "--set", "Dimension=3"]),
    # Expressions: parsed before the mesh, finite where evaluated.
    "expression_does_not_parse": case(
        "body force `foo(x); 0`",
        ["Entry <Body force/Function expression>: cannot parse <foo(x); 0>: "
         "Unexpected token \"foo\" found at position 0."],
        files={"scene.prm": section("Body force",
                                    Function_expression="foo(x); 0")},
        absent=["Message:", "Formula:", "Errc", "Mesh quality"]),
    "body_force_not_finite": case(
        "body force `1/0; 0`",
        ["Entry <Body force/Function expression> is not finite at the point",
         "<1/0> gives inf"],
        files={"scene.prm": section("Body force",
                                    Function_expression="1/0; 0")},
        stage="level"),
    "pressure_not_finite": case(
        "fracture pressure `sqrt(-1)`",
        ["Entry <Fractures/Pressure> is not finite at the point",
         "gives NaN", "root or logarithm of a negative number"],
        files={"scene.prm": SEGMENT + section("Fractures",
                                              Pressure="sqrt(-1)")},
        stage="level"),
    "dirichlet_not_finite": case(
        "Dirichlet data `log(x - 5); 0`",
        ["Entry <Boundary conditions/Dirichlet expression> is not finite"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_expression="log(x - 5); 0")},
        stage="level"),
    "neumann_not_finite": case(
        "Neumann traction `1/(x - 1); 0` on the face x = 1",
        ["Entry <Boundary conditions/Neumann traction> is not finite at the "
         "point (1 "],
        files={"scene.prm": section("Boundary conditions",
                                    Neumann_boundary_ids="1",
                                    Neumann_traction="1/(x - 1); 0")},
        stage="level"),
    "traction_not_finite": case(
        "fracture traction `0; 1/0`",
        ["Entry <Fractures/Traction> is not finite"],
        files={"scene.prm": SEGMENT + section("Fractures",
                                              Traction="0; 1/0")},
        stage="level"),
    "tresca_threshold_not_finite": case(
        "Tresca threshold `1/0` (was taken as infinite)",
        ["Entry <Contact/Tresca threshold> is not finite"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Tresca", Tresca_threshold="1/0")},
        stage="level"),
    "exact_displacement_not_finite": case(
        "exact displacement `sqrt(x - 2); 0`",
        ["Entry <Exact solution/Displacement> is not finite"],
        files={"scene.prm": section("Exact solution",
                                    Displacement="sqrt(x - 2); 0")},
        stage="level"),
    "exact_jump_not_finite": case(
        "exact displacement jump `1/0; 0`",
        ["Entry <Exact solution/Displacement jump> is not finite"],
        files={"scene.prm": SEGMENT + section("Exact solution",
                                              Displacement_jump="1/0; 0")},
        stage="level"),
    "exact_contact_traction_not_finite": case(
        "exact contact traction `log(-1); 0`",
        ["Entry <Exact solution/Contact traction> is not finite"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="frictionless") + section(
            "Exact solution", Contact_traction="log(-1); 0")},
        stage="level"),
    "exact_contact_traction_beyond_double": case(
        "exact contact traction `1e300; 0`: finite, but its error integral "
        "is not (was exit 0 with -nan errors in convergence.csv)",
        ["Level 0 gives err_lambda_", "not a finite number",
         "beyond the range of double precision"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="frictionless") + section(
            "Exact solution", Contact_traction="1e300; 0")},
        stage="level"),
    # Boundary ids.
    "neumann_id_unknown": case(
        "`Neumann boundary ids = 7` on a box (ids 0 to 3)",
        ["Boundary conditions/Neumann boundary ids lists the id 7, which no "
         "boundary face of the mesh carries. The mesh has the boundary ids "
         "0, 1, 2, 3"],
        files={"scene.prm": section("Boundary conditions",
                                    Neumann_boundary_ids="7")},
        stage="level"),
    "dirichlet_id_unknown": case(
        "`Dirichlet boundary ids = 0, 9`",
        ["Boundary conditions/Dirichlet boundary ids lists the id 9"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_boundary_ids="0, 9")},
        stage="level"),
    # Rollers: Boundary conditions/Dirichlet components.
    "dirichlet_components_malformed": case(
        "`Dirichlet components = 0 x` (no colon)",
        ["entry <Boundary conditions/Dirichlet components>: <0 x> must read "
         "<id: components>, e.g. <0: x; 2: y>"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_components="0 x")}),
    "dirichlet_components_unknown_component": case(
        "`Dirichlet components = 0: z` in 2D",
        ["<z> (boundary id 0) is not a component: use x or y"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_components="0: z")}),
    "dirichlet_components_twice": case(
        "`Dirichlet components = 0: x; 0: y`",
        ["the boundary id 0 is listed twice: give all its components in one "
         "item, e.g. <0: x, y>"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_components="0: x; 0: y")}),
    "dirichlet_components_not_dirichlet": case(
        "`Dirichlet components = 1: x` with `Neumann boundary ids = 1`",
        ["the boundary id 1 is not a Dirichlet id",
         "add it to Dirichlet boundary ids or remove it here"],
        files={"scene.prm": section("Boundary conditions",
                                    Neumann_boundary_ids="1",
                                    Dirichlet_components="1: x")}),
    "dirichlet_components_id_unknown": case(
        "`Dirichlet components = 6: x` on a box (ids 0 to 3), Dirichlet "
        "boundary ids empty (all ids not Neumann)",
        ["Boundary conditions/Dirichlet components lists the id 6, which no "
         "boundary face of the mesh carries"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_components="6: x")},
        stage="level"),
    "dirichlet_components_free_rigid_motion": case(
        "rollers fixing only x everywhere (y translation free)",
        ["no Dirichlet boundary face fixes the y component, so rigid motions "
         "are free: fix it on some Dirichlet id"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_boundary_ids="0, 1",
                                    Dirichlet_components="0: x; 1: x")},
        stage="level"),
    # Initial stress.
    "initial_stress_components": case(
        "`Initial stress/Stress = -1; 0; -1` in 2D (3 of 4 entries)",
        ["entry <Initial stress/Stress> has 3 components, expected 4"],
        files={"scene.prm": section("Initial stress", Stress="-1; 0; -1")}),
    "initial_stress_does_not_parse": case(
        "`Initial stress/Stress = -1; 0; 0; foo`",
        ["Entry <Initial stress/Stress>: cannot parse"],
        files={"scene.prm": section("Initial stress",
                                    Stress="-1; 0; 0; foo")}),
    "initial_stress_not_symmetric": case(
        "`Initial stress/Stress = -1; 0.5; 0; -1` (not symmetric)",
        ["Initial stress/Stress is not symmetric at",
         "give the same expression to the entries ij and ji"],
        files={"scene.prm": section("Initial stress",
                                    Stress="-1; 0.5; 0; -1")},
        stage="level"),
    "initial_stress_not_finite": case(
        "`Initial stress/Stress = sqrt(x - 2); 0; 0; sqrt(x - 2)`",
        ["Entry <Initial stress/Stress> is not finite"],
        files={"scene.prm": section("Mesh", Subdivisions="3, 3") + section(
            "Initial stress", Stress="sqrt(x - 2); 0; 0; sqrt(x - 2)")},
        stage="level"),
    # Analytic solutions.
    "analytic_solution_needs_poromechanics": case(
        "`Analytic solution = terzaghi` with Model = elasticity",
        ["Exact solution/Analytic solution = terzaghi: a poroelastic "
         "solution needs Model/Model = poromechanics"],
        files={"scene.prm": section("Exact solution",
                                    Analytic_solution="terzaghi",
                                    Analytic_load="1")}),
    "analytic_solution_mandel_3d": case(
        "`Analytic solution = mandel` in 3D",
        ["Mandel's problem is plane strain: set Dimension = 2"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Exact solution", Analytic_solution="mandel",
            Analytic_load="6e8")},
        base=BASE_3D),
    "analytic_solution_gmsh_box": case(
        "`Analytic solution = terzaghi` on a gmsh mesh of another box",
        ["lives on the box of Mesh/Lower left corner and Upper right corner, "
         "but the mesh spans [0.000000, 2.000000] in direction 0 against "
         "[-1.000000, 1.000000]: set the corners to the box of the mesh"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Mesh", Source="gmsh", File_name="box.geo") + section(
            "Boundary conditions", Dirichlet_boundary_ids="1") + section(
            "Exact solution", Analytic_solution="terzaghi",
            Analytic_load="1"),
            "box.geo": BOX_GEO},
        stage="level"),
    "gmsh_face_in_two_groups": case(
        "a gmsh boundary curve in two physical groups (1: all sides, 2: "
        "the top), which used to take the first group's id silently",
        ["The gmsh mesh <", "box.geo>: the element with nodes",
         "is in the physical groups 1 and 2 of dimension 1, but a boundary "
         "face has one boundary id: keep it in one of them."],
        files={"scene.prm": section(
            "Mesh", Source="gmsh", File_name="box.geo") + section(
            "Boundary conditions", Dirichlet_boundary_ids="1",
            Neumann_boundary_ids="2", Neumann_traction="0; -1"),
            "box.geo": BOX_GEO + "Physical Curve(2) = {3};\n"},
        stage="level"),
    "degenerate_gmsh_cell": case(
        "a gmsh mesh with a flat triangle (its vertices on one line)",
        ["Cell 0 (vertex average 0.5 0, diameter 1) has measure 0: it is "
         "degenerate", "in a gmsh mesh, the element is flat"],
        files={"scene.prm": section("Mesh", Source="gmsh",
                                    File_name="flat.msh"),
               "flat.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                           "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
                           "4 0 1 0\n5 0.5 0 0\n$EndNodes\n"
                           "$Elements\n3\n1 2 2 100 1 1 5 2\n"
                           "2 2 2 100 1 1 2 3\n3 2 2 100 1 1 3 4\n"
                           "$EndElements\n"},
        stage="level"),
    "analytic_solution_and_displacement": case(
        "`Analytic solution = terzaghi` and an exact Displacement",
        ["it gives the exact displacement: leave Exact solution/Displacement "
         "empty"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Exact solution", Analytic_solution="terzaghi",
            Analytic_load="1", Displacement="x; y")}),
    "analytic_solution_without_load": case(
        "`Analytic solution = mandel` without `Analytic load`",
        ["set Exact solution/Analytic load, the compressive load (Mandel: "
         "the force F per unit length on the plate, in N/m), to a non-zero "
         "value"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Exact solution", Analytic_solution="mandel")}),
    # The coupled step and the time steps.
    "analytic_solution_with_fractures": case(
        "`Analytic solution = terzaghi` on a fractured scene (was accepted)",
        ["Exact solution/Analytic solution = terzaghi: it is the solution "
         "of an unfractured column", "remove the fractures"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               SEGMENT + section("Exact solution",
                                 Analytic_solution="terzaghi",
                                 Analytic_load="1e6")}),
    "analytic_solution_with_exact_pressure": case(
        "`Analytic solution = terzaghi` with `Exact solution/Matrix "
        "pressure = 0` (was silently replaced)",
        ["it gives the exact pressure: leave Exact solution/Matrix pressure "
         "and Fracture pressure empty"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Exact solution", Analytic_solution="terzaghi",
                       Analytic_load="1e6", Matrix_pressure="0")}),
    "analytic_solution_other_traction": case(
        "`Analytic solution = terzaghi`, `Analytic load = 1e6` with the "
        "top pressed by `Neumann traction = 0; -5e5` (was accepted: the "
        "errors compared a run under half the load with the series)",
        ["Analytic solution = terzaghi loads the boundary with the traction "
         "(0, -1e+06) on the top", "Neumann traction is <0; -5e5>"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Boundary conditions", Neumann_boundary_ids="3",
                       Neumann_traction="0; -5e5") +
               section("Exact solution", Analytic_solution="terzaghi",
                       Analytic_load="1e6")}),
    "analytic_solution_body_force": case(
        "`Analytic solution = terzaghi` with a body force (was accepted)",
        ["describes the scene without Body force/Function expression (it is "
         "<0; -1e4>, not 0)"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Body force", Function_expression="0; -1e4") +
               section("Exact solution", Analytic_solution="terzaghi",
                       Analytic_load="1e6")}),
    "analytic_solution_matrix_source": case(
        "`Analytic solution = mandel` with a matrix source (was accepted)",
        ["describes the scene without Flow/Matrix source (it is <1e-3>"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Flow", Matrix_source="1e-3") +
               section("Exact solution", Analytic_solution="mandel",
                       Analytic_load="1e6")}),
    "pressure_stabilisation_with_face_bubbles": case(
        "`Flow/Pressure stabilisation = 0.25` with the face bubbles (default)",
        ["Flow/Pressure stabilisation = 0.25 with Flow/Face bubbles = true",
         "Set it to 0, or set Face bubbles = false"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Flow", Pressure_stabilisation="0.25")}),
    "fracture_pressure_under_poromechanics": case(
        "`Fractures/Pressure = 1e6` under Model = poromechanics (it was "
        "silently added to the flow's fracture pressure as a wall load)",
        ["subsection <Fractures>: <Pressure> = 1e6 with Model = "
         "poromechanics", "Flow/Initial pressure"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               SEGMENT + section("Fractures", Pressure="1e6")}),
    "coupling_tolerance_loose": case(
        "`Nonlinear solver/Coupling tolerance = 0.5` (one iteration passed, "
        "and the energy check with it)",
        ["<Coupling tolerance> = 0.5 must be in (0, 1e-4]",
         "the energy check"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Nonlinear solver", Coupling_tolerance="0.5")}),
    "monolithic_nodal_pair_without_fractures": case(
        "`Coupling scheme = monolithic` with `Face bubbles = false` and no "
        "fractures (the linear monolithic step needs the bubbles)",
        ["Nonlinear solver/Coupling scheme = monolithic is not available "
         "without fractures and without Flow/Face bubbles yet: set it to "
         "fixed-stress or automatic"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Flow", Face_bubbles="false") +
               section("Nonlinear solver", Coupling_scheme="monolithic")},
        stage="level"),
    "coupling_iterations_too_few": case(
        "`Nonlinear solver/Maximum coupling iterations = 2` for a fractured "
        "scene whose fixed-stress iteration needs more: every attempt and "
        "its halvings fail, and the message says whether the increments "
        "were still falling",
        ["the fixed-stress iterations did not converge in 2 iterations",
         "still contracting: it fell from",
         "raising Nonlinear solver/Maximum coupling iterations may let it "
         "converge", "It failed after halving the time step 10 times"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               SEGMENT + section("Flow", Fracture_source="1e-6") +
               section("Nonlinear solver", Coupling_scheme="fixed-stress",
                       Maximum_coupling_iterations="2") +
               section("Output", Write_VTU="false")},
        stage="level"),
    "coupling_scheme_unknown": case(
        "`Coupling scheme = newton`",
        ["Coupling scheme", "newton"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Nonlinear solver", Coupling_scheme="newton")}),
    "closed_fracture_impermeable_incompressible": case(
        "a closed fracture in an impermeable matrix with Fracture "
        "compressibility = 0, by the fixed-stress split (its flow half has "
        "no equation for a fracture pressure in contact; the monolithic "
        "Newton, the default, solves the scene: the mechanics determines "
        "that pressure)",
        ["is singular: some pressures are determined by nothing",
         "Set Flow/Fracture compressibility or Inverse Biot modulus > 0"],
        files={"scene.prm": section("Model", Model="poromechanics") +
               section("Nonlinear solver", Coupling_scheme="fixed-stress") +
               SEGMENT + section("Flow", Permeability="0",
                                 Inverse_Biot_modulus="0",
                                 Fracture_compressibility="0",
                                 Fracture_source="1e-6") + section(
                   "Boundary conditions", Dirichlet_boundary_ids="2",
                   Neumann_boundary_ids="0, 1, 3",
                   Neumann_traction="0; y > 0.99 ? -1e6 : 0") +
               # The initial state (t = 0) is written before the first
               # step by design: the failing step is the subject here.
               section("Output", Write_VTU="false")},
        stage="level"),
    "too_many_time_steps": case(
        "`End time = 1e300` (a run that would never end)",
        ["subsection <Time>: End time = 1e+300 in steps of 0.1 takes 1e+301 "
         "steps, above Maximum steps = 5000: lengthen Time step or raise "
         "Maximum steps"],
        files={"scene.prm": section("Model", Model="poromechanics") + section(
            "Time", End_time="1e300")}),
    "output_times_decreasing": case(
        "`Output times = 0.5, 0.2`",
        ["subsection <Time>: Output times must increase and lie in (0, End "
         "time = 1]; entry 2 is 0.2"],
        files={"scene.prm": section("Model", Model="flow") + section(
            "Time", Output_times="0.5, 0.2")}),
    "output_time_after_end": case(
        "`Output times = 2` with End time = 1",
        ["Output times must increase and lie in (0, End time = 1]; entry 1 "
         "is 2"],
        files={"scene.prm": section("Model", Model="flow") + section(
            "Time", Output_times="2")}),
    # Fracture geometry.
    "duplicate_fractures": case(
        "the same segment given twice",
        ["Fractures 0 (0 -0.5 : 0 0.5) and 1 (0 -0.5 : 0 0.5) overlap",
         "Remove the duplicate"],
        files={"scene.prm": section(
            "Fractures", Segments="0, -0.5 : 0, 0.5 ; 0, -0.5 : 0, 0.5")},
        stage="level", absent=["not resolved"]),
    "overlapping_fractures": case(
        "segments (0,-0.5)-(0,0.5) and (0,0)-(0,1)",
        ["Fractures 0 (0 -0.5 : 0 0.5) and 1 (0 0 : 0 1) overlap"],
        files={"scene.prm": section(
            "Fractures", Segments="0, -0.5 : 0, 0.5 ; 0, 0 : 0, 1")},
        stage="level", absent=["not resolved"]),
    "non_convex_polygon": case(
        "a 3D polygon with a reflex vertex (an arrow)",
        ["The fracture polygon -0.5 -0.5 0 : 0.5 -0.5 0 : 0 0 0 : 0.5 0.5 0 "
         ": -0.5 0.5 0 is not convex (at its vertex 3)"],
        files={"scene.prm": section(
            "Fractures", Polygons="-0.5, -0.5, 0 : 0.5, -0.5, 0 : 0, 0, 0 : "
            "0.5, 0.5, 0 : -0.5, 0.5, 0")},
        base=BASE_3D, stage="level", absent=["not resolved"]),
    # Solvers and meshes.
    "singular_jacobian_with_bubbles": case(
        "Tresca contact, Bubbles = true, a block cut off by a fracture "
        "without Dirichlet boundary (nearly singular: the residual blows up at Newton iteration 5)",
        ["the Newton Jacobian of the contact problem is singular",
         "a part of the domain is free to move"],
        files={"scene.prm": CONTACT + section(
            "Fractures", Segments="0, -1 : 0, 1") + section(
            "Contact", Friction_law="Tresca", Bubbles="true") + section(
            "Boundary conditions", Dirichlet_boundary_ids="0",
            Neumann_boundary_ids="1, 2, 3") + section(
            "Body force", Function_expression="1; 1") + section(
            "Material", Lame_lambda="1", Lame_mu="1")},
        stage="level", absent=["Use Bubbles = true", "set Bubbles = true"]),
    "block_free_to_move_stiff_rock": case(
        "the block of `singular_jacobian_with_bubbles` with the SI defaults "
        "of `Material` (10 GPa) and plus-side bubbles: the momentum residual "
        "grows to 1e3 of the load, too little to be detected as singular "
        "(was \"try more load steps\" only; with split bubbles, the "
        "default, it blows up and is)",
        ["The contact solver did not converge", "a part of the domain may "
         "be free to move", "Boundary conditions/Dirichlet boundary ids"],
        files={"scene.prm": CONTACT + section(
            "Fractures", Segments="0, -1 : 0, 1") + section(
            "Contact", Friction_law="Tresca", Bubbles="true",
            Bubble_placement="plus side") + section(
            "Boundary conditions", Dirichlet_boundary_ids="0",
            Neumann_boundary_ids="1, 2, 3") + section(
            "Body force", Function_expression="1; 1")},
        stage="level"),
    "output_directory_unwritable": case(
        "`Output directory = blocker/out` where blocker is a file",
        ["cannot create the output directory <blocker/out> (Not a directory)",
         "set Output/Output directory to a directory you can write"],
        files={"scene.prm": section("Output",
                                    Output_directory="blocker/out"),
               "blocker": "a file\n"}),
    "mesh_too_large": case(
        "`Subdivisions = 100000, 100000`, `Global refinements = 12`",
        ["the finest mesh would have about", "cells and need at least",
         "GB of memory of this machine", "Lower Mesh/Subdivisions"],
        files={"scene.prm": section("Mesh", Subdivisions="100000, 100000",
                                    Global_refinements="12")},
        absent=["bad_alloc"]),
    "out_of_memory": case(
        "a 512 x 512 mesh (estimated 1.7 GB) run with 1 GB of address space",
        ["out of memory (std::bad_alloc)", "lower Mesh/Subdivisions"],
        files={"scene.prm": section("Mesh", Subdivisions="512, 512")},
        stage="level", address_space=10**9),
    "lame_lambda_below_bound": case(
        "`Lame lambda = -1`, `Lame mu = 1` in 2D",
        ["<Lame lambda> = -1.000000 is not admissible",
         "lambda > -2 mu/d = -1.000000"],
        files={"scene.prm": section("Material", Lame_lambda="-1",
                                    Lame_mu="1")}),
    "lame_lambda_beyond_round_off": case(
        "`Lame lambda = 1e300`, `Lame mu = 1` (was exit 0: the shear "
        "stiffness was lost in round-off)",
        ["<Lame lambda> = 1e+300 is more than 1e12 times <Lame mu> = 1",
         "lost in the round-off"],
        files={"scene.prm": section("Material", Lame_lambda="1e300",
                                    Lame_mu="1")}),
    "lame_lambda_negative_admissible": case(
        "`Lame lambda = -0.5`, `Lame mu = 1` in 2D: right, runs",
        [], files={"scene.prm": section("Material", Lame_lambda="-0.5",
                                        Lame_mu="1")}, status=0),
    "complementarity_parameter_beyond_round_off": case(
        "`Complementarity parameter = 1e300` (was exit 0: the contact states "
        "followed round-off, the compressed fracture came out open, and -nan "
        "in a Newton line)",
        ["Contact/Complementarity parameter = 1e+300 is out of range",
         "within a factor 1e8 of the scale-aware (2 mu + lambda)/h_sigma",
         "Use auto"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Complementarity_parameter="1e300")},
        stage="level", absent=["nan"]),
    "complementarity_parameter_beneath_round_off": case(
        "`Complementarity parameter = 1e-300`",
        ["Contact/Complementarity parameter = 1e-300 is out of range"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Complementarity_parameter="1e-300")},
        stage="level"),
    "tresca_threshold_under_coulomb": case(
        "`Tresca threshold = -1` under `Friction law = Coulomb`: a warning "
        "(was silently ignored), runs",
        ["Warning: Contact/Tresca threshold is not used by Contact/Friction "
         "law = Coulomb and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Coulomb", Tresca_threshold="-1")},
        status=0),
    "friction_coefficient_under_tresca": case(
        "`Friction coefficient = 0.6` under `Friction law = Tresca`: a "
        "warning, runs",
        ["Warning: Contact/Friction coefficient is not used by "
         "Contact/Friction law = Tresca and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Tresca", Tresca_threshold="1",
            Friction_coefficient="0.6")},
        status=0),
    "bubble_placement_without_bubbles": case(
        "`Bubble placement = plus side` with `Bubbles = false`: a warning "
        "(without bubbles there is nothing to place), runs",
        ["Warning: Contact/Bubble placement is not used by Contact/Bubbles = "
         "false and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Bubbles="false", Bubble_placement="plus side")},
        status=0),
    "cohesion_under_coulomb": case(
        "`Cohesion = 1e6` under `Friction law = Coulomb`: a warning, runs",
        ["Warning: Contact/Cohesion is not used by Contact/Friction law = "
         "Coulomb and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Coulomb", Cohesion="1e6")},
        status=0),
    "cohesion_negative": case(
        "`Friction law = Coulomb with cohesion`, `Cohesion = -1`",
        ["subsection <Contact>: <Cohesion> must be a finite stress >= 0 (Pa), "
         "not -1"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Coulomb with cohesion", Cohesion="-1")}),
    "cohesion_not_finite": case(
        "`Friction law = Coulomb with cohesion`, `Cohesion = 1e400` (inf): "
        "refused by the entry's pattern",
        ["The entry value 1e400 for the entry named Cohesion does not match "
         "the given pattern"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Coulomb with cohesion",
            Cohesion="1e400")}),
    "dynamic_friction_above_static": case(
        "`Friction law = linear slip weakening`, `Dynamic friction "
        "coefficient = 0.7` above `Friction coefficient = 0.6`",
        ["<Dynamic friction coefficient> must lie in [0, Friction "
         "coefficient] = [0, 0.6], not 0.7"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="linear slip weakening",
            Friction_coefficient="0.6", Dynamic_friction_coefficient="0.7")}),
    "slip_weakening_distance_zero": case(
        "`Friction law = linear slip weakening`, `Slip-weakening distance = "
        "0`",
        ["<Slip-weakening distance> must be a finite length > 0 (m), not 0"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="linear slip weakening",
            **{"Slip-weakening distance": "0"})}),
    "dynamic_friction_under_coulomb": case(
        "`Dynamic friction coefficient = 0.3` under `Friction law = "
        "Coulomb`: a warning, runs",
        ["Warning: Contact/Dynamic friction coefficient is not used by "
         "Contact/Friction law = Coulomb and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Friction_law="Coulomb",
            Dynamic_friction_coefficient="0.3")},
        status=0),
    "quasi_static_steps_with_load_steps": case(
        "`Quasi-static time steps = true` with `Number of load steps = 3`",
        ["subsection <Contact>: <Number of load steps> = 3 with <Quasi-static "
         "time steps> = true: the time steps are the load steps"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Contact", Number_of_load_steps="3",
            **{"Quasi-static time steps": "true"})}),
    "weakened_start_equilibrium": case(
        "slip weakening in quasi-static steps with a fault traction above "
        "the static peak already at t = 0 (0.5 MPa above it at x = 0: the "
        "start, at the static bound, slips more than a step may)",
        ["The equilibrium at t = 0 slips fracture face", "more than the "
         "0.00025 that linear slip weakening allows a step", "a Fractures/"
         "Traction that is 0 at t = 0"],
        files={"scene.prm": NUCLEATION + section(
            "Fractures", Segments="-50, 0 : 50, 0",
            Traction="1.5e6*exp(-x^2/400); 0")},
        base="", stage="level"),
    "quasi_static_steps_under_elasticity": case(
        "`Quasi-static time steps = true` under `Model = elasticity`",
        ["Warning: Contact/Quasi-static time steps is not used by Model = "
         "elasticity and is ignored"],
        files={"scene.prm": SEGMENT + section(
            "Contact", **{"Quasi-static time steps": "true"})},
        status=0),
    "time_step_static_contact": case(
        "`Time/Time step = 0.01` under a static `Model = contact mechanics`",
        ["Warning: Time/Time step is not used by a static Model = contact "
         "mechanics and is ignored"],
        files={"scene.prm": CONTACT + SEGMENT + section(
            "Time", Time_step="0.01")},
        status=0),
    "slip_weakening_distance_under_flow": case(
        "`Model = flow`, `Slip-weakening distance = 0.01` (was silently "
        "ignored: the flow model's list of contact entries predated the "
        "law)",
        ["Warning: Contact/Slip-weakening distance is not used by Model = "
         "flow and is ignored"],
        files={"scene.prm": FLOW + section(
            "Contact", **{"Slip-weakening distance": "0.01"})},
        status=0),
    "linear_solver_tolerance_zero": case(
        "`Linear solver/Tolerance = 0` (was accepted: an iterative solve "
        "can never reach it)",
        ["subsection <Linear solver>: <Tolerance> must be in (0, 1), not 0: it "
         "is relative"],
        files={"scene.prm": section("Linear solver", Tolerance="0")}),
    "nonlinear_tolerance_one": case(
        "`Nonlinear solver/Tolerance = 1` (was accepted: one Newton step "
        "passes)",
        ["subsection <Nonlinear solver>: <Tolerance> must be in (0, 1), not 1"],
        files={"scene.prm": section("Nonlinear solver", Tolerance="1")}),
    "forcing_term_one": case(
        "`Forcing term = 1` (was accepted: the Krylov solve of a Newton step "
        "could stop at once)",
        ["subsection <Nonlinear solver>: <Forcing term> must be in [0, 1), not "
         "1: the Krylov solve"],
        files={"scene.prm": section("Nonlinear solver", Forcing_term="1")}),
    "mobility_beyond_double": case(
        "`Permeability = 1e-306`, `Viscosity = 1e3` under `Model = "
        "poromechanics` (k/viscosity = 1e-309, a denormal)",
        ["Flow/Permeability = 1e-306", "with Flow/Viscosity = 1000",
         "beyond the range of double precision"],
        files={"scene.prm": section("Model", Model="poromechanics") + SEGMENT
               + section("Boundary conditions",
                         Dirichlet_boundary_ids="0, 1, 2, 3")
               + section("Flow", Permeability="1e-306", Viscosity="1e3")
               + section("Time", End_time="0.1", Time_step="0.1")},
        stage="level", absent=["Stacktrace"]),
    "viscosity_beyond_double": case(
        "`Viscosity = 1e300` (was \"the poromechanical system is singular\" "
        "with a deal.II stack trace in the message)",
        ["<Minimum fracture aperture> = 1e-5 with <Viscosity> = 1e300",
         "not a positive double"],
        files={"scene.prm": section("Flow", Viscosity="1e300")}),
    "fracture_aperture_beyond_double": case(
        "`Fracture aperture at contact = 1e300` (was: \"the poromechanical "
        "system is singular\" with a deal.II stack trace in the message)",
        ["<Fracture aperture at contact> = 1e300 with <Viscosity> = 1e-3",
         "cubic-law conductivity", "not a positive double"],
        files={"scene.prm": section("Flow", Fracture_aperture_at_contact="1e300")},
        absent=["Stacktrace", "An error occurred"]),
    "fracture_property_count": case(
        "`Fracture normal transmissibility = 1e-9, 1e-12` in a scene with "
        "one fracture (a list per fracture of the wrong length)",
        ["subsection <Flow>: <Fracture normal transmissibility> lists 2 "
         "values, but the scene has 1 fractures", "one per fracture"],
        files={"scene.prm": SEGMENT + section(
            "Flow", Fracture_normal_transmissibility="1e-9, 1e-12")}),
    "fracture_permeability_not_a_number": case(
        "`Fracture permeability = cubic, 1e-12` (a misspelt keyword)",
        ["<Fracture permeability> = cubic, 1e-12: each value must be > 0 "
         "(m^2) or cubic law, not <cubic>"],
        files={"scene.prm": section("Flow",
                                    Fracture_permeability="cubic, 1e-12")}),
    "fracture_intersections_misspelt": case(
        "`Fracture intersections = harmonic` (not one of the choices)",
        ["Line <", "The entry value harmonic for the entry named Fracture "
         "intersections does not match the given pattern",
         "shared pressure|harmonic mean"],
        files={"scene.prm": section("Flow",
                                    Fracture_intersections="harmonic")}),
    "minimum_aperture_beneath_double": case(
        "`Minimum fracture aperture = 1e-300` with `Fracture aperture at "
        "contact = 0`: d^3 underflows to 0",
        ["<Minimum fracture aperture> = 1e-300", "= 0, which is not a "
         "positive double"],
        files={"scene.prm": section("Flow", Fracture_aperture_at_contact="0",
                                    Minimum_fracture_aperture="1e-300")}),
    "hfv_stabilisation_huge": case(
        "`HFV stabilisation = 1e300` (was: a singular poromechanical system "
        "with a deal.II stack trace in the message)",
        ["<HFV stabilisation> must be auto or a number in [1e-6, 1e6]"],
        files={"scene.prm": section("Flow", HFV_stabilisation="1e300")}),
    "mesh_file_without_gmsh_source": case(
        "`Mesh/File name = box.geo` without `Source = gmsh` (was silently "
        "ignored: the run meshed the default box)",
        ["subsection <Mesh>: <File name> = box.geo is read only with <Source "
         "= gmsh>, but Source is hyper rectangle"],
        files={"scene.prm": section("Mesh", File_name="box.geo"),
               "box.geo": BOX_GEO}),
    "subdivisions_with_gmsh_source": case(
        "`Subdivisions = 4, 4` and `Cell type = simplex` with `Source = gmsh`: "
        "warnings, runs",
        ["Warning: Mesh/Subdivisions is not used by Mesh/Source = gmsh",
         "Warning: Mesh/Cell type is not used by Mesh/Source = gmsh"],
        files={"scene.prm": section(
            "Mesh", Source="gmsh", File_name="box.geo",
            Cell_type="simplex") + section(
            "Boundary conditions", Dirichlet_boundary_ids="1"),
            "box.geo": BOX_GEO},
        status=0),
    "local_refinement_box_not_finite": case(
        "`Local refinement box = nan, 0 : 0.5, 0.5` (was accepted)",
        ["subsection <Mesh> <Local refinement box>: <nan> is not a finite "
         "number"],
        files={"scene.prm": section("Mesh", Local_refinement_box="nan, 0 : "
                                    "0.5, 0.5", Local_refinements="1")}),
    "local_refinement_box_inverted": case(
        "`Local refinement box = 0.5, 0.5 : -0.5, -0.5` (was accepted: "
        "nothing refined)",
        ["its lower corner lies above its upper one in direction 0"],
        files={"scene.prm": section("Mesh", Local_refinement_box="0.5, 0.5 : "
                                    "-0.5, -0.5", Local_refinements="1")}),
    "local_refinement_box_without_refinements": case(
        "`Local refinement box` set with `Local refinements = 0`: a "
        "warning, runs",
        ["Warning: Mesh/Local refinement box is not used by Mesh/Local "
         "refinements = 0"],
        files={"scene.prm": section("Mesh", Local_refinement_box="0, 0 : "
                                    "0.5, 0.5")}, status=0),
    "segment_not_finite": case(
        "`Segments = nan, 0 : 0.5, 0` (was refused as a segment of length 0, "
        "not naming the entry)",
        ["subsection <Fractures> <Segments>: <nan> is not a finite number"],
        files={"scene.prm": section("Fractures",
                                    Segments="nan, 0 : 0.5, 0")}),
    "segment_of_length_zero": case(
        "`Segments = 0, 0 : 0, 0` (was \"A fracture segment has length 0\", "
        "not naming the entry)",
        ["subsection <Fractures> <Segments>: segment 0 has length 0"],
        files={"scene.prm": section("Fractures", Segments="0, 0 : 0, 0")}),
    "output_directory_empty": case(
        "`Output directory =` (empty; was a raw filesystem error)",
        ["Output/Output directory is empty: name a directory"],
        files={"scene.prm": section("Output", Output_directory="")},
        absent=["filesystem error"]),
    "box_beyond_double": case(
        "`Upper right corner = 1e300, 1e300` (was \"cell 0 has measure inf: "
        "it is degenerate\", not naming the entry)",
        ["<Upper right corner> = 1e300, 1e300 has measure inf",
         "beyond the range of double precision"],
        files={"scene.prm": section("Mesh",
                                    Upper_right_corner="1e300, 1e300")}),
    "flux_expression_without_ids": case(
        "`Flux boundary expression = 1/0` under `Model = flow` without flux "
        "ids: a warning (was silently ignored), runs",
        ["Warning: Flow/Flux boundary expression is not used by a scene "
         "without Flow/Flux boundary ids"],
        files={"scene.prm": FLOW + section(
            "Flow", Pressure_boundary_ids="0", Flux_boundary_expression="1/0")
            + section("Time", End_time="0.1", Time_step="0.1")},
        status=0),
    "biot_coefficient_under_flow": case(
        "`Biot coefficient = 0.8` and `Initial porosity = 0.3` under `Model "
        "= flow`: warnings (were silently ignored), runs",
        ["Warning: Flow/Biot coefficient is not used by Model = flow",
         "Warning: Flow/Initial porosity is not used by Model = flow"],
        files={"scene.prm": FLOW + section(
            "Flow", Pressure_boundary_ids="0", Biot_coefficient="0.8",
            Initial_porosity="0.3")
            + section("Time", End_time="0.1", Time_step="0.1")},
        status=0),
    "random_seed_without_distortion": case(
        "`Random seed = 3` with `Distortion = 0`: a warning, runs",
        ["Warning: Mesh/Random seed is not used by Mesh/Distortion = 0"],
        files={"scene.prm": section("Mesh", Random_seed="3")}, status=0),
    "neumann_traction_without_ids": case(
        "`Neumann traction = 0; -1` with no Neumann boundary ids: a warning "
        "(was silently ignored), runs",
        ["Warning: Boundary conditions/Neumann traction is not used by a "
         "scene without Boundary conditions/Neumann boundary ids"],
        files={"scene.prm": section("Boundary conditions",
                                    Neumann_traction="0; -1")}, status=0),
    "fracture_pressure_without_fractures": case(
        "`Fractures/Pressure = 1` in a scene without fractures: a warning "
        "(was silently ignored), runs",
        ["Warning: Fractures/Pressure is not used by a scene without "
         "fractures"],
        files={"scene.prm": section("Fractures", Pressure="1")}, status=0),
    "analytic_load_without_solution": case(
        "`Exact solution/Analytic load = 5` without an analytic solution: a "
        "warning (was silently ignored), runs",
        ["Warning: Exact solution/Analytic load is not used by Exact "
         "solution/Analytic solution = none"],
        files={"scene.prm": section("Exact solution", Analytic_load="5")},
        status=0),
    "smoother_sweeps_with_direct": case(
        "`Smoother sweeps = 2` with `Method = direct`: a warning, runs",
        ["Linear solver/Smoother sweeps is not used by Linear solver/Method "
         "= direct and is ignored"],
        files={"scene.prm": section("Linear solver", Method="direct",
                                    Smoother_sweeps="2")},
        status=0),
    "adaptive_flow": case(
        "`Mesh/Refinement = adaptive` with `Model = flow`",
        ["subsection <Mesh>", "<Refinement = adaptive> needs an a posteriori "
         "error indicator", "Model = flow needs <Refinement = uniform>"],
        files={"scene.prm": FLOW + section("Mesh", Refinement="adaptive")}),
    "adaptive_zero_fraction": case(
        "`Mesh/Refinement = adaptive` with `Refined fraction = 0`",
        ["subsection <Mesh>", "<Refinement = adaptive> needs <Refined "
         "fraction> > 0"],
        files={"scene.prm": section("Mesh", Refinement="adaptive",
                                    Refined_fraction="0")}),
    "refined_fraction_uniform": case(
        "`Refined fraction = 0.5` with `Refinement = uniform`: a warning, runs",
        ["Mesh/Refined fraction is not used by Mesh/Refinement = uniform and "
         "is ignored"],
        files={"scene.prm": section("Mesh", Refined_fraction="0.5")},
        status=0),
    "fracture_refinements_without_fractures": case(
        "`Mesh/Fracture refinements = 2` in a scene without fractures",
        ["subsection <Mesh>: <Fracture refinements> = 2 refines the cells "
         "that touch a fracture, but the scene has none", "set it to 0 or "
         "give the fractures"],
        files={"scene.prm": section("Mesh", Fracture_refinements="2")}),
    "fracture_refinements": case(
        "`Mesh/Fracture refinements = 2` next to a segment: a correct run "
        "(the cells that touch it are refined twice)",
        [], files={"scene.prm": SEGMENT + section("Mesh",
                                                  Fracture_refinements="2")},
        status=0, written=["results/convergence.csv"]),
    "region_value_missing": case(
        "`Lame mu = 1: 3e9` with Mesh/Region boxes making regions 0 and 1 "
        "(a region without a value)",
        ["subsection <Material>: <Lame mu> gives regions 1, but cells of "
         "region 0 have no value; the mesh has the regions 0, 1"],
        files={"scene.prm": section("Mesh", Region_boxes="-1, -1 : 1, 0",
                                    Region_box_ids="1")
               + section("Material", Lame_mu="1: 3e9")},
        stage="level"),
    "region_not_in_mesh": case(
        "`Permeability = 0: 1e-15, 1: 1e-15, 2: 1e-18` where the mesh has "
        "regions 0 and 1 (a region that no cell has)",
        ["subsection <Flow>: <Permeability> gives region 2, which no cell of "
         "the mesh has; the mesh has the regions 0, 1"],
        files={"scene.prm": section("Model", Model="flow")
               + section("Mesh", Region_boxes="-1, -1 : 1, 0",
                         Region_box_ids="1")
               + section("Flow", Permeability="0: 1e-15, 1: 1e-15, 2: 1e-18")},
        stage="level"),
    "region_box_ids_count": case(
        "`Region boxes` with one box and `Region box ids = 1, 2`",
        ["<Region boxes> = -1, -1 : 1, 0 gives 1 boxes, but <Region box "
         "ids> = 1, 2 gives 2 ids"],
        files={"scene.prm": section("Mesh", Region_boxes="-1, -1 : 1, 0",
                                    Region_box_ids="1, 2")}),
    "boundary_box_ids_count": case(
        "`Boundary boxes` with two boxes and `Boundary box ids = 6`",
        ["<Boundary boxes> = -1, -1 : -1, 0; 1, -1 : 1, 1 gives 2 boxes, but "
         "<Boundary box ids> = 6 gives 1 ids: give one id per box"],
        files={"scene.prm": section("Mesh",
                                    Boundary_boxes="-1, -1 : -1, 0; "
                                    "1, -1 : 1, 1",
                                    Boundary_box_ids="6")}),
    "boundary_box_upside_down": case(
        "`Boundary boxes = 1, -1 : -1, 0` (lower corner above the upper)",
        ["<Boundary boxes> = 1, -1 : -1, 0: box 0 has its lower corner above "
         "its upper one in direction 0"],
        files={"scene.prm": section("Mesh", Boundary_boxes="1, -1 : -1, 0",
                                    Boundary_box_ids="6")}),
    "boundary_box_id_unused_by_faces": case(
        "`Boundary boxes` catching no boundary face, its id 6 given to "
        "`Dirichlet boundary ids`",
        ["lists the id 6, which no boundary face of the mesh carries"],
        files={"scene.prm": section("Mesh", Boundary_boxes="-0.5, -0.5 : "
                                    "0.5, 0.5", Boundary_box_ids="6")
               + section("Boundary conditions", Dirichlet_boundary_ids="6")},
        stage="level"),
    "lithostatic_without_gravity": case(
        "`Initial stress/Kind = lithostatic` without Gravity/Vector",
        ["subsection <Initial stress>: <Kind> = lithostatic is the weight of "
         "the rock under gravity, but Gravity/Vector is zero"],
        files={"scene.prm": section("Initial stress", Kind="lithostatic")}),
    "hydrostatic_without_gravity": case(
        "`Flow/Initial pressure = hydrostatic` without Gravity/Vector",
        ["subsection <Flow>: <Initial pressure> = hydrostatic is the weight "
         "of the fluid under gravity, but Gravity/Vector is zero"],
        files={"scene.prm": section("Model", Model="flow")
               + section("Flow", Initial_pressure="hydrostatic")}),
    "gravity_components": case(
        "`Gravity/Vector = 0, 0, -9.81` in 2D",
        ["subsection <Gravity>, <Vector>: the point <0, 0, -9.81> has 3 "
         "coordinates, expected 2"],
        files={"scene.prm": section("Gravity", Vector="0, 0, -9.81")}),
    "density_negative": case(
        "`Material/Density = -2500`",
        ["<Density> = -2500: each value must be >= 0 (kg/m^3)"],
        files={"scene.prm": section("Material", Density="-2500")}),
    "lithostatic_pressure_expression": case(
        "`Initial stress/Kind = lithostatic` under poromechanics with "
        "`Flow/Initial pressure` an expression",
        ["Kind = lithostatic with Model = poromechanics takes the effective "
         "stress of the rock over a fluid at rest, but Flow/Initial pressure "
         "is an expression: set it to hydrostatic"],
        files={"scene.prm": section("Model", Model="poromechanics")
               + section("Gravity", Vector="0, -9.81")
               + section("Initial stress", Kind="lithostatic")}),
    "lithostatic_regions_side_by_side": case(
        "`Initial stress/Kind = lithostatic` with two regions of different "
        "densities side by side (x < 0 and x > 0)",
        ["Kind = lithostatic stacks the regions along the vertical, but "
         "regions 0 and 1 share the elevations",
         "with different Material/Density or Flow/Biot coefficient"],
        files={"scene.prm": section("Mesh", Region_boxes="-1, -1 : 0, 1",
                                    Region_box_ids="1")
               + section("Gravity", Vector="0, -9.81")
               + section("Material", Density="0: 2000, 1: 2500")
               + section("Initial stress", Kind="lithostatic")},
        stage="level"),
    "analytic_solution_with_gravity": case(
        "`Analytic solution = terzaghi` with `Gravity/Vector = 0, -9.81`",
        ["Exact solution/Analytic solution = terzaghi: it is the solution of "
         "a weightless column: set Gravity/Vector to 0"],
        files={"scene.prm": section("Model", Model="poromechanics")
               + section("Gravity", Vector="0, -9.81")
               + section("Exact solution", Analytic_solution="terzaghi",
                         Analytic_load="1e6")}),
    "line_probe_malformed": case(
        "`Output/Line probes = top: 0, 0 : 1, 1` (no number of points)",
        ["subsection <Output>, <Line probes>: <top: 0, 0 : 1, 1> is not "
         "<NAME: x0, y0[, z0] : x1, y1[, z1] : N>"],
        files={"scene.prm": section("Output", Line_probes="top: 0, 0 : 1, 1")}),
    "line_probe_one_point": case(
        "`Output/Line probes = top: 0, 0 : 1, 1 : 1`",
        ["<top: 0, 0 : 1, 1 : 1>: the number of points <1> must be an "
         "integer from 2 to 1e6"],
        files={"scene.prm": section("Output",
                                    Line_probes="top: 0, 0 : 1, 1 : 1")}),
    "tracer_porosity_zero": case(
        "`Transport/Porosity = 0` with the tracer on",
        ["subsection <Transport>", "<Porosity>", "in (0, 1]"],
        files={"scene.prm": FLOW + section("Transport", Enabled="true",
                                           Porosity="0")}),
    "tracer_fracture_porosity_above_one": case(
        "`Transport/Fracture porosity = 1.5`",
        ["subsection <Transport>: <Fracture porosity> = 1.5: each value must "
         "be in (0, 1]"],
        files={"scene.prm": FLOW + SEGMENT + section(
            "Transport", Enabled="true", Fracture_porosity="1.5")}),
    "tracer_fracture_porosity_count": case(
        "`Transport/Fracture porosity = 0.5, 0.5` for one fracture",
        ["<Fracture porosity> lists 2 values, but the scene has 1 fractures"],
        files={"scene.prm": FLOW + SEGMENT + section(
            "Transport", Enabled="true", Fracture_porosity="0.5, 0.5")}),
    "tracer_with_poromechanics": case(
        "`Transport/Enabled = true` with `Model = poromechanics`",
        ["subsection <Transport>: <Enabled = true> with Model = "
         "poromechanics: only Model = flow carries the passive tracer"],
        files={"scene.prm": section("Model", Model="poromechanics")
               + section("Transport", Enabled="true")}),
    "tracer_inflow_not_an_expression": case(
        "`Transport/Inflow concentration = 1 +`",
        ["Transport/Inflow concentration"],
        files={"scene.prm": FLOW + section("Transport", Enabled="true",
                                           Inflow_concentration="1 +")}),
    "tracer_porosity_missing_region": case(
        "`Transport/Porosity = 0: 0.2` on a mesh of regions 0 and 1",
        ["subsection <Transport>: <Porosity> gives regions 0, but cells of "
         "region 1 have no value"],
        files={"scene.prm": FLOW + section(
            "Mesh", Region_boxes="-1, -1 : 0, 1", Region_box_ids="1")
            + section("Transport", Enabled="true", Porosity="0: 0.2")},
        stage="level"),
    "lame_mu_zero": case(
        "`Lame mu = 0`",
        ["<Lame mu> = 0: each value must be > 0, not <0>"],
        files={"scene.prm": section("Material", Lame_mu="0")}),
    # Flow.
    "flow_zero_viscosity": case(
        "`Model = flow`, `Flow/Viscosity = 0`",
        ["subsection <Flow>", "<Viscosity> must be > 0 (Pa s), not 0"],
        files={"scene.prm": FLOW + section("Flow", Viscosity="0")}),
    "flow_isolated_fracture_without_storage": case(
        "`Model = flow`: a fracture fed by a source, cut off from the matrix "
        "(Permeability = 0) and from every boundary, with Fracture "
        "compressibility = 0, while the matrix has storage and a drained "
        "side (was: p_f = 1.35e19 Pa written, exit 0); refused before the "
        "first step",
        ["a part of the flow domain (", "among them the fracture face at",
         "has neither a prescribed pressure nor storage",
         "Set Flow/Fracture compressibility or Inverse Biot modulus > 0"],
        files={"scene.prm": FLOW + SEGMENT + section(
            "Mesh", Subdivisions="8, 8") + section(
            "Flow", Permeability="0", Fracture_source="1e-6",
            Fracture_compressibility="0", Pressure_boundary_ids="0")},
        stage="level"),
    "function_constants_variable": case(
        "`Expressions/Function constants = x=1` (was SIGABRT: muparser's "
        "error escaped at the first expression)",
        ["<Function constants>: <x=1>: <x> is a variable or constant of "
         "every expression already"],
        files={"scene.prm": section("Expressions", Function_constants="x=1")}),
    "function_constants_not_a_name": case(
        "`Expressions/Function constants = 2a=1` (was SIGABRT, as x=1)",
        ["<Function constants>: <2a=1>: <2a> is not a name"],
        files={"scene.prm": section("Expressions", Function_constants="2a=1")}),
    "function_constants_twice": case(
        "`Expressions/Function constants = c=1, c=2` (the second silently "
        "won)",
        ["<Function constants>: <c=2>: <c> is defined twice"],
        files={"scene.prm": section("Expressions",
                                    Function_constants="c=1, c=2")}),
    "function_constants_not_a_number": case(
        "`Expressions/Function constants = c=abc`: refused by the entry's "
        "pattern",
        ["The entry value c=abc for the entry named Function constants does "
         "not match the given pattern"],
        files={"scene.prm": section("Expressions",
                                    Function_constants="c=abc")}),
    "exact_pressure_beyond_double": case(
        "`Model = flow`, `Exact solution/Matrix pressure = 1e300` (was exit "
        "0 with err_pressure = -nan: the error squares the field)",
        ["gives err_pressure = ", "not a finite number",
         "beyond the range of double precision"],
        files={"scene.prm": FLOW + section(
            "Flow", Pressure_boundary_ids="0") + section(
            "Exact solution", Matrix_pressure="1e300") + section(
            "Output", Write_VTU="false")},
        stage="level"),
    # On 2 ranks, an error found by one rank only (an expression evaluated
    # on its own cells) or after one rank's check used to hang: the other
    # rank waited in a collective call while the first unwound through
    # MUMPS's collective destructor.
    "exact_contact_traction_not_finite_2_ranks": case(
        "2 ranks, poromechanics: exact contact traction `1/0; 0`, found by "
        "the rank that owns the fracture faces (was a hang)",
        ["stopped on rank", "Entry <Exact solution/Contact traction> is not "
         "finite"],
        files={"scene.prm": POROMECHANICS_2_RANKS + section(
            "Exact solution", Contact_traction="1/0; 0")},
        stage="level", ranks=2),
    "exact_jump_not_finite_2_ranks": case(
        "2 ranks, poromechanics: exact displacement jump `1/0; 0` (was a "
        "hang)",
        ["stopped on rank", "Entry <Exact solution/Displacement jump> is not "
         "finite"],
        files={"scene.prm": POROMECHANICS_2_RANKS + section(
            "Exact solution", Displacement_jump="1/0; 0")},
        stage="level", ranks=2),
    "exact_pressure_beyond_double_2_ranks": case(
        "2 ranks, poromechanics: exact matrix pressure `1e300`, whose error "
        "is not finite at the equilibrium step (was a hang: rank 0 alone "
        "checked the time series)",
        ["stopped on rank", "The step to t = 0.000000 gives err_pressure = ",
         "not a finite number"],
        files={"scene.prm": POROMECHANICS_2_RANKS + section(
            "Exact solution", Matrix_pressure="1e300")},
        stage="level", ranks=2),
    "exact_fracture_pressure_beyond_double_2_ranks": case(
        "2 ranks, poromechanics: exact fracture pressure `t*1e300`, not "
        "finite in the error of the first step (was a hang)",
        ["stopped on rank", "The step to t = 0.100000 gives "
         "err_fracture_pressure = ", "not a finite number"],
        files={"scene.prm": POROMECHANICS_2_RANKS + section(
            "Exact solution", Fracture_pressure="t*1e300")},
        stage="level", ranks=2),
    "exact_displacement_beyond_double_2_ranks": case(
        "2 ranks, poromechanics: exact displacement `t*1e300; 0` (was a "
        "hang)",
        ["stopped on rank", "The step to t = 0.100000 gives err_u = ",
         "not a finite number"],
        files={"scene.prm": POROMECHANICS_2_RANKS + section(
            "Exact solution", Displacement="t*1e300; 0")},
        stage="level", ranks=2),
    "flow_time_dependent_permeability": case(
        "`Model = flow`, `Flow/Permeability = 1e-15 * (1 + t)` (was "
        "evaluated at t = 0 only)",
        ["subsection <Flow>: <Permeability> = 1e-15 * (1 + t) depends on t",
         "evaluated once, at t = 0"],
        files={"scene.prm": FLOW + section("Flow",
                                           Permeability="1e-15 * (1 + t)")}),
    "flow_entries_of_mechanics": case(
        "`Model = flow` with `Material/Lame mu`, a Dirichlet boundary and an "
        "initial stress set: a correct run that warns about each (the "
        "opposite direction already warned)",
        ["Warning: Boundary conditions/Dirichlet boundary ids is not used by "
         "Model = flow", "Warning: Material/Lame mu is not used by Model = "
         "flow", "Warning: Initial stress/Stress is not used by Model = flow"],
        files={"scene.prm": FLOW + section("Material", Lame_mu="2e9") +
               section("Boundary conditions", Dirichlet_boundary_ids="0") +
               section("Initial stress", Stress="-1e6; 0; 0; -1e6")},
        status=0, written=["results/convergence.csv"]),
    "flow_tiny_negative_permeability": case(
        "`Model = flow`, `Flow/Permeability = -1e-20` (was printed "
        "\"-0.000000 < 0\")",
        ["Flow/Permeability is -1e-20 < 0 at the point",
         "a permeability must be >= 0"],
        files={"scene.prm": FLOW + section("Flow", Permeability="-1e-20")},
        stage="level"),
    "flow_negative_permeability": case(
        "`Model = flow`, `Flow/Permeability = x - 2` (negative in the box)",
        ["Flow/Permeability is", "< 0 at the point",
         "a permeability must be >= 0"],
        files={"scene.prm": FLOW + section("Flow", Permeability="x - 2")},
        stage="level"),
    "flow_pressure_and_flux_id": case(
        "`Flow/Pressure boundary ids = 0` and `Flux boundary ids = 0, 1`",
        ["subsection <Flow>", "boundary id 0 is listed in both <Pressure "
         "boundary ids> and <Flux boundary ids>"],
        files={"scene.prm": FLOW + section("Flow", Pressure_boundary_ids="0",
                                           Flux_boundary_ids="0, 1")}),
    "dirichlet_and_neumann_id": case(
        "`Dirichlet boundary ids = 0, 1` and `Neumann boundary ids = 1, 2` "
        "(the traction on 1 was dropped)",
        ["subsection <Boundary conditions>", "boundary id 1 is listed in "
         "both <Dirichlet boundary ids> and <Neumann boundary ids>",
         "give each boundary one kind of data"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_boundary_ids="0, 1",
                                    Neumann_boundary_ids="1, 2")}),
    "dirichlet_id_twice": case(
        "`Dirichlet boundary ids = 0, 0`",
        ["<Dirichlet boundary ids> lists 0 twice"],
        files={"scene.prm": section("Boundary conditions",
                                    Dirichlet_boundary_ids="0, 0")}),
    "fracture_outside_domain": case(
        "`Fractures/Segments = 2, 0 : 3, 0`, outside the box (was \"not "
        "resolved by the mesh ... adapt Subdivisions\")",
        ["Fracture 0 (2 0 : 3 0): its point (2 0) lies outside the mesh",
         "A fracture must lie inside the domain"],
        files={"scene.prm": section("Fractures", Segments="2, 0 : 3, 0")},
        stage="level"),
    "fracture_on_boundary": case(
        "`Fractures/Segments = -1, -1 : 1, -1`, on the bottom of the box (was "
        "\"not resolved by the mesh\")",
        ["Fracture 0 (-1 -1 : 1 -1) lies on the boundary of the domain"],
        files={"scene.prm": section("Fractures", Segments="-1, -1 : 1, -1")},
        stage="level"),
    "gmsh_empty_mesh_file": case(
        "`Mesh/Source = gmsh` with an empty `empty.msh` (was \"is "
        "-1-dimensional\")",
        ["The gmsh mesh <", "empty.msh> holds no mesh or geometry that gmsh "
         "can read", "check Mesh/File name"],
        files={"scene.prm": section("Mesh", Source="gmsh",
                                    File_name="empty.msh"),
               "empty.msh": ""},
        stage="level"),
    "gmsh_refinement_too_large": case(
        "`Global refinements = 9` of a gmsh mesh of 944 triangles (the "
        "memory estimate skipped gmsh meshes)",
        ["the finest mesh would have about 2.47e+08 cells",
         "Lower Mesh/Global refinements or coarsen the gmsh mesh <box.geo>"],
        files={"scene.prm": section("Mesh", Source="gmsh",
                                    File_name="box.geo",
                                    Global_refinements="9"),
               "box.geo": FINE_BOX_GEO},
        stage="level"),
    "gmsh_refinement_out_of_memory": case(
        "`Global refinements = 5` of a gmsh mesh of 944 triangles, run "
        "with 1 GB of address space (was a segmentation fault in "
        "gmsh::finalize)",
        ["out of memory (std::bad_alloc)", "lower Mesh/Subdivisions, "
         "Mesh/Global refinements"],
        files={"scene.prm": section("Mesh", Source="gmsh",
                                    File_name="box.geo",
                                    Global_refinements="5"),
               "box.geo": FINE_BOX_GEO},
        stage="level", absent=["cannot be read or meshed"],
        address_space=10**9),
    "umfpack_out_of_memory": case(
        "`Global refinements = 4` of a gmsh mesh of 944 triangles (241,664 "
        "cells), `Linear solver/Method = direct`, run with 1 GB of address "
        "space (was UMFPACK's list of "
        "the causes of every error status; where the memory runs out, in "
        "UMFPACK or before, depends on the machine)",
        ["out of memory", "use Linear solver/Method = AMG"],
        files={"scene.prm": section("Mesh", Source="gmsh",
                                    File_name="box.geo",
                                    Global_refinements="4") +
               section("Linear solver", Method="direct"),
               "box.geo": FINE_BOX_GEO},
        stage="level", absent=["rank deficient"], address_space=10**9),
    "gmsh_physical_tag_twice": case(
        "`Fractures/Gmsh physical tags = 11, 11` (made two coincident "
        "fractures)",
        ["subsection <Fractures>: <Gmsh physical tags> lists 11 twice"],
        files={"scene.prm": section("Fractures",
                                    Gmsh_physical_tags="11, 11")}),
    "flow_unknown_pressure_id": case(
        "`Model = flow`, `Flow/Pressure boundary ids = 7`",
        ["Flow/Pressure boundary ids lists the id 7",
         "which no boundary face of the mesh carries"],
        files={"scene.prm": FLOW + section("Flow", Pressure_boundary_ids="7")},
        stage="level"),
}


# The exit status of a skipped case (ctest's SKIP_RETURN_CODE).
SKIPPED = 77
# Seconds after which a run on several ranks counts as a hang: each such
# case stops in a few seconds.
TIMEOUT_RANKS = 120


def prepare(name, directory):
    """Writes the files of case @p name into the empty @p directory."""
    shutil.rmtree(directory, ignore_errors=True)
    directory.mkdir(parents=True)
    for file_name, content in CASES[name]["files"].items():
        path = directory / file_name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)


def execute(program, name, directory):
    """Runs case @p name in @p directory; returns (status, stdout, stderr),
    the status None if a run on several ranks did not end (killed after
    TIMEOUT_RANKS seconds)."""
    prepare(name, directory)
    environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                       OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    spec = CASES[name]
    limit = spec["address_space"]

    def limit_address_space():
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    command = [os.path.abspath(program)] + spec["args"]
    if spec["ranks"] > 1:
        # timeout(1) sends SIGTERM to mpirun, which passes it on to the
        # ranks, and SIGKILL 20 s later; its status is then 124 or 137.
        command = ["timeout", "--kill-after=20", str(TIMEOUT_RANKS),
                   "mpirun", "-np", str(spec["ranks"]),
                   "--oversubscribe"] + command
    run = subprocess.run(command, cwd=directory, capture_output=True,
                         text=True, env=environment, timeout=600,
                         preexec_fn=limit_address_space if limit else None)
    hung = spec["ranks"] > 1 and run.returncode in (124, 137)
    return None if hung else run.returncode, run.stdout, run.stderr


def problems(name, directory, status, stdout, stderr):
    """What is wrong with the outcome of case @p name (empty: passed)."""
    spec = CASES[name]
    found = []
    text = stdout + stderr
    if status is None:
        found.append("the run did not end within %d s (a hang)"
                     % TIMEOUT_RANKS)
    elif status != spec["status"]:
        found.append("exit status %d, expected %d" % (status, spec["status"]))
    for part in spec["expect"]:
        if part not in text:
            found.append("the message lacks <%s>" % part)
    for part in spec["absent"]:
        if part in text:
            found.append("the message contains <%s>" % part)
    for path in spec["written"]:
        if not (directory / path).is_file():
            found.append("%s was not written" % path)
    if spec["status"] != 0:
        results = [str(p.relative_to(directory)) for p in directory.rglob("*")
                   if p.name == "convergence.csv" or p.suffix == ".vtu"]
        if results:
            found.append("results written: " + ", ".join(results))
        if spec["stage"] == "parse" and (directory / "results").exists():
            found.append("the output directory was created")
    return found


def sanitized(program):
    """True if @p program runs under AddressSanitizer, whose shadow memory
    needs more address space than any limit that makes a run fail."""
    libraries = subprocess.run(["ldd", program], capture_output=True,
                               text=True).stdout
    return "libasan" in libraries


def first_line(stdout, stderr):
    """The first line of the error message (or of the output)."""
    for line in (stderr or stdout).splitlines():
        if line.strip():
            return line.strip().replace("PolyFrac stopped: ", "")
    return ""


def main():
    if sys.argv[1:] == ["--list"]:
        print("\n".join(CASES))
        return 0
    if len(sys.argv) == 3 and sys.argv[1] == "--list-ranks":
        print("\n".join(name for name, spec in CASES.items()
                        if spec["ranks"] == int(sys.argv[2])))
        return 0
    if len(sys.argv) == 5 and sys.argv[1] == "run":
        program, name, directory = sys.argv[2], sys.argv[3], sys.argv[4]
        directory = pathlib.Path(directory)
        if CASES[name]["address_space"] and sanitized(program):
            print("skipped: an address-space limit cannot be combined with "
                  "AddressSanitizer")
            return SKIPPED
        status, stdout, stderr = execute(program, name, directory)
        print("$ polyfrac " + " ".join(CASES[name]["args"]))
        print(stdout + stderr)
        found = problems(name, directory, status, stdout, stderr)
        for problem in found:
            print("FAILED: " + problem)
        return 1 if found else 0
    if len(sys.argv) == 4 and sys.argv[1] == "table":
        program, root = sys.argv[2], pathlib.Path(sys.argv[3])
        print("| input | message (first line) | test |")
        print("|---|---|---|")
        for name, spec in CASES.items():
            status, stdout, stderr = execute(program, name, root / name)
            line = first_line(stdout, stderr) if spec["status"] != 0 else \
                "(exit 0) " + first_line(stdout, "")
            passed = not problems(name, root / name, status, stdout, stderr)
            print("| %s | %s | `bad_input/%s`%s |" % (
                spec["input"], line.replace("|", "\\|"), name,
                "" if passed else " FAILS"))
        return 0
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
