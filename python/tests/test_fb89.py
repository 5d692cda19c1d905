"""The fb89 Python module against the command line it wraps (run by ctest: python.pytest).

FB89_CLI names the fb89 executable of the same build; PYTHONPATH the build's python folder.
"""
import gc
import os
import subprocess
import sys
import threading

import matplotlib.image
import numpy as np
import pytest

import fb89

CLI = os.environ.get("FB89_CLI", "fb89")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False)


def test_the_lists_are_the_command_lines():
    listed = cli("list").stdout
    for names in (fb89.methods(), fb89.hosts(), fb89.profiles(), fb89.experiments()):
        assert names
        for name in names:
            assert name in listed, name
    assert "demo" in fb89.scenes() and "garish_room" in fb89.scenes()


def test_a_render_gives_the_image_the_ids_and_the_split():
    r = fb89.render("demo", method="zbuffer", size="256x195")
    assert r.image.shape == (195, 256, 3) and r.image.dtype == np.uint8
    assert r.ids.shape == (195, 256) and r.ids.dtype == np.int32
    assert r.ids.min() == -1 and r.ids.max() >= 0
    assert r.split["bound_by"] in ("host", "controller")
    assert r.split["controller_ms"] > 0 and r.split["host_ms"] > 0
    assert r.counters["depth_tests"] > 0
    assert r.times["hidden_surface"]["cpu_ms"] >= 0
    assert r.controller_figures["frames"][0]["width"] == 256
    assert r.period is None
    # the background is the scene's: every pixel without a face has the frame's clear colour
    begin = r.commands[0]
    assert begin["opcode"] == fb89.FRAME_BEGIN and (begin["w"], begin["h"]) == (256, 195)
    background = r.image[r.ids == -1]
    assert (background == [begin["r"], begin["g"], begin["b"]]).all()


def test_the_image_is_a_view_that_keeps_its_render_alive():
    r = fb89.render("demo", size="128x98")
    image = r.image
    assert not image.flags.owndata and image.base is not None
    assert np.shares_memory(image, r.image)
    copy = image.copy()
    del r
    gc.collect()
    assert (image == copy).all()  # the render is still there behind the view


@pytest.mark.parametrize("method", ["zbuffer", "scanline", "warnock", "hybrid", "raytrace", "beam"])
def test_the_ids_are_the_command_lines_ids_png(method, tmp_path):
    png = tmp_path / "ids.png"
    hybrid = {"threshold": "paper"} if method == "hybrid" else {}
    done = cli("render", "A", "--method", method, "--size", "160x122", "--ids", str(png), "-q",
               *(["--threshold", "paper"] if hybrid else []))
    assert done.returncode == 0, done.stderr
    rgb = np.rint(matplotlib.image.imread(png)[:, :, :3] * 255).astype(np.int32)
    expected = (rgb[:, :, 0] << 16 | rgb[:, :, 1] << 8 | rgb[:, :, 2]) - 1
    r = fb89.render("A", method=method, size="160x122", **hybrid)
    assert np.array_equal(r.ids, expected)


def test_a_stream_round_trips_through_python(tmp_path):
    r = fb89.render("G", method="beam", size="128x98")
    first, second = tmp_path / "a.fb89", tmp_path / "b.fb89"
    r.stream.save(str(first))
    s = fb89.Stream.open(str(first))
    assert s.version == 1 and s.header["method"] == "beam" and s.header["scene"] == "G"
    assert np.array_equal(s.commands, r.commands) and len(s) == len(r.commands)
    assert s.frames == 1
    s.save(str(second))
    assert first.read_bytes() == second.read_bytes()
    # the same frame as the command line's replay, and as the render's own controller
    assert np.array_equal(fb89.replay(s).image, r.image)
    assert np.array_equal(fb89.replay(str(first)).image, r.image)
    info = cli("info", str(first), "--json")
    assert info.returncode == 0, info.stderr
    assert f'"commands":{len(s)}' in info.stdout.replace(" ", "")


def test_errors_are_python_exceptions_with_the_command_lines_messages(tmp_path):
    with pytest.raises(fb89.SceneError, match="cannot open the scene file") as e:
        fb89.render("no_such_scene")
    assert isinstance(e.value, ValueError) and isinstance(e.value, fb89.Error)
    with pytest.raises(fb89.OptionError, match="zbuffer"):
        fb89.render("demo", method="zbuf")
    with pytest.raises(fb89.OptionError):
        fb89.render("demo", size="12")
    with pytest.raises(fb89.OptionError, match="threshold"):
        fb89.render("demo", method="hybrid", threshold="lots")
    corrupt = tmp_path / "corrupt.fb89"
    corrupt.write_bytes(b"FB89\x01\x00garbage")
    with pytest.raises(fb89.FileError) as e:
        fb89.Stream.open(str(corrupt))
    assert isinstance(e.value, OSError)
    with pytest.raises(fb89.FileError):
        fb89.Stream.open(str(tmp_path / "missing.fb89"))
    with pytest.raises(fb89.OptionError, match="host"):
        fb89.render("demo", host="sun5-60")
    with pytest.raises(fb89.OptionError, match="controller"):
        fb89.render("demo", controller="tms9918")
    with pytest.raises(fb89.OptionError, match="does not use it"):
        fb89.render("demo", method="zbuffer", threshold="paper")
    with pytest.raises(TypeError):
        fb89.render("demo", methd="zbuffer")  # a keyword argument is checked by name


def test_a_render_lets_other_python_threads_run():
    # the GIL is released while fb89 renders: the main thread counts on meanwhile
    counted = 0
    worker = threading.Thread(target=lambda: fb89.render("F", method="warnock", repeat=3))
    worker.start()
    while worker.is_alive():
        counted += 1
    worker.join()
    assert counted > 10000


def test_a_render_on_a_1989_host_is_modelled_from_its_emulated_run():
    here = fb89.render("A", method="scanline", size="64x49")
    then = fb89.render("A", method="scanline", size="64x49", host="sun4-260")
    assert then.period["profile"] == "sun4-260" and then.period["instructions"] > 0
    assert then.period["same_frame"]
    assert np.array_equal(then.ids, here.ids) and np.array_equal(then.image, here.image)
    assert then.split["host_ms"] > 100 * here.split["host_ms"]  # a 1989 workstation


def test_the_example_draws_its_chart(tmp_path):
    example = os.path.join(os.path.dirname(__file__), "..", "examples", "split_chart.py")
    out = tmp_path / "split.png"
    done = subprocess.run([sys.executable, example, str(out)], capture_output=True, text=True,
                          check=False)
    assert done.returncode == 0, done.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
