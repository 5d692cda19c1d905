"""fb89.radiosity, model, host_validate, controller_validate and info against the commands
they are (fb89 radiosity, model, host-validate, controller-validate, info), the profile=
keyword and its old name controller=, the check of unknown keywords, and checksums as the
commands print them.

FB89_CLI names the fb89 executable of the same build; PYTHONPATH the build's python folder.
"""
import json
import os
import re
import subprocess

import numpy as np
import pytest

import fb89

CLI = os.environ.get("FB89_CLI", "fb89")
SMALL = dict(patches=120, size="256x195")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, check=False)


# ---- radiosity ----

def test_radiosity_hierarchical_gives_the_image_and_the_counts():
    r = fb89.radiosity("garish_room", ff="hierarchical")
    assert r.image.shape == (780, 1024, 3) and r.image.dtype == np.uint8
    assert r.ids.shape == (780, 1024) and r.ids.dtype == np.int32
    h = r.counts["hierarchical"]
    assert h["leaves"] == r.counts["patches"] > 29 and h["links"] > 0 and h["rays"] > 0
    assert r.counts["solver"] == "push-pull" and r.counts["converged"]
    assert r.counts["counters"]["flux_rays"] == h["rays"]
    assert "hierarchy:" in r.summary and "form factors hierarchical" in r.summary
    assert r.ids.min() >= 0, "every pixel of the closed room is some patch's"


def test_radiosity_counts_and_image_are_the_commands(tmp_path):
    stats, png = tmp_path / "s.json", tmp_path / "r.png"
    run = cli("radiosity", "garish_room", "--ff", "hybrid", "--patches", "120", "--size",
              "256x195", "-q", "--stats", str(stats), "--png", str(png))
    assert run.returncode == 0, run.stderr
    want = json.loads(stats.read_text())
    r = fb89.radiosity("garish_room", ff="hybrid", **SMALL)
    for key in ("patches", "elements", "iterations", "residual", "max_row_sum", "exposure"):
        assert r.counts[key] == want["radiosity"][key], key
    for name in ("radiosity_facing_pairs", "flux_rays", "volume_queries"):
        if name in want["host"]["counters"]:
            assert r.counts["counters"][name] == want["host"]["counters"][name], name
    assert r.controller_figures["frames"][0]["checksum"] == \
        want["controller"]["frames"][0]["checksum"]
    import matplotlib.image
    image = (matplotlib.image.imread(str(png))[..., :3] * 255).round().astype(np.uint8)
    assert np.array_equal(image, r.image)


def test_radiosity_takes_every_ff_and_the_hierarchys_options():
    for ff in ("flux", "hybrid", "disk", "exact"):
        assert fb89.radiosity("garish_room", ff=ff, **SMALL).counts["ff"] == ff
    hemi = fb89.radiosity("garish_room", ff="hemicube", hemicube_res=16, **SMALL)
    assert hemi.stats["radiosity"]["hemicube_res"] == 16
    plain = fb89.radiosity("garish_room", ff="hierarchical", epsilon=0.05, link_rays=2,
                           min_area=0.05, max_links=100000, **SMALL)
    culled = fb89.radiosity("garish_room", ff="hierarchical", epsilon=0.05, link_rays=2,
                            min_area=0.05, max_links=100000, shaft_culling=True, **SMALL)
    h = culled.counts["hierarchical"]
    assert h["epsilon"] == 0.05 and h["link_rays"] == 2 and h["shaft_culling"]
    assert h["rays"] < plain.counts["hierarchical"]["rays"]
    assert np.array_equal(plain.image, culled.image)
    prog = fb89.radiosity("garish_room", solver="progressive", tolerance=1e-3,
                          max_iterations=50, exposure=2.0, **SMALL)
    assert prog.counts["solver"] == "progressive" and prog.counts["exposure"] == 2.0
    adaptive = fb89.radiosity("garish_room", adaptive=0.3, adaptive_passes=1, **SMALL)
    assert len(adaptive.counts["adaptive"]["patches_per_pass"]) >= 1


