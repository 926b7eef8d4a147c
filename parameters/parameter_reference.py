#!/usr/bin/env python3
"""Writes doc/parameters.md, the parameter reference, from the program's own
list (`nitsche-contact --print-parameters`): every entry with its default and
help text, section by section.

  python3 parameters/parameter_reference.py build/nitsche-contact > doc/parameters.md

tests/verification/parameter_reference.py checks that doc/parameters.md is
what this script writes for the current program."""
import subprocess
import sys


def entries(listing):
    """(section path, name, default, help) for every 'set' line of a
    ParameterHandler listing, the help being the comment block above it."""
    path, comment, out = [], [], []
    for raw in listing.splitlines():
        line = raw.strip()
        if line.startswith("# Listing of Parameters") or line.startswith("# ----"):
            continue
        if line.startswith("#"):
            comment.append(line[1:].strip())
        elif line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
            comment = []
        elif line == "end":
            path.pop()
            comment = []
        elif line.startswith("set "):
            name, _, value = line[4:].partition("=")
            out.append(("/".join(path), name.strip(), value.strip(), " ".join(comment)))
            comment = []
        elif not line:
            comment = [] if not comment else comment
    return out


# the sections that describe the problem; the others (the models' own
# sections, the nonlinear solver, the output) how it is solved and written
PROBLEM = ("", "Geometry", "Material", "Load", "Obstacle", "Contact", "Reference solution")


def markdown(items):
    lines = ["# Parameter reference", "",
             "Every entry of a parameter file, with its default and what it does,",
             "as `nitsche-contact --print-parameters` prints them (this page is",
             "written by `python3 parameters/parameter_reference.py build/nitsche-contact`).",
             "Every model's section is declared on every run, so one file may hold all of",
             "them; a model reads the common sections and its own.", ""]
    groups = [("## The problem", [i for i in items if i[0].split("/")[0] in PROBLEM]),
              ("## The method, the solvers and the output",
               [i for i in items if i[0].split("/")[0] not in PROBLEM])]
    for title, group in groups:
        lines += [title, ""]
        lines += section_lines(group)
    return "\n".join(lines).rstrip() + "\n"


def section_lines(items):
    lines = []
    section = None
    for path, name, default, text in items:
        if path != section:
            section = path
            lines += ["### %s" % (path or "Top level"), ""]
        lines += ["- **`%s`** = `%s`" % (name, default) if default else
                  "- **`%s`** (empty by default)" % name]
        if text:
            lines += ["  " + text]
        lines += [""]
    return lines


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else "build/nitsche-contact"
    listing = subprocess.run([exe, "--print-parameters"], check=True,
                             stdout=subprocess.PIPE, text=True).stdout
    sys.stdout.write(markdown(entries(listing)))


if __name__ == "__main__":
    main()
