#!/usr/bin/python3
"""Sweeps every entry of `polyfrac --print-parameters` over wrong values.

  entry_sweep.py POLYFRAC WORK_DIR [--models M ...] [--timeout S]
                 [--ranks N] [--summary-only]

For each model (elasticity, contact mechanics, flow, poromechanics) a small
2D base scene is written to WORK_DIR and checked to run; then every entry is
overridden, one at a time, with `--set "Section/Entry=value"` by variants
chosen from the shape of its default value and its help text (zero,
negative, huge, NaN/inf, empty, time-dependent and non-constant
expressions, wrong component counts, duplicate/unknown/negative ids,
conflicting ids, unknown selection words, `maybe` booleans, missing files,
directories). Each outcome is classified as

  refused          exit status != 0 with a message (names_entry: whether the
                   entry's name appears in it)
  ran              exit status 0
  ran, NaN/inf     exit status 0 and nan/inf in a written csv file or in the
                   printed output (a silent wrong answer)
  warned           exit status 0 with a line starting with `Warning:`
  crash            killed by a signal, or `Segmentation fault`, `terminate
                   called`, `Aborted`, `*** Error`, `An error occurred in line`
  hang             the timeout was reached

Writes WORK_DIR/entry_sweep.csv (one row per run, appended as the sweep
goes) and the logs of each run in WORK_DIR/logs/, and prints a markdown
summary. --summary-only prints the summary of an existing
WORK_DIR/entry_sweep.csv without running anything.

Python 3, standard library only.
"""

import argparse
import csv
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time

MODELS = ["elasticity", "contact mechanics", "flow", "poromechanics"]

CRASH_TEXTS = ["Segmentation fault", "terminate called", "Aborted",
               "*** Error", "An error occurred in line"]

FIELDS = ["model", "entry", "value", "kind", "outcome", "names_entry",
          "exit_status", "message", "seconds", "out_of_range"]


# --------------------------------------------------------------------------
# The entries.

def read_entries(polyfrac, env):
    """[(path, default, help)] from --print-parameters (dimension 2)."""
    text = subprocess.run([polyfrac, "--print-parameters"], env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          universal_newlines=True, timeout=60).stdout
    entries = []
    stack = []
    comment = []
    for raw in text.splitlines():
        line = raw.strip()
        if not line:
            comment = []
            continue
        if line.startswith("#"):
            comment.append(line.lstrip("#").strip())
            continue
        m = re.match(r"subsection\s+(.*)$", line)
        if m:
            stack.append(m.group(1).strip())
            comment = []
            continue
        if line == "end":
            stack.pop()
            comment = []
            continue
        m = re.match(r"set\s+(.*?)\s*=\s*(.*)$", line)
        if m:
            path = "/".join(stack + [m.group(1)])
            entries.append((path, m.group(2).strip(), " ".join(comment)))
            comment = []
    return entries


def is_number(s):
    try:
        float(s)
        return True
    except ValueError:
        return False


INTEGERS = {"Number of load steps", "Number of refinement levels",
            "Maximum iterations", "Smoother sweeps", "Cells per polytope",
            "Fracture refinements", "Global refinements", "Local refinements",
            "Random seed", "Anderson depth", "Maximum coupling iterations",
            "Checkpoint interval", "Maximum steps"}

# Ranges the help text implies without a '> 0' the parser can read (the
# physical meaning of the entry); used only to flag suspicious 'ran' cases.
EXTRA_BOUNDS = {
    "Time/Time step": (0.0, True, None, None),
    "Time/End time": (0.0, True, None, None),
    "Time/Maximum time step": (0.0, False, None, None),
    "Linear solver/Tolerance": (0.0, True, None, None),
    "Nonlinear solver/Tolerance": (0.0, True, None, None),
    "Nonlinear solver/Forcing term": (0.0, False, None, None),
    "Mesh/Refined fraction": (0.0, True, 1.0, False),
    "Mesh/Distortion": (0.0, False, None, None),
    # lambda > -2 mu/d with the base scenes' mu = 1e10 (the default), d = 2.
    "Material/Lame lambda": (-1e10, True, None, None),
    "Linear solver/Maximum iterations": (1.0, False, None, None),
    "Nonlinear solver/Maximum iterations": (1.0, False, None, None),
    "Nonlinear solver/Maximum coupling iterations": (1.0, False, None, None),
    "Time/Maximum steps": (1.0, False, None, None),
    "Convergence study/Number of refinement levels": (1.0, False, None, None),
    "Contact/Number of load steps": (1.0, False, None, None),
    "Linear solver/Smoother sweeps": (1.0, False, None, None),
    "Nonlinear solver/Anderson depth": (0.0, False, None, None),
    "Output/Checkpoint interval": (0.0, False, None, None),
    "Mesh/Global refinements": (0.0, False, None, None),
    "Mesh/Local refinements": (0.0, False, None, None),
    "Mesh/Fracture refinements": (0.0, False, None, None),
}


