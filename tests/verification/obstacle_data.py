"""Obstacles from data ('Obstacle/Type = data'): heights on a uniform grid,
bilinear between its points, no obstacle outside it; in every model (the
paper's plate, clamped, q = -0.02; the plates on 16^2 -> 64^2 cells, the 3D
body on 8^2 -> 16^2 x 1 cells).

- A bilinear height z = -0.1 - 0.002 x - 0.001 y + 0.0002 x y given on
  the 3 x 3 grid of [0, 10]^2 is the same obstacle as the formula: every
  model gives the formula's reaction and probes to 1e-8.
- The dome z = -0.1 - 0.004 ((x-5)^2 + (y-5)^2) sampled on n x n grids:
  the bilinear interpolant differs from it by at most h^2/4 * 0.008 (h =
  10/(n-1)), so the runs on the data approach the run on the formula at
  the rate 2 in the grid size. The membrane's reaction differs by 0.0296,
  0.0077, 0.0022, 0.00057 for n = 5, 9, 17, 33 (falling 3.8x, 3.5x, 3.8x;
  checked: at least 3x per step); for the plates and the 3D body, whose
  contact zones settle onto the dome's grid less smoothly, the difference
  falls by at least 8x from n = 5 to n = 17 (measured: Mindlin 11x,
  Kirchhoff 760x, 3D 57x).
- A grid over the left half [0, 5] x [0, 10] only (the plane z = -0.1
  there, -0.03 for the membrane): the plate rests on it at (2.5, 5) and
  sags below its level at (7.5, 5), where no obstacle is, in every
  model.
- The bilinear data file with Windows (CR LF) and old Mac (CR) line ends
  gives the membrane's run on the file with LF line ends to the last bit."""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, run, check, close, finish

args = parse_args()
os.makedirs(args.workdir, exist_ok=True)

MODELS = {"membrane": "16, 16", "mindlin": "16, 16", "kirchhoff": "16, 16",
          "elasticity": "8, 8, 1"}
TEMPLATE = """set Model = %(model)s
subsection Geometry
  set Subdivisions = %(sub)s
  set Number of cycles = %(cycles)d
end
subsection Obstacle
  %(obstacle)s
end
subsection Elasticity
  set Refine through thickness = false
end
subsection Output
  set Probe points = 5, 5; 2.5, 5; 7.5, 5; 2, 8
end
"""


def write_grid(name, x, y, n, height):
    path = os.path.join(args.workdir, name)
    with open(path, "w") as f:
        f.write("# heights on %d x %d points\n%r %r %d   # x_min x_max n_x\n"
                "%r %r %d   # y_min y_max n_y\n" % (n, n, x[0], x[1], n, y[0], y[1], n))
        for j in range(n):
            yj = y[0] + (y[1] - y[0]) * j / (n - 1)
            f.write(" ".join(repr(height(x[0] + (x[1] - x[0]) * i / (n - 1), yj))
                             for i in range(n)) + "\n")
    return path


def solve(model, tag, obstacle):
    cycles = 2 if model == "elasticity" else 3
    s, _ = run(args, "%s_%s" % (model, tag),
               TEMPLATE % dict(model=model, sub=MODELS[model], cycles=cycles,
                               obstacle=obstacle), pinned="rigid")
    check(all(c["converged"] for c in s["cycles"]), "%s %s: every cycle converged" % (model, tag))
    return s["cycles"][-1]


def data(path):
    return "set Type = data\n  set Data file = " + path


def formula(text):
    return "set Type = function\n  set Height = " + text


# 1. a bilinear height: the data are the formula
runs_on_data = {}
bilinear = write_grid("bilinear.txt", (0., 10.), (0., 10.), 3,
                      lambda x, y: -0.1 - 0.002 * x - 0.001 * y + 0.0002 * x * y)
for model in MODELS:
    a = solve(model, "bilinear_formula", formula("-0.1 - 0.002*x - 0.001*y + 0.0002*x*y"))
    b = solve(model, "bilinear_data", data(bilinear))
    runs_on_data[model] = b
    check(a["contact_force"] > 0, "%s: the plate touches the bilinear obstacle" % model)
    close(b["contact_force"], a["contact_force"], 1e-8, "%s: bilinear, reaction, data vs formula"
          % model)
    for j in range(4):
        close(b["probes"][j], a["probes"][j], 1e-8,
              "%s: bilinear, probe %d, data vs formula" % (model, j))

# the same file with the line ends of other platforms
lf = open(bilinear, newline="").read()
reference = runs_on_data["membrane"]
for tag, end in [("crlf", "\r\n"), ("cr", "\r")]:
    path = os.path.join(args.workdir, "bilinear_%s.txt" % tag)
    with open(path, "w", newline="") as f:
        f.write(lf.replace("\n", end))
    c = solve("membrane", "bilinear_data_" + tag, data(path))
    check(c["contact_force"] == reference["contact_force"] and c["probes"] == reference["probes"],
          "membrane: the data file with %s line ends gives the run of LF line ends"
          % tag.upper())

# 2. the dome sampled on finer and finer grids
dome = lambda x, y: -0.1 - 0.004 * ((x - 5) ** 2 + (y - 5) ** 2)
grids = {n: write_grid("dome%d.txt" % n, (0., 10.), (0., 10.), n, dome) for n in (5, 9, 17, 33)}
for model in MODELS:
    reference = solve(model, "dome_formula",
                      formula("-0.1 - 0.004*((x-5)^2 + (y-5)^2)"))["contact_force"]
    sizes = (5, 9, 17, 33) if model == "membrane" else (5, 17)
    diff = [abs(solve(model, "dome_data%d" % n, data(grids[n]))["contact_force"] - reference)
            for n in sizes]
    text = ", ".join("%.3g" % d for d in diff)
    if model == "membrane":
        check(all(d1 >= 3 * d2 for d1, d2 in zip(diff, diff[1:])),
              "membrane: the reaction on the dome's data approaches the formula's at least 3x "
              "per halving of the data grid (%s)" % text)
    else:
        check(diff[0] >= 8 * diff[1],
              "%s: the reaction on the dome's data approaches the formula's at least 8x from "
              "n = 5 to n = 17 (%s)" % (model, text))

# 3. data over the left half only: no obstacle on the right half
# (the membrane, without thickness, deflects less: its data lie at -0.03)
for model in MODELS:
    level = -0.03 if model == "membrane" else -0.1
    half = write_grid("left_half_%s.txt" % model, (0., 5.), (0., 10.), 2, lambda x, y: level)
    c = solve(model, "left_half", data(half))
    # the membrane on the plane, the plates' lower face (t = 0.01) on it
    rest = level if model == "membrane" else level + 0.005
    w = c["probes"]
    check(abs(w[1] - rest) < 1e-4 and w[2] < rest - 0.01,
          "%s: the plate rests on the data at (2.5, 5) (w = %.6f) and sags below their level "
          "at (7.5, 5), off the grid (w = %.6f)" % (model, w[1], w[2]))
finish()
