"""Python held to the command line's checks (issue 50): every keyword's range and type from the
same limits as the CLI's options (frontend/option_limits.h), the same error class for the same
failure in every function, streams checked when built, a dict scene named as such."""
import os
import subprocess

import numpy as np
import pytest

import fb89

CLI = os.environ.get("FB89_CLI", "fb89")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False)


# ---- ranges: the same limits, the same words, from the same code ----

# (what the refusal says after the option's name, the Python call, the command line's words)
REFUSED = [
    ("0 is not in [1, 10000]", lambda: fb89.render("demo", repeat=0),
     ["render", "demo", "--repeat", "0"]),
    ("-3 is not in [1, 10000]", lambda: fb89.render("demo", repeat=-3),
     ["render", "demo", "--repeat", "-3"]),
    ("100000 is not in [1, 10000]", lambda: fb89.render("demo", repeat=100000),
     ["render", "demo", "--repeat", "100000"]),
    ("17 is not in [0, 16]", lambda: fb89.render("demo", method="raytrace", reflections=17),
     ["render", "demo", "--method", "raytrace", "--reflections", "17"]),
    ("1001 is not in [1, 1000]", lambda: fb89.experiment("fig2.1", ["A"], repeat=1001),
     ["experiment", "fig2.1", "A", "--repeat", "1001"]),
    ("1 is not in [2, 16]", lambda: fb89.experiment("ff-error", reference_rays=1),
     ["experiment", "ff-error", "--reference-rays", "1"]),
    ("-1 is not in [0, 100000]", lambda: fb89.experiment("radiosity", patches=-1),
     ["experiment", "radiosity", "--patches", "-1"]),
    ("0 is not in [1, 256]", lambda: fb89.experiment("fig2.1", ["A"], host="sun3-60", jobs=0),
     ["experiment", "fig2.1", "A", "--host", "sun3-60", "--jobs", "0"]),
    ("201 is not in [1, 200]", lambda: fb89.sweep("threshold", "A", steps=201),
     ["sweep", "threshold", "A", "--steps", "201"]),
    ("0 is not in [1, 200]", lambda: fb89.calibrate("hybrid", ["A"], steps=0),
     ["calibrate", "A", "--steps", "0"]),
    ("101 is not in [0, 100]", lambda: fb89.calibrate("hybrid", ["A"], tolerance=101),
     ["calibrate", "A", "--tolerance", "101"]),
    ("0 is not in [1, 1000]", lambda: fb89.compare("A", repeat=0),
     ["compare", "A", "--repeat", "0"]),
]


@pytest.mark.parametrize("words,call,args", REFUSED, ids=[" ".join(r[2][:1] + r[2][-2:])
                                                           for r in REFUSED])
def test_a_number_out_of_range_is_refused_in_the_command_lines_words(words, call, args):
    with pytest.raises(fb89.OptionError) as e:
        call()
    keyword = args[-2].lstrip("-").replace("-", "_")
    assert str(e.value) == f"{keyword}: {words}"
    done = cli(*args)
    assert done.returncode == 2 and f"{args[-2]}: {words}" in done.stderr, done.stderr


def test_repeat_zero_is_refused_before_any_time_is_taken():
    # it used to return a hidden-surface time of 0 ms: silently wrong data
    with pytest.raises(fb89.OptionError, match=r"^repeat: 0 is not in \[1, 10000\]$"):
        fb89.render("demo", repeat=0)


def test_a_fraction_is_not_an_integer_as_on_the_command_line():
    with pytest.raises(fb89.OptionError, match=r"^repeat: 2\.5 is not an integer$"):
        fb89.render("demo", repeat=2.5)
    done = cli("render", "demo", "--repeat", "2.5")
    assert done.returncode == 2 and "--repeat: 2.5 is not an integer" in done.stderr
    with pytest.raises(fb89.OptionError, match=r"^size: 64\.5 is not an integer$"):
        fb89.render("demo", size=(64.5, 48))
    with pytest.raises(fb89.OptionError, match=r"size: 0 is not in \[1, 16384\]"):
        fb89.render("demo", size=(0, 48))
    with pytest.raises(fb89.OptionError, match="size: width and height must be in"):
        fb89.render("demo", size="64x0")
    # numpy's integers are integers
    assert fb89.render("A", size=(np.int64(32), 24), repeat=np.int32(1)).ids.shape == (24, 32)


# ---- types: a clean TypeError naming the keyword, never pybind11's signatures ----