def bounds(help_text, path=None):
    """(lower, lower_strict, upper, upper_strict) from the help text (or
    EXTRA_BOUNDS), or None where none is known."""
    if path in EXTRA_BOUNDS:
        return EXTRA_BOUNDS[path]
    lo = lo_strict = hi = hi_strict = None
    m = re.search(r"in ([\[(])\s*([-0-9.e+]+)\s*,\s*([-0-9.e+]+)\s*([\])])",
                  help_text)
    if m:
        lo, lo_strict = float(m.group(2)), m.group(1) == "("
        hi, hi_strict = float(m.group(3)), m.group(4) == ")"
        return lo, lo_strict, hi, hi_strict
    m = re.search(r"(>=|>)\s*(-?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?)(?![0-9a-zA-Z(]|\.[0-9])",
                  help_text)
    if m and "-2 mu" not in help_text:
        lo, lo_strict = float(m.group(2)), m.group(1) == ">"
    if lo is None:
        return None
    return lo, lo_strict, hi, hi_strict


def out_of_range(value, bnd):
    """The reason a value is outside the help text's range, or ''."""
    if bnd is None:
        return ""
    v = value.strip()
    if v.lower() in ("nan", "inf", "-inf"):
        try:
            x = float(v)
        except ValueError:
            return ""
    else:
        try:
            x = float(v)
        except ValueError:
            return ""
    lo, lo_strict, hi, hi_strict = bnd
    if math.isnan(x):
        return "NaN where the help gives a range"
    if lo is not None and (x < lo or (lo_strict and x == lo)):
        return "below the help's range (%s %g)" % (
            ">" if lo_strict else ">=", lo)
    if hi is not None and (x > hi or (hi_strict and x == hi)):
        return "above the help's range (%s %g)" % (
            "<" if hi_strict else "<=", hi)
    return ""


# Entries whose default is a word but which take a number too.
NUMBER_OR_AUTO = {"Contact/Complementarity parameter",
                  "Flow/HFV stabilisation"}
SELECTIONS = {"Contact/Bubble placement", "Contact/Friction law",
              "Exact solution/Analytic solution", "Linear solver/Method",
              "Mesh/Cell type", "Mesh/Distortion type", "Mesh/Refinement",
              "Mesh/Source", "Model/Model", "Nonlinear solver/Coupling scheme",
              "Nonlinear solver/Initial guess", "Output/VTU compression"}
VECTOR_EXACT = {"Exact solution/Displacement",
                "Exact solution/Contact traction",
                "Exact solution/Displacement jump"}
SCALAR_EXACT = {"Exact solution/Fracture pressure",
                "Exact solution/Matrix pressure"}


