"""Accuracy as the profile's controller draws it: the depth commands' frames with the
profile's depth word, in compare() and render(), the same counts as the command line."""
import os
import re
import subprocess

import numpy as np

import fb89

CLI = os.environ.get("FB89_CLI", "fb89")


def test_compare_counts_the_depth_words_ties_as_render_ids_does(tmp_path):
    rows = {r["method"]: r for r in fb89.compare("demo", repeat=1).rows}
    ids = tmp_path / "zspans.ids.png"
    out = subprocess.run([CLI, "render", "demo", "--method", "zspans", "--ids",
                          str(ids)], capture_output=True, text=True, check=True).stdout
    m = re.search(r"\((\d+)-bit depth word\): ([\d,]+) of [\d,]+ pixels differ: ([\d,]+) ties",
                  out)
    assert m, out
    assert rows["zspans"]["depth_bits"] == int(m.group(1)) == 16
    assert rows["zspans"]["pixels_differing"] == int(m.group(2).replace(",", ""))
    assert rows["zspans"]["px_ties"] == int(m.group(3).replace(",", "")) > 1000
    assert rows["faces"]["px_ties"] > 1000 and rows["faces"]["faces"] > 0
    assert "px_ties" not in rows["zbuffer"]


def test_the_depth_commands_image_is_the_profiles_frame():
    board = fb89.render("demo", method="zspans").ids
    ideal = fb89.render("demo", method="zspans", profile="ideal").ids
    zbuffer = fb89.render("demo").ids
    assert np.count_nonzero(board != zbuffer) > 1000  # the 16-bit word's ties
    assert np.count_nonzero(ideal != zbuffer) < 100  # the 32-bit word tells them apart
