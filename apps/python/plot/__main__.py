# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint plot RUN_DIR [options]: every clearance joint's figure as PNG and SVG;
clearjoint plot RUN_DIR RUN_DIR ... --out FIG: the runs overlaid in one figure
(docs/viewing-runs.md). Runs as ``python3 -m clearjoint.plot`` or through the clearjoint
program, which hands its arguments over."""
import argparse
import sys
from typing import List, Optional


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="clearjoint plot",
        description="One run: draw one figure per clearance joint of a run of `clearjoint simulate`: "
                    "the journal orbit in clearance units (both base centres for a spatial joint), the "
                    "normal force (and the film's for a lubricated joint), the film thickness, the "
                    "axial position and tilt, and the slider's acceleration beside an ideal run's; "
                    "coloured by contact scenario, impacts marked. Writes joint_<name>.png and .svg. "
                    "Several runs (any engine, CSV or HDF5): overlay them in one figure with a legend "
                    "(orbit, joint force, film, slider acceleration, energy), written to --out FIG.")
    parser.add_argument("run", metavar="RUN_DIR", nargs="+",
                        help="a folder written by clearjoint simulate --out (or clearjoint-mujoco --out); "
                             "several to compare them")
    parser.add_argument("--label", nargs="+", action="extend", metavar="LABEL",
                        help="the runs' names in the comparison's legend, one per run (default: the "
                             "folders' names)")
    parser.add_argument("--model", nargs="+", action="extend",
                        help="the run's model file (default: RUN_DIR/model.json; without one, lengths "
                             "are drawn in metres instead of clearance units); one per run when "
                             "comparing (`-` for a run's own)")
    parser.add_argument("--ideal", metavar="IDEAL_RUN_DIR",
                        help="a run of the same mechanism with ideal joints: its slider acceleration "
                             "is drawn beside this run's")
    parser.add_argument("--out", metavar="DIR_OR_FIG",
                        help="one run: the folder the files go into (default: RUN_DIR/figures); several "
                             "runs: the figure's file, its extension the format (.png, .svg, .pdf); "
                             "required")
    parser.add_argument("--joint", help="only this clearance joint (default: every one)")
    parser.add_argument("--panels", help="comma-separated, among orbit,force,film,axial,tilt,slider "
                                         "(default: all that apply; one run only)")
    parser.add_argument("--from", dest="start", type=float, metavar="T0",
                        help="start of the time window [s] (comparison's default: past the first 10 %% "
                             "of the span the runs share)")
    parser.add_argument("--to", dest="end", type=float, metavar="T1", help="end of the time window [s]")
    parser.add_argument("--x", choices=("time", "angle"), default="time",
                        help="abscissa of the time panels: time [s] or the crank's angle [deg]")
    parser.add_argument("--slider", help="the body whose acceleration is drawn (default: slider)")
    parser.add_argument("--format", default="png,svg", help="comma-separated file formats (default png,svg)")
    return parser


def _compare(args) -> int:
    from .compare import compare
    from .run_folder import RunError
    if args.out is None:
        print("clearjoint plot: --out FIG: needed to compare runs (the figure's file, e.g. runs.png)",
              file=sys.stderr)
        return 1
    for option, value in (("--panels", args.panels), ("--x", None if args.x == "time" else args.x)):
        if value is not None:
            print(f"clearjoint plot: {option}: applies to one run's figures, not to a comparison",
                  file=sys.stderr)
            return 1
    models = None
    if args.model is not None:
        if len(args.model) != len(args.run):
            print(f"clearjoint plot: --model: {len(args.model)} given for {len(args.run)} runs (one per "
                  "run, - for a run's own)", file=sys.stderr)
            return 1
        models = [None if m == "-" else m for m in args.model]
    try:
        result = compare(args.run, labels=args.label, out=args.out, window=(args.start, args.end),
                         ideal=args.ideal, joint=args.joint, models=models, slider=args.slider)
    except (RunError, ValueError, OSError) as error:
        print(f"clearjoint plot: {error}", file=sys.stderr)
        return 1
    except MemoryError:
        print("clearjoint plot: not enough memory to read and draw the runs", file=sys.stderr)
        return 1
    for note in result.notes:
        print(f"clearjoint plot: note: {note}", file=sys.stderr)
    print(args.out)
    return 0


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    try:
        import matplotlib
    except ImportError:
        print(f"clearjoint plot: needs matplotlib for {sys.executable} (Debian: python3-matplotlib)",
              file=sys.stderr)
        return 1
    matplotlib.use("Agg")  # files only, also on a machine with a display
    if len(args.run) > 1:
        return _compare(args)
    from .figures import save_joint_figures
    from .run_folder import RunError, read_run
    if args.label is not None or (args.model is not None and len(args.model) > 1):
        print("clearjoint plot: --label and several --model apply to a comparison of several runs",
              file=sys.stderr)
        return 1
    folder = args.run[0]
    options = dict(ideal=args.ideal, window=(args.start, args.end), x=args.x, slider=args.slider,
                   panels=args.panels.split(",") if args.panels else None)
    try:
        run = read_run(folder, args.model[0] if args.model else None)
        if run.model is None:
            print(f"clearjoint plot: {folder} has no model.json and no --model: lengths in m",
                  file=sys.stderr)
        written = save_joint_figures(run, args.out, joint=args.joint,
                                     formats=[f for f in args.format.split(",") if f], **options)
    except (RunError, ValueError, OSError) as error:
        print(f"clearjoint plot: {error}", file=sys.stderr)
        return 1
    except MemoryError:
        print(f"clearjoint plot: not enough memory to read and draw the run {folder}", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