# The variants of the entries whose values have a structure of their own.
FIXED_VARIANTS = {
    "Expressions/Function constants": [
        ('duplicate', 'c=1, c=2'),
        ('conflicting (variable)', 'x=1'),
        ('conflicting (t)', 't=1'),
        ('nan', 'c=nan'),
        ('inf', 'c=1/0'),
        ('malformed', 'c'),
    ],
    "Convergence study/Maximum errors": [
        ('negative', 'err_u: -1'),
        ('unknown column', 'nosuch: 1'),
        ('nan', 'err_u: nan'),
        ('malformed', 'err_u'),
        ('duplicate', 'err_u: 1, err_u: 2'),
        ('not used by this model', 'err_pressure: 1'),
    ],
    "Convergence study/Minimum rates": [
        ('negative', 'err_u: -1'),
        ('unknown column', 'nosuch: 1'),
        ('nan', 'err_u: nan'),
        ('malformed', 'err_u'),
        ('huge', 'err_u: 1e300'),
        ('single level', 'h: 1'),
    ],
    "Boundary conditions/Dirichlet components": [
        ('unknown component', '0: w'),
        ('id that does not exist', '99: x'),
        ('duplicate', '0: x; 0: y'),
        ('repeated component', '0: x, x'),
        ('negative id', '-1: x'),
        ('malformed', '0 x'),
    ],
    "Time/Output times": [
        ('duplicate', '0.1, 0.1'),
        ('decreasing', '0.15, 0.1'),
        ('negative', '-1'),
        ('beyond End time', '1e300'),
        ('zero', '0'),
        ('nan', 'nan'),
    ],
    "Fractures/Segments": [
        ('degenerate', '0, 0 : 0, 0'),
        ('duplicate', '-0.5, 0 : 0.5, 0; -0.5, 0 : 0.5, 0'),
        ('outside the box', '5, 5 : 6, 6'),
        ('nan', 'nan, 0 : 0.5, 0'),
        ('malformed', '-0.5, 0 : 0.5'),
        ('empty', ''),
    ],
    "Fractures/Polygons": [
        ('not used in 2D', '0,0,0 : 1,0,0 : 0,1,0'),
        ('malformed', 'garbage'),
        ('nan', 'nan,0,0 : 1,0,0 : 0,1,0'),
    ],
    "Fractures/Gmsh physical tags": [
        ('not used by this mesh source', '1'),
        ('negative', '-1'),
        ('duplicate', '1, 1'),
        ('malformed', 'a'),
    ],
    "Mesh/Local refinement box": [
        ('inverted', '0.5, 0.5 : -0.5, -0.5'),
        ('outside the box', '5, 5 : 6, 6'),
        ('nan', 'nan, 0 : 0.5, 0.5'),
        ('huge', '-1e300, -1e300 : 1e300, 1e300'),
        ('wrong component count', '0 : 1'),
        ('empty', ''),
    ],
}


def variants(path, default, help_text, work_dir):
    """[(kind, value)] for one entry, at most about 6."""
    name = path.split("/")[-1]
    h = help_text.lower()
    numbers = [("zero", "0"), ("negative", "-1"), ("huge", "1e300"),
               ("huge negative", "-1e300"), ("nan", "nan"), ("inf", "inf"),
               ("empty", "")]
    if path == "Dimension":
        return []
    if default in ("true", "false"):
        return [("unknown word", "maybe"), ("empty", ""),
                ("other value", "false" if default == "true" else "true")]
    if path in NUMBER_OR_AUTO:
        return [("unknown word", "autox"), ("zero", "0"), ("negative", "-1"),
                ("huge", "1e300"), ("nan", "nan"), ("empty", "")]
    if path in SELECTIONS:
        return [("unknown word", "frobnicate"), ("empty", "")]
    if path == "Mesh/File name":
        return [("missing file", os.path.join(work_dir, "missing.msh")),
                ("directory", work_dir),
                ("not a mesh", os.path.join(work_dir, "not_a_mesh.msh"))]
    if path == "Output/Output directory":
        return [("empty", ""),
                ("a file", os.path.join(work_dir, "not_a_mesh.msh")),
                ("unwritable", "/proc/polyfrac-out")]
    if path in FIXED_VARIANTS:
        return FIXED_VARIANTS[path]
    if "boundary ids" in name.lower():
        return [("duplicate", "0, 0"), ("id that does not exist", "99"),
                ("negative", "-1"), ("conflicting", "0"),
                ("malformed", "a"), ("all ids", "0, 1, 2, 3")]
    # Expressions.
    is_expr = (path in VECTOR_EXACT or path in SCALAR_EXACT
               or "expression" in h or ";" in default
               or path == "Initial stress/Stress")
    if is_expr:
        vector = ";" in default or path in VECTOR_EXACT
        if path == "Initial stress/Stress":
            return [("inf", "1/0"), ("nan", "nan"),
                    ("time-dependent huge", "t*1e300"),
                    ("non-constant", "x; 0; 0; x"),
                    ("wrong component count", "1; 0"),
                    ("not symmetric", "0; 1; 2; 0")]
        if vector:
            return [("inf", "1/0; 0"), ("nan", "nan; 0"),
                    ("time-dependent huge", "t*1e300; 0"),
                    ("non-constant", "x; y"),
                    ("wrong component count", "0"),
                    ("wrong component count", "0; 0; 0")]
        out = [("inf", "1/0"), ("nan", "nan"),
               ("time-dependent huge", "t*1e300"), ("non-constant", "x")]
        if bounds(help_text, path) is not None:
            out.append(("negative", "-1"))
            out.append(("zero", "0"))
        else:
            out.append(("wrong component count", "0; 0"))
            out.append(("huge", "1e300"))
        return out[:6]
    parts = [p.strip() for p in default.split(",")]
    if len(parts) > 1 and all(is_number(p) for p in parts):
        n = len(parts)
        out = [("zero", ", ".join(["0"] * n)),
               ("negative", ", ".join(["-1"] * n)),
               ("huge", ", ".join(["1e300"] * n)),
               ("nan", ", ".join(["nan"] * n)),
               ("wrong component count", parts[0])]
        if name == "Lower left corner":
            out.append(("inconsistent (= Upper right corner)", "1, 1"))
        elif name == "Upper right corner":
            out.append(("inconsistent (< Lower left corner)", "-2, -2"))
        else:
            out.append(("wrong component count",
                        ", ".join(parts + [parts[0]])))
        return out
    if is_number(default):
        integer = (re.fullmatch(r"-?[0-9]+", default) is not None
                   and name in INTEGERS)
        out = [("zero", "0"), ("negative", "-1")]
        if integer:
            out += [("huge", "2147483648"), ("huge", "1e300"),
                    ("nan", "nan"), ("empty", "")]
        else:
            out += [("huge", "1e300"), ("huge negative", "-1e300"),
                    ("nan", "nan"), ("inf", "inf")]
        return out
    if default == "":
        return [("malformed", "a"), ("nan", "nan")]
    return [("unknown word", "frobnicate"), ("empty", "")]


