"""glint.render: one frame of `glint render` as a numpy array, pixel for pixel the PNG the command
writes for the same frame and options (headless GL: llvmpipe here, the GPU's driver there)."""
import os
import subprocess

import numpy as np
import pytest
from PIL import Image

import glint

CLI = os.environ.get("GLINT_CLI")
FRAME, WIDTH, HEIGHT = 2100, 160, 90


def test_render_equals_the_cli_png(tmp_path):
    image = glint.render("atrium-simple", frame=FRAME, width=WIDTH, height=HEIGHT, reflections="hybrid")
    assert image.dtype == np.uint8 and image.shape == (HEIGHT, WIDTH, 4)
    assert (image[..., 3] == 255).all()
    assert image[..., :3].std() > 10  # a picture, not a cleared target
    if not CLI:
        pytest.skip("GLINT_CLI is not set (CTest sets it to the built glint)")
    subprocess.run([CLI, "render", "atrium-simple", "--frames", str(FRAME), "--width", str(WIDTH),
                    "--height", str(HEIGHT), "--reflections", "hybrid", "--out", str(tmp_path), "--overwrite"],
                   check=True, capture_output=True)
    pngs = sorted(p for p in os.listdir(tmp_path) if p.endswith(".png"))
    assert len(pngs) == 1, pngs
    written = np.asarray(Image.open(tmp_path / pngs[0]).convert("RGBA"))
    np.testing.assert_array_equal(image, written)


def test_render_options_change_the_frame():
    off = glint.render("atrium-simple", frame=FRAME, width=WIDTH, height=HEIGHT, reflections="off")
    hybrid = glint.render("atrium-simple", frame=FRAME, width=WIDTH, height=HEIGHT, reflections="hybrid")
    assert off.shape == hybrid.shape
    assert (off != hybrid).any(axis=2).mean() > 0.01  # the polished floor shows reflections


@pytest.mark.parametrize("kwargs,match", [
    (dict(frame=10**6), r"past the walkthrough's last frame"),
    (dict(frame=-1), r"frame selection"),
    (dict(width=0), r"width and height must be 1 to 16384 pixels, got 0x90"),
    (dict(reflections="mirror"), r"mirror"),
    (dict(scene="no-such-scene.obj"), r"no-such-scene.obj"),
])
def test_render_errors(kwargs, match):
    args = dict(scene="atrium-simple", frame=FRAME, width=WIDTH, height=HEIGHT)
    args.update(kwargs)
    with pytest.raises(glint.Error, match=match):
        glint.render(**args)
