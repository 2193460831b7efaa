# SPDX-License-Identifier: BSD-3-Clause
"""python3 -m clearjoint.study run|plot|summary STUDY (also `clearjoint study ...`)."""
import argparse
import os
import sys

from .study_file import StudyError, load_study

USAGE = """clearjoint study COMMAND STUDY [options]   (or python3 -m clearjoint.study ...)
  run STUDY      run every run the store does not hold yet (resumes an interrupted study),
                 then write the summary tables
  plot STUDY     draw the study's figures from the store (PNG)
  summary STUDY  rewrite the summary tables from the store and print where they are"""

STUDY_HELP = "the study file (JSON; docs/studies.md)"


def _parser():
    parser = argparse.ArgumentParser(prog="clearjoint study", usage=USAGE,
                                     description="Parameter studies of clearjoint models on Dask distributed "
                                                 "(docs/studies.md).")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    # prog given: a subcommand's usage line is otherwise built from the whole USAGE text above.
    run = sub.add_parser("run", prog="clearjoint study run", help="run the study",
                         description="Runs every run the store does not hold yet, then writes the summary tables "
                                     "and draws the figures (docs/studies.md).")
    run.add_argument("study", help=STUDY_HELP)
    run.add_argument("--scheduler", help="an existing Dask scheduler (tcp://host:8786); default: a local "
                     "cluster with one worker process per core")
    run.add_argument("--workers", type=int, help="local cluster: worker processes (default: one per core)")
    run.add_argument("--memory-limit", metavar="LIMIT",
                     help="local cluster: memory per worker before Dask pauses and restarts it: auto (the "
                     "machine's memory shared out by core; the default unless the study's "
                     "worker_memory_limit says otherwise), a size such as 4GiB, a share of the memory up to 1, "
                     "or 0 for no limit")
    run.add_argument("--force", action="store_true", help="run again runs the store already holds")
    run.add_argument("--no-progress", action="store_true", help="no progress bar")
    run.add_argument("--no-plot", action="store_true", help="do not draw the figures afterwards")
    plot = sub.add_parser("plot", prog="clearjoint study plot", help="draw the study's figures from the store",
                          description="Draws the study's figures from the store (PNG).")
    plot.add_argument("study", help=STUDY_HELP)
    plot.add_argument("--out", help="directory for the figures (default: as the study file says, or STORE/figures)")
    summary = sub.add_parser("summary", prog="clearjoint study summary", help="rewrite the summary tables from the store",
                             description="Rewrites the summary tables from the store and prints where they are.")
    summary.add_argument("study", help=STUDY_HELP)
    return parser


def _summary(study):
    """Rewrites the summary tables; names on stderr the stored runs that could not be read."""
    from .expand import expand_study
    from .runner import store_error
    from .store import Store, StoreError
    from .summary import summarise
    points, _, membership = expand_study(study)
    store = Store(study.store_path)
    try:
        store.open_for_reading()
        summary = summarise(study, store, points, membership)
    except StoreError as error:
        raise store_error(study, error)
    for error in summary["unreadable_runs"].values():
        print("clearjoint study: %s; not in the summary (`study run` sets it aside and runs it again)" % error,
              file=sys.stderr)
    return summary


def _draw(study, summary, directory=None):
    from .plot import draw_all
    paths = draw_all(study, summary, directory)
    for path in paths:
        print("figure %s" % path, file=sys.stderr)
    return paths


def main(argv=None):
    args = _parser().parse_args(argv)
    try:
        study = load_study(args.study)
        if args.command == "run":
            if args.workers is not None and args.workers < 1:
                raise StudyError("--workers %d: must be at least 1" % args.workers)
            if args.workers is not None and args.scheduler:
                raise StudyError("--workers %d: only for the local cluster, not with --scheduler" % args.workers)
            from .runner import run_study
            report = run_study(study, scheduler=args.scheduler, workers=args.workers,
                               progress=not args.no_progress and sys.stderr.isatty(), force=args.force,
                               memory_limit=args.memory_limit)
            print("study %s: %d runs stored now, %d reused, %d failed, %.1f s; summary in %s" % (
                study.name, len(report.computed), report.reused, len(report.failed), report.seconds,
                os.path.join(study.store_path, "summary")), file=sys.stderr)
            if report.failed:
                for run_id, error in report.failed.items():
                    print("  run %s failed: %s" % (run_id, error), file=sys.stderr)
                return 1
            if not args.no_plot:
                _draw(study, _summary(study))
        elif args.command == "plot":
            from .plot import plots_of
            if not plots_of(study):
                raise StudyError("%s: no figure to draw: the study has no plots, and no design has an x with "
                                 "reductions to plot against it" % study.path)
            _draw(study, _summary(study), args.out)
        else:
            summary = _summary(study)
            print(os.path.join(study.store_path, "summary"))
            if summary["unreadable_runs"]:
                return 1
        return 0
    except StudyError as error:
        print("clearjoint study: %s" % error, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
