# SPDX-License-Identifier: BSD-3-Clause
"""The viewer's web server: the page and its vendored scripts from web/, and the run's manifest
and frames from memory, on 127.0.0.1 only (a run may be private; nothing is listening on other
interfaces). Nothing is fetched from the internet: the page works offline.

Listening on the loopback interface is not enough: a web page of another site can make its own
name resolve to 127.0.0.1 (DNS rebinding) and then read this server as "its" origin. Such a
request carries the other site's name in its Host header, so every request whose Host is not a
loopback name with the served port is refused (421 Misdirected Request)."""
from __future__ import annotations

import json
import os
import threading
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Dict, Optional, Tuple

from .frames import ViewerData

WEB_DIRECTORY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "web")
# Module scripts must come with a JavaScript type, or the browser refuses them.
CONTENT_TYPES = {".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8",
                 ".css": "text/css; charset=utf-8", ".json": "application/json",
                 ".txt": "text/plain; charset=utf-8", ".png": "image/png"}


def _static_files() -> Dict[str, str]:
    """URL path -> file, for every file under web/: a fixed list, so no request can name a file
    outside it (no path traversal to check)."""
    files = {}
    for directory, _, names in os.walk(WEB_DIRECTORY):
        for name in names:
            path = os.path.join(directory, name)
            files["/" + os.path.relpath(path, WEB_DIRECTORY).replace(os.sep, "/")] = path
    files["/"] = os.path.join(WEB_DIRECTORY, "index.html")
    return files


#: The host names a request may address the server by: the loopback names (RFC 6761 reserves
#: "localhost"; 127.0.0.1 is where the server listens, and [::1] is IPv6's loopback).
LOOPBACK_HOSTS = ("localhost", "127.0.0.1", "[::1]")

#: Largest TCP port number (RFC 793: ports are 16-bit); 0 asks the system for a free one.
MAX_PORT = 65535


def check_port(port: int) -> int:
    """`port` when it is a whole number from 0 (a free port) to MAX_PORT, else ValueError naming it."""
    if isinstance(port, bool) or not isinstance(port, int) or not 0 <= port <= MAX_PORT:
        raise ValueError(f"port = {port!r}: must be a whole number from 0 (a free port) to {MAX_PORT}")
    return port


def host_allowed(host: Optional[str], port: int) -> bool:
    """Whether a request's Host header names this server: a loopback name, with the served port
    or none (a browser omits the scheme's default port), compared without case."""
    if host is None:
        return False
    host = host.strip().lower()
    for name in LOOPBACK_HOSTS:
        if host == name or host == f"{name}:{port}":
            return True
    return False


class ViewerServer:
    """Serves one run's ViewerData; ``url`` is the page. Use as a context manager, or call
    ``serve_forever()`` / ``start()`` and ``close()``."""

    def __init__(self, data: ViewerData, port: int = 0, quiet: bool = True) -> None:
        check_port(port)
        self.data = data
        payload: Dict[str, Tuple[bytes, str]] = {
            "/run/manifest.json": (json.dumps(data.manifest).encode(), "application/json"),
            "/run/frames.f32": (data.frames.tobytes(), "application/octet-stream"),
        }
        static = _static_files()

        class Handler(BaseHTTPRequestHandler):
            def do_GET(self) -> None:  # noqa: N802 (the http.server name)
                if not host_allowed(self.headers.get("Host"), self.server.server_address[1]):
                    self.send_error(HTTPStatus.MISDIRECTED_REQUEST,
                                    "this server answers only to localhost, 127.0.0.1 and [::1]")
                    return
                path = self.path.split("?", 1)[0]
                if path in payload:
                    body, content_type = payload[path]
                elif path in static:
                    with open(static[path], "rb") as stream:
                        body = stream.read()
                    content_type = CONTENT_TYPES.get(os.path.splitext(static[path])[1],
                                                     "application/octet-stream")
                else:
                    self.send_error(HTTPStatus.NOT_FOUND)
                    return
                self.send_response(HTTPStatus.OK)
                self.send_header("Content-Type", content_type)
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Cache-Control", "no-store")
                self.end_headers()
                self.wfile.write(body)

            def log_message(self, format: str, *args) -> None:  # noqa: A002
                if not quiet:
                    super().log_message(format, *args)

        self._server = ThreadingHTTPServer(("127.0.0.1", port), Handler)
        self._server.daemon_threads = True
        self._thread: Optional[threading.Thread] = None

    @property
    def url(self) -> str:
        host, port = self._server.server_address[:2]
        return f"http://{host}:{port}/"

    def start(self) -> "ViewerServer":
        """Serve from a background thread (tests, notebooks); a started server stays as it is."""
        if self._thread is None:
            self._thread = threading.Thread(target=self._server.serve_forever, daemon=True)
            self._thread.start()
        return self

    def serve_forever(self) -> None:
        self._server.serve_forever()

    def close(self) -> None:
        if self._thread is not None:  # serve_forever runs in it: stop it first
            self._server.shutdown()
        self._server.server_close()

    def __enter__(self) -> "ViewerServer":
        return self.start()

    def __exit__(self, *exc) -> None:
        self.close()
