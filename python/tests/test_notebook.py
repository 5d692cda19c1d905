"""What a notebook can now do that the command line does (issue 50): compare() as `fb89
compare`, buffer= on render() and replay() as --buffer, and the timeline as render's and
replay's --timeline; each checked against the command line of the same build."""
import csv
import io
import json
import os
import re
import subprocess

import matplotlib.image
import pytest

import fb89

CLI = os.environ.get("FB89_CLI", "fb89")

# what compare counts (not times): the same in both front ends
COUNTED = ("scene", "method", "host", "commands", "fills", "spans", "bound_by",
           "pixels_differing")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False)


# ---- compare ----

def test_compare_is_the_command_lines_table_rows_and_sheet(tmp_path):
    sheet, table, rows = tmp_path / "s.png", tmp_path / "t.csv", tmp_path / "r.json"
    done = cli("compare", "A", "--size", "96x73", "--repeat", "1", "-q", "--sheet", str(sheet),
               "--csv", str(table), "--json", str(rows))
    assert done.returncode == 0, done.stderr
    c = fb89.compare("A", size=(96, 73), repeat=1, progress=False)
    theirs = list(csv.DictReader(io.StringIO(table.read_text())))
    assert c.table.columns == list(theirs[0].keys()) and len(c.table) == len(theirs)
    for mine, other in zip(c.table, theirs):
        for column in COUNTED:
            assert str(mine[column]) == other[column], column
    their_rows = json.loads(rows.read_text())
    assert [sorted(r) for r in c.rows] == [sorted(r) for r in their_rows]
    assert [r["pixels_differing"] for r in c.rows] == [r["pixels_differing"] for r in their_rows]
    assert c.sheet.shape == matplotlib.image.imread(sheet).shape[:2] + (3,)
    assert set(c.frames) == set(fb89.methods())
    assert all(f.shape == (73, 96, 3) for f in c.frames.values())
    assert c.thresholds.startswith("hybrid threshold")
    assert {p.name for p in tmp_path.iterdir()} == {"s.png", "t.csv", "r.json"}  # nothing more


def test_compare_writes_only_what_it_is_asked_to(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    fb89.compare("A", size="48x36", repeat=1, progress=False)
    assert list(tmp_path.iterdir()) == []  # unlike the command, no out/compare.png unasked
    fb89.compare("A", size="48x36", repeat=1, progress=False, csv="t.csv")
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]


# ---- buffer= ----

def test_render_takes_the_command_buffer_as_render_buffer_does(tmp_path):
    stats = tmp_path / "stats.json"
    done = cli("render", "A", "--size", "96x73", "-q", "--buffer", "4096", "--stats", str(stats))
    assert done.returncode == 0, done.stderr
    theirs = json.loads(stats.read_text())["pipeline"]
    mine = fb89.render("A", size="96x73", buffer=4096).pipeline
    assert mine["buffer_bytes"] == theirs["buffer_bytes"] == 4096
    assert sorted(mine) == sorted(theirs)
    assert fb89.render("A", size="96x73", buffer="unbounded").pipeline["buffer_bytes"] == \
        fb89.render("A", size="96x73").pipeline["buffer_bytes"]
    with pytest.raises(fb89.OptionError, match="^buffer: 5 bytes cannot hold a command"):
        fb89.render("A", buffer=5)
    with pytest.raises(fb89.OptionError, match=r"^buffer: 0 is not in \[1, 1099511627776\]"):
        fb89.render("A", buffer=0)
    with pytest.raises(fb89.OptionError, match="^buffer: 'lots': a whole number of bytes"):
        fb89.render("A", buffer="lots")
    with pytest.raises(TypeError, match="^buffer"):
        fb89.render("A", buffer=True)


def pipeline_lines(text):
    """replay --buffer's per-frame line as numbers: frame, host, stalled, idle ms, high water."""
    pattern = (r"pipeline, frame (\d+) .*: frame ([\d.]+) ms, host ([\d.]+) ms, host stalled "
               r"([\d.]+) ms \(bus or full buffer\), controller idle ([\d.]+) ms, buffer high water (\d+) bytes")
    return [tuple(float(x) for x in m.groups()) for m in re.finditer(pattern, text)]


@pytest.mark.parametrize("untimed", [False, True])
def test_replay_follows_each_frame_through_the_buffer_as_replay_buffer_does(tmp_path, untimed):
    stream = str(tmp_path / "a.fb89")
    done = cli("render", "A", "--size", "96x73", "-q", "--stream", stream,
               *(["--untimed-stream"] if untimed else []))
    assert done.returncode == 0, done.stderr
    theirs = pipeline_lines(cli("replay", stream, "--buffer", "2048").stdout)
    mine = fb89.replay(stream, buffer=2048).pipelines
    assert len(mine) == len(theirs) == 1
    p = mine[0]
    assert (0, round(p["frame_ms"], 3), round(p["host_ms"], 3), round(p["host_stalled_ms"], 3),
            round(p["controller_idle_ms"], 3), p["buffer_high_water_bytes"]) == \
        pytest.approx(theirs[0], abs=1.5e-3)
    assert p["buffer_bytes"] == 2048
    assert fb89.replay(stream).pipelines is None
    with pytest.raises(fb89.OptionError, match="^buffer: 5 bytes cannot hold"):
        fb89.replay(stream, buffer=5)


# ---- the timeline ----

@pytest.mark.parametrize("buffer", [None, "1024"])
def test_replays_timeline_is_the_command_lines_byte_for_byte(tmp_path, buffer):
    stream = str(tmp_path / "a.fb89")
    assert cli("render", "G", "--method", "beam", "--size", "96x73", "-q", "--stream",
               stream).returncode == 0
    theirs, mine = tmp_path / "theirs.json", tmp_path / "mine.json"
    done = cli("replay", stream, "-q", "--timeline", str(theirs),
               *(["--buffer", buffer] if buffer else []))
    assert done.returncode == 0, done.stderr
    fb89.replay(stream, timeline=str(mine), buffer=int(buffer) if buffer else None)
    assert mine.read_bytes() == theirs.read_bytes()


def test_a_renders_timeline_has_the_command_lines_lanes_and_events(tmp_path):
    theirs = tmp_path / "theirs.json"
    done = cli("render", "A", "--method", "warnock", "--size", "96x73", "-q", "--timeline",
               str(theirs))
    assert done.returncode == 0, done.stderr
    r = fb89.render("A", method="warnock", size="96x73")
    mine = r.timeline()
    other = json.loads(theirs.read_text())
    # the times are measured, so differ run to run; what happened does not
    def shape(trace):
        return sorted((e.get("ph"), e.get("name"), e.get("tid")) for e in trace["traceEvents"]
                      if e.get("name") != "stall")
    assert shape(mine) == shape(other)
    assert mine["otherData"]["title"] == other["otherData"]["title"]
    saved = tmp_path / "saved.json"
    r.save_timeline(str(saved))
    assert json.loads(saved.read_text()) == mine
