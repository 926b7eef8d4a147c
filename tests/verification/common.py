"""Helpers for the verification tests: run nitsche-contact on a parameter
text and return the parsed summary.json. Each test script asserts numbers
against an independent source and exits non-zero on failure."""
import argparse
import json
import shutil
import os
import re
import subprocess
import sys


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("--exe", required=True)
    p.add_argument("--mpiexec", default="mpiexec")
    p.add_argument("--workdir", required=True)
    args = p.parse_args()
    global _exe
    _exe = args.exe
    return args


# the executable of the run, for the parameter listing set_entries() reads
_exe = None
_entry_paths = None


def parameter_entries(text):
    """The (subsections + [entry], value) of each 'set' line of a parameter
    text, in order ('#' starts a comment)."""
    found, stack = [], []
    for line in text.splitlines():
        line = line.split("#")[0].strip()
        if line.startswith("subsection "):
            stack.append(line[len("subsection "):].strip())
        elif line == "end":
            stack.pop()
        elif line.startswith("set ") and "=" in line:
            entry, value = line[4:].split("=", 1)
            found.append((stack + [entry.strip()], value.strip()))
    return found


_models = None


def registered_models():
    """The (name, description) of every model, as `nitsche-contact --help`
    lists them, and the default model (of 'set Model' in the listing)."""
    global _models
    if _models is not None:
        return _models
    help_text = subprocess.run([_exe, "--help"], check=True,
                               stdout=subprocess.PIPE, text=True).stdout
    block = help_text.split("Models:\n", 1)[1].split("\n\n", 1)[0]
    models = [tuple(line.strip().split(None, 1)) for line in block.splitlines()]
    listing = subprocess.run([_exe, "--print-parameters"], check=True,
                             stdout=subprocess.PIPE, text=True).stdout
    default = re.search(r"(?m)^set Model\s*=\s*(\w+)", listing).group(1)
    _models = (models, default)
    return _models


def entry_subsections(entry, text):
    """The subsections of `entry` in nitsche-contact's parameter listing. An
    entry name found only in the models' own subsections (e.g. 'Contact
    quadrature rule') is taken from the subsection of the model that `text`
    sets last; any other name found in several subsections (e.g. 'Type') is
    an error: set it in the text itself."""
    global _entry_paths
    if _entry_paths is None:
        listing = subprocess.run([_exe, "--print-parameters"], check=True,
                                 stdout=subprocess.PIPE, text=True).stdout
        _entry_paths = [path for path, _ in parameter_entries(listing)]
    found = [p[:-1] for p in _entry_paths if p[-1] == entry]
    names, default = registered_models()
    # a model's own subsection is its name, capitalised
    sections = [name.capitalize() for name, _ in names]
    if len(found) > 1 and all(p and p[0] in sections for p in found):
        m = re.findall(r"(?m)^\s*set Model\s*=\s*(\w+)", text)
        model = (m[-1] if m else default).capitalize()
        found = [p for p in found if p[0] == model]
    if len(found) != 1:
        fail("entry '%s': %d subsections in the parameter listing" % (entry, len(found)))
    return found[0]


def set_entries(text, entries, name):
    """Set each (entry, value) of entries in the parameter text: replace
    its 'set' line (a name's line in any subsection), or, for an entry the
    text leaves at its default, append it in its subsection. An entry set more than once fails a check named
    after `name`."""
    for entry, value in entries:
        text, n = re.subn(r"(?m)^(\s*set %s\s*=).*$" % re.escape(entry),
                          lambda m: m.group(1) + " " + value, text)
        if n == 0:
            path = entry_subsections(entry, text)
            text += ("\n" + "".join("subsection %s\n" % s for s in path) +
                     "  set %s = %s\n" % (entry, value) + "end\n" * len(path))
        check(n <= 1, "%s: at most one entry '%s'" % (name, entry))
    return text


# The discrete problem most tests check: the rigid obstacle, Gauss contact
# points, gamma0 = 20, the nested start and the paper's contact stress of
# the Mindlin plate (the program's defaults choose the obstacle compliance,
# the nodes as contact points, the plate predictor for speed and the
# Mindlin plate's equilibrium stress 'gsv' for accuracy).
PINNED = """subsection Contact
  set Obstacle compliance = 0
  set Nitsche gamma0 = 20
end
subsection Elasticity
  set Contact quadrature rule = gauss
  set Plate predictor = false
end
subsection Mindlin
  set Contact quadrature rule = gauss
  set Contact formulation = nitsche
end
"""


