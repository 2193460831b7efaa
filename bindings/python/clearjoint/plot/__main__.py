# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint plot RUN_DIR [options]: every clearance joint's figure as PNG and SVG
(docs/viewing-runs.md). Runs as ``python3 -m clearjoint.plot`` or through the clearjoint
program, which hands its arguments over."""
import argparse
import sys
from typing import List, Optional


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="clearjoint plot",
        description="Draw one figure per clearance joint of a run of `clearjoint simulate`: the "
                    "journal orbit in clearance units (both base centres for a spatial joint), the "
                    "normal force, the axial position and tilt, and the slider's acceleration "
                    "beside an ideal run's; coloured by contact scenario, impacts marked. Writes "
                    "joint_<name>.png and .svg.")
    parser.add_argument("run", metavar="RUN_DIR", help="a folder written by clearjoint simulate --out")
    parser.add_argument("--model", help="the run's model file (default: RUN_DIR/model.json; without "
                                        "one, lengths are drawn in mm instead of clearance units)")
    parser.add_argument("--ideal", metavar="IDEAL_RUN_DIR",
                        help="a run of the same mechanism with ideal joints: its slider acceleration "
                             "is drawn beside this run's")
    parser.add_argument("--out", metavar="DIR", help="where the files go (default: RUN_DIR/figures)")
    parser.add_argument("--joint", help="only this clearance joint (default: every one)")
    parser.add_argument("--panels", help="comma-separated, among orbit,force,axial,tilt,slider "
                                         "(default: all that apply)")
    parser.add_argument("--from", dest="start", type=float, metavar="T0", help="start of the time window [s]")
    parser.add_argument("--to", dest="end", type=float, metavar="T1", help="end of the time window [s]")
    parser.add_argument("--x", choices=("time", "angle"), default="time",
                        help="abscissa of the time panels: time [s] or the crank's angle [deg]")
    parser.add_argument("--slider", help="the body whose acceleration is drawn (default: slider)")
    parser.add_argument("--format", default="png,svg", help="comma-separated file formats (default png,svg)")
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    try:
        import matplotlib
    except ImportError:
        print(f"clearjoint plot: needs matplotlib for {sys.executable} (Debian: python3-matplotlib)",
              file=sys.stderr)
        return 1
    matplotlib.use("Agg")  # files only, also on a machine with a display
    from .figures import save_joint_figures
    from .run_folder import RunError, read_run
    options = dict(ideal=args.ideal, window=(args.start, args.end), x=args.x, slider=args.slider,
                   panels=args.panels.split(",") if args.panels else None)
    try:
        run = read_run(args.run, args.model)
        if run.model is None:
            print(f"clearjoint plot: {args.run} has no model.json and no --model: lengths in mm",
                  file=sys.stderr)
        written = save_joint_figures(run, args.out, joint=args.joint,
                                     formats=[f for f in args.format.split(",") if f], **options)
    except (RunError, ValueError, OSError) as error:
        print(f"clearjoint plot: {error}", file=sys.stderr)
        return 1
    except MemoryError:
        print(f"clearjoint plot: not enough memory to read and draw the run {args.run}", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
