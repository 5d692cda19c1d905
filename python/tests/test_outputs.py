"""Every Python function that writes files writes them as the command line does (issue 50): all
together or not at all, under an OutputBatch of the call's own. One table: each function with an
output path x each way it can fail (bad input found late, a selection that matches nothing, a
later output that cannot be written, rows the format cannot carry), with and without old files
there before; after the failure every old file is byte for byte as it was and nothing new is
left, neither a partial file nor a hidden temporary."""
import threading

import numpy as np
import pytest

import fb89

OLD = b"precious: must survive a failed call\n"

def everything(folder):
    """Every file under `folder` (hidden ones too) -> its bytes; folders -> None."""
    return {p.relative_to(folder).as_posix(): (None if p.is_dir() else p.read_bytes())
            for p in sorted(folder.rglob("*"))}


def rows_of_frames(frames, spans=40, colour=(255, 0, 0)):
    rows = np.zeros(frames * (spans + 2), dtype=fb89.COMMAND_DTYPE)
    i = 0
    for f in range(frames):
        rows[i] = (fb89.FRAME_BEGIN, 0, 0, 64, 48, 0, 0, 0, f)
        i += 1
        for y in range(spans):
            rows[i] = (fb89.DRAW_SPAN, 0, y, 32, 1, *colour, 0)
            i += 1
        rows[i] = (fb89.FRAME_END, 0, 0, 0, 0, 0, 0, 0, 0)
        i += 1
    return rows


def cut_in_the_last_frame(path):
    """The stream file cut inside its last frame's spans, mid-record."""
    data = path.read_bytes()
    path.write_bytes(data[:len(data) - 300 + 7])


@pytest.fixture(scope="module")
def inputs(tmp_path_factory):
    """Streams the failing calls read, in a folder apart from the one checked."""
    folder = tmp_path_factory.mktemp("inputs")
    good = folder / "good.fb89"
    fb89.Stream(rows_of_frames(3)).save(str(good))
    cut = folder / "cut.fb89"
    fb89.Stream(rows_of_frames(3)).save(str(cut))
    cut_in_the_last_frame(cut)
    other_cut = folder / "other_cut.fb89"  # frame 0 differs from good's, then it is cut
    rows = rows_of_frames(3)
    rows[1]["g"] = 255
    fb89.Stream(rows).save(str(other_cut))
    cut_in_the_last_frame(other_cut)
    return {"good": str(good), "cut": str(cut), "other_cut": str(other_cut)}


def save_a_row_gone_bad(i, out):
    s = fb89.Stream(rows_of_frames(3))
    s.commands[len(s) - 2]["opcode"] = 11  # found late: the last span
    s.save(out["out.fb89"])


def replay_a_row_gone_bad(i, out):
    s = fb89.Stream(rows_of_frames(3))
    s.commands[len(s) - 2]["opcode"] = 11
    fb89.replay(s, timeline=out["timeline.json"])


def replay_without_a_complete_frame(i, out):
    fb89.replay(fb89.Stream(rows_of_frames(1)[:-1]), timeline=out["timeline.json"])


def compare_with(unwritable):
    def call(i, out):
        targets = dict(out)
        targets[unwritable] = out[unwritable + "/"]  # a folder: cannot be written as a file
        fb89.compare("A", size="48x36", repeat=1, progress=False, sheet=targets["sheet.png"],
                     csv=targets["table.csv"], json=targets["rows.json"])
    return call


# (name, the outputs it writes (a name ending in "/" is a folder in the way), the call, the error)
CASES = [
    ("save, invalid rows", ["out.fb89"], save_a_row_gone_bad, fb89.OptionError),
    ("trim, bad input found late", ["out.fb89"],
     lambda i, out: fb89.trim(i["cut"], out["out.fb89"], frames="0-"), fb89.FileError),
    ("trim, a selection that matches nothing", ["out.fb89"],
     lambda i, out: fb89.trim(i["good"], out["out.fb89"], calls="100000-"), fb89.OptionError),
    ("diff, bad input found late", ["diff.png"],
     lambda i, out: fb89.diff(i["good"], i["other_cut"], image=out["diff.png"]), fb89.FileError),
    ("replay, invalid rows", ["timeline.json"], replay_a_row_gone_bad, fb89.OptionError),
    ("replay, no complete frame", ["timeline.json"], replay_without_a_complete_frame,
     fb89.FileError),
    ("compare, an unwritable later output", ["sheet.png", "table.csv", "rows.json/"],
     compare_with("rows.json"), fb89.FileError),
    ("compare, an unwritable middle output", ["sheet.png", "table.csv/", "rows.json"],
     compare_with("table.csv"), fb89.FileError),
]