# The Mindlin plate's equilibrium contact stress with its own gamma0, for
# tests whose text (or PINNED) sets the paper's form: appended, it wins.
MINDLIN_GSV = """
subsection Mindlin
  set Contact formulation = gsv
end
subsection Contact
  set Nitsche gamma0 = auto
end
"""


def run(args, name, prm_text, np=1, expect_status=0, output_format="none", pinned=True):
    """Write <workdir>/<name>.prm (with Output/Directory set to <name>),
    run the program, and return (summary dict or None, stdout+stderr).
    expect_status: the exit status required, or a list of allowed ones;
    output_format: Output/Format (no graphical output by default);
    pinned: True: the file starts with PINNED, so that the tests check
    that discrete problem unless their text sets an entry of it (a later
    'set' wins); "rigid": only the rigid obstacle, the program's defaults
    otherwise; False: the program's defaults."""
    os.makedirs(args.workdir, exist_ok=True)
    outdir = os.path.join(args.workdir, name)
    # no files of an earlier run may pass for this run's output
    shutil.rmtree(outdir, ignore_errors=True)
    prm_file = os.path.join(args.workdir, name + ".prm")
    with open(prm_file, "w") as f:
        if pinned == "rigid":
            f.write("subsection Contact\n  set Obstacle compliance = 0\nend\n")
        elif pinned:
            f.write(PINNED)
        f.write(prm_text)
        f.write("\nsubsection Output\n  set Directory = %s\n  set Format = %s\nend\n"
                % (outdir, output_format))
    cmd = [args.exe, prm_file]
    if np > 1:
        cmd = [args.mpiexec or "mpiexec", "-np", str(np)] + cmd
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, cwd=args.workdir)
    allowed = expect_status if isinstance(expect_status, (list, tuple)) else [expect_status]
    if proc.returncode not in allowed:
        print(proc.stdout)
        fail("%s: exit status %d, expected %s" % (name, proc.returncode, expect_status))
    summary = None
    path = os.path.join(outdir, "summary.json")
    if os.path.exists(path):
        with open(path) as f:
            summary = json.load(f)
    return summary, proc.stdout


def read_vtu(path):
    """{name: (list of values, components)} of a VTU file as deal.II writes
    it: ASCII, or each DataArray inline as base64(header) + base64(zlib
    blocks), the header being the uint32s (blocks, block size, last size,
    compressed sizes...). Plain Python (the tests do not need numpy)."""
    import base64, struct, zlib
    import xml.etree.ElementTree as ET
    types = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
             "UInt8": "B", "UInt32": "I"}
    arrays = {}
    for d in ET.parse(path).getroot().iter("DataArray"):
        name = d.get("Name") or "Points"
        text = (d.text or "").strip()
        if not text:  # a rank without cells writes empty arrays
            values = []
        elif d.get("format") == "ascii":
            values = [float(v) for v in text.split()]
        else:
            blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
            n_header = 3 + blocks
            chars = 4 * ((4 * n_header + 2) // 3)
            header = struct.unpack("<%dI" % n_header, base64.b64decode(text[:chars]))
            data, raw, pos = base64.b64decode(text[chars:]), b"", 0
            for size in header[3:]:
                raw += zlib.decompress(data[pos:pos + size])
                pos += size
            code = types[d.get("type")]
            values = list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code), code), raw))
        arrays[name] = (values, int(d.get("NumberOfComponents", "1")))
    return arrays


def integrate_patch_field(arrays, name):
    """Integral over the x-y projection of a VTU made of quadrilaterals
    (a plate, or the bottom faces of the 3D model) of a field that is
    constant on every quadrilateral (cell data, which deal.II writes as
    point values), and the projected area."""
    points, dim = arrays["Points"]
    connectivity = arrays["connectivity"][0]
    field = arrays[name][0]
    total = area = 0.
    for k in range(0, len(connectivity), 4):
        q = connectivity[k:k + 4]
        x = [points[dim * i] for i in q]
        y = [points[dim * i + 1] for i in q]
        a = 0.5 * abs((x[0] - x[2]) * (y[1] - y[3]) - (x[1] - x[3]) * (y[0] - y[2]))
        total += a * field[q[0]]
        area += a
    return total, area