def test_radiosity_refuses_what_the_command_refuses():
    with pytest.raises(fb89.OptionError, match="^epsilon: only ff='hierarchical'"):
        fb89.radiosity("garish_room", epsilon=0.1)
    with pytest.raises(fb89.OptionError, match="^solver: ff='hierarchical'"):
        fb89.radiosity("garish_room", ff="hierarchical", solver="progressive")
    with pytest.raises(fb89.OptionError, match="^hemicube_res: only ff='hemicube'"):
        fb89.radiosity("garish_room", hemicube_res=64)
    with pytest.raises(fb89.OptionError, match="^adaptive_passes: needs adaptive="):
        fb89.radiosity("garish_room", adaptive_passes=2)
    with pytest.raises(fb89.OptionError, match="^ff: 'beams'.*did you mean 'beam'|^ff: 'beams'"):
        fb89.radiosity("garish_room", ff="beams")
    with pytest.raises(fb89.OptionError, match=r"^patches: 0 is not in \[1, 8192\]"):
        fb89.radiosity("garish_room", patches=0)
    with pytest.raises(fb89.OptionError, match=r"^link_rays: 0 is not in \[1, 4096\]"):
        fb89.radiosity("garish_room", ff="hierarchical", link_rays=0)
    with pytest.raises(TypeError, match="shaft_culling"):
        fb89.radiosity("garish_room", ff="hierarchical", shaft_culling=1)
    with pytest.raises(fb89.OptionError, match="no face emits light"):
        fb89.radiosity("demo")


def test_radiosity_writes_the_commands_files(tmp_path):
    out = {k: tmp_path / f"r.{k}" for k in ("png", "ids", "ids_view", "stream", "stats")}
    r = fb89.radiosity("garish_room", **SMALL, **{k: str(v) for k, v in out.items()})
    assert all(p.exists() for p in out.values())
    assert json.loads(out["stats"].read_text())["radiosity"]["patches"] == r.counts["patches"]
    saved = fb89.Stream.open(str(out["stream"]))
    assert np.array_equal(saved.commands, r.stream.commands)
    assert fb89.replay(saved).checksum == r.controller_figures["frames"][0]["checksum"]


# ---- model ----

def test_model_is_the_commands_table(tmp_path):
    csv = tmp_path / "m.csv"
    assert cli("model", "--es", "16..64*2", "--fv", "1,4", "--csv", str(csv)).returncode == 0
    t = fb89.model(es="16..64*2", fv=[1, 4])
    assert t.csv() == csv.read_text()
    assert len(t) == 6 and t.columns[:3] == ["e_s", "f_v", "d"]
    assert str(t) == cli("model", "--es", "16..64*2", "--fv", "1,4").stdout
    samples, windows = fb89.model(es=64, fv=16, fw=[16, 64], ew=8, faces=100)
    assert "expr_2_7" in windows.columns and len(windows) == 2 and len(samples) == 1
    with pytest.raises(fb89.OptionError, match="^fv: Eq. 2.4 needs both es and fv"):
        fb89.model(es=16)
    with pytest.raises(fb89.OptionError, match="^es: expected a positive number"):
        fb89.model(es=-1, fv=1)


# ---- the validations ----

def test_controller_validate_is_the_commands_table(tmp_path):
    csv = tmp_path / "c.csv"
    run = cli("controller-validate", "--csv", str(csv))
    v = fb89.controller_validate()
    assert isinstance(v, fb89.Table) and v.table is v
    assert v.table.csv() == csv.read_text()
    assert v.table.columns[:3] == ["figure", "unit", "source"] and len(v.table) > 5
    assert v.text == cli("controller-validate").stdout
    assert v.all_pass == (cli("controller-validate", "--check", "-q").returncode == 0)
    assert run.returncode == 0 and v.listing is None
    assert "cycles" in fb89.controller_validate(listing=True).listing.lower()
    with pytest.raises(fb89.OptionError, match="^profile: "):
        fb89.controller_validate(profile="ideal")


def test_host_validate_is_the_commands_table(tmp_path):
    csv = tmp_path / "h.csv"
    run = cli("host-validate", "--profile", "sun3-60", "--csv", str(csv), "-q")
    assert run.returncode == 0, run.stderr
    v = fb89.host_validate(profile="sun3-60", progress=False)
    assert v.table.csv() == csv.read_text()
    assert v.table.columns[:3] == ["kernel", "profile", "figure"]
    assert set(v.table["profile"]) >= {"sun3-60"}
    assert "sources:" in v.text
    with pytest.raises(fb89.OptionError, match="^profile: "):
        fb89.host_validate(profile="sun5-60")


# ---- info ----