# --------------------------------------------------------------------------
# The base scenes.

def base_scene(model, out_dir):
    lines = ["set Dimension = 2",
             "subsection Model", "  set Model = %s" % model, "end",
             "subsection Mesh", "  set Subdivisions = 4, 4", "end"]
    if model != "elasticity":
        lines += ["subsection Fractures",
                  "  set Segments = -0.5, 0 : 0.5, 0", "end"]
    if model in ("elasticity", "contact mechanics", "poromechanics"):
        lines += ["subsection Boundary conditions",
                  "  set Dirichlet boundary ids = 0, 1, 2, 3", "end"]
    if model in ("flow", "poromechanics"):
        lines += ["subsection Time", "  set End time = 0.2",
                  "  set Time step = 0.1", "end",
                  "subsection Flow", "  set Fracture source = 1e-6", "end"]
    if model == "flow":
        lines += ["subsection Flow", "  set Pressure boundary ids = 0, 1",
                  "end"]
    if model == "elasticity":
        lines += ["subsection Body force",
                  "  set Function expression = 1; 0", "end"]
    if model == "contact mechanics":
        lines += ["subsection Boundary conditions",
                  "  set Dirichlet expression = 0; y > 0 ? -0.01 : 0.01",
                  "end"]
    lines += ["subsection Output",
              "  set Output directory = %s" % out_dir,
              "  set Write VTU = true", "  set Print timings = false", "end"]
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# One run.

NAN_RE = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf|infinity)(?![A-Za-z_])",
                    re.IGNORECASE)


def scan_nan(out_dir, printed, value):
    """Where nan/inf appears in the csv files or the printed output, or ''."""
    for root, _, files in os.walk(out_dir):
        for f in sorted(files):
            if f.endswith(".csv"):
                try:
                    with open(os.path.join(root, f), errors="replace") as fh:
                        for line in fh:
                            if NAN_RE.search(line):
                                return "%s: %s" % (f, line.strip()[:150])
                except OSError:
                    pass
    for line in printed.splitlines():
        if value and value in line:
            continue  # the input echoed back
        if "--set" in line or line.startswith("Warning:"):
            continue
        if NAN_RE.search(line):
            return line.strip()[:200]
    return ""