def first_corrections(log):
    """|dU|_a/|U|_a of the first Newton iteration of every cycle in a log
    with 'Print iterations = true' (a start from U = 0 gives 1: the first
    iterate is the correction itself)."""
    firsts = []
    for block in re.split(r"(?m)^Cycle \d+:", log)[1:]:
        m = re.search(r"iteration +1: .*?\|dU\|_a/\|U\|_a ([0-9.e+-]+)", block)
        firsts.append(float(m.group(1)) if m else float("nan"))
    return firsts


def shipped_prm(name, replacements, extra=""):
    """The text of parameters/<name> (or of the file at the absolute path
    name) with each (entry, value) of replacements set (set_entries()),
    followed by extra."""
    here = os.path.dirname(os.path.abspath(__file__))
    path = name if os.path.isabs(name) else os.path.join(here, "..", "..", "parameters", name)
    return set_entries(open(path).read(), replacements, name) + extra


# The elastic block of verification/elasticity_friction pressed onto a plane
# by a top traction q, sheared by a tangential top traction s, held
# tangentially only by Coulomb friction F (x-faces free).
SLIDING_BLOCK = """
set Model = elasticity
subsection Geometry
  set Length x = 2
  set Length y = 1
  set Thickness = 0.2
  set Boundary conditions = 0: free; 1: free; 2: symmetry; 3: symmetry
  set Subdivisions = %(sub)s
end
subsection Material
  set Young's modulus = 100
  set Poisson ratio = 0.3
end
subsection Load
  set Transverse load = %(q)r
end
subsection Obstacle
  set Type = plane
  set Level = -0.1
end
subsection Contact
  set Nitsche theta = %(theta)d
  set Nitsche gamma0 = 20
  set Friction coefficient = %(F)r
end
subsection Elasticity
  set Polynomial degree = %(degree)d
  set Load applied as = top traction
  set Top tangential traction = %(s)r; 0
end
subsection Nonlinear solver
  set Scheme = %(scheme)s
  set Tolerance = 1e-11
  set Maximum iterations = %(maxit)d
end
subsection Output
  set Probe points = 1, 0.5
end
"""


def sliding_block_prm(sub, q, theta, F, degree, s, scheme="newton", maxit=60):
    return SLIDING_BLOCK % dict(sub=sub, q=q, theta=theta, F=F, degree=degree,
                                s=s, scheme=scheme, maxit=maxit)


failures = []


def check(condition, message):
    print(("ok    " if condition else "FAIL  ") + message)
    if not condition:
        failures.append(message)


def fail(message):
    print("FAIL  " + message)
    sys.exit(1)


def close(value, reference, rel_tol, what):
    err = abs(value - reference) / max(abs(reference), 1e-300)
    check(err <= rel_tol, "%s: %.10g vs %.10g (rel. error %.2e <= %.1e)"
          % (what, value, reference, err, rel_tol))


def compare_cycle(what, ref, new, rtol, names):
    """Two converged runs of the same problem by two methods (names = their
    labels): both converged, active points within 0.5 % of each other
    (points at s_n = 0 within round-off may end on either side), contact
    force and probe deflections within rtol (relative)."""
    check(ref["converged"] and new["converged"], what + ": both converged")
    na, nb = ref["active_points"], new["active_points"]
    check(na > 0 and abs(na - nb) <= 0.005 * na,
          what + ": active points %d (%s), %d (%s)" % (na, names[0], nb, names[1]))
    close(new["contact_force"], ref["contact_force"], rtol,
          what + ": contact force %s vs %s" % (names[1], names[0]))
    for k, (wr, wn) in enumerate(zip(ref["probes"], new["probes"])):
        close(wn, wr, rtol, what + ": probe %d %s vs %s" % (k, names[1], names[0]))


def finish():
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


