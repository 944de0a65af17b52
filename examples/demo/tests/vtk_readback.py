#!/usr/bin/env python3
"""Reads a scene's VTK output back with a real VTK reader and asserts it.

    vtk_readback.py DEMO SCENE OUT_DIR

Runs DEMO (b2b_demo) on SCENE into OUT_DIR, then reads OUT_DIR/<scene>.pvd
(the collection) and every .vtp it lists with vtkXMLPolyDataReader (VTK's
Python module, e.g. Debian's python3-vtk9) and asserts, for every step:

  * the collection lists steps 0, every vtk_every-th and the last, with increasing
    load factors ending at 1, the same as the history CSV;
  * points = the scene's nodes (counted from its &beam groups) plus one per
    active contact of that step (history CSV), lines = beams, verts = contacts;
  * point arrays radius (1 component), displacement, rotation, normal_force,
    friction_force (3 each), cell arrays beam and group;
  * radius > 0 on the beam nodes; displacement = point - its step-0 position;
    normal_force and friction_force zero on the beam nodes, and on the contact
    vertices their magnitudes add up to the history's normal_force and
    friction_force sums of that step (relative 1e-9).

Exit codes: 0 passed, 1 failed, 77 skipped (no VTK Python module: ctest's
SKIP_RETURN_CODE, so the test shows as skipped, never as passed).
"""
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SKIP = 77

try:
    import vtk  # noqa: F401
except ImportError:
    # Debian's python3-vtk9 lives in /usr/lib/python3/dist-packages, seen
    # only by the system interpreter: try it once if we are another one.
    system = "/usr/bin/python3"
    if (os.path.exists(system) and os.path.realpath(sys.executable) != os.path.realpath(system)
            and not os.environ.get("B2B_VTK_READBACK_REEXEC")):
        os.environ["B2B_VTK_READBACK_REEXEC"] = "1"
        os.execv(system, [system] + sys.argv)
    print("SKIPPED: no VTK Python module (import vtk failed); install python3-vtk9 or use pvpython")
    sys.exit(SKIP)

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

failures = []


def check(cond, msg):
    if not cond:
        failures.append(msg)
        print("FAIL: " + msg)


def scene_counts(path):
    """Nodes and beams of a scene from its &beam groups; n_steps of &scene."""
    text = "\n".join(line.split("!", 1)[0] for line in open(path))
    nodes = beams = 0
    for group in re.findall(r"&beam\b(.*?)/", text, flags=re.S | re.I):
        shape = re.search(r"shape\s*=\s*'(\w+)'", group, flags=re.I).group(1).lower()
        n_el = int(re.search(r"n_el\s*=\s*(\d+)", group, flags=re.I).group(1))
        nodes += n_el if shape == "ring" else n_el + 1
        beams += 1
    n_steps = int(re.search(r"&scene\b.*?n_steps\s*=\s*(\d+)", text, flags=re.S | re.I).group(1))
    every = re.search(r"&output\b[^/]*?vtk_every\s*=\s*(\d+)", text, flags=re.S | re.I)
    return nodes, beams, n_steps, int(every.group(1)) if every else 1


def history(path):
    rows = [line.strip().split(",") for line in open(path) if line.strip()]
    head = rows[0]
    return [{k: float(v) for k, v in zip(head, r)} for r in rows[1:]]


def array(pd, name, comps):
    a = pd.GetArray(name)
    check(a is not None, f"array {name} missing")
    if a is None:
        return None
    check(a.GetNumberOfComponents() == comps, f"array {name}: {a.GetNumberOfComponents()} components, want {comps}")
    return a


