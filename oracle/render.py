"""Render a pour headless with PyBullet's software renderer (TinyRenderer):
an animated GIF, and optionally one PNG per frame."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np

from . import physics, scoring
from pantarhei.oracle.base import Outcome
from pantarhei.oracle.stepping import run
from pantarhei.oracle.world import World


def _camera(client: Any, width: int, height: int) -> tuple[list[float], list[float]]:
    # from the side (-y), a little above the rim, looking at the space between the bowls
    view = client.computeViewMatrix(cameraEyePosition=[0.08, -0.62, 0.24],
                                    cameraTargetPosition=[0.08, 0.0, 0.1],
                                    cameraUpVector=[0, 0, 1])
    proj = client.computeProjectionMatrixFOV(fov=45, aspect=width / height, nearVal=0.02, farVal=3.0)
    return view, proj


def render(p: np.ndarray, out: str | Path, frames_dir: Optional[str | Path] = None, fps: int = 15,
           width: int = 480, height: int = 360,
           fidelity: physics.Fidelity = physics.CHOSEN_FIDELITY) -> tuple[int, Outcome]:
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