def test_info_is_what_info_json_reports(tmp_path):
    path = tmp_path / "s.fb89"
    fb89.render("A", size="64x48").stream.save(str(path))
    want = json.loads(cli("info", str(path), "--json").stdout)
    got = fb89.info(path)
    assert got == want
    assert re.fullmatch(r"[0-9a-f]{16}", got["frames"][0]["checksum"])
    assert got["frames"][0]["checksum"] == fb89.replay(str(path)).checksum
    assert fb89.info(str(path), profile="ideal")["bytes_profile"] == "ideal"
    with pytest.raises(fb89.FileError):
        fb89.info(tmp_path / "missing.fb89")


# ---- profile=, controller=, unknown keywords, checksums ----

def test_profile_is_taken_everywhere_controller_was(tmp_path):
    r = fb89.render("A", size="32x24", profile="tms34020-40mhz")
    assert r.profile == r.controller == "tms34020-40mhz"
    old = fb89.render("A", size="32x24", controller="tms34020-40mhz")
    assert old.profile == "tms34020-40mhz"
    assert fb89.replay(r.stream, profile="ideal").stats["profile"]["name"] == "ideal"
    for call in (lambda **k: fb89.render("A", size="32x24", **k),
                 lambda **k: fb89.replay(r.stream, **k),
                 lambda **k: fb89.experiment("fig2.1", ["A"], progress=False, **k),
                 lambda **k: fb89.sweep("threshold", "A", progress=False, **k),
                 lambda **k: fb89.compare("A", progress=False, **k),
                 lambda **k: fb89.radiosity("garish_room", **k),
                 lambda **k: fb89.info(tmp_path / "none.fb89", **k),
                 lambda **k: fb89.controller_validate(**k)):
        with pytest.raises(TypeError, match="profile=.*controller=.*give one"):
            call(profile="ideal", controller="ideal")


def test_an_unknown_keyword_is_named_with_the_known_ones():
    with pytest.raises(TypeError, match=r"render\(\) got an unknown keyword 'methd'; did you "
                                        r"mean 'method'\? \(its keywords: .*threshold"):
        fb89.render("demo", methd="zbuffer")
    with pytest.raises(TypeError, match="'epsilom'; did you mean 'epsilon'"):
        fb89.radiosity("garish_room", epsilom=0.1)
    with pytest.raises(TypeError, match="'frobnicate' \\(its keywords: es, fv, d"):
        fb89.model(frobnicate=1)
    with pytest.raises(TypeError, match="Stream.open\\(\\) got an unknown keyword 'call'; "
                                        "did you mean 'calls'"):
        fb89.Stream.open("x.fb89", call="/span")
    stream = fb89.render("A", size="32x24").stream
    with pytest.raises(TypeError, match="Stream.save\\(\\) got an unknown keyword 'file'; "
                                        "did you mean 'path'|Stream.save\\(\\) got an unknown "
                                        "keyword 'file'"):
        stream.save(file="x.fb89")
    for function in (fb89.experiment, fb89.sweep, fb89.compare, fb89.calibrate, fb89.replay,
                     fb89.trim, fb89.diff, fb89.load_scene, fb89.host_validate,
                     fb89.controller_validate, fb89.info):
        with pytest.raises(TypeError, match="unknown keyword 'nonsense'"):
            function("x", nonsense=1) if function not in (
                fb89.host_validate, fb89.controller_validate) else function(nonsense=1)


def test_checksums_are_shown_as_the_commands_print_them(tmp_path):
    path = tmp_path / "s.fb89"
    fb89.render("A", size="64x48").stream.save(str(path))
    printed = cli("replay", str(path)).stdout
    checksum = fb89.replay(str(path)).checksum
    assert re.fullmatch(r"[0-9a-f]{16}", checksum)
    assert checksum in printed


def test_the_stubs_name_every_call_with_its_keywords():
    import ast
    import inspect
    stubs = ast.parse(open(os.path.join(os.path.dirname(fb89.__file__), "__init__.pyi")).read())
    declared = {node.name: node for node in stubs.body
                if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    for name in fb89.__all__:
        thing = getattr(fb89, name)
        if inspect.isclass(thing) or not callable(thing):
            assert name in declared or name.isupper(), name
            continue
        assert name in declared, name
        stub = declared[name].args
        keywords = [a.arg for a in stub.args + stub.kwonlyargs]
        try:
            real = list(inspect.signature(thing).parameters)
        except ValueError:  # a compiled function: its own stub is its docstring
            continue
        assert sorted(keywords) == sorted(real), name
