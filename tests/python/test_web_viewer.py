"""A recording opens in Rerun's web viewer, as `fgdwa inspect --web` serves it,
looked at through headless Chromium (Debian's `chromium`, driven over its
DevTools protocol with tornado's websocket client): the map and the robot appear."""

import asyncio
import base64
import io
import json
import os
import shutil
import signal
import socket
import subprocess
import time
import urllib.request

import numpy as np
import pytest

pytest.importorskip("rerun")
CHROMIUM = shutil.which("chromium")
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="needs Debian's chromium (make test installs it)")

FREE, OCCUPIED = 245, 40  # the grey levels the recording gives the map's free and occupied cells
ROBOT = (30, 30, 200)  # the colour of the robot's true outline and trail


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _wait_for(url: str, seconds: float):
    deadline = time.monotonic() + seconds
    while True:
        try:
            return urllib.request.urlopen(url, timeout=2).read()
        except OSError:
            if time.monotonic() > deadline:
                raise
            time.sleep(0.2)


async def _screenshots(page_ws: str, url: str, until, seconds: float):
    """Load ``url`` and take a screenshot every 2 s until ``until(image)`` or ``seconds``; the last one."""
    from PIL import Image
    from tornado.websocket import websocket_connect

    ws = await websocket_connect(page_ws, max_message_size=1 << 28)
    calls = 0

    async def call(method, **params):
        nonlocal calls
        calls += 1
        await ws.write_message(json.dumps({"id": calls, "method": method, "params": params}))
        while True:
            message = json.loads(await ws.read_message())
            if message.get("id") == calls:
                return message["result"]

    await call("Page.enable")
    await call("Page.navigate", url=url)
    deadline = time.monotonic() + seconds
    while True:
        await asyncio.sleep(2.0)
        shot = await call("Page.captureScreenshot", format="png")
        image = np.asarray(Image.open(io.BytesIO(base64.b64decode(shot["data"]))).convert("RGB"))
        if until(image) or time.monotonic() > deadline:
            ws.close()
            return image


def _shows_the_run(image) -> bool:
    """The map (static) and the robot's trail (logged per cycle) are on the screen."""
    grey = (image[..., 0] == image[..., 1]) & (image[..., 1] == image[..., 2])
    robot = np.all(np.abs(image.astype(int) - ROBOT) <= 8, axis=-1)
    return (np.mean(grey & (image[..., 0] == FREE)) > 0.05 and np.mean(grey & (image[..., 0] == OCCUPIED)) > 0.01
            and robot.sum() > 50)


def test_the_web_viewer_shows_a_recorded_run(tmp_path):
    from fgdwa.cli import main
    from fgdwa.plot.recording import viewer_command

    rrd = tmp_path / "demo.rrd"
    assert main(["run", "demo", "--max-steps", "20", "--out", str(tmp_path), "--record", str(rrd)]) in (0, 1)
    web, grpc, devtools = _free_port(), _free_port(), _free_port()
    # In a session of its own: the `rerun` script starts the viewer as a child, and both must go at the end.
    viewer = subprocess.Popen(viewer_command(rrd, web=True, web_port=web, grpc_port=grpc),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    browser = subprocess.Popen([CHROMIUM, "--headless=new", "--no-sandbox", "--enable-unsafe-swiftshader",
                                "--use-angle=swiftshader", "--window-size=1600,1000",
                                f"--user-data-dir={tmp_path / 'chromium'}", f"--remote-debugging-port={devtools}",
                                "about:blank"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               start_new_session=True)
    try:
        _wait_for(f"http://127.0.0.1:{web}/", 30)
        pages = json.loads(_wait_for(f"http://127.0.0.1:{devtools}/json/list", 30))
        page = next(p for p in pages if p["type"] == "page")
        url = f"http://127.0.0.1:{web}/?url=rerun%2Bhttp://127.0.0.1:{grpc}/proxy"
        image = asyncio.run(_screenshots(page["webSocketDebuggerUrl"], url, _shows_the_run, 150))
    finally:
        for process in (browser, viewer):
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    from PIL import Image

    Image.fromarray(image).save(tmp_path / "viewer.png")
    assert _shows_the_run(image), f"the web viewer did not show the map and the trail; screenshot: {tmp_path / 'viewer.png'}"
