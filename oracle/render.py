"""Render a pour headless with PyBullet's software renderer (TinyRenderer):
an animated GIF, and optionally one PNG per frame."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np

from . import scoring
from pantarhei.oracle.base import Outcome
from pantarhei.oracle.fidelity import CHOSEN_FIDELITY, Fidelity
from pantarhei.oracle.stepping import run
from pantarhei.oracle.world import World


#: The most memory render's frames may take (bytes): it holds every frame
#: (3 bytes a pixel) and the GIF's palette copy of it (1 byte a pixel)
#: until the GIF is written, so frames x width x height x 4 bytes must stay
#: within this bound; a larger --size or --fps is refused before simulating.
FRAME_BYTES_AT_MOST = 512 * 2**20

#: Bytes a pixel of a frame takes while the GIF is made (see FRAME_BYTES_AT_MOST).
BYTES_A_PIXEL = 4


def frames_at_most(p: np.ndarray, fps: int,
                   fidelity: Fidelity = CHOSEN_FIDELITY) -> int:
    """The most frames a render of the pour `p` draws at `fps` frames per
    simulated second: its approach, retreat and longest settling, the first
    and the last frame."""
    from pantarhei.oracle import generative

    d = generative.to_dict(p)
    seconds = (d["approach_duration"] + d["retreat_duration"] + fidelity.settle_ms) / 1000.0
    return int(seconds * fps) + 2


def frame_bytes(p: np.ndarray, fps: int, width: int, height: int,
                fidelity: Fidelity = CHOSEN_FIDELITY) -> int:
    """The memory the frames of a render take at most (bytes)."""
    return frames_at_most(p, fps, fidelity) * width * height * BYTES_A_PIXEL


def _camera(client: Any, width: int, height: int) -> tuple[list[float], list[float]]:
    # from the side (-y), a little above the rim, looking at the space between the bowls
    view = client.computeViewMatrix(cameraEyePosition=[0.08, -0.62, 0.24],
                                    cameraTargetPosition=[0.08, 0.0, 0.1],
                                    cameraUpVector=[0, 0, 1])
    proj = client.computeProjectionMatrixFOV(fov=45, aspect=width / height, nearVal=0.02, farVal=3.0)
    return view, proj


def render(p: np.ndarray, out: str | Path, frames_dir: Optional[str | Path] = None, fps: int = 15,
           width: int = 480, height: int = 360,
           fidelity: Fidelity = CHOSEN_FIDELITY) -> tuple[int, Outcome]:
    """Simulate the pour `p` and write it as a GIF to `out` (and PNGs to
    `frames_dir`); the number of frames and the outcome."""
    from PIL import Image

    images: list[Image.Image] = []
    cam: dict[str, Any] = {}

    def on_frame(world: World, t: float) -> None:
        c = world.client
        if not cam:
            cam["view"], cam["proj"] = _camera(c, width, height)
        _, _, rgba, _, _ = c.getCameraImage(width, height, cam["view"], cam["proj"],
                                            lightDirection=[0.4, -0.6, 1.0], shadow=1,
                                            renderer=c.ER_TINY_RENDERER)
        arr = np.reshape(np.asarray(rgba, dtype=np.uint8), (height, width, 4))[:, :, :3]
        images.append(Image.fromarray(arr))

    record = run(np.asarray(p, dtype=float), fidelity, on_frame=on_frame, frame_hz=fps)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    images[0].save(out, save_all=True, append_images=images[1:], duration=int(1000 / fps),
                   loop=0, optimize=False)
    if frames_dir is not None:
        d = Path(frames_dir)
        d.mkdir(parents=True, exist_ok=True)
        for k, im in enumerate(images):
            im.save(d / f"frame_{k:04d}.png")
    return len(images), Outcome(scoring.scores(record), record)
