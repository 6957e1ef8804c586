"""oracle/render.py: a pour rendered headless as an animated GIF and one
PNG per frame (through `pantarhei render`, as a user would)."""
from __future__ import annotations

import pytest


@pytest.mark.slow
def test_render_writes_a_gif_and_frames(cli, tmp_path):
    out = tmp_path / "pour.gif"
    r = cli("render", "--antecedent", "pour_centred,pour_low,pour_steeply_tilted,little_liquid",
            "--seed", "1", "--out", str(out), "--frames", str(tmp_path / "frames"), "--fps", "5",
            "--size", "160x120")
    assert r.code == 0, r.err
    from PIL import Image
    with Image.open(out) as im:
        assert im.size == (160, 120) and im.n_frames > 3
        n = im.n_frames
    pngs = sorted((tmp_path / "frames").glob("*.png"))
    assert len(pngs) >= n       # a GIF merges identical frames (everything at rest)
    with Image.open(pngs[0]) as a, Image.open(pngs[-1]) as b:
        assert a.tobytes() != b.tobytes()       # something moved