def params():
    for name, outputs, call, error in CASES:
        for old in (True, False):
            yield pytest.param(outputs, call, error, old,
                               id=f"{name}, {'old files there' if old else 'no old files'}")


@pytest.mark.parametrize("outputs,call,error,old", params())
def test_a_failed_call_leaves_every_old_file_and_no_new_one(inputs, tmp_path, outputs, call,
                                                            error, old):
    out = {}
    for name in outputs:
        target = tmp_path / name.rstrip("/")
        if name.endswith("/"):
            target.mkdir()
            (target / "kept").write_bytes(OLD)
            out[name] = str(target)
            out[name.rstrip("/")] = None
        else:
            if old:
                target.write_bytes(OLD)
            out[name] = str(target)
    before = everything(tmp_path)
    with pytest.raises(error):
        call(inputs, out)
    assert everything(tmp_path) == before


def test_each_case_writes_its_outputs_when_nothing_fails(inputs, tmp_path):
    # the same calls, well made, write where the failing ones did not, folders made
    deep = tmp_path / "made" / "on" / "the way"
    s = fb89.Stream(rows_of_frames(3))
    s.save(str(deep / "out.fb89"))
    assert fb89.Stream.open(str(deep / "out.fb89")).frames == 3
    kept = fb89.trim(inputs["good"], str(deep / "trim" / "out.fb89"), frames="1")
    assert kept["frames"] == 1
    rows = rows_of_frames(3)
    rows[1]["g"] = 255
    fb89.Stream(rows).save(str(tmp_path / "other.fb89"))
    d = fb89.diff(inputs["good"], str(tmp_path / "other.fb89"), image=str(deep / "d" / "d.png"))
    assert d.image_frame == 0 and (deep / "d" / "d.png").read_bytes()[:4] == b"\x89PNG"
    fb89.replay(s, timeline=str(deep / "t" / "timeline.json"))
    assert (deep / "t" / "timeline.json").read_text().lstrip().startswith("{")
    fb89.render("A", size="32x24").save_timeline(str(deep / "r" / "render.json"))
    c = fb89.compare("A", size="48x36", repeat=1, progress=False,
                     sheet=str(deep / "c" / "sheet.png"), csv=str(deep / "c" / "t.csv"),
                     json=str(deep / "c" / "rows.json"))
    assert (deep / "c" / "t.csv").read_text() == c.table.csv()
    assert not [p for p in tmp_path.rglob(".*")]  # no hidden temporary left anywhere


def test_threads_that_write_take_turns(tmp_path):
    # the batch is the process's: calls that write wait for each other, never mix their files
    s = fb89.Stream(rows_of_frames(2))
    expected = None
    errors = []

    def save(k):
        try:
            for n in range(10):
                s.save(str(tmp_path / f"t{k}" / f"{n}.fb89"))
        except Exception as e:  # noqa: BLE001 (reported below)
            errors.append(e)

    threads = [threading.Thread(target=save, args=(k,)) for k in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    for k in range(3):
        for n in range(10):
            data = (tmp_path / f"t{k}" / f"{n}.fb89").read_bytes()
            expected = expected or data
            assert data == expected


def test_a_call_that_writes_from_inside_anothers_progress_is_refused(tmp_path):
    s = fb89.Stream(rows_of_frames(1))

    def save_while_experimenting(what, done, total, unit):
        s.save(str(tmp_path / "inner.fb89"))

    with pytest.raises(fb89.Error, match="progress callback"):
        fb89.experiment("fig2.1", ["A"], size="32x24", repeat=1,
                        progress=save_while_experimenting)
    assert not (tmp_path / "inner.fb89").exists()
