# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint view RUN_DIR [--model MODEL.json]: animate a run in the browser
(docs/viewing-runs.md). Runs as ``python3 -m clearjoint.view`` or through the clearjoint
program, which hands its arguments over."""
import argparse
import math
import sys
import time
import webbrowser
from typing import List, Optional


def _port(text: str) -> int:
    from .server import MAX_PORT
    try:
        port = int(text)
    except ValueError:
        port = -1
    if not 0 <= port <= MAX_PORT:
        raise argparse.ArgumentTypeError(f"{text!r}: must be a whole number from 0 (a free port) to {MAX_PORT}")
    return port


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text!r}: must be a whole number of at least 1")
    return value


def _magnification(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (math.isfinite(value) and value > 0.0):
        raise argparse.ArgumentTypeError(f"{text!r}: must be a finite positive number")
    return value


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="clearjoint view",
        description="Animate a run of `clearjoint simulate` in 3-D in the browser: the bodies, the "
                    "clearance joint's journal in its bearing with the clearance magnified, the "
                    "contacts coloured by scenario, the orbit and the normal force in step. Serves "
                    "a page on 127.0.0.1 until Ctrl-C.")
    parser.add_argument("run", metavar="RUN_DIR", help="a folder written by clearjoint simulate --out")
    parser.add_argument("--model", help="the run's model file (default: RUN_DIR/model.json)")
    parser.add_argument("--port", type=_port, default=0, help="port on 127.0.0.1 (default: a free one)")
    parser.add_argument("--magnify", type=_magnification, metavar="FACTOR",
                        help="clearance magnification (default: clearance shown as 15 %% of the "
                             "bearing radius, rounded to 1, 2, 5 x 10^k; changeable in the page)")
    parser.add_argument("--max-frames", type=_positive_int, default=None,
                        help="frames sent to the page at most (default 20000; longer runs are "
                             "decimated, force peaks kept)")
    parser.add_argument("--no-browser", action="store_true", help="print the URL only")
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    from ..plot.run_folder import RunError, read_run
    from .frames import DEFAULT_MAX_FRAMES, viewer_data
    from .server import ViewerServer
    started = time.monotonic()
    try:
        run = read_run(args.run, args.model)
        # The joints the frames draw: the model's, whose tables are in the run (frames.viewer_data).
        if run.model is not None and not any(j.table in run.tables for j in run.clearance_joints):
            print(f"clearjoint view: {args.run} has no clearance joint: showing the bodies only",
                  file=sys.stderr)
        data = viewer_data(run, max_frames=args.max_frames or DEFAULT_MAX_FRAMES,
                           magnification=args.magnify)
        server = ViewerServer(data, port=args.port)
    except (RunError, ValueError, OSError) as error:
        print(f"clearjoint view: {error}", file=sys.stderr)
        return 1
    except MemoryError:
        print(f"clearjoint view: not enough memory to read and pack the run {args.run}", file=sys.stderr)
        return 1
    manifest = data.manifest
    print(f"clearjoint view: {manifest['row_count']} report times as {manifest['frame_count']} frames "
          f"(every {manifest['decimation_step']}), packed in {time.monotonic() - started:.2f} s")
    print(f"clearjoint view: serving {server.url} (Ctrl-C stops)", flush=True)
    if not args.no_browser:
        webbrowser.open(server.url)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass
    finally:
        server.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