def run_one(polyfrac, env, prm, out_dir, path, value, timeout, ranks=1):
    """Runs polyfrac (under mpirun on @p ranks > 1 ranks); on the timeout
    its whole process group (mpirun and every rank) is killed."""
    if os.path.isdir(out_dir):
        shutil.rmtree(out_dir, ignore_errors=True)
    launcher = [] if ranks == 1 else ["mpirun", "-np", str(ranks),
                                      "--oversubscribe"]
    args = launcher + [polyfrac, prm, "--set",
                       "Output/Output directory=%s" % out_dir]
    if path is not None:
        args += ["--set", "%s=%s" % (path, value)]
    t0 = time.time()
    p = subprocess.Popen(args, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, universal_newlines=True,
                         errors="replace", start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        # mpirun passes SIGTERM on to its ranks (which may have left its
        # process group); what is left of the group is then killed.
        p.terminate()
        try:
            out, err = p.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            out, err = p.communicate()
        rc = None
    seconds = time.time() - t0
    return rc, out, err, seconds


def classify(rc, out, err, entry_path, value, out_dir):
    text = out + "\n" + err
    lines = [l for l in text.splitlines() if l.strip()]
    name = entry_path.split("/")[-1] if entry_path else ""

    def names(msg_lines):
        t = "\n".join(msg_lines).lower()
        return bool(name) and (name.lower() in t)

    if rc is None:
        return "hang", "", (lines[-1] if lines else "")
    for c in CRASH_TEXTS:
        for i, l in enumerate(lines):
            if c in l:
                msg = l.strip()
                # deal.II's assertion: add the violated condition/details.
                for j in range(i + 1, min(i + 12, len(lines))):
                    if lines[j].strip().startswith(("The violated condition",
                                                    "Additional information")):
                        if j + 1 < len(lines):
                            msg += " / " + lines[j].strip() + " " + \
                                lines[j + 1].strip()
                        break
                stopped = [x for x in lines
                           if x.startswith("PolyFrac stopped:")]
                if stopped:
                    msg += " / exit %s after: %s" % (rc, stopped[0].strip())
                return "crash", "yes" if names(lines[i:]) else "no", msg
    if rc < 0 or (rc >= 128 and rc not in (130, 143)):
        return "crash", "", ("signal %d; " % -rc if rc < 0 else "") + (
            err.strip().splitlines()[-1] if err.strip() else "")
    if rc != 0:
        stopped = [i for i, l in enumerate(lines)
                   if l.startswith("PolyFrac stopped:")]
        if stopped:
            msg = lines[stopped[0]:]
        else:
            msg = err.strip().splitlines() or lines[-3:]
        return "refused", "yes" if names(msg) else "no", \
            (msg[0].strip() if msg else "")
    nan = scan_nan(out_dir, out + "\n" + err, value)
    if nan:
        return "ran, NaN/inf in output", "", nan
    warns = [l for l in lines if l.startswith("Warning:")]
    if warns:
        return "warned", "yes" if names(warns) else "no", warns[0].strip()
    return "ran", "", ""


# --------------------------------------------------------------------------
# The summary.

def summary(csv_path, entries_help):
    rows = list(csv.DictReader(open(csv_path, newline="")))
    outcomes = ["refused", "warned", "ran", "ran, NaN/inf in output",
                "crash", "hang"]
    models = [m for m in MODELS if any(r["model"] == m for r in rows)]
    p = print
    p("## Entry sweep: %d runs" % len(rows))
    p("")
    p("| model | runs | " + " | ".join(outcomes) +
      " | refused, entry not named | seconds |")
    p("|---|---:|" + "---:|" * (len(outcomes) + 2))
    for m in models:
        rs = [r for r in rows if r["model"] == m]
        counts = [sum(1 for r in rs if r["outcome"] == o) for o in outcomes]
        unnamed = sum(1 for r in rs if r["outcome"] == "refused"
                      and r["names_entry"] == "no")
        secs = sum(float(r["seconds"]) for r in rs)
        p("| %s | %d | %s | %d | %.0f |" % (
            m, len(rs), " | ".join(str(c) for c in counts), unnamed, secs))
    p("")

    def table(title, sel, cols=("model", "entry", "value", "exit_status",
                                "message")):
        p("### %s (%d)" % (title, len(sel)))
        p("")
        if not sel:
            p("none")
            p("")
            return
        p("| " + " | ".join(cols) + " |")
        p("|" + "---|" * len(cols))
        for r in sel:
            p("| " + " | ".join("`%s`" % r[c].replace("|", "\\|")
                                if c in ("value",) else
                                r[c].replace("|", "\\|")[:220]
                                for c in cols) + " |")
        p("")

    table("Crashes", [r for r in rows if r["outcome"] == "crash"])
    table("Hangs (timeout)", [r for r in rows if r["outcome"] == "hang"])
    table("Ran with NaN/inf in the output",
          [r for r in rows if r["outcome"] == "ran, NaN/inf in output"])
    table("Ran (or only warned) with a value outside the help text's range",
          [r for r in rows if r["outcome"] in ("ran", "warned")
           and r["out_of_range"]],
          cols=("model", "entry", "value", "outcome", "out_of_range",
                "message"))
    silent_kinds = ("inf", "nan", "malformed", "inverted", "outside the box",
                    "duplicate", "missing file", "directory", "not a mesh",
                    "id that does not exist", "negative id", "unknown word",
                    "unknown component", "repeated component", "conflicting",
                    "conflicting (variable)", "conflicting (t)",
                    "time-dependent huge", "huge", "huge negative",
                    "decreasing", "beyond End time", "not symmetric",
                    "wrong component count")
    table("Ran without any warning with a non-finite, huge, malformed, "
          "duplicate or conflicting value (accepted silently; often an "
          "entry the scene does not use)",
          [r for r in rows if r["outcome"] == "ran"
           and r["kind"] in silent_kinds and not r["out_of_range"]],
          cols=("model", "entry", "value", "kind"))
    table("Refused at run time by a solver failure or an internal check, "
          "not by an input check (message says failed / did not converge / "
          "a bug)",
          [r for r in rows if r["outcome"] == "refused"
           and re.search(r"failed|did not converge|is a bug", r["message"])],
          cols=("model", "entry", "value", "kind", "message"))
    table("Refusals whose message does not name the entry",
          [r for r in rows if r["outcome"] == "refused"
           and r["names_entry"] == "no"])


# --------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("polyfrac")
    ap.add_argument("work_dir")
    ap.add_argument("--models", nargs="+", default=MODELS,
                    help="model names (quote the ones with a space)")
    ap.add_argument("--timeout", type=float, default=20)
    ap.add_argument("--ranks", type=int, default=1,
                    help="run every scene under mpirun on this many ranks")
    ap.add_argument("--summary-only", action="store_true")
    ap.add_argument("--entries", nargs="+", default=None,
                    help="only these entries (Section/Entry)")
    a = ap.parse_args()
    polyfrac = os.path.abspath(a.polyfrac)
    work = os.path.abspath(a.work_dir)
    os.makedirs(work, exist_ok=True)
    csv_path = os.path.join(work, "entry_sweep.csv")
    env = dict(os.environ)
    if a.ranks > 1:
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    if a.summary_only:
        summary(csv_path, None)
        return 0
    for m in a.models:
        if m not in MODELS:
            sys.exit("unknown model <%s>; one of %s" % (m, MODELS))

    entries = read_entries(polyfrac, env)
    if a.entries:
        entries = [e for e in entries if e[0] in a.entries]
    with open(os.path.join(work, "not_a_mesh.msh"), "w") as f:
        f.write("this is not a mesh\n")
    logs = os.path.join(work, "logs")
    os.makedirs(logs, exist_ok=True)

    new = not os.path.exists(csv_path)
    fh = open(csv_path, "a", newline="")
    w = csv.DictWriter(fh, fieldnames=FIELDS)
    if new:
        w.writeheader()
    t_start = time.time()
    n = 0
    for model in a.models:
        tag = model.replace(" ", "_")
        prm = os.path.join(work, "base-%s.prm" % tag)
        out_dir = os.path.join(work, "run-%s" % tag)
        with open(prm, "w") as f:
            f.write(base_scene(model, out_dir))
        rc, out, err, sec = run_one(polyfrac, env, prm, out_dir, None, "",
                                    a.timeout, a.ranks)
        outcome = classify(rc, out, err, "", "", out_dir)[0]
        print("base scene %s: exit %s, %s, %.1f s" % (model, rc, outcome,
                                                       sec), file=sys.stderr)
        if rc != 0 or outcome != "ran":
            print(out + err, file=sys.stderr)
            sys.exit("the base scene of %s does not run cleanly" % model)
        for path, default, help_text in entries:
            bnd = bounds(help_text, path)
            for kind, value in variants(path, default, help_text, work):
                rc, out, err, sec = run_one(polyfrac, env, prm, out_dir, path,
                                            value, a.timeout, a.ranks)
                outcome, named, msg = classify(rc, out, err, path, value,
                                               out_dir)
                n += 1
                log = os.path.join(logs, "%s-%04d.txt" % (tag, n))
                with open(log, "w") as lf:
                    lf.write("--set %s=%s\nexit %s\n--- stdout\n%s\n--- "
                             "stderr\n%s\n" % (path, value, rc, out, err))
                w.writerow(dict(model=model, entry=path, value=value,
                                kind=kind, outcome=outcome,
                                names_entry=named,
                                exit_status="timeout" if rc is None else rc,
                                message=msg, seconds="%.2f" % sec,
                                out_of_range=out_of_range(value, bnd)))
                fh.flush()
                print("%s | %s = %r: %s %s" % (model, path, value, outcome,
                                               msg[:100]), file=sys.stderr)
        shutil.rmtree(out_dir, ignore_errors=True)
    fh.close()
    print("%d runs in %.0f s" % (n, time.time() - t_start), file=sys.stderr)
    summary(csv_path, None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
