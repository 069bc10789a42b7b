#!/usr/bin/python3
"""The monolithic Newton of poromechanics solved by FGMRES with the
fixed-stress block preconditioner (Linear solver/Method = AMG,
doc/scheme.md §10): prm/poromechanics-2d-slip.prm (tight rock, k = 1e-17,
where the fixed-stress diagonal b^2/K_dr outweighs the storage and the
fluxes) on three uniformly refined levels, three steps each. Per level the
FGMRES iterations per Newton iteration of the coupled steps (the step
lines' counts; step 0, the equilibrium with held pressures, left out):

- at most 15 on every level (measured 5.6, 11.8, 12.5; without the
  fixed-stress diagonal, M alone for the Schur complement: 5.5, 17.4,
  18.7);
- at most 1.5 times the previous level's from level 1 to 2 (about
  independent of the mesh; level 0's 16 fracture faces are a coarser
  problem than the others').

usage: fixed_stress_preconditioner.py POLYFRAC SOURCE_DIR WORK_DIR
Exits non-zero on the first failed check.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                os.pardir, "io"))
from scene_summary import run_scene  # noqa: E402

program, source, work = sys.argv[1:4]
_, output = run_scene(program, source, work, "slip",
                      "poromechanics-2d-slip.prm",
                      "Nonlinear solver/Coupling scheme=monolithic",
                      "Linear solver/Method=AMG",
                      "Convergence study/Number of refinement levels=3",
                      "Time/End time=3", "Output/Write VTU=false",
                      "Output/Print timings=false")
per_level = []
for block in re.split(r"^Level \d+:", output, flags=re.M)[1:]:
    steps = re.findall(r"^Step to t = .*?(\d+) FGMRES iterations?\), "
                       r"(\d+) Newton iterations?", block, flags=re.M)
    if len(steps) != 3:
        sys.exit(f"fixed_stress_preconditioner: {len(steps)} coupled steps "
                 "with FGMRES counts on a level, expected 3:\n" + output)
    krylov = sum(int(k) for k, _ in steps)
    newton = sum(int(n) for _, n in steps)
    per_level.append(krylov / newton)
    print(f"level {len(per_level) - 1}: {krylov} FGMRES iterations in "
          f"{newton} Newton iterations ({per_level[-1]:.1f} each)")
if len(per_level) != 3:
    sys.exit(f"fixed_stress_preconditioner: {len(per_level)} levels, "
             "expected 3")
if max(per_level) > 15:
    sys.exit("fixed_stress_preconditioner: more than 15 FGMRES iterations "
             "per Newton iteration")
if per_level[2] > 1.5 * per_level[1]:
    sys.exit("fixed_stress_preconditioner: the iterations per Newton "
             "iteration grow by more than 1.5 from level 1 to level 2")
print("fixed_stress_preconditioner: all checks passed")
