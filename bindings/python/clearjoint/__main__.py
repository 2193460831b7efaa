# SPDX-License-Identifier: BSD-3-Clause
"""The `clearjoint` command of a pip install (and ``python3 -m clearjoint``).

The full `clearjoint` command is a C++ program (apps/clearjoint, built and installed by CMake) whose
`plot`, `view` and `study` subcommands hand over to this package. `pip install .` builds only the
package's compiled core, not the program, so it installs this command in its place: `plot`,
`view` and `study` run here, as the program would run them; every other subcommand (`simulate`,
`detect`, `intersect`, `bearing`) is handed to the C++ program when one is found (the
CLEARJOINT_PROGRAM environment variable, else the first `clearjoint` on PATH that is a program,
not a script such as this one), and otherwise refused with a line saying how to get it
(docs/python.md, "Install").
"""
import os
import sys

# Subcommands written in Python: name -> (module whose __main__ has main(argv), what it does), as
# the C++ program lists them.
PYTHON_COMMANDS = {
    "study": ("clearjoint.study", "parameter studies on Dask: run, plot, summary"),
    "plot": ("clearjoint.plot", "figures of runs' clearance joints, PNG and SVG"),
    "view": ("clearjoint.view", "a run animated in 3-D in the browser"),
}
# Subcommands only the C++ program has.
PROGRAM_COMMANDS = ("simulate", "detect", "intersect", "bearing")
# Set in the environment of the C++ program this command starts: a `clearjoint` found on PATH
# that turns out to hand back to this command again is then refused instead of looping.
HANDED_OVER = "CLEARJOINT_HANDED_OVER_FROM_PYTHON"
# The first bytes of a script (#!): a `clearjoint` on PATH that starts with them is a console
# script like this one, not the C++ program.
SCRIPT_MAGIC = b"#!"


def usage(to):
    to.write("usage: clearjoint COMMAND [ARGS...]\n       clearjoint --version\ncommands:\n")
    for name, (_, what) in PYTHON_COMMANDS.items():
        to.write("  %-10s %s\n" % (name, what))
    to.write("  %s: the C++ program `clearjoint` (%s)\n" % (", ".join(PROGRAM_COMMANDS), _program_text()))


def _is_program(path):
    """An executable regular file that is not a script."""
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        return False
    try:
        with open(path, "rb") as f:
            return f.read(len(SCRIPT_MAGIC)) != SCRIPT_MAGIC
    except OSError:
        return False


def find_program():
    """The C++ `clearjoint` program: CLEARJOINT_PROGRAM when set, else the first `clearjoint` on
    PATH that is a program; None when there is none."""
    named = os.environ.get("CLEARJOINT_PROGRAM")
    if named:
        return named
    for folder in os.environ.get("PATH", "").split(os.pathsep):
        candidate = os.path.join(folder or ".", "clearjoint")
        if _is_program(candidate):
            return candidate
    return None


def _program_text():
    program = find_program()
    return "found: %s" % program if program else "not found: not installed by pip"


def _hand_over(command, args):
    program = find_program()
    if program is None:
        sys.stderr.write("clearjoint %s: this is the clearjoint command of the Python package, which runs plot, view "
                         "and study; %s is a command of the C++ program `clearjoint`, which pip does not install: "
                         "build and install it with CMake (README.md, docs/python.md \"Install\") or name it in "
                         "CLEARJOINT_PROGRAM; from Python, clearjoint.simulate runs a model\n" % (command, command))
        return 2
    if os.environ.get(HANDED_OVER):
        sys.stderr.write("clearjoint %s: %s handed the command back to the Python package; set CLEARJOINT_PROGRAM "
                         "to the C++ program\n" % (command, program))
        return 2
    os.environ[HANDED_OVER] = "1"
    try:
        os.execv(program, [program, command] + list(args))
    except OSError as error:
        sys.stderr.write("clearjoint %s: cannot start the C++ program %s (%s)\n" % (command, program,
                                                                                   error.strerror or error))
        return 2


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv:
        usage(sys.stderr)
        return 2
    command, args = argv[0], argv[1:]
    if command in ("-h", "--help", "help"):
        usage(sys.stdout)
        return 0
    if command == "--version":
        from . import __version__
        print("clearjoint %s (the Python package's command)" % __version__)
        return 0
    if command in PYTHON_COMMANDS:
        import importlib
        return importlib.import_module(PYTHON_COMMANDS[command][0] + ".__main__").main(args)
    if command in PROGRAM_COMMANDS:
        return _hand_over(command, args)
    sys.stderr.write("clearjoint: unknown command %r\n" % command)
    usage(sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