@pytest.mark.parametrize("call,keyword", [
    (lambda: fb89.render("demo", repeat="3"), "repeat"),
    (lambda: fb89.render("demo", repeat=True), "repeat"),
    (lambda: fb89.render("demo", method=3), "method"),
    (lambda: fb89.render("demo", profile=3), "profile"),
    (lambda: fb89.render("demo", size=5), "size"),
    (lambda: fb89.render("demo", method="hybrid", threshold=[1]), "threshold"),
    (lambda: fb89.render("demo", buffer=[4096]), "buffer"),
    (lambda: fb89.render(5), "scene"),
    (lambda: fb89.experiment("fig2.1", ["A"], methods="zbuffer"), "methods"),
    (lambda: fb89.experiment("fig2.1", ["A"], patches="many"), "patches"),
    (lambda: fb89.sweep("threshold", "A", start="small"), "start"),
    (lambda: fb89.calibrate("hybrid", ["A"], save="yes"), "save"),
    (lambda: fb89.compare("A", sheet=3), "sheet"),
    (lambda: fb89.trim(3, "out.fb89", calls="0"), "stream"),
    (lambda: fb89.diff("a.fb89", "b.fb89", image=3), "image"),
    (lambda: fb89.Stream.open(3), "path"),
    (lambda: fb89.Stream("not rows"), "commands"),
    (lambda: fb89.Stream(np.zeros(1, fb89.COMMAND_DTYPE), header={"scene": 1}), "header"),
    (lambda: fb89.Stream(np.zeros(1, fb89.COMMAND_DTYPE), markers=[(0,)]), "markers"),
])
def test_a_value_of_the_wrong_type_is_a_type_error_naming_the_keyword(call, keyword):
    with pytest.raises(TypeError) as e:
        call()
    message = str(e.value)
    assert message.startswith(keyword), message
    assert "incompatible" not in message and "arg0" not in message, message


# ---- the same class for the same failure, in every function ----

def test_a_missing_file_is_a_file_error_everywhere(tmp_path):
    missing = str(tmp_path / "missing.fb89")
    present = str(tmp_path / "present.fb89")
    fb89.render("A", size="32x24").stream.save(present)
    for call in (lambda: fb89.Stream.open(missing), lambda: fb89.replay(missing),
                 lambda: fb89.diff(missing, present), lambda: fb89.diff(present, missing),
                 lambda: fb89.trim(missing, str(tmp_path / "t.fb89"), frames="0")):
        with pytest.raises(fb89.FileError, match="missing.fb89"):
            call()


def test_an_unwritable_output_is_a_file_error_everywhere(tmp_path):
    stream = str(tmp_path / "s.fb89")
    r = fb89.render("A", size="32x24")
    r.stream.save(stream)
    blocker = tmp_path / "a_file"
    blocker.write_text("in the way\n")
    out = str(blocker / "out")  # a folder that cannot be made: a file is there
    for call in (lambda: r.stream.save(out), lambda: fb89.trim(stream, out, frames="0"),
                 lambda: r.save_timeline(out), lambda: fb89.replay(stream, timeline=out)):
        with pytest.raises(fb89.FileError):
            call()
    assert blocker.read_text() == "in the way\n"


def test_a_bad_profile_is_an_option_error_everywhere(tmp_path):
    stream = str(tmp_path / "s.fb89")
    fb89.render("A", size="32x24").stream.save(stream)
    for call in (lambda: fb89.render("A", controller="tms9918"),
                 lambda: fb89.replay(stream, controller="tms9918"),
                 lambda: fb89.experiment("fig2.1", ["A"], controller="tms9918", progress=False),
                 lambda: fb89.sweep("threshold", "A", controller="tms9918", progress=False),
                 lambda: fb89.compare("A", controller="tms9918", progress=False)):
        with pytest.raises(fb89.OptionError, match="^profile: .*tms9918"):
            call()


def test_a_bad_host_is_an_option_error_everywhere():
    for call in (lambda: fb89.render("A", host="sun5-60"),
                 lambda: fb89.experiment("fig2.1", ["A"], host="sun5-60", progress=False),
                 lambda: fb89.compare("A", host="sun5-60", progress=False)):
        with pytest.raises(fb89.OptionError, match="host"):
            call()


def test_the_requests_name_the_keywords_not_the_options():
    with pytest.raises(fb89.OptionError, match="^start and stop: need 0 < start < stop$"):
        fb89.sweep("threshold", "A", start=1, stop=0.1)
    with pytest.raises(fb89.OptionError, match="^window_test: 'middle': area or centres$"):
        fb89.sweep("threshold", "A", window_test="middle")
    with pytest.raises(fb89.OptionError, match="^accel: 'kd': bvh or grid$"):
        fb89.experiment("fig4.8", accel="kd")
    with pytest.raises(fb89.OptionError, match="^method: 'warnock': hybrid or beam$"):
        fb89.calibrate("warnock")


