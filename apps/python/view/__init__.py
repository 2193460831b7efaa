# SPDX-License-Identifier: BSD-3-Clause
"""clearjoint.view: a run animated in 3-D in the browser (docs/viewing-runs.md).

``serve(run, model=None)`` packs the run (``frames.viewer_data``) and returns a started
:class:`ViewerServer` on 127.0.0.1; open its ``url``. ``clearjoint view RUN_DIR`` does the same
from the command line and opens the browser.
"""
from typing import Any, Optional

from ..plot.run_folder import RunError, read_run
from .frames import DEFAULT_MAX_FRAMES, ViewerData, viewer_data
from .server import ViewerServer


def serve(run: Any, model: Any = None, *, port: int = 0, max_frames: int = DEFAULT_MAX_FRAMES,
          magnification: Optional[float] = None) -> ViewerServer:
    """Serve the viewer page of ``run`` (a run folder or a SimulationResult, with its ``model``
    file or dict) from a background thread; ``.url`` is the page, ``.close()`` stops it."""
    data = viewer_data(read_run(run, model), max_frames=max_frames, magnification=magnification)
    return ViewerServer(data, port=port).start()


__all__ = ["DEFAULT_MAX_FRAMES", "RunError", "ViewerData", "ViewerServer", "serve", "viewer_data"]
