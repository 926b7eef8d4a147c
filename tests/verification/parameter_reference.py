"""doc/parameters.md is the parameter list of this build: what
parameters/parameter_reference.py writes from `nitsche-contact
--print-parameters` (every entry, its default and its help). A changed entry
without the regenerated page fails here; regenerate with
  python3 parameters/parameter_reference.py build/nitsche-contact > doc/parameters.md"""
import os, subprocess, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import parse_args, check, finish

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
finish()