# ---- a dict scene is named as such ----

A_SCENE = {
    "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fovy": 45,
               "near": 0.1, "far": 100},
    "image": {"width": 64, "height": 48},
    "background": [0, 0, 0],
    "objects": [{"polygon": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]],
                 "material": {"color": [1, 0, 0]}}],
}


def test_a_dict_scene_is_named_as_a_dict_scene_in_its_errors():
    bad = {"objects": [{"polygon": [[0, 0, 0]]}]}
    for call in (lambda: fb89.load_scene(bad), lambda: fb89.render(bad),
                 lambda: fb89.experiment("fig2.1", [bad], progress=False)):
        with pytest.raises(fb89.SceneError) as e:
            call()
        assert str(e.value).startswith("<dict scene>"), str(e.value)
        assert "fb89_scene_" not in str(e.value)
    with pytest.raises(fb89.SceneError, match="^room: "):
        fb89.load_scene(bad, name="room")


def test_a_dict_scene_goes_by_its_name_in_tables_headers_and_reprs():
    made = fb89.load_scene(A_SCENE)
    assert made.name == "<dict scene>" and "<dict scene>" in repr(made)
    r = fb89.render(made, size="32x24")
    assert r.stream.header["scene"] == "<dict scene>" and "<dict scene>" in repr(r)
    table = fb89.experiment("fig2.1", [made], size="32x24", repeat=1, progress=False)
    assert set(table["scene"]) == {"<dict scene>"}
    named = fb89.load_scene(A_SCENE, name="triangle")
    assert fb89.render(named, size="32x24").stream.header["scene"] == "triangle"


# ---- streams are checked when built ----

def frame_rows(n_spans=1):
    rows = np.zeros(2 + n_spans, dtype=fb89.COMMAND_DTYPE)
    rows[0] = (fb89.FRAME_BEGIN, 0, 0, 16, 8, 0, 0, 0, 0)
    for i in range(n_spans):
        rows[1 + i] = (fb89.DRAW_SPAN, 0, i, 8, 1, 255, 0, 0, 0)
    rows[-1] = (fb89.FRAME_END, 0, 0, 0, 0, 0, 0, 0, 0)
    return rows


@pytest.mark.parametrize("row,field,value,says", [
    (1, "opcode", 11, "row 1: opcode 11 is none of 1"),
    (1, "opcode", 0, "row 1: opcode 0 is none of 1"),
    (1, "w", 0, "row 1: DRAW_SPAN of width 0"),
    (0, "w", 0, r"row 0 \(FRAME_BEGIN\): width 0 is outside 1..16384"),
    (0, "h", 20000, r"row 0 \(FRAME_BEGIN\): height 20000 is outside 1..16384"),
])
def test_a_stream_of_rows_the_format_cannot_carry_is_refused_naming_the_row(row, field, value,
                                                                            says):
    rows = frame_rows()
    rows[row][field] = value
    with pytest.raises(fb89.OptionError, match="commands: " + says):
        fb89.Stream(rows)


def test_a_row_changed_after_the_stream_was_built_is_refused_by_save_and_replay(tmp_path):
    s = fb89.Stream(frame_rows(3))
    s.commands[2]["opcode"] = 7  # the commands are a writable view
    with pytest.raises(fb89.OptionError, match="commands: row 2: opcode 7"):
        s.save(str(tmp_path / "s.fb89"))
    with pytest.raises(fb89.OptionError, match="commands: row 2: opcode 7"):
        fb89.replay(s)
    assert list(tmp_path.iterdir()) == []


def test_markers_and_headers_are_checked_when_the_stream_is_built():
    rows = frame_rows()
    with pytest.raises(fb89.OptionError, match="markers: row 1 is not a MARKER"):
        fb89.Stream(rows, markers=[(1, "x")])
    with pytest.raises(fb89.OptionError, match="markers: row 9 is not a MARKER"):
        fb89.Stream(rows, markers=[(9, "x")])
    with pytest.raises(fb89.OptionError, match="header: property key"):
        fb89.Stream(rows, header={"": "empty key"})
    rows[1]["opcode"] = fb89.MARKER
    with pytest.raises(fb89.OptionError, match="markers: row 1: longer than"):
        fb89.Stream(rows, markers=[(1, "x" * 70000)])
    assert fb89.Stream(rows, markers=[(1, "ok")]).markers == [(1, "ok")]
