"""doc/parameters.md is the parameter list of this build: what
parameters/parameter_reference.py writes from `nitsche-contact
--print-parameters` (every entry, its default and its help). A changed entry
without the regenerated page fails here; regenerate with
  python3 parameters/parameter_reference.py build/nitsche-contact > doc/parameters.md

The paper files (parameters/paper_*.prm, kirchhoff_nitsche.prm) set only
entries whose value differs from the default ('Model' apart, which names
the file's model), so that a change of a default reaches them.

README.md's model table names the models of `--help` (in an order of its
own: the 3D model, the plates, the membrane), and
each model has its own subsection (its name, capitalised)."""
import glob, os, re, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, check, finish, parameter_entries, registered_models

args = parse_args()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
page = subprocess.run([sys.executable, os.path.join(root, "parameters", "parameter_reference.py"),
                       args.exe], check=True, stdout=subprocess.PIPE, text=True).stdout
listing = subprocess.run([args.exe, "--print-parameters"], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
n_set = sum(1 for l in listing.splitlines() if l.strip().startswith("set "))
check(page.count("\n- **`") == n_set,
      "the page lists all %d entries of --print-parameters" % n_set)
with open(os.path.join(root, "doc", "parameters.md")) as f:
    check(f.read() == page, "doc/parameters.md is up to date")


def entries(text):
    """{subsection path/entry: value} of a parameter text."""
    return {"/".join(path): value for path, value in parameter_entries(text)}


def same_value(a, b):
    """The same text, or the same numbers written differently (1e-06, 1e-6)."""
    fields = lambda v: [f for f in re.split(r"[\s,;:]+", v) if f]
    fa, fb = fields(a), fields(b)
    if len(fa) != len(fb):
        return False
    for x, y in zip(fa, fb):
        try:
            if float(x) != float(y):
                return False
        except ValueError:
            if x != y:
                return False
    return True


models, default = registered_models()
names = [name for name, _ in models]
with open(os.path.join(root, "README.md")) as f:
    table = re.findall(r"(?m)^\| `(\w+)` \|", f.read())
check(sorted(table) == sorted(names),
      "README.md's model table %s names the models of --help %s"
      % (table, names))
top_sections = re.findall(r"(?m)^subsection (\S.*)$", listing)
check(all(n.capitalize() in top_sections for n in names),
      "every model has a subsection of its own in the parameter listing")
check(default in names, "the default model '%s' is registered" % default)

defaults = entries(listing)
papers = sorted(glob.glob(os.path.join(root, "parameters", "paper_*.prm")) +
                [os.path.join(root, "parameters", "kirchhoff_nitsche.prm")])
for path in papers:
    same = [k for k, v in entries(open(path).read()).items()
            if k != "Model" and k in defaults and same_value(defaults[k], v)]
    check(not same, "%s sets only entries that differ from their defaults%s"
          % (os.path.basename(path), (" (not: %s)" % "; ".join(same)) if same else ""))
finish()