def write_msh(path, lx, ly, nx, ny, removed, position=None, material=None):
    """Gmsh 2.2 (or UCD for a .ucd path, Abaqus for a .inp path): the cells of the nx x ny grid of [0,lx] x [0,ly] whose
    centre is not in removed(x, y), and the boundary edges with the
    built-in shapes' ids (physical tags) 0..3 on x = 0, lx, y = 0, ly and
    4 elsewhere; position(x, y), if given, moves the grid's nodes; in Gmsh
    the cells' physical tag (material id) is material(x, y) of their centre,
    7 if not given."""
    moved = position or (lambda x, y: (x, y))
    node = lambda i, j: j * (nx + 1) + i + 1
    cells = [(i, j) for j in range(ny) for i in range(nx)
             if not removed((i + 0.5) * lx / nx, (j + 0.5) * ly / ny)]
    edges, side = {}, {}
    for c, (i, j) in enumerate(cells):
        for k, (a, b) in enumerate(((node(i, j), node(i + 1, j)), (node(i + 1, j), node(i + 1, j + 1)),
                                    (node(i + 1, j + 1), node(i, j + 1)), (node(i, j + 1), node(i, j)))):
            key = (min(a, b), max(a, b))
            edges[key] = None if key in edges else (a, b)
            side[(a, b)] = (c + 1, k + 1)  # Abaqus: element, side S1..S4
    xy = lambda n: (((n - 1) % (nx + 1)) * lx / nx, ((n - 1) // (nx + 1)) * ly / ny)
    lines = []
    for e in edges.values():
        if e is None:
            continue
        (x0, y0), (x1, y1) = xy(e[0]), xy(e[1])
        tag = (0 if x0 == x1 == 0 else 1 if x0 == x1 == lx else
               2 if y0 == y1 == 0 else 3 if y0 == y1 == ly else 4)
        lines.append((tag, e))
    if path.endswith(".inp"):
        # boundary ids from the surfaces SS<id>, the cells' material id 1
        with open(path, "w") as f:
            f.write("*Heading\n*Part, name=plate\n*Node\n")
            for j in range(ny + 1):
                for i in range(nx + 1):
                    f.write("%d, %r, %r\n" % ((node(i, j),) + moved(i * lx / nx, j * ly / ny)))
            f.write("*Element, type=CPS4, ELSET=EB1\n")
            for c, (i, j) in enumerate(cells):
                f.write("%d, %d, %d, %d, %d\n" % (c + 1, node(i, j), node(i + 1, j),
                                                    node(i + 1, j + 1), node(i, j + 1)))
            for tag in sorted(set(t for t, _ in lines)):
                f.write("*Surface, type=ELEMENT, name=SS%d\n" % tag)
                for t, e in lines:
                    if t == tag:
                        f.write("%d, S%d\n" % side[e])
            f.write("*End Part\n")
        return
    if path.endswith(".ucd"):
        with open(path, "w") as f:
            f.write("# UCD\n%d %d 0 0 0\n" % ((nx + 1) * (ny + 1), len(lines) + len(cells)))
            for j in range(ny + 1):
                for i in range(nx + 1):
                    f.write("%d %r %r 0\n" % ((node(i, j),) + moved(i * lx / nx, j * ly / ny)))
            k = 1
            for i, j in cells:
                f.write("%d 0 quad %d %d %d %d\n" % (k, node(i, j), node(i + 1, j),
                                                      node(i + 1, j + 1), node(i, j + 1)))
                k += 1
            for tag, (a, b) in lines:
                f.write("%d %d line %d %d\n" % (k, tag, a, b))
                k += 1
        return
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % ((nx + 1) * (ny + 1)))
        for j in range(ny + 1):
            for i in range(nx + 1):
                f.write("%d %r %r 0\n" % ((node(i, j),) + moved(i * lx / nx, j * ly / ny)))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(cells)))
        k = 1
        for tag, (a, b) in lines:
            f.write("%d 1 2 %d %d %d %d\n" % (k, tag, tag + 1, a, b))
            k += 1
        for i, j in cells:
            m = material((i + 0.5) * lx / nx, (j + 0.5) * ly / ny) if material else 7
            f.write("%d 3 2 %d %d %d %d %d %d\n" % (k, m, m, node(i, j), node(i + 1, j),
                                                   node(i + 1, j + 1), node(i, j + 1)))
            k += 1
        f.write("$EndElements\n")