def main():
    demo, scene, out = sys.argv[1:4]
    name = os.path.splitext(os.path.basename(scene))[0]
    os.makedirs(out, exist_ok=True)
    run = subprocess.run([demo, scene, out], capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout[-3000:], run.stderr[-3000:])
        print(f"FAIL: b2b_demo exited with {run.returncode}")
        return 1
    n_nodes, n_beams, n_steps, every = scene_counts(scene)
    hist = history(os.path.join(out, name + "_history.csv"))
    check(len(hist) == n_steps, f"history has {len(hist)} steps, scene {n_steps}")

    sets = ET.parse(os.path.join(out, name + ".pvd")).getroot().findall("./Collection/DataSet")
    want_steps = [0] + [k for k in range(1, n_steps + 1) if k % every == 0 or k == n_steps]
    steps = [int(re.search(r"_(\d+)\.vtp$", s.get("file")).group(1)) for s in sets]
    check(steps == want_steps, f"collection lists steps {steps}, want {want_steps} (vtk_every = {every})")
    times = [float(s.get("timestep")) for s in sets]
    check(all(b > a for a, b in zip(times, times[1:])), "load factors in the collection do not increase")
    check(abs(times[-1] - 1.0) < 1e-12, f"last load factor {times[-1]}")

    x0 = None
    n_contacts_seen = n_friction_seen = 0
    for step, ds in zip(steps, sets):
        r = vtkXMLPolyDataReader()
        r.SetFileName(os.path.join(out, ds.get("file")))
        r.Update()
        poly = r.GetOutput()
        where = f"{ds.get('file')}"
        want_c = 0 if step == 0 else int(hist[step - 1]["contacts"])
        if step > 0:
            check(abs(float(ds.get("timestep")) - hist[step - 1]["load_factor"]) < 1e-12,
                  f"{where}: load factor off the history")
        check(poly.GetNumberOfPoints() == n_nodes + want_c,
              f"{where}: {poly.GetNumberOfPoints()} points, want {n_nodes} nodes + {want_c} contacts")
        check(poly.GetNumberOfLines() == n_beams, f"{where}: {poly.GetNumberOfLines()} lines, want {n_beams}")
        check(poly.GetNumberOfVerts() == want_c, f"{where}: {poly.GetNumberOfVerts()} verts, want {want_c}")
        pd, cd = poly.GetPointData(), poly.GetCellData()
        rad = array(pd, "radius", 1)
        disp = array(pd, "displacement", 3)
        array(pd, "rotation", 3)
        fn = array(pd, "normal_force", 3)
        ft = array(pd, "friction_force", 3)
        array(cd, "beam", 1)
        array(cd, "group", 1)
        if failures:
            break
        pts = [poly.GetPoint(i) for i in range(n_nodes)]
        if x0 is None:
            x0 = pts
        for i in range(n_nodes):
            check(rad.GetValue(i) > 0, f"{where}: radius {rad.GetValue(i)} at node {i}")
            d = disp.GetTuple3(i)
            check(all(abs(d[k] - (pts[i][k] - x0[i][k])) <= 1e-9 * (1 + abs(pts[i][k])) for k in range(3)),
                  f"{where}: displacement at node {i} is not point - initial point")
            check(fn.GetTuple3(i) == (0.0, 0.0, 0.0) and ft.GetTuple3(i) == (0.0, 0.0, 0.0),
                  f"{where}: contact force on beam node {i}")
        sn = sum(math.hypot(*fn.GetTuple3(n_nodes + k)) for k in range(want_c))
        st = sum(math.hypot(*ft.GetTuple3(n_nodes + k)) for k in range(want_c))
        if step > 0:
            hn, ht = hist[step - 1]["normal_force"], hist[step - 1]["friction_force"]
            check(abs(sn - hn) <= 1e-9 * max(hn, 1e-300) + 1e-300, f"{where}: sum |normal_force| {sn} vs history {hn}")
            check(abs(st - ht) <= 1e-9 * max(ht, 1e-300) + 1e-300, f"{where}: sum |friction_force| {st} vs history {ht}")
        n_contacts_seen += want_c
        n_friction_seen += st > 0
        if len(failures) > 20:
            break
    print(f"{name}: {len(sets)} files read with VTK {vtk.vtkVersion.GetVTKVersion()}: {n_nodes} nodes, "
          f"{n_beams} beams, {n_contacts_seen} contact vertices in all, {n_friction_seen} steps with friction force")
    print("vtk read-back: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
